// line_clip.h — (internal) Liang–Barsky parameter clipping shared by every line drawer.
#ifndef TINY3D_LINE_CLIP_H
#define TINY3D_LINE_CLIP_H

namespace tiny3d::detail {

// Liang–Barsky: the parameter interval [t0, t1] ⊂ [0, 1] of P(t) = P0 + t·D that lies in
// the box [xmin, xmax] × [ymin, ymax]; false if the segment misses the box. Double
// precision, so endpoints of ±1e9 and beyond clip to within 1e-6 px.
inline bool clip_parameter_range(double x0, double y0, double dx, double dy, double xmin, double ymin,
                                 double xmax, double ymax, double &t0, double &t1) {
    t0 = 0.0;
    t1 = 1.0;
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
            if (r > t0) t0 = r;
        } else {
            if (r < t0) return false;
            if (r < t1) t1 = r;
        }
    }
    return true;
}

// The "over" combine used by the anti-aliased lines: v ← v + c·(1 − v), for c, v in 0..1.
inline void combine_over(float &pixel, float c) { pixel += c * (1.0f - pixel); }

}  // namespace tiny3d::detail

#endif
