// clipping.cpp — homogeneous Liang–Barsky against the frustum planes, segment vs circle,
// frustum planes from a matrix and sphere culling. See include/pipeline.h.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "pipeline.h"

namespace tiny3d {

namespace {

constexpr int plane_count = 6;

// Signed distance to clip plane i (order of clip_plane_bits), ≥ 0 inside.
double plane_distance(int i, const vec4_t &p) {
    switch (i) {
        case 0: return double(p.z) + p.w;
        case 1: return double(p.w) - p.z;
        case 2: return double(p.x) + p.w;
        case 3: return double(p.w) - p.x;
        case 4: return double(p.y) + p.w;
        default: return double(p.w) - p.y;
    }
}

bool finite4(const vec4_t &p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

// double → float, ±inf beyond the float range (a plain conversion would be undefined).
float to_float(double v) {
    constexpr double float_max = std::numeric_limits<float>::max();
    if (v > float_max) return std::numeric_limits<float>::infinity();
    if (v < -float_max) return -std::numeric_limits<float>::infinity();
    return float(v);
}

// row(3) + sign · row(r) of the column-major matrix, in double (a plane of clip space).
std::array<double, 4> plane_row(const mat4_t &m, int r, double sign) {
    std::array<double, 4> p;
    for (int c = 0; c < 4; ++c) p[c] = double(m.m[c * 4 + 3]) + sign * double(m.m[c * 4 + r]);
    return p;
}

}  // namespace

unsigned clip_outcode(vec4_t p, float guard) {
    if (!finite4(p)) return clip_all;
    const float gw = guard * p.w;
    const float distance[plane_count] = {p.z + p.w, p.w - p.z, p.x + gw, gw - p.x, p.y + gw, gw - p.y};
    unsigned code = 0;
    for (int i = 0; i < plane_count; ++i)
        if (!(distance[i] >= 0.0f)) code |= 1u << i;
    return code;
}

segment_clip clip_segment(vec4_t a, vec4_t b, unsigned planes) {
    if (!finite4(a) || !finite4(b)) return {false, 0.0, 0.0};
    double t0 = 0.0, t1 = 1.0;
    for (int i = 0; i < plane_count; ++i) {
        if (!(planes & (1u << i))) continue;
        const double da = plane_distance(i, a), db = plane_distance(i, b);
        if (da < 0.0 && db < 0.0) return {false, 0.0, 0.0};
        // Where the distance, linear in t, crosses 0.
        if (da < 0.0) t0 = std::max(t0, da / (da - db));
        else if (db < 0.0) t1 = std::min(t1, da / (da - db));
    }
    if (t0 > t1) return {false, 0.0, 0.0};
    return {true, t0, t1};
}

vec4_t lerp4(vec4_t a, vec4_t b, float t) {
    return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z), a.w + t * (b.w - a.w)};
}

circle circular_viewport(const canvas_t &canvas) {
    return {canvas.width * 0.5f, canvas.height * 0.5f, std::min(canvas.width, canvas.height) * 0.5f};
}

bool point_in_circle(const circle &c, float x, float y) {
    const double dx = double(x) - c.cx, dy = double(y) - c.cy;
    return dx * dx + dy * dy <= double(c.radius) * c.radius;  // false for NaN
}

segment_clip clip_segment_circle(const circle &c, float x0, float y0, float x1, float y1) {
    constexpr segment_clip none{false, 0.0, 0.0};
    if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1)) return none;
    // |f + t·d|² = r²  ⇔  a t² + b t + cc = 0 with f = p0 − centre.
    const double dx = double(x1) - x0, dy = double(y1) - y0;
    const double fx = double(x0) - c.cx, fy = double(y0) - c.cy;
    const double a = dx * dx + dy * dy, b = 2.0 * (fx * dx + fy * dy);
    const double cc = fx * fx + fy * fy - double(c.radius) * c.radius;
    if (a == 0.0) return cc <= 0.0 ? segment_clip{true, 0.0, 1.0} : none;
    const double disc = b * b - 4.0 * a * cc;
    if (!(disc > 0.0)) return none;  // misses or only touches the circle
    // Roots without cancellation: q = −(b + sign(b)·√disc)/2, roots q/a and cc/q.
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    double r0 = q / a, r1 = cc / q;
    if (r0 > r1) std::swap(r0, r1);
    const double t0 = std::max(0.0, r0), t1 = std::min(1.0, r1);
    if (!(t0 <= t1)) return none;
    return {true, t0, t1};
}

frustum frustum_from_matrix(const mat4_t &m) {
    // Gribb–Hartmann: near/far from row 2, left/right from row 0, bottom/top from row 1.
    static constexpr int rows[6] = {2, 2, 0, 0, 1, 1};
    frustum f;
    for (int i = 0; i < 6; ++i) {
        // In double: the matrix that frames a mesh of radius r has entries ~1/r, whose
        // squares leave the float range for r beyond ~1e19 or below ~1e-19 (a zero length
        // would make the plane "constrain nothing", an infinite one a zero plane).
        const std::array<double, 4> p = plane_row(m, rows[i], i % 2 == 0 ? 1.0 : -1.0);
        const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        // A plane with no normal (e.g. a far plane at infinity) constrains nothing; a NaN
        // plane (non-finite matrix) stays NaN, so cull_sphere says "intersecting". An offset
        // beyond float (|w| > FLT_MAX · |normal|) becomes ±inf: no float point reaches it.
        if (len == 0.0) f.plane[i] = {0.0f, 0.0f, 0.0f, std::numeric_limits<float>::infinity()};
        else f.plane[i] = {float(p[0] / len), float(p[1] / len), float(p[2] / len), to_float(p[3] / len)};
    }
    return f;
}

cull_result cull_sphere(const frustum &f, const bounding_sphere &s) {
    if (!(s.radius >= 0.0f)) return cull_result::outside;
    cull_result result = cull_result::inside;
    for (const vec4_t &p : f.plane) {
        // In double: p · centre of a centre near ±FLT_MAX can overflow float.
        const double d = double(p.x) * s.center.x + double(p.y) * s.center.y + double(p.z) * s.center.z + p.w;
        if (d < -double(s.radius)) return cull_result::outside;
        if (!(d >= double(s.radius))) result = cull_result::intersecting;
    }
    return result;
}

}  // namespace tiny3d

bool clip_to_circular_viewport(canvas_t *c, float x, float y) {
    return c && tiny3d::point_in_circle(tiny3d::circular_viewport(*c), x, y);
}
