// tiny3d_compat.h — OPT-IN: the rarer names and forms other libtiny3d programs call.
//
// Include this instead of (or after) tiny3d.h in a program written against another
// libtiny3d implementation. It is not included by any library header, because these names
// are also the names user programs give their OWN helpers, and these plain overloads would
// clash with them (a program that defines `static vec3_t vec3_add(vec3_t, vec3_t)` must
// still compile against the normal headers).
// The common alternates (canvas_create, mat4_mul, bezier, …) need no opt-in: they are in
// the normal headers (include/compat/*_alias.h), and so are the names programs also define
// themselves that step aside for a program's own function (save_canvas_pgm & co., the
// 7-argument draw_line_f, vec3_normalize, mat4_perspective, create_cube: see
// compat/user_first.h).
//
// Every function here is a thin inline alias of the one implementation in the normal
// headers: same conventions (column-major mat4_t, radians, the report's spherical
// convention, PGM as canvas.h writes it). documentation/compat.md has the table.
//
// Overloads added here make the report's names overloaded (e.g. mat4_identity() and
// mat4_identity(mat4_t *)): taking their address then needs a cast to the wanted type.
// Null pointers never crash: a null output is ignored, a null input matrix counts as the
// identity, a null input vector as {0, 0, 0}.
#ifndef TINY3D_COMPAT_H
#define TINY3D_COMPAT_H

#include "tiny3d.h"

#ifndef __cplusplus
#error "tiny3d_compat.h is C++ (overloads); from C, canvas.h, math3d.h, renderer.h, lighting.h and animation.h give the C forms (documentation/compat.md)"
#endif

namespace tiny3d::compat_detail {
inline mat4_t matrix_or_identity(const mat4_t *m) { return m ? *m : mat4_identity(); }
inline vec3_t vector_or_zero(const vec3_t *v) { return v ? *v : vec3_t{0.0f, 0.0f, 0.0f}; }
inline void store(mat4_t *out, const mat4_t &value) {
    if (out) *out = value;
}
}  // namespace tiny3d::compat_detail

// ---- matrices: out-parameter builders (out first; mat4_identity(&m) is math3d.h's) -----
inline void mat4_translate(mat4_t *out, float tx, float ty, float tz) {
    tiny3d::compat_detail::store(out, mat4_translate(tx, ty, tz));
}
inline void mat4_translate(mat4_t *out, vec3_t offset) { mat4_translate(out, offset.x, offset.y, offset.z); }
inline void mat4_scale(mat4_t *out, float sx, float sy, float sz) {
    tiny3d::compat_detail::store(out, mat4_scale(sx, sy, sz));
}
inline void mat4_scale(mat4_t *out, vec3_t factors) { mat4_scale(out, factors.x, factors.y, factors.z); }
// Angles in radians; R = Rz·Ry·Rx as mat4_rotate_xyz.
inline void mat4_rotate_xyz(mat4_t *out, float rx, float ry, float rz) {
    tiny3d::compat_detail::store(out, mat4_rotate_xyz(rx, ry, rz));
}
inline void mat4_rotate_xyz(mat4_t *out, vec3_t angles) { mat4_rotate_xyz(out, angles.x, angles.y, angles.z); }
inline void mat4_frustum_asymmetric(mat4_t *out, float left, float right, float bottom, float top,
                                    float near_plane, float far_plane) {
    tiny3d::compat_detail::store(out, mat4_frustum_asymmetric(left, right, bottom, top, near_plane, far_plane));
}

// ---- matrices: pointer forms of the product (a·b, b applied first) ----------------------
// (mat4_mul(&a, &b), mat4_mul(&out, &a, &b) and mat4_mul_vec3(&m, v) are math3d.h's.)
inline mat4_t mat4_multiply(const mat4_t *a, const mat4_t *b) {
    return mat4_multiply(tiny3d::compat_detail::matrix_or_identity(a), tiny3d::compat_detail::matrix_or_identity(b));
}
// *out = a·b; out may be the same matrix as a or b.
inline void mat4_multiply(mat4_t *out, const mat4_t *a, const mat4_t *b) {
    tiny3d::compat_detail::store(out, mat4_multiply(a, b));
}

// ---- vectors ------------------------------------------------------------------------------
// {x, y, z} (vec3_from_cartesian's other name).
inline vec3_t vec3_create(float x, float y, float z) { return vec3_from_cartesian(x, y, z); }

// Pointer form of the report's slerp (same faithful variant: Quake-normalised inputs).
inline vec3_t vec3_slerp(const vec3_t *a, const vec3_t *b, float t) {
    return vec3_slerp(tiny3d::compat_detail::vector_or_zero(a), tiny3d::compat_detail::vector_or_zero(b), t);
}

// Implementations whose vec3_t stores r, θ, φ beside x, y, z keep the two in step with
// these. Ours stores only x, y, z (the spherical form is computed when asked:
// vec3_to_spherical), so there is nothing to update: both leave *v unchanged (a null
// pointer is ignored). Code that read v.r / v.theta / v.phi must call vec3_to_spherical.
inline void vec3_update_spherical(vec3_t *v) { (void)v; }
inline void vec3_update_cartesian(vec3_t *v) { (void)v; }

// The small vector helpers many programs also define themselves (hence opt-in here).
// (vec3_sub and vec3_length are math3d.h's.)
inline vec3_t vec3_add(vec3_t a, vec3_t b) { return a + b; }
inline vec3_t vec3_scale(vec3_t v, float s) { return v * s; }
inline float vec3_dot(vec3_t a, vec3_t b) { return tiny3d::vec3_dot(a, b); }
inline vec3_t vec3_cross(vec3_t a, vec3_t b) { return tiny3d::vec3_cross(a, b); }  // right-handed

#endif
