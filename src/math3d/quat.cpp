// quat.cpp — unit quaternions for orientation; arithmetic in double, rounded once.
#include <cmath>

#include "math3d.h"
#include "rows3.h"

namespace {

struct dquat {
    double x, y, z, w;
};

double dot(dquat a, dquat b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }

// d / |d|, or the identity when d is zero or not finite.
dquat unit(dquat d) {
    const double len = std::sqrt(dot(d, d));
    if (!(len > 0.0) || !std::isfinite(len)) return {0.0, 0.0, 0.0, 1.0};
    return {d.x / len, d.y / len, d.z / len, d.w / len};
}

dquat unit(tiny3d::quat q) { return unit(dquat{q.x, q.y, q.z, q.w}); }

tiny3d::quat to_float(dquat q) { return {float(q.x), float(q.y), float(q.z), float(q.w)}; }

// sin(x)/x, with its Taylor series where the quotient would lose digits (|x| < 1e-4:
// the next term x⁴/120 < 1e-18).
double sin_x_over_x(double x) { return std::fabs(x) < 1e-4 ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

}  // namespace

namespace tiny3d {

quat quat_from_axis_angle(vec3_t axis, float angle) {
    const double x = axis.x, y = axis.y, z = axis.z;
    const double len = std::sqrt(x * x + y * y + z * z);
    if (!(len > 0.0) || !std::isfinite(len) || !std::isfinite(angle)) return quat_identity();
    const double half = 0.5 * double(angle), s = std::sin(half) / len;
    return to_float({x * s, y * s, z * s, std::cos(half)});
}

quat quat_multiply(quat a, quat b) {
    const dquat p = {a.x, a.y, a.z, a.w}, q = {b.x, b.y, b.z, b.w};
    return to_float({p.w * q.x + p.x * q.w + p.y * q.z - p.z * q.y, p.w * q.y - p.x * q.z + p.y * q.w + p.z * q.x,
                     p.w * q.z + p.x * q.y - p.y * q.x + p.z * q.w, p.w * q.w - p.x * q.x - p.y * q.y - p.z * q.z});
}

quat quat_normalize(quat q) { return to_float(unit(q)); }

mat4_t quat_to_mat4(quat q) {
    const dquat u = unit(q);
    const double x = u.x, y = u.y, z = u.z, w = u.w;
    const double r[3][3] = {
        {1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - z * w), 2.0 * (x * z + y * w)},
        {2.0 * (x * y + z * w), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - x * w)},
        {2.0 * (x * z - y * w), 2.0 * (y * z + x * w), 1.0 - 2.0 * (x * x + y * y)},
    };
    return detail::from_rows3(r);
}

// v' = v + 2w(u×v) + 2u×(u×v) for the unit q = (u, w).
vec3_t quat_rotate(quat q, vec3_t v) {
    const dquat n = unit(q);
    const double vx = v.x, vy = v.y, vz = v.z;
    const double tx = 2.0 * (n.y * vz - n.z * vy), ty = 2.0 * (n.z * vx - n.x * vz), tz = 2.0 * (n.x * vy - n.y * vx);
    return {float(vx + n.w * tx + (n.y * tz - n.z * ty)), float(vy + n.w * ty + (n.z * tx - n.x * tz)),
            float(vz + n.w * tz + (n.x * ty - n.y * tx))};
}

// pbrt-v4's form: slerp = a·(1−t)·sinc((1−t)θ)/sinc θ + b·t·sinc(tθ)/sinc θ, with
// θ = 2·atan2(|a − b|, |a + b|) (accurate for every angle); b is first flipped to the
// hemisphere of a so θ ≤ π/2 and sinc θ ≥ 2/π.
quat quat_slerp(quat a, quat b, float t) {
    const dquat p = unit(a);
    dquat q = unit(b);
    if (dot(p, q) < 0.0) q = {-q.x, -q.y, -q.z, -q.w};
    const dquat diff = {p.x - q.x, p.y - q.y, p.z - q.z, p.w - q.w};
    const dquat sum = {p.x + q.x, p.y + q.y, p.z + q.z, p.w + q.w};
    const double theta = 2.0 * std::atan2(std::sqrt(dot(diff, diff)), std::sqrt(dot(sum, sum)));
    const double td = std::isfinite(t) ? double(t) : 0.0;
    const double sinc_theta = sin_x_over_x(theta);
    const double wp = (1.0 - td) * sin_x_over_x((1.0 - td) * theta) / sinc_theta;
    const double wq = td * sin_x_over_x(td * theta) / sinc_theta;
    const dquat r = {wp * p.x + wq * q.x, wp * p.y + wq * q.y, wp * p.z + wq * q.z, wp * p.w + wq * q.w};
    return to_float(unit(r));
}

}  // namespace tiny3d
