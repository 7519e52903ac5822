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

// One monotone piece of a chain over [x1, x2]: a straight segment from (x1, y1) to (x2, y2),
// or the arc y = cy + s·√(h² − (X − cx)²) (s = +1 upper half, −1 lower half) lying on one
// side of cx.
struct outline_piece {
    double x1, x2, y1, y2;
    bool arc;
    double cx, cy, s;
};

// The stroke's upper or lower boundary as a function of X, left to right.
struct outline_chain {
    static constexpr int kMaxPieces = 5;  // cap arc (2 halves), side, cap arc (2 halves)
    outline_piece piece[kMaxPieces];
    int n = 0;

    void add_line(double xa, double ya, double xb, double yb) {
        if (xb > xa) piece[n++] = {xa, xb, ya, yb, false, 0, 0, 0};
    }
    // The arc of the disc (cx, cy, h) on side s over [xa, xb], split at cx.
    void add_arc(double xa, double xb, double cx, double cy, double s, double h) {
        auto y = [&](double x) { return cy + s * std::sqrt(std::max(0.0, h * h - (x - cx) * (x - cx))); };
        if (xa < cx && cx < xb) {
            piece[n++] = {xa, cx, y(xa), cy + s * h, true, cx, cy, s};
            piece[n++] = {cx, xb, cy + s * h, y(xb), true, cx, cy, s};
        } else if (xb > xa) {
            piece[n++] = {xa, xb, y(xa), y(xb), true, cx, cy, s};
        }
    }
};

// Upper and lower chains of the stroke of half-width h from A = (0, 0) along the unit
// direction (dx, dy), dx ≥ |dy|, of length L, with a round or butt cap at each end.
struct stroke_outline {
    outline_chain upper, lower;
    double h;
    double x_min, x_max;  // the stroke's X extent

    stroke_outline(double dx, double dy, double length, double half_width, bool round_a, bool round_b)
        : h(half_width) {
        // Corners of the rectangle: A ± h·n, B ± h·n with n = (−dy, dx) (points up: dx ≥ 0).
        const double bx = length * dx, by = length * dy;
        const double apx = -h * dy, apy = h * dx, amx = h * dy, amy = -h * dx;  // A+, A−
        const double bpx = bx + apx, bpy = by + apy, bmx = bx + amx, bmy = by + amy;  // B+, B−
        // End A: the round cap's arcs run from the leftmost point (−h, 0) to A+ and A−; a
        // butt end is the segment A+A−, on the lower chain when it falls left to right.
        if (round_a) {
            upper.add_arc(-h, apx, 0.0, 0.0, 1.0, h);
            lower.add_arc(-h, amx, 0.0, 0.0, -1.0, h);
        } else if (dy < 0) {
            upper.add_line(amx, amy, apx, apy);
        } else {
            lower.add_line(apx, apy, amx, amy);
        }
        upper.add_line(apx, apy, bpx, bpy);
        lower.add_line(amx, amy, bmx, bmy);
        if (round_b) {
            upper.add_arc(bpx, bx + h, bx, by, 1.0, h);
            lower.add_arc(bmx, bx + h, bx, by, -1.0, h);
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

// A piece restricted to one column: [xa, xb], its ends' heights and ∫ y dX over it.
struct piece_span {
    const outline_piece *p;
    double xa, xb, ya, yb, integral, sa, sb;  // sa, sb: S(xa − cx), S(xb − cx) for arcs
};

// S(w) = ∫₀ʷ √(h² − v²) dv for |w| ≤ h (the arc's primitive; see the file comment).
inline double arc_primitive(double w, double h) {
    const double root = std::sqrt(std::max(0.0, h * h - w * w));
    return 0.5 * (w * root + h * h * fast_atan2(w, root));
}

// The pieces of `chain` over the column [c0, c1]; returns their number (≤ kMaxPieces).
inline int chain_spans(const outline_chain &chain, double h, double c0, double c1, piece_span *out) {
    int n = 0;
    for (int k = 0; k < chain.n; ++k) {
        const outline_piece &p = chain.piece[k];
        const double xa = std::max(c0, p.x1), xb = std::min(c1, p.x2);
        if (!(xb > xa)) continue;
        piece_span &s = out[n++];
        s.p = &p;
        s.xa = xa;
        s.xb = xb;
        if (p.arc) {
            s.ya = xa == p.x1 ? p.y1 : p.cy + p.s * std::sqrt(std::max(0.0, h * h - (xa - p.cx) * (xa - p.cx)));
            s.yb = xb == p.x2 ? p.y2 : p.cy + p.s * std::sqrt(std::max(0.0, h * h - (xb - p.cx) * (xb - p.cx)));
            s.sa = arc_primitive(xa - p.cx, h);
            s.sb = arc_primitive(xb - p.cx, h);
            s.integral = p.cy * (xb - xa) + p.s * (s.sb - s.sa);
        } else {
            const double slope = (p.y2 - p.y1) / (p.x2 - p.x1);
            s.ya = p.y1 + slope * (xa - p.x1);
            s.yb = p.y1 + slope * (xb - p.x1);
            s.integral = 0.5 * (s.ya + s.yb) * (xb - xa);
        }
    }
    return n;
}

// E(t) = ∫ max(y(X) − t, 0) dX over one span (closed form; see the file comment).
inline double span_excess(const piece_span &s, double t, double h) {
    const double hi = std::max(s.ya, s.yb), lo = std::min(s.ya, s.yb);
    if (t >= hi) return 0.0;
    const double width = s.xb - s.xa;
    if (t <= lo) return s.integral - t * width;
    const outline_piece &p = *s.p;
    if (!p.arc) return width * (hi - t) * (hi - t) / (2.0 * (hi - lo));  // the triangle above t
    // The arc crosses t once, at w = ±√(h² − (t − cy)²) on the piece's side of cx.
    const double q = t - p.cy;
    const double side = p.x1 + p.x2 < 2.0 * p.cx ? -1.0 : 1.0;
    const double wc = side * std::sqrt(std::max(0.0, h * h - q * q));
    const double xc = std::clamp(p.cx + wc, s.xa, s.xb);
    const double sc = arc_primitive(xc - p.cx, h);
    // The part above t: left of the crossing if the piece falls, right of it if it rises.
    if (s.ya > s.yb) return -q * (xc - s.xa) + p.s * (sc - s.sa);
    return -q * (s.xb - xc) + p.s * (s.sb - sc);
}

inline double chain_excess(const piece_span *spans, int n, double t, double h) {
    double sum = 0.0;
    for (int k = 0; k < n; ++k) sum += span_excess(spans[k], t, h);
    return sum;
}

// Draws one major column [c0, c0 + 1] (X relative to A) of the stroke: every row the
// outline reaches gets its exact area, times `intensity`, combined "over". `column` points
// at the column's pixel in row 0; rows are `stride` apart, `rows` of them; the row j
// spans Y = j − ay relative to A.
inline void draw_outline_column(const stroke_outline &outline, double c0, double ay, float *column,
                                std::ptrdiff_t stride, int rows, float intensity) {
    piece_span up[outline_chain::kMaxPieces], low[outline_chain::kMaxPieces];
    const int n_up = chain_spans(outline.upper, outline.h, c0, c0 + 1.0, up);
    const int n_low = chain_spans(outline.lower, outline.h, c0, c0 + 1.0, low);
    if (n_up == 0 || n_low == 0) return;
    double y_lo = low[0].ya, y_hi = up[0].ya;
    for (int k = 0; k < n_low; ++k) y_lo = std::min({y_lo, low[k].ya, low[k].yb});
    for (int k = 0; k < n_up; ++k) y_hi = std::max({y_hi, up[k].ya, up[k].yb});
    const int j_first = int(std::clamp(std::floor(ay + y_lo), 0.0, double(rows)));
    const int j_last = int(std::clamp(std::ceil(ay + y_hi), 0.0, double(rows))) - 1;
    if (j_first > j_last) return;
    const double h = outline.h;
    double t = j_first - ay;
    double e_up = chain_excess(up, n_up, t, h), e_low = chain_excess(low, n_low, t, h);
    for (int j = j_first; j <= j_last; ++j) {
        t = (j + 1) - ay;
        const double next_up = chain_excess(up, n_up, t, h), next_low = chain_excess(low, n_low, t, h);
        const double area = (e_up - next_up) - (e_low - next_low);
        if (area > 0.0) combine_over(column[j * stride], intensity * float(std::min(area, 1.0)));
        e_up = next_up;
        e_low = next_low;
    }
}

}  // namespace tiny3d::detail

#endif
