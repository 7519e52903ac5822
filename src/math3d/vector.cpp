// vector.cpp — lengths, the three normalisations, the spherical form.
//
// Normalisation variants compared by tests/bench/normalize (speed and error = max over
// components of |computed − exact unit vector|; the figures are in
// documentation/benchmarks.md): Quake's 0x5f3759df + 1 Newton step (the report's, error
// ~1.7e-3), 1/std::sqrt in float (vec3_normalize_fast_accurate, ~1.7e-7, the choice),
// double sqrt and divide (vec3_normalize, exact), rsqrtss + 1 Newton step (~2e-7, over the
// 2e-7 bound) and rsqrtss + a 2nd-order correction (~1.7e-7). sqrtss + divss cost no more than the integer trick on current x86 cores (its moves
// between integer and float registers are not free). 1/sqrtf ties with the best rsqrtss
// candidate and keeps its bound on every IEEE machine (sqrt and division are correctly
// rounded, while rsqrtss's precision differs between CPU vendors), so it is the choice.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "math3d.h"

namespace {

// Squared lengths inside [2^-100, 2^100] are computed without overflow, underflow or
// loss to denormals (a component whose square is denormal contributes < 2^-26 of the
// total); outside it the vector is first rescaled by an exact power of two.
constexpr float kSafeSquaredMin = 0x1p-100f;
constexpr float kSafeSquaredMax = 0x1p100f;

constexpr std::uint32_t kQuakeMagic = 0x5f3759df;

float squared_length(vec3_t v) { return v.x * v.x + v.y * v.y + v.z * v.z; }

float unit_or_zero_sign(float c) { return std::isinf(c) ? std::copysign(1.0f, c) : 0.0f; }

// The cases the fast paths leave out: NaN → zero; infinite components → the direction of
// the infinities; zero → zero; tiny or huge → rescaled so the largest component lies in
// [1, 2) (exact: a power of two changes no mantissa), then `core`.
// Out of line and cold, so the common path stays a few instructions with no stack frame.
template <class Core>
[[gnu::noinline, gnu::cold]] vec3_t normalize_unusual(vec3_t v, Core core) {
    if (std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z)) return {0.0f, 0.0f, 0.0f};
    if (std::isinf(v.x) || std::isinf(v.y) || std::isinf(v.z))
        v = {unit_or_zero_sign(v.x), unit_or_zero_sign(v.y), unit_or_zero_sign(v.z)};
    const float largest = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (largest == 0.0f) return {0.0f, 0.0f, 0.0f};
    const int shift = -std::ilogb(largest);
    return core(vec3_t{std::scalbn(v.x, shift), std::scalbn(v.y, shift), std::scalbn(v.z, shift)});
}

// Float normalisers share the range check: the core runs directly when the squared
// length is in the safe range (NaN fails the test and goes the unusual way).
template <class Core>
vec3_t normalize_float(vec3_t v, Core core) {
    const float sq = squared_length(v);
    if (sq >= kSafeSquaredMin && sq <= kSafeSquaredMax) [[likely]]
        return core(v);
    return normalize_unusual(v, core);
}

// The cores are lambdas (one type each) so normalize_float inlines them.
// The report's code, arithmetic order kept: y·(1.5 − (x/2)·y·y) after the magic guess.
constexpr auto quake_core = [](vec3_t v) -> vec3_t {
    const float sq = squared_length(v);
    const float half = sq * 0.5f;
    const std::uint32_t bits = kQuakeMagic - (std::bit_cast<std::uint32_t>(sq) >> 1);
    float y = std::bit_cast<float>(bits);
    y = y * (1.5f - (half * y * y));
    return {v.x * y, v.y * y, v.z * y};
};

constexpr auto reciprocal_sqrt_core = [](vec3_t v) -> vec3_t {
    const float inv = 1.0f / std::sqrt(squared_length(v));
    return {v.x * inv, v.y * inv, v.z * inv};
};

// In double: the squares of any finite floats neither overflow nor underflow, so only
// the sum needs checking; one rounding per component at the end.
constexpr auto exact_core = [](vec3_t v) -> vec3_t {
    const double x = v.x, y = v.y, z = v.z;
    const double inv = 1.0 / std::sqrt(x * x + y * y + z * z);
    return {float(x * inv), float(y * inv), float(z * inv)};
};

}  // namespace

vec3_t vec3_normalize_fast(vec3_t v) { return normalize_float(v, quake_core); }

void vec3_normalize_fast(vec3_t *v) {
    if (v) *v = vec3_normalize_fast(*v);
}

vec3_t vec3_from_spherical(float r, float theta, float phi) {
    const double rd = r, sin_phi = std::sin(double(phi));
    return {float(rd * sin_phi * std::cos(double(theta))), float(rd * sin_phi * std::sin(double(theta))),
            float(rd * std::cos(double(phi)))};
}

void vec3_to_spherical(vec3_t v, float *r, float *theta, float *phi) {
    const double x = v.x, y = v.y, z = v.z;
    const double planar = std::sqrt(x * x + y * y);
    // On the z axis (and at the origin) the azimuth is undefined: 0 by convention, also
    // for signed zeros (atan2(±0, −0) would give ±π).
    const double azimuth = planar == 0.0 ? 0.0 : std::atan2(y, x);
    const double polar = (planar == 0.0 && z == 0.0) ? 0.0 : std::atan2(planar, z);
    if (r) *r = float(std::sqrt(x * x + y * y + z * z));
    if (theta) *theta = float(azimuth);
    if (phi) *phi = float(polar);
}

namespace tiny3d {

float vec3_length(vec3_t v) {
    const double x = v.x, y = v.y, z = v.z;
    return float(std::sqrt(x * x + y * y + z * z));
}

vec3_t vec3_normalize(vec3_t v) {
    const double x = v.x, y = v.y, z = v.z;
    const double sq = x * x + y * y + z * z;
    if (sq > 0.0 && std::isfinite(sq)) [[likely]]
        return exact_core(v);
    return normalize_unusual(v, exact_core);
}

vec3_t vec3_normalize_fast_accurate(vec3_t v) { return normalize_float(v, reciprocal_sqrt_core); }

vec3_t vec3_any_perpendicular(vec3_t v) {
    const vec3_t n = vec3_normalize(v);  // zero for zero or NaN input
    const float ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
    if (ax == 0.0f && ay == 0.0f && az == 0.0f) return {1.0f, 0.0f, 0.0f};
    vec3_t axis = {0.0f, 0.0f, 1.0f};  // the axis of the smallest component
    if (ax <= ay && ax <= az) axis = {1.0f, 0.0f, 0.0f};
    else if (ay <= az) axis = {0.0f, 1.0f, 0.0f};
    // |n × axis| = sqrt(1 − n_axis²) ≥ sqrt(2/3): well conditioned.
    return vec3_normalize(vec3_cross(n, axis));
}

}  // namespace tiny3d
