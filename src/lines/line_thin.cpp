// line_thin.cpp — one-pixel lines: integer Bresenham, the gradient line and Xiaolin Wu's
// anti-aliased line. Each has one code path for all eight octants: the axes are swapped so
// the line advances along "major" faster than along "minor", and the ends are ordered along
// major.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "canvas.h"
#include "lines.h"
#include "line_clip.h"

namespace tiny3d {
namespace {

__extension__ typedef __int128 wide_int;  // 2·k·dy reaches 2^65 for int endpoints

inline float clamp_unit(float v) { return v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v); }

// A canvas seen with its axes optionally swapped: pixel (major, minor).
struct oriented_canvas {
    canvas_t *canvas;
    bool steep;
    int major_size() const { return steep ? canvas->height : canvas->width; }
    int minor_size() const { return steep ? canvas->width : canvas->height; }
    float *at(std::int64_t major, std::int64_t minor) const {
        const int x = int(steep ? minor : major), y = int(steep ? major : minor);
        return &canvas->pixels[y][x];
    }
    bool inside(std::int64_t major, std::int64_t minor) const {
        return major >= 0 && minor >= 0 && major < major_size() && minor < minor_size();
    }
};

// Bresenham's walk from (x0, y0) to (x1, y1), clipped to the canvas. Calls
// plot(pixel, k, n) for each visible pixel, k = its step from the ordered start, n = the
// number of steps; `reversed` says the ends were swapped to order them along major.
//
// After ordering, the minor offset at step k is c_k = ceil((2k·dy − dx) / (2dx)) — the
// closed form of Bresenham's decision variable D (D_k = 2(k+1)dy − dx − 2dx·c_k; step up
// when D_k > 0) — so the walk can start at the first visible step without iterating up to
// it.
template <class Plot>
void bresenham_walk(canvas_t *canvas, int x0, int y0, int x1, int y1, Plot &&plot) {
    const bool steep = std::llabs(std::int64_t(y1) - y0) > std::llabs(std::int64_t(x1) - x0);
    std::int64_t a0 = steep ? y0 : x0, b0 = steep ? x0 : y0, a1 = steep ? y1 : x1, b1 = steep ? x1 : y1;
    const bool reversed = a0 > a1;
    if (reversed) {
        std::swap(a0, a1);
        std::swap(b0, b1);
    }
    const oriented_canvas view{canvas, steep};
    const std::int64_t dx = a1 - a0;
    const std::int64_t step = b1 >= b0 ? 1 : -1;
    const std::int64_t dy = (b1 - b0) * step;
    if (dx == 0) {
        if (view.inside(a0, b0)) plot(view.at(a0, b0), std::int64_t(0), std::int64_t(0), reversed);
        return;
    }
    // Visible steps: the real line clipped to the canvas grown by half a pixel on the minor
    // axis (c_k is within ½ of k·dy/dx), then every pixel is still bounds-checked.
    double t0, t1;
    if (!detail::clip_parameter_range(double(a0), double(b0), double(dx), double(b1 - b0), -1.0, -1.0,
                                      double(view.major_size()), double(view.minor_size()), t0, t1))
        return;
    const std::int64_t k_first = std::max<std::int64_t>(0, std::int64_t(std::floor(t0 * double(dx))) - 1);
    const std::int64_t k_last = std::min<std::int64_t>(dx, std::int64_t(std::ceil(t1 * double(dx))) + 1);
    // c = ceil(num / den) for den > 0 via floor division of (num + den − 1).
    const wide_int num = wide_int(2) * k_first * dy - dx, den = wide_int(2) * dx;
    wide_int c_wide = num >= 0 ? (num + den - 1) / den : -((-num) / den);
    std::int64_t c = std::int64_t(c_wide);
    std::int64_t d = std::int64_t(wide_int(2) * (k_first + 1) * dy - dx - den * c_wide);
    for (std::int64_t k = k_first; k <= k_last; ++k) {
        const std::int64_t major = a0 + k, minor = b0 + step * c;
        if (view.inside(major, minor)) plot(view.at(major, minor), k, dx, reversed);
        if (d > 0) {
            ++c;
            d -= 2 * dx;
        }
        d += 2 * dy;
    }
}

}  // namespace

void draw_line_bresenham(canvas_t *canvas, int x0, int y0, int x1, int y1, float intensity) {
    if (!canvas || std::isnan(intensity)) return;
    const float value = clamp_unit(intensity);
    bresenham_walk(canvas, x0, y0, x1, y1, [value](float *p, std::int64_t, std::int64_t, bool) { *p = value; });
}

float mix_intensity(float a, float b, float t) {
    const float s = std::isnan(t) ? 0.0f : clamp_unit(t);
    return a * (1.0f - s) + b * s;
}

void draw_line_gradient(canvas_t *canvas, int x0, int y0, int x1, int y1, float intensity0, float intensity1) {
    if (!canvas || std::isnan(intensity0) || std::isnan(intensity1)) return;
    bresenham_walk(canvas, x0, y0, x1, y1, [&](float *p, std::int64_t k, std::int64_t n, bool reversed) {
        const float t = n == 0 ? 0.0f : float(double(reversed ? n - k : k) / double(n));
        *p = clamp_unit(mix_intensity(intensity0, intensity1, t));
    });
}

void draw_line_wu(canvas_t *canvas, float x0, float y0, float x1, float y1, float intensity) {
    if (!canvas || !std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1) ||
        !std::isfinite(intensity) || !(intensity > 0.0f))
        return;
    const float value = std::min(intensity, 1.0f);
    const bool steep = std::fabs(double(y1) - y0) > std::fabs(double(x1) - x0);
    // Lattice coordinates: pixel centres at integers (shift by −½), major axis first.
    double a0 = (steep ? y0 : x0) - 0.5, b0 = (steep ? x0 : y0) - 0.5;
    double a1 = (steep ? y1 : x1) - 0.5, b1 = (steep ? x1 : y1) - 0.5;
    if (a0 > a1 || (a0 == a1 && b0 > b1)) {
        std::swap(a0, a1);
        std::swap(b0, b1);
    }
    const oriented_canvas view{canvas, steep};
    const double slope = a1 > a0 ? (b1 - b0) / (a1 - a0) : 0.0;
    // Clip to the canvas grown by 2 px: a clipped end's column falls off the canvas.
    constexpr double kMargin = 2.0;
    detail::clipped_segment clip;
    if (!detail::clip_segment(a0, b0, a1, b1, -kMargin, -kMargin, view.major_size() + kMargin,
                              view.minor_size() + kMargin, clip))
        return;
    const double ca0 = clip.x0, ca1 = clip.x1, cb0 = clip.y0;
    auto plot_pair = [&](std::int64_t major, double minor, double weight) {
        const double base = std::floor(minor);
        const double frac = minor - base;
        const std::int64_t m = std::int64_t(base);
        if (view.inside(major, m)) detail::combine_over(*view.at(major, m), float(value * weight * (1.0 - frac)));
        if (view.inside(major, m + 1)) detail::combine_over(*view.at(major, m + 1), float(value * weight * frac));
    };
    // End columns: the segment covers only part of them (Wu's "gap" weight).
    const double first = std::round(ca0), last = std::round(ca1);
    const auto minor_at = [&](double a) { return cb0 + slope * (a - ca0); };
    if (first == last) {
        plot_pair(std::int64_t(first), minor_at(0.5 * (ca0 + ca1)), ca1 - ca0 + (ca1 == ca0 ? 1.0 : 0.0));
        return;
    }
    plot_pair(std::int64_t(first), minor_at(first), first + 0.5 - ca0);
    plot_pair(std::int64_t(last), minor_at(last), ca1 - (last - 0.5));
    for (std::int64_t a = std::int64_t(first) + 1; a < std::int64_t(last); ++a) plot_pair(a, minor_at(double(a)), 1.0);
}

}  // namespace tiny3d
