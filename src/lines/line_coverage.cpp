// line_coverage.cpp — the exact-coverage thick line (fast), its double-precision reference
// and a supersampled variant for the benchmark.
//
// The stroke of segment A→B with half-width h is  rectangle ∪ (round caps: two half-discs).
// In the line's frame (u across, v along, origin A) the rectangle is |u| ≤ h, 0 ≤ v ≤ L.
// A major column lying between the end regions sees only the band |u| ≤ h, and the area
// of a unit square inside a band depends only on the angle and the centre's u (closed
// form below). The two or three columns at each end are integrated exactly from the
// stroke's outline (stroke_outline.h). The reference clips each pixel's square instead
// (polygon clipping + circle-segment areas): an independent method.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>
#include <vector>

#include "canvas.h"
#include "lines.h"
#include "coverage_geometry.h"
#include "line_clip.h"
#include "../canvas/splat.h"  // floor_to_int
#include "square_cdf.h"
#include "stroke_outline.h"

namespace tiny3d {
namespace {

using detail::clip_half_plane;
using detail::polygon_disc_area;
using detail::signed_area;
using detail::small_polygon;
using detail::band_writer;
using detail::square_cdf;

// Below this length (px) a segment is a point: its direction is taken as +x.
constexpr double kPointLength = 1e-9;
// Half the diagonal of a unit pixel: no point of a pixel is farther than this from its centre.
constexpr double kHalfDiagonal = 0.70710678118654752;
// Margin (px) beyond the stroke's reach when clipping, so clipped ends stay off the canvas.
constexpr double kClipSlack = 2.0;
// Strokes spanning more rows than this per column draw each column by the general path.
constexpr double kMaxWindowRows = 64.0;

// The reference's stroke in a local frame: origin A, unit direction (dx, dy), normal
// (−dy, dx), length L, half-width h; round caps at A and/or B.
struct stroke_frame {
    double dx, dy, length, half;
    bool cap_a, cap_b;

    // Exact area of the convex polygon `sq` (coordinates relative to A) inside the stroke:
    // the rectangle's four half-planes, then each cap's disc beyond its end.
    double area(const small_polygon<double> &sq) const {
        const double nx = -dy, ny = dx;
        small_polygon<double> body = clip_half_plane(sq, nx, ny, half);
        body = clip_half_plane(body, -nx, -ny, half);
        body = clip_half_plane(body, -dx, -dy, 0.0);
        body = clip_half_plane(body, dx, dy, length);
        double total = std::fabs(signed_area(body));
        if (cap_a) total += polygon_disc_area(clip_half_plane(sq, dx, dy, 0.0), 0.0, 0.0, half);
        if (cap_b)
            total += polygon_disc_area(clip_half_plane(sq, -dx, -dy, -length), dx * length, dy * length, half);
        return total;
    }

    static small_polygon<double> square(double x, double y) {
        small_polygon<double> sq;
        sq.n = 4;
        sq.v[0] = {x, y};
        sq.v[1] = {x + 1, y};
        sq.v[2] = {x + 1, y + 1};
        sq.v[3] = {x, y + 1};
        return sq;
    }
};

// Direction, length and normal of a segment, with a point treated as direction +x.
struct segment_axes {
    double dx = 1.0, dy = 0.0, length = 0.0;
    segment_axes(double x0, double y0, double x1, double y1) {
        const double len = std::hypot(x1 - x0, y1 - y0);
        if (len > kPointLength && std::isfinite(len)) {
            dx = (x1 - x0) / len;
            dy = (y1 - y0) / len;
            length = len;
        }
    }
};

bool finite_all(std::initializer_list<double> values) {
    for (double v : values)
        if (!std::isfinite(v)) return false;
    return true;
}

// Pixel cells [first, last] of a row of `size` that the open span (lo, hi) (px) touches,
// clamped to the row; first > last when none. (Clamping first keeps the int conversions
// in range and lets truncation stand in for floor.)
std::pair<int, int> touched_cells(double lo, double hi, int size) {
    lo = std::max(lo, 0.0);
    hi = std::min(hi, double(size));
    if (!(lo < hi)) return {0, -1};
    const int first = int(lo);
    int end = int(hi);
    if (double(end) < hi) ++end;  // ceil(hi)
    return {first, end - 1};
}

// A cell index (a floor or ceil already taken) clamped to [−1, size]: safe to convert.
int clamp_cell(double cell, int size) { return int(std::clamp(cell, -1.0, double(size))); }

// Distance from (px, py) to the stroke's centre segment, in the frame of `axes` from (x0, y0).
double distance_to_segment(double px, double py, double x0, double y0, const segment_axes &axes) {
    const double rx = px - x0, ry = py - y0;
    const double v = std::clamp(rx * axes.dx + ry * axes.dy, 0.0, axes.length);
    return std::hypot(rx - v * axes.dx, ry - v * axes.dy);
}

// Is the offset (rx, ry) from the first endpoint inside the stroke?
bool inside_stroke(double rx, double ry, const segment_axes &axes, double h, line_cap cap) {
    const double v = rx * axes.dx + ry * axes.dy;
    const double u = ry * axes.dx - rx * axes.dy;
    if (cap == line_cap::butt) return std::fabs(u) <= h && v >= 0.0 && v <= axes.length;
    const double vc = std::clamp(v, 0.0, axes.length);
    const double ex = rx - vc * axes.dx, ey = ry - vc * axes.dy;
    return ex * ex + ey * ey <= h * h;
}

}  // namespace

void draw_line_coverage(canvas_t *canvas, float x0, float y0, float x1, float y1, float thickness,
                        const line_style &style) {
    if (!canvas || !finite_all({x0, y0, x1, y1, thickness, style.intensity}) || !(thickness > 0.0f) ||
        !(style.intensity > 0.0f))
        return;
    const float intensity = std::min(style.intensity, 1.0f);
    const bool round = style.cap == line_cap::round;
    const double h = 0.5 * double(thickness);

    // Work in (major, minor) coordinates: the major axis is the one the line advances
    // along faster, so every major column holds a short run of pixels. One code path.
    const bool steep = std::fabs(double(y1) - y0) > std::fabs(double(x1) - x0);
    double ax = steep ? y0 : x0, ay = steep ? x0 : y0, bx = steep ? y1 : x1, by = steep ? x1 : y1;
    // Canonical endpoint order, so drawing B→A is bit-identical to A→B.
    if (bx < ax || (bx == ax && by < ay)) {
        std::swap(ax, bx);
        std::swap(ay, by);
    }
    const int major_size = steep ? canvas->height : canvas->width;
    const int minor_size = steep ? canvas->width : canvas->height;
    const std::ptrdiff_t major_stride = steep ? canvas->width : 1;
    const std::ptrdiff_t minor_stride = steep ? 1 : canvas->width;

    // Clip to the canvas grown by the stroke's reach: a clipped end lies ≥ kClipSlack px
    // off the canvas, so its (dropped) cap cannot touch a canvas pixel.
    const segment_axes axes(ax, ay, bx, by);
    const double margin = h + kClipSlack;
    detail::clipped_segment clip;
    if (!detail::clip_segment(ax, ay, bx, by, -margin, -margin, major_size + margin, minor_size + margin, clip))
        return;
    const double cax = clip.x0, cay = clip.y0;
    const double length = (clip.start_clipped || clip.end_clipped)
                              ? std::max(0.0, (clip.x1 - cax) * axes.dx + (clip.y1 - cay) * axes.dy)
                              : axes.length;
    // A stroke wider than the canvas may contain it whole (convex: if it holds the four
    // corners): every pixel is then covered exactly once. (Also where huge half-widths would
    // cost the outline's double precision: its integrals grow like h.)
    if (2.0 * h >= std::min(major_size, minor_size)) {
        bool all_inside = true;
        for (int corner = 0; corner < 4 && all_inside; ++corner)
            all_inside = inside_stroke((corner & 1 ? major_size : 0) - ax, (corner & 2 ? minor_size : 0) - ay, axes, h,
                                       style.cap);
        if (all_inside) {
            for (std::size_t k = 0; k < std::size_t(major_size) * std::size_t(minor_size); ++k)
                detail::combine_over(canvas->data[k], intensity);
            return;
        }
    }
    const bool round_a = round && !clip.start_clipped, round_b = round && !clip.end_clipped;
    const detail::stroke_outline outline(axes.dx, axes.dy, length, h, round_a, round_b);

    // Columns of the major axis: near each end (where the stroke's X extent begins, up to
    // where the end line v = 0 or v = L stops: ±h·|dy| around the end's X) every pixel is
    // computed from the outline; between them each column crosses only the band |u| ≤ h,
    // whose closed form is exact there.
    const double end_halo = h * std::fabs(axes.dy);
    const double bx_local = length * axes.dx;
    const int first_col = clamp_cell(std::floor(cax + outline.x_min), major_size);
    const int last_col = clamp_cell(std::ceil(cax + outline.x_max) - 1.0, major_size);
    int end_a_last = clamp_cell(std::ceil(cax + end_halo) - 1.0, major_size);
    int end_b_first = clamp_cell(std::floor(cax + bx_local - end_halo), major_size);
    if (end_b_first <= end_a_last + 1) {  // short: the ends' columns meet
        end_a_last = last_col;
        end_b_first = last_col + 1;
    }
    float *const data = canvas->data;
    detail::outline_columns ends(outline);
    auto end_columns = [&](int from, int to) {
        for (int i = std::max(from, 0); i <= std::min(to, major_size - 1); ++i)
            ends.draw(i - cax, cay, data + i * major_stride, minor_stride, minor_size, intensity);
    };
    end_columns(first_col, end_a_last);
    end_columns(end_b_first, last_col);

    const int body_first = std::max(end_a_last + 1, 0), body_last = std::min(end_b_first, major_size) - 1;
    if (body_first > body_last) return;
    const double nx = -axes.dy, ny = axes.dx;  // unit normal; axes.dx ≥ |axes.dy|
    const square_cdf cdf(nx, ny);
    const float hf = float(h);
    // Minor span of the band over a column: |minor − centreline| ≤ h / axes.dx.
    const double slope = axes.dy / axes.dx, band_half = h / axes.dx;
    if (minor_stride == 1) {
        // Steep on the canvas: each major column is a canvas row holding a short run.
        const double span_lo = std::min(0.0, slope) - band_half, span_hi = std::max(0.0, slope) + band_half;
        const band_writer writer(cdf, hf, intensity, ny);
        // Rows a column can touch: at most ⌈span⌉ + 1, covered by a window of 4-groups
        // (0: a stroke too wide for a window; every column then takes the general path).
        const double span = span_hi - span_lo;
        const int groups = span < kMaxWindowRows ? (int(std::ceil(span)) + 1 + 3) / 4 : 0;
        // Step from column to column (a DDA): `first` = the window's first row, `frac` the
        // window's lower bound above it, u the signed distance of pixel (i, first).
        const double lower = cay + (body_first - cax) * slope + span_lo;
        int first = groups > 0 ? detail::floor_to_int(lower) : -1;  // then |lower| ≤ canvas + 2·margin
        double frac = lower - first;
        double u = (body_first + 0.5 - cax) * nx + (first + 0.5 - cay) * ny;
        for (int i = body_first; i <= body_last; ++i) {
            float *row = data + i * major_stride;
            if (groups > 0 && first >= 0 && first + 4 * groups <= minor_size) {
                writer.window(row + first, float(u), groups);
            } else {
                const double y_left = cay + (i - cax) * slope;
                const auto [row_first, row_last] = touched_cells(y_left + span_lo, y_left + span_hi, minor_size);
                if (row_first <= row_last)
                    writer.run(row, minor_size, row_first, row_last, (i + 0.5 - cax) * nx + (row_first + 0.5 - cay) * ny);
            }
            // |slope| ≤ 1: the window moves by at most one row per column.
            frac += slope;
            u += nx;
            if (frac >= 1.0) {
                frac -= 1.0;
                ++first;
                u += ny;
            } else if (frac < 0.0) {
                frac += 1.0;
                --first;
                u -= ny;
            }
        }
        return;
    }
    // Shallow on the canvas: walk the canvas rows the band crosses over the body columns;
    // in row j, u = nx·(i + ½ − A.x) + ny·(j + ½ − A.y) is linear in i, and the run is
    // where |u| < h + w_hi (beyond it the square misses the band).
    const band_writer writer(cdf, hf, intensity, nx);
    const double reach = h + double(cdf.w_hi);
    const double y_first = cay + (body_first - cax) * slope, y_last = cay + (body_last + 1 - cax) * slope;
    const auto [row_first, row_last] =
        touched_cells(std::min(y_first, y_last) - band_half, std::max(y_first, y_last) + band_half, minor_size);
    const double inv_nx = nx != 0.0 ? 1.0 / nx : 0.0;
    for (int j = row_first; j <= row_last; ++j) {
        const double r = ny * (j + 0.5 - cay);  // u = r + nx·(i + ½ − A.x)
        int lo = body_first, hi = body_last;
        if (nx != 0.0) {
            const double x_a = cax - 0.5 + (-reach - r) * inv_nx, x_b = cax - 0.5 + (reach - r) * inv_nx;
            lo = std::max(lo, clamp_cell(std::floor(std::min(x_a, x_b)), major_size));
            hi = std::min(hi, clamp_cell(std::ceil(std::max(x_a, x_b)), major_size));
        } else if (!(std::fabs(r) < reach)) {
            continue;
        }
        if (lo > hi) continue;
        // Whole groups while they stay inside the body columns (pixels past hi there lie
        // beyond the band: coverage 0), the rest masked.
        float *row = data + j * minor_stride;
        const double u_lo = r + nx * (lo + 0.5 - cax);
        const int groups = std::min((hi - lo + 4) / 4, (body_last - lo + 1) / 4);
        writer.window(row + lo, float(u_lo), groups);
        if (lo + 4 * groups <= hi) writer.run(row, major_size, lo + 4 * groups, hi, u_lo + 4.0 * groups * nx);
    }
}

namespace {

// Calls visit(x, y) for the canvas pixels whose centre is within h + half a diagonal of
// the segment: a superset of the pixels the stroke touches (round or butt caps).
template <class Visit>
void for_pixels_near_stroke(int width, int height, double x0, double y0, double x1, double y1, double h,
                            Visit &&visit) {
    const segment_axes axes(x0, y0, x1, y1);
    const double reach = h + kHalfDiagonal;
    detail::clipped_segment clip;
    if (!detail::clip_segment(x0, y0, x1, y1, -reach, -reach, width + reach, height + reach, clip)) return;
    const double ax = clip.x0, ay = clip.y0, bx = clip.x1, by = clip.y1;
    // Distances to the clipped part, measured from its start (small numbers even for far
    // ends); a canvas pixel's nearest point never lies on the part clipped away.
    segment_axes near = axes;
    if (clip.start_clipped || clip.end_clipped) near.length = std::max(0.0, (bx - ax) * axes.dx + (by - ay) * axes.dy);
    const auto [xa, xb] = touched_cells(std::min(ax, bx) - reach, std::max(ax, bx) + reach, width);
    const auto [ya, yb] = touched_cells(std::min(ay, by) - reach, std::max(ay, by) + reach, height);
    for (int y = ya; y <= yb; ++y)
        for (int x = xa; x <= xb; ++x)
            if (distance_to_segment(x + 0.5, y + 0.5, ax, ay, near) <= reach) visit(x, y);
}

bool reference_inputs_ok(double x0, double y0, double x1, double y1, double thickness) {
    return finite_all({x0, y0, x1, y1, thickness}) && thickness > 0.0;
}

}  // namespace

double line_coverage_reference_at(int px, int py, double x0, double y0, double x1, double y1, double thickness,
                                  line_cap cap) {
    if (!reference_inputs_ok(x0, y0, x1, y1, thickness)) return 0.0;
    const segment_axes axes(x0, y0, x1, y1);
    const double h = 0.5 * thickness;
    // Only the part of the segment near this pixel matters: clip it to the pixel grown by
    // the stroke's reach, and measure from the clipped start, so coordinates stay small
    // (exact even for ends at ±1e300). A clipped end is ≥ kClipSlack px away: its cap
    // cannot reach the pixel.
    const double margin = h + kClipSlack;
    detail::clipped_segment clip;
    if (!detail::clip_segment(x0, y0, x1, y1, px - margin, py - margin, px + 1 + margin, py + 1 + margin, clip))
        return 0.0;
    const double length = (clip.start_clipped || clip.end_clipped)
                              ? std::max(0.0, (clip.x1 - clip.x0) * axes.dx + (clip.y1 - clip.y0) * axes.dy)
                              : axes.length;
    const bool round = cap == line_cap::round;
    const stroke_frame frame{axes.dx, axes.dy, length, h, round && !clip.start_clipped,
                                     round && !clip.end_clipped};
    return std::min(frame.area(stroke_frame::square(px - clip.x0, py - clip.y0)), 1.0);
}

void line_coverage_reference(std::vector<double> &coverage, int width, int height, double x0, double y0,
                             double x1, double y1, double thickness, line_cap cap) {
    coverage.assign(std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0)), 0.0);
    if (width <= 0 || height <= 0 || !reference_inputs_ok(x0, y0, x1, y1, thickness)) return;
    for_pixels_near_stroke(width, height, x0, y0, x1, y1, 0.5 * thickness, [&](int x, int y) {
        coverage[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
            line_coverage_reference_at(x, y, x0, y0, x1, y1, thickness, cap);
    });
}

void draw_line_supersampled(canvas_t *canvas, float x0, float y0, float x1, float y1, float thickness,
                            int samples_per_axis, const line_style &style) {
    if (!canvas || !reference_inputs_ok(x0, y0, x1, y1, thickness) || samples_per_axis < 1 ||
        !std::isfinite(style.intensity) || !(style.intensity > 0.0f))
        return;
    const float intensity = std::min(style.intensity, 1.0f);
    const segment_axes axes(x0, y0, x1, y1);
    const double h = 0.5 * double(thickness);
    const double step = 1.0 / samples_per_axis;
    const double weight = step * step;
    for_pixels_near_stroke(canvas->width, canvas->height, x0, y0, x1, y1, h, [&](int x, int y) {
        int hits = 0;
        for (int sy = 0; sy < samples_per_axis; ++sy)
            for (int sx = 0; sx < samples_per_axis; ++sx)
                hits += inside_stroke(x + (sx + 0.5) * step - x0, y + (sy + 0.5) * step - y0, axes, h, style.cap);
        if (hits) detail::combine_over(canvas->pixels[y][x], float(intensity * hits * weight));
    });
}

}  // namespace tiny3d
