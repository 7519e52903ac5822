// compat/math_alias.h — other libtiny3d implementations' names for the math API.
//
// Included at the end of math3d.h (and self-contained). Thin inline aliases of the one
// implementation in math3d.h. Rarer forms (out-parameter builders, pointer forms) are
// opt-in in tiny3d_compat.h. documentation/compat.md has the full table.
//
// Already in math3d.h itself: the pointer form vec3_normalize_fast(vec3_t *) and M_PI.
#ifndef TINY3D_COMPAT_MATH_ALIAS_H
#define TINY3D_COMPAT_MATH_ALIAS_H

#include <cstddef>
#include <type_traits>

#include "../math3d.h"
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

// Short type names some programs use.
typedef vec3_t vec3;
typedef mat4_t mat4;

// mat4_multiply(a, b) = a·b (b applied first), column-major.
inline mat4_t mat4_mul(mat4_t a, mat4_t b) { return mat4_multiply(a, b); }

// apply_transform: M·(x, y, z, 1) divided by w. Dividing by w = 1 changes nothing, so
// this is "always divide by w" as these names' users expect — except that w = 0 (a point
// at infinity, only from a projective M) returns x, y, z undivided instead of inf/NaN.
inline vec3_t mat4_mul_vec3(mat4_t m, vec3_t v) { return apply_transform(m, v); }
inline vec3_t mat4_transform_vec3(mat4_t m, vec3_t v) { return apply_transform(m, v); }

// A vector from cartesian coordinates. Implementations that store r, θ, φ in vec3_t fill
// them here; ours computes the spherical form on demand (vec3_to_spherical), so this is
// just {x, y, z}.
inline vec3_t vec3_from_cartesian(float x, float y, float z) { return vec3_t{x, y, z}; }

// ---- names programs also give their own functions (compat/user_first.h) ----------------
// A program that defines or declares its own function of one of these names calls its own.

// tiny3d::vec3_normalize (exact unit vector; zero or NaN input gives {0, 0, 0}) as a global
// name, by value. Not the report's Quake vec3_normalize_fast. A template: a program's own
// vec3_normalize(vec3_t) or (const vec3_t &) wins; with `using namespace tiny3d` the call
// reaches tiny3d::vec3_normalize itself. Braced arguments work: vec3_normalize({3, 4, 0}),
// vec3_normalize((vec3_t){3, 4, 0}).
template <class = void>
vec3_t vec3_normalize(vec3_t v) {
    return tiny3d::vec3_normalize(v);
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

#endif
