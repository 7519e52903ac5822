// stroke_outline.h — (internal) exact pixel coverage of a stroke near its ends, column by
// column, from the stroke's outline.
//
// In the line's (major, minor) = (X, Y) frame with the major axis the one the line advances
// along faster, the stroke (a capsule for round caps, a rectangle for butt caps) is convex,
// so over each X its cross-section is one interval [lower(X), upper(X)]. The area of pixel
// [i, i+1] × [j, j+1] inside the stroke is then
//     ∫ over the column of  clamp(upper(X) − j, 0, 1) − clamp(lower(X) − j, 0, 1)  dX
//   = (E_up(j) − E_up(j+1)) − (E_low(j) − E_low(j+1)),   E(t) = ∫ max(y(X) − t, 0) dX,
// where the integrals run over the part of the column inside the stroke's X extent. Each
// chain (upper, lower) is a few pieces, each monotone in Y: the straight sides, the butt
// ends, and the caps' arcs y = cy ± √(h² − (X − cx)²) split at their top or bottom. For a
// monotone piece E(t) is closed form: the whole piece above t integrates its primitive; a
// piece crossing t integrates only the part above the crossing. The arc's primitive is
//     S(w) = ∫ √(h² − w²) dw = ½ (w·√(h² − w²) + h²·asin(w/h)),
// so a column needs a handful of square roots and arcsines whatever its number of rows.
// Everything is in double, relative to the segment's first end (small numbers).
#ifndef TINY3D_STROKE_OUTLINE_H
#define TINY3D_STROKE_OUTLINE_H

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "coverage_geometry.h"
#include "line_clip.h"

namespace tiny3d::detail {

// S(w) = ∫₀ʷ √(h² − v²) dv for |w| ≤ h (the arc's primitive; see the file comment).
inline double arc_primitive(double w, double h) {
    const double root = std::sqrt(std::max(0.0, h * h - w * w));
    return 0.5 * (w * root + h * h * fast_atan2(w, root));
}

// One monotone piece of a chain over [x1, x2]: a straight segment from (x1, y1) to (x2, y2),
// or the arc y = cy + s·√(h² − (X − cx)²) (s = +1 upper half, −1 lower half) of disc
// `disc` (0 at A, 1 at B) lying on one side of cx, with S at its ends (s1, s2).
struct outline_piece {
    double x1, x2, y1, y2;
    bool arc;
    int disc;
    double cx, cy, s, s1, s2;
};

// The stroke's upper or lower boundary as a function of X, left to right.
struct outline_chain {
    static constexpr int kMaxPieces = 5;  // cap arc (2 halves), side, cap arc (2 halves)
    outline_piece piece[kMaxPieces];
    int n = 0;

    void add_line(double xa, double ya, double xb, double yb) {
        if (xb > xa) piece[n++] = {xa, xb, ya, yb, false, 0, 0, 0, 0, 0, 0};
    }
    // The arc of disc `disc` (centre cx, cy, radius h) on side s from (xa, ya) to (xb, yb),
    // split at cx (height cy + s·h, S = 0); sa, sb: S at xa − cx and xb − cx.
    void add_arc(double xa, double ya, double sa, double xb, double yb, double sb, int disc, double cx, double cy,
                 double s, double h) {
        if (xa < cx && cx < xb) {
            piece[n++] = {xa, cx, ya, cy + s * h, true, disc, cx, cy, s, sa, 0.0};
            piece[n++] = {cx, xb, cy + s * h, yb, true, disc, cx, cy, s, 0.0, sb};
        } else if (xb > xa) {
            piece[n++] = {xa, xb, ya, yb, true, disc, cx, cy, s, sa, sb};
        }
    }
};

// Upper and lower chains of the stroke of half-width h from A = (0, 0) along the unit
// direction (dx, dy), dx ≥ |dy|, of length L, with a round or butt cap at each end.
struct stroke_outline {
    outline_chain upper, lower;
    double h;
    double x_min, x_max;  // the stroke's X extent
    double cx[2], cy[2];  // the discs' centres (A, B)

    stroke_outline(double dx, double dy, double length, double half_width, bool round_a, bool round_b)
        : h(half_width) {
        // Corners of the rectangle: A ± h·n, B ± h·n with n = (−dy, dx) (points up: dx ≥ 0).
        const double bx = length * dx, by = length * dy;
        const double apx = -h * dy, apy = h * dx, amx = h * dy, amy = -h * dx;  // A+, A−
        const double bpx = bx + apx, bpy = by + apy, bmx = bx + amx, bmy = by + amy;  // B+, B−
        cx[0] = cy[0] = 0.0;
        cx[1] = bx;
        cy[1] = by;
        // S at the arcs' ends: ±S(h) = ±πh²/4 at the leftmost/rightmost points and, S being
        // odd, ±S(h·dy) at the tangent points (w = ∓h·dy on both discs).
        const double quarter = 0.25 * 3.14159265358979323846 * h * h;
        const double tangent = (round_a || round_b) ? arc_primitive(h * dy, h) : 0.0;
        // End A: the round cap's arcs run from the leftmost point (−h, 0) to A+ and A−; a
        // butt end is the segment A+A−, on the lower chain when it falls left to right.
        if (round_a) {
            upper.add_arc(-h, 0.0, -quarter, apx, apy, -tangent, 0, 0.0, 0.0, 1.0, h);
            lower.add_arc(-h, 0.0, -quarter, amx, amy, tangent, 0, 0.0, 0.0, -1.0, h);
        } else if (dy < 0) {
            upper.add_line(amx, amy, apx, apy);
        } else {
            lower.add_line(apx, apy, amx, amy);
        }
        upper.add_line(apx, apy, bpx, bpy);
        lower.add_line(amx, amy, bmx, bmy);
        if (round_b) {
            upper.add_arc(bpx, bpy, -tangent, bx + h, by, quarter, 1, bx, by, 1.0, h);
            lower.add_arc(bmx, bmy, tangent, bx + h, by, quarter, 1, bx, by, -1.0, h);
        } else if (dy > 0) {
            upper.add_line(bpx, bpy, bmx, bmy);
        } else {
            lower.add_line(bmx, bmy, bpx, bpy);
        }
        const double reach_a = round_a ? h : h * std::fabs(dy), reach_b = round_b ? h : h * std::fabs(dy);
        x_min = -reach_a;
        x_max = bx + reach_b;
    }
};

// Draws the stroke's columns from its outline, one major column [c0, c0 + 1] at a time
// (X relative to A). S at a column line is shared by the upper and lower arcs of a disc
// and by the column on either side of the line.
class outline_columns {
public:
    explicit outline_columns(const stroke_outline &outline) : o_(outline) {}

    // Every row the outline reaches in column [c0, c0 + 1] gets its exact area, times
    // `intensity`, combined "over". `column` points at the column's pixel in row 0; rows
    // are `stride` apart, `rows` of them; row j spans Y = j − ay relative to A.
    void draw(double c0, double ay, float *column, std::ptrdiff_t stride, int rows, float intensity) {
        const double c1 = c0 + 1.0;
        // Column-line primitives: reuse the previous column's right line as this left one.
        for (int d = 0; d < 2; ++d) {
            left_[d] = c0 == right_line_ ? right_[d] : line_point{};
            right_[d] = line_point{};
        }
        right_line_ = c1;
        span up[outline_chain::kMaxPieces], low[outline_chain::kMaxPieces];
        const int n_up = spans(o_.upper, c0, c1, up), n_low = spans(o_.lower, c0, c1, low);
        if (n_up == 0 || n_low == 0) return;
        double y_lo = low[0].ya, y_hi = up[0].ya;
        for (int k = 0; k < n_low; ++k) y_lo = std::min({y_lo, low[k].ya, low[k].yb});
        for (int k = 0; k < n_up; ++k) y_hi = std::max({y_hi, up[k].ya, up[k].yb});
        // Rows whose span meets (y_lo, y_hi); clamped before converting (truncation of a
        // non-negative value is floor; ceil(v) = −floor(−v)).
        const double lo_row = std::clamp(ay + y_lo, 0.0, double(rows)), hi_row = std::clamp(ay + y_hi, 0.0, double(rows));
        const int j_first = int(lo_row);
        const int j_last = rows - int(double(rows) - hi_row) - 1;
        // D(t) = E_up(t) − E_low(t) at the row lines of a block of rows; the area of row j
        // is D(j) − D(j + 1).
        for (int j0 = j_first; j0 <= j_last; j0 += kRowBlock) {
            const int count = std::min(kRowBlock, j_last - j0 + 1);
            double d[kRowBlock + 1] = {};
            const double t0 = j0 - ay;
            for (int k = 0; k < n_up; ++k) add_excess(up[k], t0, count, 1.0, d);
            for (int k = 0; k < n_low; ++k) add_excess(low[k], t0, count, -1.0, d);
            for (int r = 0; r < count; ++r) {
                const double area = d[r] - d[r + 1];
                if (area > 0.0) combine_over(column[(j0 + r) * stride], intensity * float(std::min(area, 1.0)));
            }
        }
    }

private:
    static constexpr int kRowBlock = 16;
    static constexpr double kUnset = -1.0;  // no square root is negative

    // A piece restricted to one column: [xa, xb], its ends' heights, ∫ y dX over it and
    // (arcs) S at its ends.
    struct span {
        const outline_piece *p;
        double xa, xb, ya, yb, integral, sa, sb;
    };

    // The arc of disc d at this column's left (side 0) or right (side 1) line x:
    // √(h² − w²) and S(w), w = x − cx.
    struct line_point {
        double root = kUnset, primitive = 0.0;
    };
    const line_point &at_line(int d, int side, double x) {
        line_point &pt = side == 0 ? left_[d] : right_[d];
        if (pt.root == kUnset) {
            const double w = x - o_.cx[d], h = o_.h;
            pt.root = std::sqrt(std::max(0.0, h * h - w * w));
            pt.primitive = 0.5 * (w * pt.root + h * h * fast_atan2(w, pt.root));
        }
        return pt;
    }

    int spans(const outline_chain &chain, double c0, double c1, span *out) {
        int n = 0;
        for (int k = 0; k < chain.n; ++k) {
            const outline_piece &p = chain.piece[k];
            if (p.x1 >= c1) break;  // pieces run left to right
            const bool clip_a = c0 > p.x1, clip_b = c1 < p.x2;
            const double xa = clip_a ? c0 : p.x1, xb = clip_b ? c1 : p.x2;
            if (!(xb > xa)) continue;
            span &s = out[n++];
            s.p = &p;
            s.xa = xa;
            s.xb = xb;
            if (p.arc) {
                // A clipped end lies on a column line (shared values); otherwise the piece's own.
                auto end_at = [&](bool clipped, int side, double x, double y_own, double s_own, double &y, double &prim) {
                    if (!clipped) {
                        y = y_own;
                        prim = s_own;
                        return;
                    }
                    const line_point &pt = at_line(p.disc, side, x);
                    y = p.cy + p.s * pt.root;
                    prim = pt.primitive;
                };
                end_at(clip_a, 0, xa, p.y1, p.s1, s.ya, s.sa);
                end_at(clip_b, 1, xb, p.y2, p.s2, s.yb, s.sb);
                s.integral = p.cy * (xb - xa) + p.s * (s.sb - s.sa);
            } else {
                const double slope = (p.y2 - p.y1) / (p.x2 - p.x1);
                s.ya = clip_a ? p.y1 + slope * (xa - p.x1) : p.y1;
                s.yb = clip_b ? p.y1 + slope * (xb - p.x1) : p.y2;
                s.integral = 0.5 * (s.ya + s.yb) * (xb - xa);
            }
        }
        return n;
    }

    // d[k] += sign · E(t0 + k), k = 0..count, for one span, E(t) = ∫ max(y(X) − t, 0) dX
    // in closed form (see the file comment); t grows with k.
    void add_excess(const span &s, double t0, int count, double sign, double *d) const {
        const double hi = std::max(s.ya, s.yb), lo = std::min(s.ya, s.yb), width = s.xb - s.xa;
        const outline_piece &p = *s.p;
        int k = 0;
        for (; k <= count && t0 + k <= lo; ++k) d[k] += sign * (s.integral - (t0 + k) * width);  // all above t
        for (; k <= count && t0 + k < hi; ++k) {
            const double t = t0 + k;
            double e;
            if (!p.arc) {
                e = width * (hi - t) * (hi - t) / (2.0 * (hi - lo));  // the triangle above t
            } else {
                // The arc crosses t once, at w = ±√(h² − (t − cy)²) on the piece's side of cx.
                const double q = t - p.cy, h = o_.h;
                const double side = p.x1 + p.x2 < 2.0 * p.cx ? -1.0 : 1.0;
                const double xc = std::clamp(p.cx + side * std::sqrt(std::max(0.0, h * h - q * q)), s.xa, s.xb);
                const double sc = arc_primitive(xc - p.cx, h);
                // The part above t: left of the crossing if the piece falls, right if it rises.
                e = s.ya > s.yb ? -q * (xc - s.xa) + p.s * (sc - s.sa) : -q * (s.xb - xc) + p.s * (s.sb - sc);
            }
            d[k] += sign * e;
        }
    }

    const stroke_outline &o_;
    line_point left_[2], right_[2];
    double right_line_ = kUnset;
};

}  // namespace tiny3d::detail

#endif
