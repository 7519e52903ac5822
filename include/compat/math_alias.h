// compat/math_alias.h — other libtiny3d implementations' names for the math API.
//
// Included at the end of math3d.h (and self-contained). Thin aliases of the one
// implementation in math3d.h. Rarer forms (out-parameter builders) are opt-in in
// tiny3d_compat.h. documentation/compat.md has the full table.
//
// Already in math3d.h itself: M_PI, the global mat4_rotate_x/y/z (C and C++) and the
// pointer form vec3_normalize_fast(vec3_t *) (C++).
//
// How the names here step aside for a program's own function of the same name:
//  * C++: every alias is a template or takes fallback<> parameters (compat/user_first.h),
//    so a program's own function of the name — any signature, static or not — wins.
//  * C (one function per name): the value forms a C program calls (mat4_mul,
//    mat4_mul_vec3, mat4_transform_vec3, vec3_from_cartesian) are declared with C linkage;
//    each is alone in its object file of the archive (src/compat/), so a program that
//    defines its own (same form) links its own. The pointer forms and the names programs
//    define in other forms (vec3_normalize, vec3_length, vec3_sub, mat4_frustum, …) are
//    not declared in C.
#ifndef TINY3D_COMPAT_MATH_ALIAS_H
#define TINY3D_COMPAT_MATH_ALIAS_H

#include "../math3d.h"

// Short type names some programs use.
typedef vec3_t vec3;
typedef mat4_t mat4;

#ifndef __cplusplus
// ---- C: the value forms, C linkage (the C++ forms below say what each does) ------------
mat4_t mat4_mul(mat4_t a, mat4_t b);
vec3_t mat4_mul_vec3(mat4_t m, vec3_t v);
vec3_t mat4_transform_vec3(mat4_t m, vec3_t v);
vec3_t vec3_from_cartesian(float x, float y, float z);
#else
#include <cstddef>
#include <type_traits>

#include "user_first.h"

// The forms those programs rely on: plain aggregates (so (vec3_t){1, 2, 3}, {.x = 1} and
// mat4_t m = {0} compile), x, y, z first, m[16] column-major, M_PI, the pointer normalise.
static_assert(std::is_aggregate_v<vec3_t> && std::is_trivially_copyable_v<vec3_t>, "vec3_t must stay a plain aggregate");
static_assert(std::is_same_v<decltype(vec3_t::x), float> && offsetof(vec3_t, x) == 0 &&
                  offsetof(vec3_t, y) == sizeof(float) && offsetof(vec3_t, z) == 2 * sizeof(float),
              "vec3_t must start with float x, y, z");
static_assert(std::is_aggregate_v<mat4_t> && std::is_same_v<decltype(mat4_t::m), float[16]>,
              "mat4_t must stay { float m[16]; }");
static_assert(std::is_same_v<decltype(vec3_normalize_fast(static_cast<vec3_t *>(nullptr))), void>,
              "the pointer form vec3_normalize_fast(vec3_t *)");
#ifndef M_PI
#error "math3d.h must make M_PI visible"
#endif

// mat4_multiply(a, b) = a·b (b applied first), column-major.
template <class = void>
mat4_t mat4_mul(mat4_t a, mat4_t b) {
    return mat4_multiply(a, b);
}
// The pointer form: *a · *b (a null pointer counts as the identity).
template <class = void>
mat4_t mat4_mul(const mat4_t *a, const mat4_t *b) {
    return mat4_multiply(a ? *a : mat4_identity(), b ? *b : mat4_identity());
}
// The out-parameter form: *out = *a · *b; out may be a or b; a null out is ignored.
template <class = void>
void mat4_mul(mat4_t *out, const mat4_t *a, const mat4_t *b) {
    if (out) *out = mat4_mul(a, b);
}
// mat4_identity's out-parameter form: *out = the identity (a null out is ignored).
template <class = void>
void mat4_identity(mat4_t *out) {
    if (out) *out = mat4_identity();
}

// apply_transform: M·(x, y, z, 1) divided by w. Dividing by w = 1 changes nothing, so
// this is "always divide by w" as these names' users expect — except that w = 0 (a point
// at infinity, only from a projective M) returns x, y, z undivided instead of inf/NaN.
template <class = void>
vec3_t mat4_mul_vec3(mat4_t m, vec3_t v) {
    return apply_transform(m, v);
}
// The same with the matrix by pointer (a null matrix counts as the identity).
template <class = void>
vec3_t mat4_mul_vec3(const mat4_t *m, vec3_t v) {
    return m ? apply_transform(*m, v) : v;
}
template <class = void>
vec3_t mat4_transform_vec3(mat4_t m, vec3_t v) {
    return apply_transform(m, v);
}

// A vector from cartesian coordinates. Implementations that store r, θ, φ in vec3_t fill
// them here; ours computes the spherical form on demand (vec3_to_spherical), so this is
// just {x, y, z}.
template <class = void>
vec3_t vec3_from_cartesian(float x, float y, float z) {
    return vec3_t{x, y, z};
}

// mat4_frustum_asymmetric under its short name (glFrustum; bad arguments → identity).
// fallback parameters: a program's own mat4_frustum (float or double) is the better match.
inline mat4_t mat4_frustum(tiny3d::compat::fallback<float> left, tiny3d::compat::fallback<float> right,
                           tiny3d::compat::fallback<float> bottom, tiny3d::compat::fallback<float> top,
                           tiny3d::compat::fallback<float> near_plane, tiny3d::compat::fallback<float> far_plane) {
    return mat4_frustum_asymmetric(left.value, right.value, bottom.value, top.value, near_plane.value,
                                   far_plane.value);
}

// tiny3d::vec3_normalize (exact unit vector; zero or NaN input gives {0, 0, 0}) as a global
// name, by value. Not the report's Quake vec3_normalize_fast. A template: a program's own
// vec3_normalize(vec3_t) or (const vec3_t &) wins; with `using namespace tiny3d` the call
// reaches tiny3d::vec3_normalize itself. Braced arguments work: vec3_normalize({3, 4, 0}),
// vec3_normalize((vec3_t){3, 4, 0}).
template <class = void>
vec3_t vec3_normalize(vec3_t v) {
    return tiny3d::vec3_normalize(v);
}
// The pointer form: *v = tiny3d::vec3_normalize(*v) (a null pointer is ignored).
template <class = void>
void vec3_normalize(vec3_t *v) {
    if (v) *v = tiny3d::vec3_normalize(*v);
}
// |v| (tiny3d::vec3_length: in double, no overflow) and a − b.
template <class = void>
float vec3_length(vec3_t v) {
    return tiny3d::vec3_length(v);
}
template <class = void>
vec3_t vec3_sub(vec3_t a, vec3_t b) {
    return a - b;
}

// tiny3d::mat4_perspective as a global name: gluPerspective, vertical field of view `fovy`
// in RADIANS (0 < fovy < π), aspect = width / height > 0, 0 < near < far; bad arguments
// give the identity (tiny3d::perspective_checked says why). fallback parameters: a
// program's own mat4_perspective (float or double parameters, degrees or radians) is
// always the better match, and tiny3d::mat4_perspective is with `using namespace tiny3d`.
inline mat4_t mat4_perspective(tiny3d::compat::fallback<float> fovy, tiny3d::compat::fallback<float> aspect,
                               tiny3d::compat::fallback<float> near_plane,
                               tiny3d::compat::fallback<float> far_plane) {
    return tiny3d::mat4_perspective(fovy.value, aspect.value, near_plane.value, far_plane.value);
}
#endif  // __cplusplus

#endif
