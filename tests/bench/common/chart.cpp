// chart.cpp — axes, markers and whole charts drawn with the library's canvas and lines.
#include "chart.h"
#include "lines.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace tiny3d {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();

// Layout, in pixels.
constexpr int margin = 6;               // paper left free at each canvas edge
constexpr int gap = 5;                  // between neighbouring pieces of text / axes
constexpr int tick_length = 4;          // tick marks stick out of the plot frame this far
constexpr int legend_row = 11;          // legend line pitch
constexpr int legend_marker_room = 14;  // legend: marker column before the label
constexpr double legend_share = 0.38;   // the legend takes at most this share of the width
constexpr int min_plot_side = 40;       // the plot area is never smaller than this
constexpr double marker_radius = 3.5;
constexpr double legend_marker_radius = 3.0;
constexpr float line_thickness = 1.0f;  // frame, ticks, whiskers and marker outlines
constexpr float grid_intensity = 0.2f;  // grid lines: a light grey once inverted
constexpr float whisker_intensity = 0.6f;  // spread bars: lighter than markers and series lines
constexpr float series_intensity = 0.8f;   // the line joining a series' points
constexpr float tag_intensity = 0.75f;     // a point's tag beside its marker
constexpr int legend_gap = 2;              // extra space between legend entries
constexpr int min_linear_intervals = 8; // axis_ticks aims at span / 8 (gives 4..9 ticks)
constexpr double tick_tolerance = 1e-9; // relative slack when a tick sits on a range end
constexpr double end_padding = 0.05;    // choose_axis keeps values this share (of the span
                                        // or of a decade) away from the axis ends

bool valid_range(const axis_range &r) {
    if (!std::isfinite(r.lo) || !std::isfinite(r.hi) || !(r.lo < r.hi)) return false;
    return r.scale == axis_scale::linear || r.lo > 0;
}

// The smallest 1-2-5 × 10^k step ≥ raw (raw > 0).
double nice_step(double raw) {
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    const double f = raw / decade;
    return decade * (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10);
}

// Text `text` shortened with ".." so that it is at most max_width pixels wide at scale.
std::string fit_text(std::string text, int max_width, int scale) {
    if (text_width(text, scale) <= max_width) return text;
    while (!text.empty()) {
        text.pop_back();
        while (!text.empty() && (static_cast<unsigned char>(text.back()) & 0xC0) == 0x80) text.pop_back();
        if (!text.empty() && static_cast<unsigned char>(text.back()) >= 0xC0) text.pop_back();
        if (text_width(text + "..", scale) <= max_width) return text + "..";
    }
    return text_width("..", scale) <= max_width ? ".." : "";
}

// Draws the kind of ink every chart uses (white on black; draw_chart inverts at the end):
// the exact-coverage line, so a line along pixel centres is exactly one pixel wide.
void line(canvas_t &c, double x0, double y0, double x1, double y1, float intensity = 1.0f) {
    line_style style;
    style.intensity = intensity;
    draw_line_coverage(&c, float(x0), float(y0), float(x1), float(y1), line_thickness, style);
}

// Places text with its top-left corner at (x, y), moved as little as needed to keep it
// inside the canvas, and records its box.
void place_text(canvas_t &c, chart_layout &layout, int x, int y, const std::string &text, int scale = 1) {
    const int w = text_width(text, scale), h = text_height(scale);
    if (w == 0) return;
    x = std::clamp(x, 0, std::max(0, c.width - w));
    y = std::clamp(y, 0, std::max(0, c.height - h));
    draw_text(c, x, y, text, 1.0f, scale);
    layout.text_boxes.push_back({x, y, w, h});
}

void place_vertical_text(canvas_t &c, chart_layout &layout, int x, int y, const std::string &text) {
    const int w = text_height(), h = text_width(text);
    if (h == 0) return;
    y = std::clamp(y, 0, std::max(0, c.height - h));
    draw_text_vertical(c, x, y, text, 1.0f);
    layout.text_boxes.push_back({x, y, w, h});
}

// Marker outlines as closed polygons with `n` corners on a circle of radius r, the first
// at angle `phase` (radians, counter-clockwise on screen, 0 = right).
void regular_polygon(canvas_t &c, double x, double y, double r, int n, double phase) {
    double px = x + r * std::cos(phase), py = y - r * std::sin(phase);
    for (int k = 1; k <= n; ++k) {
        const double a = phase + 2.0 * pi * k / n;
        const double qx = x + r * std::cos(a), qy = y - r * std::sin(a);
        line(c, px, py, qx, qy);
        px = qx;
        py = qy;
    }
}

// Fills the pixels whose centres lie inside the same polygon (convex, so a point is
// inside when it is on the inner side of every edge).
void fill_regular_polygon(canvas_t &c, double x, double y, double r, int n, double phase) {
    const int x0 = std::max(0, int(std::floor(x - r))), x1 = std::min(c.width - 1, int(std::ceil(x + r)));
    const int y0 = std::max(0, int(std::floor(y - r))), y1 = std::min(c.height - 1, int(std::ceil(y + r)));
    for (int py = y0; py <= y1; ++py)
        for (int px = x0; px <= x1; ++px) {
            bool inside = true;
            for (int k = 0; k < n && inside; ++k) {
                const double a0 = phase + 2.0 * pi * k / n, a1 = phase + 2.0 * pi * (k + 1) / n;
                const double ax = x + r * std::cos(a0), ay = y - r * std::sin(a0);
                const double bx = x + r * std::cos(a1), by = y - r * std::sin(a1);
                // Screen y points down, so counter-clockwise corners turn clockwise here:
                // inside means the cross product is ≤ 0 for every edge.
                inside = (bx - ax) * (py + 0.5 - ay) - (by - ay) * (px + 0.5 - ax) <= 0;
            }
            if (inside) c.pixels[py][px] = 1.0f;
        }
}

enum class shape { circle, square, triangle_up, diamond, triangle_down, plus, cross, star };
struct marker_style {
    shape form;
    bool filled;
};
constexpr marker_style marker_styles[marker_count] = {
    {shape::circle, false},        {shape::square, false},       {shape::triangle_up, false},
    {shape::diamond, false},       {shape::plus, false},         {shape::cross, false},
    {shape::circle, true},         {shape::square, true},        {shape::triangle_down, false},
    {shape::star, false},          {shape::triangle_up, true},   {shape::diamond, true},
    {shape::triangle_down, true}};

struct polygon_form {
    int corners;
    double phase;  // radians
    double size;   // circumradius as a multiple of the marker radius
};

polygon_form polygon_of(shape s) {
    constexpr int circle_corners = 16;
    switch (s) {
        case shape::circle: return {circle_corners, 0.0, 1.0};
        case shape::square: return {4, pi / 4, std::numbers::sqrt2 * 0.9};
        case shape::triangle_up: return {3, pi / 2, 1.15};
        case shape::triangle_down: return {3, -pi / 2, 1.15};
        case shape::diamond: return {4, 0.0, 1.2};
        default: return {0, 0.0, 0.0};
    }
}

// `text` broken at spaces into lines at most max_width pixels wide; a single word wider
// than that is shortened with "..".
std::vector<std::string> wrap_text(const std::string &text, int max_width) {
    std::vector<std::string> lines;
    std::string current;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find(' ', start);
        if (end == std::string::npos) end = text.size();
        const std::string word = text.substr(start, end - start);
        const std::string joined = current.empty() ? word : current + " " + word;
        if (text_width(joined) <= max_width) {
            current = joined;
        } else {
            if (!current.empty()) lines.push_back(current);
            current = fit_text(word, max_width, 1);
        }
        start = end + 1;
    }
    if (!current.empty() || lines.empty()) lines.push_back(current);
    return lines;
}

bool boxes_overlap(const pixel_box &a, const pixel_box &b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

// Appends " (note)" to a legend label.
std::string with_note(const std::string &label, const char *note) {
    return label.empty() ? std::string("(") + note + ")" : label + " (" + note + ")";
}

// Axis tick labels, thinned to every k-th so that neighbours keep `spacing` apart.
int label_stride(const std::vector<double> &pixel_positions, int needed_spacing) {
    if (pixel_positions.size() < 2) return 1;
    const double pitch = std::abs(pixel_positions[1] - pixel_positions[0]);
    if (pitch <= 0) return 1;
    return std::max(1, int(std::ceil(needed_spacing / pitch)));
}

}  // namespace

double axis_to_pixel(const axis_range &range, double value, double p_lo, double p_hi) {
    if (!valid_range(range) || !std::isfinite(value)) return nan_value;
    double t;
    if (range.scale == axis_scale::log10) {
        if (value <= 0) return nan_value;
        t = (std::log10(value) - std::log10(range.lo)) / (std::log10(range.hi) - std::log10(range.lo));
    } else {
        t = (value - range.lo) / (range.hi - range.lo);
    }
    return (1.0 - t) * p_lo + t * p_hi;
}

axis_range choose_axis(std::span<const double> values) {
    double lo = INFINITY, hi = -INFINITY;
    for (const double v : values)
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    if (lo > hi) return {0.0, 1.0, axis_scale::linear};
    constexpr double decade_ratio = 10.0;
    if (lo > 0 && hi / lo >= decade_ratio) {
        const double e_lo = std::floor(std::log10(lo) - end_padding), e_hi = std::ceil(std::log10(hi) + end_padding);
        return {std::pow(10.0, e_lo), std::pow(10.0, e_hi), axis_scale::log10};
    }
    if (lo == 0 && hi == 0) return {0.0, 1.0, axis_scale::linear};  // e.g. every error exactly 0
    if (lo == hi) {
        const double half = std::abs(lo) / 2;
        lo -= half;
        hi += half;
    } else if (lo >= 0 && lo < hi / 2) {
        lo = 0;
    }
    const double step = nice_step((hi - lo) / min_linear_intervals);
    const double pad = (hi - lo) * end_padding;
    return {lo == 0 ? 0.0 : std::floor((lo - pad) / step) * step, std::ceil((hi + pad) / step) * step,
            axis_scale::linear};
}

std::vector<double> axis_ticks(const axis_range &range) {
    std::vector<double> ticks;
    if (!valid_range(range)) return ticks;
    if (range.scale == axis_scale::log10) {
        const double e_lo = std::ceil(std::log10(range.lo) - tick_tolerance);
        const double e_hi = std::floor(std::log10(range.hi) + tick_tolerance);
        for (double e = e_lo; e <= e_hi; ++e) ticks.push_back(std::pow(10.0, e));
        return ticks;
    }
    const double step = nice_step((range.hi - range.lo) / min_linear_intervals);
    const double slack = step * tick_tolerance;
    const double k_first = std::ceil((range.lo - slack) / step), k_last = std::floor((range.hi + slack) / step);
    for (double k = k_first; k <= k_last; ++k) ticks.push_back(k == 0 ? 0.0 : k * step);
    return ticks;
}

std::string tick_label(double value, axis_scale scale) {
    char buf[32];
    if (scale == axis_scale::log10 && value > 0) {
        constexpr int plain_lo = -2, plain_hi = 3;  // 0.01 … 1000 written out
        const int e = int(std::lround(std::log10(value)));
        if (e >= plain_lo && e <= plain_hi) std::snprintf(buf, sizeof buf, "%g", std::pow(10.0, e));
        else std::snprintf(buf, sizeof buf, "1e%d", e);
        return buf;
    }
    std::snprintf(buf, sizeof buf, "%.4g", value);
    return buf;
}

void draw_marker(canvas_t &canvas, double x, double y, int index, double radius) {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(radius) || radius <= 0) return;
    const marker_style style = marker_styles[((index % marker_count) + marker_count) % marker_count];
    const double r = radius;
    switch (style.form) {
        case shape::plus:
            line(canvas, x - r, y, x + r, y);
            line(canvas, x, y - r, x, y + r);
            return;
        case shape::cross:
            line(canvas, x - r, y - r, x + r, y + r);
            line(canvas, x - r, y + r, x + r, y - r);
            return;
        case shape::star: {
            const double d = r / std::numbers::sqrt2;
            line(canvas, x - r, y, x + r, y);
            line(canvas, x, y - r, x, y + r);
            line(canvas, x - d, y - d, x + d, y + d);
            line(canvas, x - d, y + d, x + d, y - d);
            return;
        }
        default: {
            const polygon_form p = polygon_of(style.form);
            regular_polygon(canvas, x, y, r * p.size, p.corners, p.phase);
            if (style.filled) fill_regular_polygon(canvas, x, y, r * p.size, p.corners, p.phase);
        }
    }
}

result<chart_layout> draw_chart(canvas_t &canvas, const chart_spec &spec) {
    if (!canvas.pixels || canvas.width < chart_min_width || canvas.height < chart_min_height)
        return error{"", 0, -1,
                     "chart: canvas " + std::to_string(canvas.width) + "x" + std::to_string(canvas.height) +
                         " is smaller than " + std::to_string(chart_min_width) + "x" +
                         std::to_string(chart_min_height)};
    if (spec.x_axis && !valid_range(*spec.x_axis))
        return error{"", 0, -1, "chart: invalid x axis range (need lo < hi, and lo > 0 on a log axis)"};
    if (spec.y_axis && !valid_range(*spec.y_axis))
        return error{"", 0, -1, "chart: invalid y axis range (need lo < hi, and lo > 0 on a log axis)"};

    chart_layout layout;
    std::vector<double> xs, ys;
    for (const chart_point &p : spec.points) {
        xs.insert(xs.end(), {p.x, p.x_lo, p.x_hi});
        ys.insert(ys.end(), {p.y, p.y_lo, p.y_hi});
    }
    // Zeros and negatives cannot sit on a log axis: leave them out when choosing it
    // unless nothing else is left.
    const auto positive_or_all = [](std::vector<double> v) {
        std::vector<double> positive;
        for (double x : v)
            if (x > 0 && std::isfinite(x)) positive.push_back(x);
        const axis_range all = choose_axis(v), pos = choose_axis(positive);
        return pos.scale == axis_scale::log10 ? pos : all;
    };
    layout.x_axis = spec.x_axis ? *spec.x_axis : positive_or_all(xs);
    layout.y_axis = spec.y_axis ? *spec.y_axis : positive_or_all(ys);
    const std::vector<double> x_ticks = axis_ticks(layout.x_axis), y_ticks = axis_ticks(layout.y_axis);
    std::vector<std::string> y_labels;
    int y_label_width = 0;
    for (const double t : y_ticks) {
        y_labels.push_back(tick_label(t, layout.y_axis.scale));
        y_label_width = std::max(y_label_width, text_width(y_labels.back()));
    }

    const int w = canvas.width, h = canvas.height;
    const int inner_width = w - 2 * margin;
    canvas_clear(&canvas, 0.0f);  // drawn as white ink on black, inverted at the end

    // Title.
    const int title_scale = text_width(spec.title, 2) <= inner_width ? 2 : 1;
    const std::string title = fit_text(spec.title, inner_width, title_scale);
    place_text(canvas, layout, (w - text_width(title, title_scale)) / 2, margin, title, title_scale);
    const int title_bottom = margin + (title.empty() ? 0 : text_height(title_scale));

    // Legend entries: one per series (named by it), one per point outside a series; notes
    // for points not drawn where they are (a series takes its first point's note).
    struct legend_entry {
        std::string key;    // the series name ("" for a point of its own)
        std::string label;  // what the legend says (with any note)
        bool noted = false;
        std::vector<std::string> lines;
    };
    std::vector<legend_entry> legend;
    layout.legend_entry.assign(spec.points.size(), 0);
    layout.marker_x.assign(spec.points.size(), nan_value);
    layout.marker_y.assign(spec.points.size(), nan_value);
    for (std::size_t i = 0; i < spec.points.size(); ++i) {
        const chart_point &p = spec.points[i];
        std::size_t e = legend.size();
        if (!p.series.empty())
            for (std::size_t k = 0; k < legend.size() && e == legend.size(); ++k)
                if (legend[k].key == p.series) e = k;
        if (e == legend.size()) legend.push_back({p.series, p.series.empty() ? p.label : p.series, false, {}});
        layout.legend_entry[i] = e;
        const double tx = axis_to_pixel(layout.x_axis, p.x, 0, 1);
        const double ty = axis_to_pixel(layout.y_axis, p.y, 0, 1);
        const bool off_log_floor =
            std::isfinite(p.y) && layout.y_axis.scale == axis_scale::log10 && p.y <= 0 && std::isfinite(tx);
        const char *note = off_log_floor                              ? "0, on the axis floor"
                           : !std::isfinite(tx) || !std::isfinite(ty) ? "n/a"
                           : tx < 0 || tx > 1 || ty < 0 || ty > 1     ? "off scale"
                                                                      : nullptr;
        if (note && !legend[e].noted) legend[e].label = with_note(legend[e].label, note);
        if (note) legend[e].noted = true;
    }
    layout.legend_entries = legend.size();
    int legend_width = 0;
    const int legend_max_width = int(inner_width * legend_share);
    for (legend_entry &entry : legend) {
        entry.lines = wrap_text(entry.label, legend_max_width - legend_marker_room);
        for (const std::string &l : entry.lines) legend_width = std::max(legend_width, legend_marker_room + text_width(l));
    }

    // The plot frame, in pixel-centre coordinates (integer + 0.5).
    const int x_title_top = h - margin - text_height();
    const int x_labels_top = x_title_top - gap - text_height();
    const int frame_bottom = x_labels_top - gap - tick_length + 1;
    const int frame_top = title_bottom + 2 * gap + text_height() / 2;
    const int frame_left = margin + text_height() + gap + y_label_width + gap + tick_length;
    int frame_right = w - margin - (legend_width > 0 ? legend_width + 2 * gap : 0) - 1;
    frame_right = std::max(frame_right, std::min(w - margin - 1, frame_left + min_plot_side));
    if (frame_bottom - frame_top < min_plot_side)
        return error{"", 0, -1, "chart: canvas too short for the title, axes and labels"};
    layout.plot_left = frame_left + 0.5;
    layout.plot_right = frame_right + 0.5;
    layout.plot_top = frame_top + 0.5;
    layout.plot_bottom = frame_bottom + 0.5;
    const auto to_x = [&](double v) { return axis_to_pixel(layout.x_axis, v, layout.plot_left, layout.plot_right); };
    const auto to_y = [&](double v) { return axis_to_pixel(layout.y_axis, v, layout.plot_bottom, layout.plot_top); };

    // Grid, frame, ticks and tick labels.
    std::vector<double> x_pixels, y_pixels;
    for (const double t : x_ticks) x_pixels.push_back(to_x(t));
    for (const double t : y_ticks) y_pixels.push_back(to_y(t));
    for (const double px : x_pixels) line(canvas, px, layout.plot_top, px, layout.plot_bottom, grid_intensity);
    for (const double py : y_pixels) line(canvas, layout.plot_left, py, layout.plot_right, py, grid_intensity);
    line(canvas, layout.plot_left, layout.plot_bottom, layout.plot_right, layout.plot_bottom);
    line(canvas, layout.plot_left, layout.plot_top, layout.plot_right, layout.plot_top);
    line(canvas, layout.plot_left, layout.plot_top, layout.plot_left, layout.plot_bottom);
    line(canvas, layout.plot_right, layout.plot_top, layout.plot_right, layout.plot_bottom);

    int x_label_width = 0;
    for (const double t : x_ticks) x_label_width = std::max(x_label_width, text_width(tick_label(t, layout.x_axis.scale)));
    const int x_stride = label_stride(x_pixels, x_label_width + gap);
    for (std::size_t i = 0; i < x_ticks.size(); ++i) {
        line(canvas, x_pixels[i], layout.plot_bottom, x_pixels[i], layout.plot_bottom + tick_length);
        if (i % std::size_t(x_stride) != 0) continue;
        const std::string label = tick_label(x_ticks[i], layout.x_axis.scale);
        place_text(canvas, layout, int(std::lround(x_pixels[i] - text_width(label) / 2.0)), x_labels_top, label);
    }
    const int y_stride = label_stride(y_pixels, text_height() + 2);
    for (std::size_t i = 0; i < y_ticks.size(); ++i) {
        line(canvas, layout.plot_left - tick_length, y_pixels[i], layout.plot_left, y_pixels[i]);
        if (i % std::size_t(y_stride) != 0) continue;
        place_text(canvas, layout, frame_left - tick_length - gap + 1 - text_width(y_labels[i]),
                   int(std::lround(y_pixels[i] - text_height() / 2.0)), y_labels[i]);
    }

    // Axis titles.
    const std::string x_title = fit_text(spec.x_title, inner_width, 1);
    place_text(canvas, layout, (frame_left + frame_right) / 2 - text_width(x_title) / 2, x_title_top, x_title);
    const std::string y_title = fit_text(spec.y_title, frame_bottom - frame_top, 1);
    place_vertical_text(canvas, layout, margin, (frame_top + frame_bottom) / 2 - text_width(y_title) / 2, y_title);

    // Points: whiskers, then series lines, then markers (clamped onto the frame when off
    // scale), then the tags that fit.
    const auto clamp_x = [&](double v) { return std::clamp(v, layout.plot_left, layout.plot_right); };
    const auto clamp_y = [&](double v) { return std::clamp(v, layout.plot_top, layout.plot_bottom); };
    for (std::size_t i = 0; i < spec.points.size(); ++i) {
        const chart_point &p = spec.points[i];
        double mx = to_x(p.x), my = to_y(p.y);
        if (std::isfinite(mx) && !std::isfinite(my) && layout.y_axis.scale == axis_scale::log10 && p.y <= 0)
            my = layout.plot_bottom;  // zero error on a log axis: on the floor
        if (!std::isfinite(mx) || !std::isfinite(my)) continue;
        mx = clamp_x(mx);
        my = clamp_y(my);
        layout.marker_x[i] = mx;
        layout.marker_y[i] = my;
        const double xl = to_x(p.x_lo), xh = to_x(p.x_hi), yl = to_y(p.y_lo), yh = to_y(p.y_hi);
        if (std::isfinite(xl) && std::isfinite(xh)) line(canvas, clamp_x(xl), my, clamp_x(xh), my, whisker_intensity);
        if (std::isfinite(yl) && std::isfinite(yh)) line(canvas, mx, clamp_y(yl), mx, clamp_y(yh), whisker_intensity);
    }
    for (std::size_t e = 0; e < legend.size(); ++e) {
        double px = nan_value, py = nan_value;
        for (std::size_t i = 0; i < spec.points.size(); ++i) {
            if (layout.legend_entry[i] != e || std::isnan(layout.marker_x[i])) continue;
            if (!std::isnan(px)) line(canvas, px, py, layout.marker_x[i], layout.marker_y[i], series_intensity);
            px = layout.marker_x[i];
            py = layout.marker_y[i];
        }
    }
    for (std::size_t i = 0; i < spec.points.size(); ++i)
        if (!std::isnan(layout.marker_x[i]))
            draw_marker(canvas, layout.marker_x[i], layout.marker_y[i], int(layout.legend_entry[i]), marker_radius);
    for (std::size_t i = 0; i < spec.points.size(); ++i) {
        const std::string &tag = spec.points[i].tag;
        if (tag.empty() || spec.points[i].series.empty() || std::isnan(layout.marker_x[i])) continue;
        const pixel_box box{int(std::lround(layout.marker_x[i] + marker_radius + 2)),
                            int(std::lround(layout.marker_y[i] - marker_radius - text_height())), text_width(tag),
                            text_height()};
        bool clear = box.x >= layout.plot_left && box.x + box.width <= layout.plot_right &&
                     box.y >= layout.plot_top && box.y + box.height <= layout.plot_bottom;
        for (std::size_t k = 0; k < layout.text_boxes.size() && clear; ++k) clear = !boxes_overlap(box, layout.text_boxes[k]);
        if (!clear) continue;
        draw_text(canvas, box.x, box.y, tag, tag_intensity);
        layout.text_boxes.push_back(box);
    }

    // Legend, top right: entries stacked (a wrapped label takes several rows); when the
    // rest does not fit, one "+N more" row says how many are left out.
    const int legend_left = w - margin - legend_width;
    const int legend_limit = frame_bottom + legend_row;  // last row may end at the frame's bottom
    int top = frame_top;
    for (std::size_t e = 0; e < legend.size(); ++e) {
        const int needed = int(legend[e].lines.size()) * legend_row;
        const bool last = e + 1 == legend.size();
        if (top + needed + (last ? 0 : legend_row) > legend_limit) {
            place_text(canvas, layout, legend_left, top, "+" + std::to_string(legend.size() - e) + " more");
            break;
        }
        draw_marker(canvas, legend_left + legend_marker_radius + 1.5, top + text_height() / 2.0, int(e),
                    legend_marker_radius);
        for (std::size_t l = 0; l < legend[e].lines.size(); ++l)
            place_text(canvas, layout, legend_left + legend_marker_room, top + int(l) * legend_row, legend[e].lines[l]);
        top += needed + legend_gap;
    }

    // Ink to dark on white paper.
    const std::size_t n = std::size_t(w) * std::size_t(h);
    for (std::size_t k = 0; k < n; ++k) canvas.data[k] = 1.0f - canvas.data[k];
    return layout;
}

}  // namespace tiny3d
