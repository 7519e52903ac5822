// line_faithful.cpp — the libtiny3d report's draw_line_f, kept as the faithful variant.
#include <cmath>
#include <cstdint>

#include "canvas.h"
#include "lines.h"
#include "line_clip.h"
#include "../canvas/splat.h"

using tiny3d::detail::clip_parameter_range;

void draw_line_f(canvas_t *c, float x0, float y0, float x1, float y1, float thickness) {
    if (!c || !std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1) ||
        !std::isfinite(thickness))
        return;
    // A disc wider than twice the canvas gains nothing but cost (and a float loop step of
    // 0.5 stops advancing past 2^23): cap it.
    const float max_thickness = 2.0f * float(c->width + c->height);
    if (thickness > max_thickness) thickness = max_thickness;

    const float dx = x1 - x0;
    const float dy = y1 - y0;
    const float len = std::hypot(dx, dy);
    if (len == 0.0f) {  // degenerate: just a point
        set_pixel_f(c, x0, y0, 1.0f);
        return;
    }
    const float step = 0.5f;  // sampling every 0.5 px
    const double steps_d = std::ceil(double(len) / step);

    // Only samples whose disc can touch the canvas matter. Keep the report's sample
    // lattice t = n/steps and visit just the n inside the canvas grown by the disc radius
    // plus the splat footprint: the image is bit-identical to visiting every n.
    const double margin = 0.5 * double(thickness) + 2.0;
    double t0, t1;
    if (!clip_parameter_range(x0, y0, dx, dy, -margin, -margin, double(c->width) + margin,
                              double(c->height) + margin, t0, t1))
        return;
    // Beyond 2^52 samples (ends ~1e15 px apart) the lattice index no longer fits exactly in
    // double / int64 (casting would be UB): draw the clipped part as its own segment.
    constexpr double max_lattice_steps = 4503599627370496.0;  // 2^52
    // The clipped ends come from the stable implicit-equation clip (P0 + t·D cancels here).
    if (steps_d > max_lattice_steps) {
        tiny3d::detail::clipped_segment s;
        if (tiny3d::detail::clip_segment(x0, y0, x1, y1, -margin, -margin, double(c->width) + margin,
                                         double(c->height) + margin, s))
            draw_line_f(c, float(s.x0), float(s.y0), float(s.x1), float(s.y1), thickness);
        return;
    }
    const std::int64_t steps = static_cast<std::int64_t>(steps_d);  // ≤ 2^52: exact, in range
    std::int64_t n_first = static_cast<std::int64_t>(std::floor(t0 * steps_d)) - 1;
    std::int64_t n_last = static_cast<std::int64_t>(std::ceil(t1 * steps_d)) + 1;
    if (n_first < 0) n_first = 0;
    if (n_last > steps) n_last = steps;

    const float half = thickness / 2;
    const float r2 = (thickness * thickness) / 4.0f;
    // A segment that needed no clipping is sampled with the report's float arithmetic,
    // bit for bit. A clipped one (possibly with far-off ends, where a float step is many
    // pixels) takes the same lattice points, computed in double.
    const bool clipped = t0 > 0.0 || t1 < 1.0;
    for (std::int64_t n = n_first; n <= n_last; ++n) {
        float px, py;
        if (!clipped) {
            const float t = float(n) / float(steps);
            px = x0 + t * dx;
            py = y0 + t * dy;
        } else {
            const double t = double(n) / steps_d;
            px = float(double(x0) + t * (double(x1) - double(x0)));
            py = float(double(y0) + t * (double(y1) - double(y0)));
        }
        // Draw a filled disc at each step for thickness (the report's 0.5 px grid).
        for (float ky = -half; ky < half; ky += 0.5f)
            for (float kx = -half; kx < half; kx += 0.5f)
                if ((kx * kx + ky * ky) <= r2) tiny3d::detail::splat(c, px + kx, py + ky, 1.0f);
    }
}
