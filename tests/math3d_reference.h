// tests/math3d_reference.h — the independent references of the math3d tests: long double
// vector arithmetic (64-bit mantissa) written from the textbook formulas, never by calling
// the function under test, and the random inputs. Error bounds use the unit roundoff of
// float, U = 2^-24, and the dot-product bound γₙ = n·U/(1 − n·U) (Higham, "Accuracy and
// Stability of Numerical Algorithms", §3.1).
#ifndef TINY3D_TEST_MATH3D_REFERENCE_H
#define TINY3D_TEST_MATH3D_REFERENCE_H

#include <algorithm>
#include <cmath>
#include <random>

#include "math3d.h"

namespace math3d_ref {

using ld = long double;
constexpr double U = 0x1p-24;  // float unit roundoff
constexpr double gamma_n(int n) { return n * U / (1.0 - n * U); }
constexpr ld PI_L = 3.141592653589793238462643383279502884L;

struct lvec {
    ld x, y, z;
};
inline lvec L(vec3_t v) { return {v.x, v.y, v.z}; }
inline ld ldot(lvec a, lvec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline lvec lcross(lvec a, lvec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline ld llen(lvec a) { return std::sqrt(ldot(a, a)); }
inline lvec lscale(lvec a, ld s) { return {a.x * s, a.y * s, a.z * s}; }
inline lvec ladd(lvec a, lvec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
// Largest component difference between a float result and a long double reference.
inline ld max_diff(vec3_t a, lvec b) {
    return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}
bool finite3(vec3_t v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

inline ld entry(const mat4_t &m, int row, int col) { return m.m[col * 4 + row]; }

inline mat4_t random_matrix(std::mt19937 &rng, float lo = -1.0f, float hi = 1.0f) {
    std::uniform_real_distribution<float> u(lo, hi);
    mat4_t m;
    for (float &v : m.m) v = u(rng);
    return m;
}

inline vec3_t random_vec(std::mt19937 &rng, float lo = -1.0f, float hi = 1.0f) {
    std::uniform_real_distribution<float> u(lo, hi);
    return {u(rng), u(rng), u(rng)};
}

// Random vector with a random scale 2^[-60, 60] and random direction.
inline vec3_t random_scaled_vec(std::mt19937 &rng) {
    std::uniform_real_distribution<float> e(-60.0f, 60.0f);
    return random_vec(rng) * std::exp2(e(rng));
}

// The reference unit vector.
inline lvec unit_ref(vec3_t v) { return lscale(L(v), 1.0L / llen(L(v))); }

}  // namespace math3d_ref

#endif
