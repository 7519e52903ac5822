// chart.h — text and charts drawn with libtiny3d's own canvas and lines.
//
// Part of the benchmarks' own library (tests/bench/common, not libtiny3d.a): the
// benchmarks draw their "time against error" charts with it; `make docs-charts` converts
// the charts to PNG with the library's save_png (canvas.h). Everything is in namespace tiny3d.
//
// Coordinates are canvas pixels as in canvas.h: origin top-left, y down, pixel (x, y)
// covers [x, x+1) × [y, y+1). Text positions are integer pixel corners.
#ifndef TINY3D_CHART_H
#define TINY3D_CHART_H

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "canvas.h"
#include "tiny3d_result.h"

namespace tiny3d {

// ---- the built-in bitmap font ---------------------------------------------------------
// A 5 × 7 pixel font for printable ASCII (32..126), defined in code (tests/bench/common/font.cpp).
// Any other character (each UTF-8 code point counts once) is drawn as a hollow box.
inline constexpr int font_glyph_width = 5;   // ink columns per glyph
inline constexpr int font_glyph_height = 7;  // ink rows per glyph
inline constexpr int font_advance = 6;       // glyph + one blank column
inline constexpr int font_line_height = 9;   // glyph + two blank rows

// True when the glyph of `c` has ink at (column, row), column 0..4 left to right, row
// 0..6 top to bottom; false outside that cell.
bool font_glyph_pixel(char32_t c, int column, int row);

// Width in pixels of `text` (UTF-8) drawn at `scale` (each font pixel becomes a
// scale × scale block): code points × font_advance × scale, minus the trailing blank
// column; 0 for empty text or scale < 1.
int text_width(std::string_view text, int scale = 1);
// Height in pixels of one line of text: font_glyph_height × scale (0 for scale < 1).
int text_height(int scale = 1);

// Draws `text` with its top-left corner at pixel (x, y): every ink pixel is SET to
// `intensity` (clamped to 0..1; not added). Parts outside the canvas are dropped; scale < 1
// draws nothing. Newlines are not interpreted (one line only).
void draw_text(canvas_t &canvas, int x, int y, std::string_view text, float intensity, int scale = 1);
// The same text turned 90° counter-clockwise (reads bottom to top), for vertical axis
// titles. (x, y) is the top-left corner of its box, text_height wide and text_width tall.
void draw_text_vertical(canvas_t &canvas, int x, int y, std::string_view text, float intensity,
                        int scale = 1);

// ---- axes ------------------------------------------------------------------------------
enum class axis_scale { linear, log10 };

// A value range drawn along one axis. Valid when lo < hi (both finite), and for log10
// when lo > 0.
struct axis_range {
    double lo = 0.0;
    double hi = 1.0;
    axis_scale scale = axis_scale::linear;
};

// Value → pixel coordinate along an axis whose ends lie at pixel coordinates p_lo (for
// range.lo) and p_hi (for range.hi). With t = (v − lo)/(hi − lo) (linear) or
// t = (log10 v − log10 lo)/(log10 hi − log10 lo) (log10) the result is (1 − t)·p_lo + t·p_hi,
// so the ends map exactly to p_lo and p_hi, decades of a log axis are equally spaced, and
// values outside the range extrapolate. NaN for a non-finite value, a value ≤ 0 on a log10
// axis, or an invalid range.
double axis_to_pixel(const axis_range &range, double value, double p_lo, double p_hi);

// A range that covers the finite `values`: log10 when all are > 0 and they span at least
// a factor of ten (ends rounded out to whole decades, keeping every value at least 0.05
// decade inside), otherwise linear with ends rounded out to a multiple of a 1-2-5 step
// (keeping 5% of the span free; starting at 0 when all values are ≥ 0 and the smallest is
// below half the largest). Non-finite values are ignored; with none left the result is
// [0, 1], as when every value is 0; a single other value v gets a range around v.
axis_range choose_axis(std::span<const double> values);

// Tick positions inside the range (ends included when they fall on a tick): every power
// of ten for log10, a 1-2-5 step giving 4 to 10 ticks for linear. Empty for an invalid range.
std::vector<double> axis_ticks(const axis_range &range);

// Short tick label: log10 ticks as "0.01", "0.1", "1", "10", "100", "1000" or "1e-5", "1e6";
// linear ticks in %g with at most 4 significant digits ("0", "2.5", "1e+06").
std::string tick_label(double value, axis_scale scale);

// ---- markers ---------------------------------------------------------------------------
// 13 distinct marker shapes: hollow circle, square, triangle, diamond, plus, cross,
// filled circle, filled square, inverted triangle, star, filled triangle, filled diamond,
// filled inverted triangle. Marker `index` uses shape index % marker_count.
inline constexpr int marker_count = 13;

// Draws marker `index` centred at (x, y) (pixel coordinates, centres at +0.5) with
// half-size `radius` pixels, ink 1 (outlines with draw_line_coverage, 1 px wide; filled
// shapes also set every pixel whose centre is inside). Non-finite positions or radius ≤ 0 draw nothing.
void draw_marker(canvas_t &canvas, double x, double y, int index, double radius);

// ---- charts ----------------------------------------------------------------------------
inline constexpr double chart_no_value = std::numeric_limits<double>::quiet_NaN();  // "not given" for optional fields

// One measured point: a marker at (x, y). Optional whiskers show a spread: x_lo..x_hi
// horizontally, y_lo..y_hi vertically (chart_no_value = none).
//  * A point with an empty `series` is a variant of its own: one legend entry, `label`.
//  * Points with the same non-empty `series` are ONE series (one method across sizes or
//    widths): one legend entry named `series`, one marker shape, joined by a line in the
//    order they are given; `tag` (e.g. "T=1.5") is written beside the point's marker when
//    it fits without touching other text. `label` is then unused.
struct chart_point {
    double x = chart_no_value;
    double y = chart_no_value;
    std::string label;
    double x_lo = chart_no_value, x_hi = chart_no_value;
    double y_lo = chart_no_value, y_hi = chart_no_value;
    std::string series = {};
    std::string tag = {};
};

struct chart_spec {
    std::string title;
    std::string x_title;
    std::string y_title;
    std::vector<chart_point> points;
    std::optional<axis_range> x_axis;  // nullopt: choose_axis over the points (and whiskers)
    std::optional<axis_range> y_axis;
};

struct pixel_box {
    int x = 0, y = 0, width = 0, height = 0;  // covers [x, x+width) × [y, y+height)
};

// Where draw_chart put things, so tests (and callers) can check them.
struct chart_layout {
    axis_range x_axis, y_axis;      // the ranges used
    double plot_left = 0, plot_right = 0;   // pixel x of x_axis.lo and x_axis.hi
    double plot_bottom = 0, plot_top = 0;   // pixel y of y_axis.lo and y_axis.hi
    std::vector<pixel_box> text_boxes;      // every piece of text drawn
    // Per point (same order as spec.points): marker centre in pixels; NaN when the point
    // has no finite position on the axes. Points beyond an axis end are drawn on that
    // end and their legend entry is marked "(off scale)"; y ≤ 0 on a log y axis (e.g. the
    // reference's zero error) is drawn on the bottom end, marked "(0, on the axis floor)";
    // points not drawn (NaN) get "(n/a)".
    std::vector<double> marker_x, marker_y;
    // Per point: its legend entry (entries in order of first appearance; a series is one).
    std::vector<std::size_t> legend_entry;
    std::size_t legend_entries = 0;
};

// The smallest canvas draw_chart accepts.
inline constexpr int chart_min_width = 240;
inline constexpr int chart_min_height = 160;

// Clears the canvas and draws the whole chart as dark ink on white paper (intensity 1 =
// paper): title on top, y axis title (vertical) and tick labels on the left, x ticks and
// title below, light grid lines at the ticks, series lines, one marker per point (marker
// shape k for legend entry k) and a legend on the right (marker + label; a label too wide
// for the legend column wraps onto further lines, never cut; entries that do not fit in
// height are summarised as "+N more"). All text stays inside the canvas. Fails (canvas untouched) when the canvas is smaller than
// chart_min_width × chart_min_height or a given axis range is invalid.
result<chart_layout> draw_chart(canvas_t &canvas, const chart_spec &spec);

}  // namespace tiny3d

#endif
