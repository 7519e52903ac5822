// math3d.h — vectors, matrices, quaternions.
//
// Conventions (pinned by tests/math3d_test.cpp):
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
#ifndef TINY3D_MATH3D_H
#define TINY3D_MATH3D_H

#include <cmath>
#include <cstddef>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

typedef struct vec3_t {
    float x, y, z;
} vec3_t;

typedef struct vec4_t {
    float x, y, z, w;
} vec4_t;

typedef struct mat4_t {
    float m[16];  // column-major: m[col*4 + row]
} mat4_t;

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

// ---- the libtiny3d report's API --------------------------------------------------------
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
vec4_t vec4_from_vec3(vec3_t v, float w);
vec4_t mat4_mul_vec4(mat4_t m, vec4_t v);

#endif
