// triangle_setup.cpp — the set-up stage, one triangle at a time (setup.h): snapping,
// orientation, culling, the top-left bias, and the fast path's row crossings and attribute
// planes.
#include <algorithm>

#include "setup.h"

namespace tiny3d {

triangle_edges triangle_setup(const screen_vertex &v0, const screen_vertex &v1, const screen_vertex &v2,
                              pixel_rect clip, cull_mode cull) {
    std::int32_t X[3], Y[3];
    constexpr int bits = RASTER_SUBPIXEL_BITS;
    if (!detail::snap_screen_point(v0.x, v0.y, bits, X[0], Y[0]) ||
        !detail::snap_screen_point(v1.x, v1.y, bits, X[1], Y[1]) || !detail::snap_screen_point(v2.x, v2.y, bits, X[2], Y[2]))
        return {};
    return detail::triangle_setup_snapped(X, Y, clip, cull);
}

namespace detail {

namespace {

constexpr std::int64_t HALF_SUBPIXEL = RASTER_SUBPIXEL_ONE / 2;  // pixel centre offset

// Rows [0, count) relative to min_y: those where no horizontal edge (a = 0, E = E0 + b·dy)
// is negative. Narrows [first, last] (relative row numbers).
inline void clip_rows_by_horizontal_edge(std::int64_t e0, std::int64_t b, int &first, int &last) {
    if (b > 0) first = static_cast<int>(std::max<std::int64_t>(first, -floor_div(e0, b)));  // dy ≥ ceil(−e0 / b)
    else last = static_cast<int>(std::min<std::int64_t>(last, floor_div(e0, -b)));         // dy ≤ floor(e0 / −b)
}

// Resets the crossings to "no edge" (set_crossing fills them).
inline void clear_crossings(fast_triangle &out) {
    constexpr double NO_EDGE = -1e30;
    for (int j = 0; j < 4; ++j) out.cross[j] = NO_EDGE, out.cross_step[j] = 0.0;
}

// Edge E(min_x + x, min_y + dy) = e0 + a·x + b·dy with a ≠ 0 crosses zero at
// x = −e0/a − (b/a)·dy. Left edges (a > 0) go to slots 0, 2, right edges (negated) to 1, 3.
inline void set_crossing(std::int64_t e0, std::int64_t a, std::int64_t b, int &left, int &right, fast_triangle &out) {
    const double inv_a = 1.0 / static_cast<double>(a);
    const bool is_left = a > 0;
    const int slot = is_left ? left : right;
    (is_left ? left : right) += 2;
    const double sign = is_left ? 1.0 : -1.0;
    out.cross[slot] = sign * (-static_cast<double>(e0) * inv_a);
    out.cross_step[slot] = sign * (-static_cast<double>(b) * inv_a);
}

}  // namespace

triangle_edges triangle_setup_snapped(const std::int32_t X[3], const std::int32_t Y[3], pixel_rect clip,
                                      cull_mode cull, int bits) {
    triangle_edges t;
    const std::int64_t area2 = snapped_area2(X, Y);
    if (area2 == 0) return t;
    t.front_facing = area2 < 0;
    if (facing_culled(area2, cull)) {
        t.culled = true;
        return t;
    }
    const std::int64_t s = area2 > 0 ? 1 : -1;  // orient so that inside is positive
    t.area2 = area2 * s;
    const std::int64_t one = std::int64_t{1} << bits, half = one / 2;
    for (int k = 0; k < 3; ++k) {
        // E(P) with P = one·pixel + half (the pixel centre): its value at pixel (0, 0), its steps.
        const snapped_edge edge = snapped_edge_at(X, Y, s, k, half, half);
        t.a[k] = -edge.dy * one;
        t.b[k] = edge.dx * one;
        t.c[k] = edge.e;
    }
    const snapped_box box = snapped_box::of(X, Y);
    axis_bounds(box.min_X, box.max_X, 0, 0, bits, clip.x0, clip.x1, t.min_x, t.max_x);
    axis_bounds(box.min_Y, box.max_Y, 0, 0, bits, clip.y0, clip.y1, t.min_y, t.max_y);
    t.span_x = box.max_X - box.min_X;
    t.span_y = box.max_Y - box.min_Y;
    snapped_to_px(X, Y, t.x, t.y, bits);
    t.valid = t.min_x <= t.max_x && t.min_y <= t.max_y;
    return t;
}

bool make_fast_triangle(const triangle_edges &t, const float depth[3], const float intensity[3],
                        std::int32_t wide_index, fast_triangle &out) {
    if (!t.valid) return false;
    out.min_x = t.min_x;
    out.max_x = t.max_x;
    int first = 0, last = t.max_y - t.min_y;
    for (int k = 0; k < 3; ++k)
        if (t.a[k] == 0) clip_rows_by_horizontal_edge(t.c[k] + t.b[k] * t.min_y, t.b[k], first, last);
    if (first > last) return false;
    out.min_y = t.min_y + first;
    out.max_y = t.min_y + last;
    const bool fits = t.span_x < FAST_SPAN_LIMIT && t.span_y < FAST_SPAN_LIMIT;
    out.wide = fits ? -1 : wide_index;
    clear_crossings(out);
    int left = 0, right = 1;
    for (int k = 0; k < 3 && fits; ++k)
        if (t.a[k] != 0) set_crossing(t.c[k] + t.a[k] * out.min_x + t.b[k] * out.min_y, t.a[k], t.b[k], left, right, out);
    set_planes(t.x, t.y, depth, intensity, out);
    return true;
}

fast_setup setup_fast_triangle(const std::int32_t X[3], const std::int32_t Y[3], std::int64_t area2, pixel_rect clip,
                               const float depth[3], const float intensity[3], fast_triangle &out) {
    const snapped_box box = snapped_box::of(X, Y);
    if (box.max_X - box.min_X >= FAST_SPAN_LIMIT || box.max_Y - box.min_Y >= FAST_SPAN_LIMIT) return fast_setup::wide;
    int min_y, max_y;
    axis_bounds(box.min_X, box.max_X, 0, 0, RASTER_SUBPIXEL_BITS, clip.x0, clip.x1, out.min_x, out.max_x);
    axis_bounds(box.min_Y, box.max_Y, 0, 0, RASTER_SUBPIXEL_BITS, clip.y0, clip.y1, min_y, max_y);
    if (out.min_x > out.max_x || min_y > max_y) return fast_setup::empty;
    // triangle_setup_snapped's edges (oriented by s, top-left bias), evaluated at the centre
    // (cx, cy) of pixel (min_x, min_y): within the box, so |e| < 2^31 and the products fit.
    const std::int64_t s = area2 > 0 ? 1 : -1;
    const std::int64_t cx = RASTER_SUBPIXEL_ONE * static_cast<std::int64_t>(out.min_x) + HALF_SUBPIXEL;
    const std::int64_t cy = RASTER_SUBPIXEL_ONE * static_cast<std::int64_t>(min_y) + HALF_SUBPIXEL;
    std::int64_t e[3], dx[3], dy[3];
    for (int k = 0; k < 3; ++k) {
        const snapped_edge edge = snapped_edge_at(X, Y, s, k, cx, cy);
        dx[k] = edge.dx, dy[k] = edge.dy, e[k] = edge.e;
    }
    int first = 0, last = max_y - min_y;
    for (int k = 0; k < 3; ++k)
        if (dy[k] == 0) clip_rows_by_horizontal_edge(e[k], dx[k] * RASTER_SUBPIXEL_ONE, first, last);
    if (first > last) return fast_setup::empty;
    out.min_y = min_y + first;
    out.max_y = min_y + last;
    out.wide = -1;
    clear_crossings(out);
    int left = 0, right = 1;
    for (int k = 0; k < 3; ++k) {
        const std::int64_t a = -dy[k] * RASTER_SUBPIXEL_ONE, b = dx[k] * RASTER_SUBPIXEL_ONE;
        if (a != 0) set_crossing(e[k] + b * first, a, b, left, right, out);
    }
    double x[3], y[3];
    snapped_to_px(X, Y, x, y);
    set_planes(x, y, depth, intensity, out);
    return fast_setup::ready;
}

}  // namespace detail

}  // namespace tiny3d
