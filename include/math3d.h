// math3d.h — vectors, matrices, quaternions.
//
// Conventions (pinned by tests/math3d_test.cpp and tests/math3d_vector_test.cpp):
//  * Right-handed coordinates; the camera looks down −z; angles in radians.
//  * mat4_t::m[16] is column-major: element (row r, column c) is m[c*4 + r]; the
//    translation sits in m[12], m[13], m[14]. Vectors are columns: v' = M·v.
//    mat4_multiply(a, b) = a·b, i.e. b is applied first.
//  * Spherical form (the libtiny3d report's): θ = azimuth in the x-y plane from +x,
//    φ = polar angle from +z: x = r sinφ cosθ, y = r sinφ sinθ, z = r cosφ.
//  * Clip space is OpenGL's: after the divide by w, NDC is [−1, 1]³ and w > 0 in front
//    of the camera.
//
// Names: the report's names (and those other libtiny3d programs call) are global, as C
// programs expect; everything libtiny3d adds lives in namespace tiny3d. vec3_t, vec4_t,
// mat4_t are plain aggregates so C-style code — (vec3_t){1, 2, 3}, {.x = 1},
// mat4_t m = {0} — compiles as C++.
//
// C: this header compiles as C11 (strict -std=c11 too). A C program sees the types, M_PI,
// the functions declared between TINY3D_C_BEGIN and TINY3D_C_END (C linkage under C++) and
// the C part of compat/math_alias.h; the operators, the pointer overloads and namespace
// tiny3d are C++ only.
#ifndef TINY3D_MATH3D_H
#define TINY3D_MATH3D_H

#include "tiny3d_result.h"

#ifdef __cplusplus
#include <cmath>
#include <cstddef>
#include <span>
#else
#include <math.h>
#endif

// Strict C11 and C++ do not define M_PI in <math.h>; the value is glibc's, token for token.
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

// Members default to 0 in C++ so C idioms such as `vec3_t v = {0};` and `vec3_t v = {1};`
// compile as C++ under -Wextra -Werror (no missing-initializer warning); the types stay
// aggregates with the same layout in C and C++.
typedef struct vec3_t {
    float x TINY3D_DEFAULT(0), y TINY3D_DEFAULT(0), z TINY3D_DEFAULT(0);
} vec3_t;

typedef struct vec4_t {
    float x TINY3D_DEFAULT(0), y TINY3D_DEFAULT(0), z TINY3D_DEFAULT(0), w TINY3D_DEFAULT(0);
} vec4_t;

typedef struct mat4_t {
    float m[16];  // column-major: m[col*4 + row]
} mat4_t;

#ifdef __cplusplus
// ---- operators on vec3_t (C++ conveniences) ------------------------------------------
inline vec3_t operator+(vec3_t a, vec3_t b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline vec3_t operator-(vec3_t a, vec3_t b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline vec3_t operator-(vec3_t a) { return {-a.x, -a.y, -a.z}; }
inline vec3_t operator*(vec3_t a, float s) { return {a.x * s, a.y * s, a.z * s}; }
inline vec3_t operator*(float s, vec3_t a) { return {a.x * s, a.y * s, a.z * s}; }
inline vec3_t operator/(vec3_t a, float s) { return {a.x / s, a.y / s, a.z / s}; }
inline vec3_t &operator+=(vec3_t &a, vec3_t b) { return a = a + b; }
inline vec3_t &operator-=(vec3_t &a, vec3_t b) { return a = a - b; }
inline vec3_t &operator*=(vec3_t &a, float s) { return a = a * s; }
inline bool operator==(vec3_t a, vec3_t b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
#endif  // __cplusplus

// ---- the libtiny3d report's API (C linkage) -------------------------------------------
TINY3D_C_BEGIN
mat4_t mat4_identity(void);
mat4_t mat4_multiply(mat4_t a, mat4_t b);               // a·b (b applied first)
mat4_t mat4_translate(float tx, float ty, float tz);
mat4_t mat4_scale(float sx, float sy, float sz);
// Rotation by rx about x, then ry about y, then rz about z: R = Rz(rz)·Ry(ry)·Rx(rx).
mat4_t mat4_rotate_xyz(float rx, float ry, float rz);
// glFrustum: maps the near-plane rectangle [l, r] × [b, t] at z = −n to NDC x, y = ±1,
// z = −n to NDC −1 and z = −f to NDC +1. Requires l ≠ r, b ≠ t, 0 < n < f; otherwise
// returns the identity (tiny3d::frustum_checked reports the reason).
mat4_t mat4_frustum_asymmetric(float left, float right, float bottom, float top, float near_plane,
                               float far_plane);
// M·(x, y, z, 1); the result is divided by w when w is neither 0 nor 1 (a projective
// transform). With w = 0 (a point at infinity) x, y, z are returned undivided;
// tiny3d::transform_point tells which happened.
vec3_t apply_transform(mat4_t m, vec3_t v);
vec4_t vec4_from_vec3(vec3_t v, float w);  // (v.x, v.y, v.z, w)
// M·v for the column vector v, in float, each row summed left to right (m0·x + m4·y +
// m8·z + m12·w): tiny3d::transform_points_homogeneous gives the same bits.
vec4_t mat4_mul_vec4(mat4_t m, vec4_t v);

// Spherical → cartesian (convention at the top of the file): r·(sinφ cosθ, sinφ sinθ, cosφ).
// Evaluated in double and rounded once, so each component is within 0.5 ulp (+ 1e-16·r)
// of the exact value for the given float arguments. Any r, θ, φ (negative r mirrors).
vec3_t vec3_from_spherical(float r, float theta, float phi);

// Cartesian → spherical: r = |v| ≥ 0, θ = atan2(y, x) in (−π, π], φ = atan2(√(x²+y²), z)
// in [0, π] (atan2, not acos(z/r): accurate at the poles). Computed in double, each value
// rounded once. Conventions where the angles are undefined: r = 0 gives θ = φ = 0; on the
// z axis (x = y = 0) θ = 0 and φ = 0 (z > 0) or π (z < 0). Signed zeros are ignored.
// Round trip vec3_from_spherical(vec3_to_spherical(v)) ≈ v within 4e-7·|v| (tested).
// |v| beyond FLT_MAX gives r = +inf. NaN components give NaN outputs. Null pointers are
// skipped (the other outputs are still written).
void vec3_to_spherical(vec3_t v, float *r, float *theta, float *phi);

// The report's normalisation: Quake III inverse square root (magic 0x5f3759df, one
// Newton step) — the faithful variant; max relative error 1.8e-3 (bench `normalize`, its
// error column). Made safe: the squared length is brought into the normal float
// range by an exact power-of-two prescale when needed, so tiny, denormal and huge inputs
// (up to FLT_MAX) give a unit vector with the same 1.8e-3 accuracy, never inf or NaN.
// The zero vector (±0) gives {0, 0, 0}; any NaN component gives {0, 0, 0}; infinite
// components give the direction of the infinities (e.g. (inf, 5, −inf) → (0.707, 0, −0.707)).
// The global name keeps the report's (Quake) behaviour so the report's programs see the
// numbers they always saw; tiny3d::vec3_normalize (exact) and
// tiny3d::vec3_normalize_fast_accurate (≤ 2e-7) are the better choices.
vec3_t vec3_normalize_fast(vec3_t v);

// The report's slerp between directions a and b, kept as the faithful variant: inputs
// normalised with vec3_normalize_fast (Quake), θ₀ = acos(a·b), linear interpolation +
// renormalisation when a·b > 0.9995, otherwise s0·a + s1·b. The Quake inputs are 1.75e-3
// off unit length, which the acos/1/sin θ₀ form amplifies as θ grows; max error
// of the unit result (t in [0, 1]): 1.8e-3 for θ ≤ 90°, 6e-3 for θ ≤ 135°, 0.05 beyond
// (tests/math3d_vector_test, tests/bench/slerp). Made safe: pairs within ~17° of antipodal
// (a·b < 0 and sin θ₀ < 0.3, where the report's formula returns vectors of length down
// to 0 and directions off by up to 0.9, and divides by ~0 at θ₀ = π) are handed to
// tiny3d::vec3_slerp_robust, so exactly antipodal inputs turn on its deterministic great
// circle; a zero or NaN input uses the other input's direction (both unusable, or a
// non-finite t → {0, 0, 0}). The result has about unit length (within 3e-3 for t in
// [0, 1]). t outside [0, 1] extrapolates as the report's formula does (its length then
// drifts further: 0.9958 at t = 1.5 for a = b).
vec3_t vec3_slerp(vec3_t a, vec3_t b, float t);

// Rotations by `angle` radians, counter-clockwise looking from +axis toward the origin
// (right-handed): rotate_z(π/2) maps +x to +y, rotate_x(π/2) maps +y to +z, rotate_y(π/2)
// maps +z to +x. Global (C and C++), as other libtiny3d programs call them; also reachable
// as tiny3d::mat4_rotate_x/y/z.
mat4_t mat4_rotate_x(float angle);
mat4_t mat4_rotate_y(float angle);
mat4_t mat4_rotate_z(float angle);

TINY3D_C_END

#ifdef __cplusplus
// Pointer form used by several other libtiny3d programs (C++ only: C has one function per
// name, the report's): *v = vec3_normalize_fast(*v). A null pointer is ignored.
void vec3_normalize_fast(vec3_t *v);

namespace tiny3d {

// ---- vectors ---------------------------------------------------------------------------
inline float vec3_dot(vec3_t a, vec3_t b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
// Right-handed: cross((1,0,0), (0,1,0)) = (0,0,1).
inline vec3_t vec3_cross(vec3_t a, vec3_t b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// The small helpers every module shares, with ONE NaN rule: vec3_dot and vec3_cross are
// plain float arithmetic (NaN in, NaN out); the guarded helpers never return NaN —
// unit_or_zero gives (0, 0, 0), clamp01 gives 0.
//
// v·(1/√|v|²) in float, or (0, 0, 0) when |v|² ≤ 1e-30 (below that the direction is noise)
// or |v|² is not finite (a NaN or overflowing component). The shading functions' normaliser
// (the render context's SIMD kernels reproduce its bits); vec3_normalize is the exact one.
inline vec3_t unit_or_zero(vec3_t v) {
    const float len2 = vec3_dot(v, v);
    constexpr float MIN_LENGTH_SQUARED = 1e-30f;
    if (!(len2 > MIN_LENGTH_SQUARED) || !std::isfinite(len2)) return {0.0f, 0.0f, 0.0f};
    return v * (1.0f / std::sqrt(len2));
}
// v clamped to [0, 1]; NaN → 0.
inline float clamp01(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }

// Euclidean length, computed in double: no overflow or underflow for any finite float
// vector (a result above FLT_MAX rounds to +inf).
float vec3_length(vec3_t v);

// Exact normalisation: computed in double and rounded once, so every component is within
// 0.5 ulp + 1e-16 of the true unit vector (max relative error ≤ 6e-8, tested). Zero (and
// NaN) input gives {0, 0, 0}, never NaN; infinite components give the direction of the
// infinities; denormal and huge inputs are exact too.
vec3_t vec3_normalize(vec3_t v);

// The fast accurate normalisation (1/sqrt in float): max relative error ≤ 2e-7 against
// the double reference; its cost beside the Quake variant's: bench `normalize`. Same
// special cases as vec3_normalize.
vec3_t vec3_normalize_fast_accurate(vec3_t v);

// Slerp that is right for every input, with constant angular speed:
//  * direction: turns from â toward b̂ along their great circle by the angle t·θ, where
//    θ = atan2(|â×b̂|, â·b̂) ∈ [0, π] (no acos cancellation near ±1); computed in double,
//    so nearly parallel and nearly antipodal inputs are accurate (error ≤ 2e-7·length);
//  * exactly antipodal inputs (â×b̂ = 0, â·b̂ < 0): the great circle through â and the
//    fixed perpendicular tiny3d::vec3_any_perpendicular(â) — deterministic, unit result;
//  * length: interpolated linearly, (1−t)|a| + t|b|, clamped at 0 (extrapolation with t
//    outside [0, 1] may reach 0; the direction still extrapolates along the circle);
//  * a zero input takes the other input's direction (both zero → {0, 0, 0});
//  * any NaN or infinite component, or a non-finite t, gives {0, 0, 0}.
vec3_t vec3_slerp_robust(vec3_t a, vec3_t b, float t);

// A unit vector perpendicular to v, deterministic: v × e where e is the axis of v's
// smallest-magnitude component (first such on ties), normalised. Zero/NaN v → (1, 0, 0).
vec3_t vec3_any_perpendicular(vec3_t v);

// ---- matrices --------------------------------------------------------------------------
// The global rotations about one axis (above), under the namespace too.
using ::mat4_rotate_x;
using ::mat4_rotate_y;
using ::mat4_rotate_z;
// Rotation about an arbitrary axis (Rodrigues; the axis need not be unit length). A zero
// or non-finite axis gives the identity.
mat4_t mat4_rotate_axis(vec3_t axis, float angle);

// The glFrustum matrix of mat4_frustum_asymmetric, or an error naming the bad argument
// (l = r, b = t, n ≤ 0, f ≤ n, or a non-finite value).
result<mat4_t> frustum_checked(float left, float right, float bottom, float top, float near_plane,
                               float far_plane);
// gluPerspective: vertical field of view `fovy` in radians (0 < fovy < π), aspect =
// width / height > 0, 0 < near < far; z = −near → NDC −1, z = −far → NDC +1.
// Bad arguments give the identity; perspective_checked says why.
mat4_t mat4_perspective(float fovy, float aspect, float near_plane, float far_plane);
result<mat4_t> perspective_checked(float fovy, float aspect, float near_plane, float far_plane);
// gluLookAt view matrix: the camera at `eye` looks toward `target` (down its −z), `up`
// projects to +y on screen. Degenerate input is handled deterministically: eye = target
// looks down −z (a pure translation by −eye); `up` parallel to the view direction (or
// zero) is replaced by vec3_any_perpendicular(view direction).
mat4_t mat4_look_at(vec3_t eye, vec3_t target, vec3_t up);

mat4_t mat4_transpose(mat4_t m);
// Determinant, computed in double.
double mat4_determinant(mat4_t m);
// General inverse (adjugate / determinant, in double, rounded once to float). Reports
// "singular matrix" when any entry is not finite or |det| ≤ 1e-12 · Π‖row‖ (Hadamard's
// bound, so the test does not depend on the scale of the rows). For an invertible M the
// computed M·M⁻¹ (exact arithmetic) is within 0.5·2⁻²³·(|M|·|M⁻¹|)ᵢⱼ of I (tested).
result<mat4_t> mat4_inverse(mat4_t m);

// ---- transforming points ---------------------------------------------------------------
struct transformed_point {
    vec3_t point;          // M·(p, 1), divided by w when divided_by_w
    float w;               // the homogeneous w before any division
    bool divided_by_w;     // false when w was exactly 0 or 1 (as apply_transform)
};
// apply_transform that also reports w and whether it divided.
transformed_point transform_point(const mat4_t &m, vec3_t p);
// The upper-left 3×3 times d (w = 0: translation and projection ignored).
vec3_t transform_direction(const mat4_t &m, vec3_t d);

// M·(p, 1) = mat4_mul_vec4(m, (p, 1)) bit for bit (the same operation order; m12·1 = m12
// exactly), inline so that per-point loops do not copy the matrix into a call.
inline vec4_t mul_point_scalar(const mat4_t &m, vec3_t p) {
    return {m.m[0] * p.x + m.m[4] * p.y + m.m[8] * p.z + m.m[12], m.m[1] * p.x + m.m[5] * p.y + m.m[9] * p.z + m.m[13],
            m.m[2] * p.x + m.m[6] * p.y + m.m[10] * p.z + m.m[14], m.m[3] * p.x + m.m[7] * p.y + m.m[11] * p.z + m.m[15]};
}

// Batch apply_transform: out[i] = apply_transform(m, in[i]), bit for bit, for every i
// (with SSE2 one point per register, its four rows at once; scalar otherwise). `out` may
// be the same span as `in` (in-place); other overlaps are not allowed. Error when
// out.size() < in.size() (nothing written).
status transform_points(const mat4_t &m, std::span<const vec3_t> in, std::span<vec3_t> out);
// Batch to clip space: out[i] = mat4_mul_vec4(m, (in[i], 1)), bit for bit, no division
// (for clipping against w). Same size rule as transform_points.
status transform_points_homogeneous(const mat4_t &m, std::span<const vec3_t> in, std::span<vec4_t> out);

// ---- quaternions (orientation) ---------------------------------------------------------
// q = (x, y, z, w) = (sin(α/2)·axis, cos(α/2)) for a rotation by α about a unit axis.
// Rotations are unit quaternions; q and −q are the same rotation.
struct quat {
    float x, y, z, w;
};
inline quat quat_identity() { return {0.0f, 0.0f, 0.0f, 1.0f}; }
// Rotation by `angle` radians about `axis` (any length; zero or non-finite → identity).
quat quat_from_axis_angle(vec3_t axis, float angle);
// Hamilton product a·b: the rotation b followed by a (as mat4_multiply).
quat quat_multiply(quat a, quat b);
// q / |q| (computed in double); zero or non-finite q → identity.
quat quat_normalize(quat q);
inline quat quat_conjugate(quat q) { return {-q.x, -q.y, -q.z, q.w}; }
// The rotation matrix of q (normalised first, so any non-zero q works).
mat4_t quat_to_mat4(quat q);
// Rotates v by q (normalised first).
vec3_t quat_rotate(quat q, vec3_t v);
// Shortest-path slerp of rotations: b is negated when a·b < 0, the angle comes from
// atan2 (accurate near 0), computed in double; always a unit quaternion; t outside
// [0, 1] extrapolates at constant angular speed. Inputs are normalised first.
quat quat_slerp(quat a, quat b, float t);

}  // namespace tiny3d
#endif  // __cplusplus

#include "compat/math_alias.h"  // other libtiny3d programs' names (mat4_mul, vec3, …)

#endif
