// coverage_geometry.h — (internal) exact areas of small convex polygons, alone and inside
// a disc, for the exact coverage reference (double; templated on the scalar type), and
// the fast arctangent the fast line's outline integration uses.
#ifndef TINY3D_COVERAGE_GEOMETRY_H
#define TINY3D_COVERAGE_GEOMETRY_H

#include <algorithm>
#include <cmath>

namespace tiny3d::detail {

template <class T>
struct point2 {
    T x, y;
};

// A convex polygon of at most kMax vertices: a square cut by up to 4 half-planes (each
// cut adds at most one vertex to a convex polygon).
template <class T>
struct small_polygon {
    static constexpr int kMax = 8;
    point2<T> v[kMax];
    int n = 0;
};

// Sutherland–Hodgman step: the part of `in` where a·x + b·y ≤ c.
template <class T>
small_polygon<T> clip_half_plane(const small_polygon<T> &in, T a, T b, T c) {
    small_polygon<T> out;
    for (int i = 0; i < in.n; ++i) {
        const point2<T> p = in.v[i], q = in.v[i + 1 == in.n ? 0 : i + 1];
        const T fp = a * p.x + b * p.y - c, fq = a * q.x + b * q.y - c;
        if (fp <= 0) out.v[out.n++] = p;
        if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
            const T t = fp / (fp - fq);
            out.v[out.n++] = {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
        }
    }
    return out;
}

// Shoelace formula: signed area, positive for counter-clockwise (in x-right, y-up terms).
// Taken relative to the first vertex, so far-off polygons do not cancel catastrophically.
template <class T>
T signed_area(const small_polygon<T> &p) {
    if (p.n < 3) return 0;
    const point2<T> o = p.v[0];
    T twice = 0;
    for (int i = 1; i + 1 < p.n; ++i) {
        const T ax = p.v[i].x - o.x, ay = p.v[i].y - o.y;
        const T bx = p.v[i + 1].x - o.x, by = p.v[i + 1].y - o.y;
        twice += ax * by - ay * bx;
    }
    return twice / 2;
}

// atan2(y, x) to within 1e-12 rad, several times cheaper than libm's: fold to
// z = min/max ∈ [0, 1], shift by π/6 when z > tan(π/12) (atan z = π/6 + atan((z − 1/√3) /
// (1 + z/√3)), leaving |z| ≤ tan(π/12) ≈ 0.268), then the Taylor series to z^17
// (remainder ≤ 0.268^19 / 19 < 1e-12), and unfold by octant.
template <class T>
T fast_atan2(T y, T x) {
    constexpr T kPi = T(3.14159265358979323846), kTanPi12 = T(0.26794919243112270), kInvSqrt3 = T(0.57735026918962576);
    const T ax = std::fabs(x), ay = std::fabs(y);
    if (ax == 0 && ay == 0) return 0;
    const bool steep = ay > ax;
    T z = steep ? ax / ay : ay / ax;
    T base = 0;
    if (z > kTanPi12) {
        z = (z - kInvSqrt3) / (1 + z * kInvSqrt3);
        base = kPi / 6;
    }
    const T z2 = z * z;
    // atan z = z·(1 − z²/3 + z⁴/5 − … + z¹⁶/17), Horner in z².
    constexpr T c3 = T(1) / 3, c5 = T(1) / 5, c7 = T(1) / 7, c9 = T(1) / 9, c11 = T(1) / 11, c13 = T(1) / 13,
                c15 = T(1) / 15, c17 = T(1) / 17;
    const T series =
        1 - z2 * (c3 - z2 * (c5 - z2 * (c7 - z2 * (c9 - z2 * (c11 - z2 * (c13 - z2 * (c15 - z2 * c17)))))));
    T angle = base + z * series;
    if (steep) angle = kPi / 2 - angle;
    if (x < 0) angle = kPi - angle;
    return y < 0 ? -angle : angle;
}

// Signed angle (in (−π, π]) from direction p to direction q.
template <class T>
T angle_between(point2<T> p, point2<T> q) {
    return std::atan2(p.x * q.y - p.y * q.x, p.x * q.x + p.y * q.y);
}

// Signed area of (triangle O, p, q) ∩ disc(O, r), O = origin, less the sectors' part: the
// edge p→q is split where it crosses the circle; inside pieces count as triangles (the
// returned area), outside pieces as sectors (their angles are added to `angles`, area r²/2
// per radian). Summed over a polygon's edges this is the exact area of polygon ∩ disc.
template <class T>
T edge_disc_area(point2<T> p, point2<T> q, T r2, T &angles) {
    const point2<T> d{q.x - p.x, q.y - p.y};
    const T a = d.x * d.x + d.y * d.y;
    if (a == 0) return 0;
    const T b = p.x * d.x + p.y * d.y;
    const T c = p.x * p.x + p.y * p.y - r2;
    if (c <= 0 && q.x * q.x + q.y * q.y <= r2) return (p.x * q.y - p.y * q.x) / 2;  // inside: a triangle
    const T disc = b * b - a * c;
    if (disc <= 0) {  // the edge's line misses the circle
        angles += angle_between(p, q);
        return 0;
    }
    const T s = std::sqrt(disc);
    const T t_in = std::clamp((-b - s) / a, T(0), T(1));
    const T t_out = std::clamp((-b + s) / a, T(0), T(1));
    const point2<T> A{p.x + t_in * d.x, p.y + t_in * d.y};
    const point2<T> B{p.x + t_out * d.x, p.y + t_out * d.y};
    if (t_in > 0) angles += angle_between(p, A);
    if (t_out < 1) angles += angle_between(B, q);
    return (A.x * B.y - A.y * B.x) / 2;
}

// Unsigned area of the convex polygon ∩ the disc of radius r centred at (cx, cy).
template <class T>
T polygon_disc_area(const small_polygon<T> &poly, T cx, T cy, T r) {
    const T r2 = r * r;
    T angles = 0;
    T sum = 0;
    for (int i = 0; i < poly.n; ++i) {
        const point2<T> p = poly.v[i], q = poly.v[i + 1 == poly.n ? 0 : i + 1];
        sum += edge_disc_area<T>({p.x - cx, p.y - cy}, {q.x - cx, q.y - cy}, r2, angles);
    }
    return std::fabs(sum + r2 / 2 * angles);
}

}  // namespace tiny3d::detail

#endif
