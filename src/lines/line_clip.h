// line_clip.h — (internal) Liang–Barsky parameter clipping shared by every line drawer.
#ifndef TINY3D_LINE_CLIP_H
#define TINY3D_LINE_CLIP_H

#include <cmath>

namespace tiny3d::detail {

// Liang–Barsky: the parameter interval [t0, t1] ⊂ [0, 1] of P(t) = P0 + t·D that lies in
// the box [xmin, xmax] × [ymin, ymax]; false if the segment misses the box. Double
// precision. side0 / side1 say which box side (0 xmin, 1 xmax, 2 ymin, 3 ymax) moved
// each end, −1 for an end that was not clipped.
inline bool liang_barsky(double x0, double y0, double dx, double dy, double xmin, double ymin, double xmax,
                         double ymax, double &t0, double &t1, int &side0, int &side1) {
    t0 = 0.0;
    t1 = 1.0;
    side0 = side1 = -1;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {x0 - xmin, xmax - x0, y0 - ymin, ymax - y0};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0) return false;
            continue;
        }
        const double r = q[i] / p[i];
        if (p[i] < 0.0) {
            if (r > t1) return false;
            if (r > t0) {
                t0 = r;
                side0 = i;
            }
        } else {
            if (r < t0) return false;
            if (r < t1) {
                t1 = r;
                side1 = i;
            }
        }
    }
    return true;
}

// The parameter interval alone (see liang_barsky).
inline bool clip_parameter_range(double x0, double y0, double dx, double dy, double xmin, double ymin,
                                 double xmax, double ymax, double &t0, double &t1) {
    int side0, side1;
    return liang_barsky(x0, y0, dx, dy, xmin, ymin, xmax, ymax, t0, t1, side0, side1);
}

// a·d − b·c to within about an ulp of the result, even when the products nearly cancel
// (Kahan's algorithm: the rounding error of b·c is recovered exactly with an fma).
inline double difference_of_products(double a, double d, double b, double c) {
    const double w = b * c;
    const double e = std::fma(-b, c, w);  // w − b·c, exactly
    const double f = std::fma(a, d, -w);
    return f + e;
}

// A segment clipped to a box, with each clipped end computed stably: the coordinate of
// the box side it lies on is taken exactly and the other follows from the line's implicit
// equation dy·x − dx·y = x0·y1 − x1·y0 with the right side computed accurately. (P0 + t·D
// cancels catastrophically for ends like ±1e30; this form's error is ~1e-16 of the
// canvas-sized terms, so (−3e38, −3e38)→(3e38, 3e38) still crosses pixel (k, k).)
struct clipped_segment {
    double x0, y0, x1, y1;
    bool start_clipped, end_clipped;
};

// How far (px) outside the box a clipped end may lie and still count as on it.
inline constexpr double kClipTolerance = 0.5;

inline bool clip_segment(double x0, double y0, double x1, double y1, double xmin, double ymin, double xmax,
                         double ymax, clipped_segment &out) {
    auto inside = [&](double x, double y) { return x >= xmin && x <= xmax && y >= ymin && y <= ymax; };
    if (inside(x0, y0) && inside(x1, y1)) {  // the common case: nothing to clip
        out = {x0, y0, x1, y1, false, false};
        return true;
    }
    const double dx = x1 - x0, dy = y1 - y0;
    const double side[4] = {xmin, xmax, ymin, ymax};
    double t0, t1;
    int side0, side1;  // the box side each end was moved to (−1: not clipped)
    if (!liang_barsky(x0, y0, dx, dy, xmin, ymin, xmax, ymax, t0, t1, side0, side1)) return false;
    const double cross = (side0 >= 0 || side1 >= 0) ? difference_of_products(x0, y1, x1, y0) : 0.0;
    auto on_side = [&](int i, double &x, double &y) {
        if (i < 2) {
            x = side[i];
            y = (dy * x - cross) / dx;
        } else {
            y = side[i];
            x = (dx * y + cross) / dy;
        }
    };
    out = {x0, y0, x1, y1, side0 >= 0, side1 >= 0};
    if (side0 >= 0) on_side(side0, out.x0, out.y0);
    if (side1 >= 0) on_side(side1, out.x1, out.y1);
    // With ends near ±1e38 the parameters t round, and Liang–Barsky may accept a segment
    // that misses the box; its exact side point then lies far outside the box (a crossing
    // segment's lies on the box to ~1e-4 px at worst). Reject those.
    auto near_box = [&](double x, double y) {
        return x >= xmin - kClipTolerance && x <= xmax + kClipTolerance && y >= ymin - kClipTolerance &&
               y <= ymax + kClipTolerance;
    };
    return near_box(out.x0, out.y0) && near_box(out.x1, out.y1);
}

// The "over" combine used by the anti-aliased lines: v ← v + c·(1 − v), for c, v in 0..1.
// c is clamped to 0..1 so float rounding of a coverage (1 + 1 ulp, or −1 ulp where a
// band's two CDF terms nearly cancel) never lifts a pixel above 1 or below 0.
inline void combine_over(float &pixel, float c) {
    c = c < 1.0f ? c : 1.0f;
    pixel += (c > 0.0f ? c : 0.0f) * (1.0f - pixel);
}

}  // namespace tiny3d::detail

#endif
