// math3d_vector_test.cpp — vectors: normalisation (exact, fast inverse square root and its
// refined form), the report's listings bit for bit, perpendiculars, spherical form, slerp
// and quaternions. Matrices and projection: math3d_test.cpp.
//
// Independent references and error bounds: math3d_reference.h (long double, U = 2^-24, γₙ).
#include "harness.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <cfloat>
#include <cmath>
#include <random>
#include <vector>

#include "math3d.h"
#include "math3d_reference.h"

using namespace tiny3d;
using namespace math3d_ref;

namespace {

// Reference slerp: rotate â about n = â×b̂ by t·θ (Rodrigues, long double), θ = acos(â·b̂);
// length max(0, (1−t)|a| + t|b|). Only for pairs that are not exactly (anti)parallel.
lvec slerp_ref(vec3_t a, vec3_t b, ld t) {
    const lvec ua = unit_ref(a), ub = unit_ref(b);
    const lvec n = lcross(ua, ub);
    const lvec k = lscale(n, 1.0L / llen(n));
    const ld theta = std::acos(std::clamp(ldot(ua, ub), -1.0L, 1.0L)) * t;
    // v cos + (k×v) sin + k(k·v)(1−cos), with k·â = 0.
    const lvec dir = ladd(lscale(ua, std::cos(theta)), lscale(lcross(k, ua), std::sin(theta)));
    return lscale(dir, std::max(0.0L, (1 - t) * llen(L(a)) + t * llen(L(b))));
}

// b at angle `angle` from unit a in the plane of a and the unit perpendicular p.
vec3_t at_angle(vec3_t a, vec3_t p, double angle) {
    return {float(a.x * std::cos(angle) + p.x * std::sin(angle)), float(a.y * std::cos(angle) + p.y * std::sin(angle)),
            float(a.z * std::cos(angle) + p.z * std::sin(angle))};
}

}  // namespace

// ---- normalisation -------------------------------------------------------------------------

namespace {

struct normalizer {
    const char *name;
    vec3_t (*fn)(vec3_t);
    double bound;  // max |component − exact| for a unit result (stated in math3d.h)
};
vec3_t normalize_fast_value(vec3_t v) { return vec3_normalize_fast(v); }
const normalizer kNormalizers[] = {
    {"quake (vec3_normalize_fast)", normalize_fast_value, 1.8e-3},
    {"vec3_normalize_fast_accurate", vec3_normalize_fast_accurate, 2e-7},
    {"vec3_normalize (exact)", vec3_normalize, 6e-8},
};

}  // namespace

TEST(normalize_variants_within_stated_error_on_random_input) {
    for (const normalizer &n : kNormalizers) {
        std::mt19937 rng(49);
        double worst = 0;
        for (int trial = 0; trial < 300000; ++trial) {
            const vec3_t v = random_scaled_vec(rng);
            if (v == vec3_t{0, 0, 0}) continue;
            worst = std::max(worst, double(max_diff(n.fn(v), unit_ref(v))));
        }
        CHECK_MSG(worst <= n.bound, std::string(n.name) + " worst " + std::to_string(worst));
        CHECK_MSG(worst > 0.0, n.name);  // the measurement measured something
    }
}

TEST(normalize_stability_zero_tiny_huge_denormal_nonfinite) {
    const float denormal = std::numeric_limits<float>::denorm_min();
    const vec3_t cases[] = {{1e-30f, 2e-30f, -2e-30f}, {1e30f, -2e30f, 2e30f}, {denormal, denormal, 0},
                            {0, 3 * denormal, -4 * denormal}, {FLT_MAX, FLT_MAX, FLT_MAX},
                            {1e-20f, 1e-20f, 1e-20f}, {1e19f, 0, 0}, {FLT_MIN, -FLT_MIN, FLT_MIN}};
    for (const normalizer &n : kNormalizers) {
        for (const vec3_t &v : cases) {
            const vec3_t r = n.fn(v);
            CHECK_MSG(finite3(r), n.name);
            CHECK_MSG(max_diff(r, unit_ref(v)) <= n.bound, n.name);
        }
        CHECK(n.fn(vec3_t{0, 0, 0}) == (vec3_t{0, 0, 0}));
        CHECK(n.fn(vec3_t{-0.0f, 0, -0.0f}) == (vec3_t{0, 0, 0}));
        CHECK(n.fn(vec3_t{NAN, 1, 1}) == (vec3_t{0, 0, 0}));
        const vec3_t inf = n.fn(vec3_t{INFINITY, 5, -INFINITY});
        CHECK_MSG(max_diff(inf, lvec{std::sqrt(0.5L), 0, -std::sqrt(0.5L)}) <= n.bound, n.name);
    }
    // The pointer form does the same in place and ignores null.
    vec3_t v = {3, 0, 4};
    vec3_normalize_fast(&v);
    CHECK(v == vec3_normalize_fast(vec3_t{3, 0, 4}));
    vec3_normalize_fast(static_cast<vec3_t *>(nullptr));
    // The report's exact arithmetic is kept: (3, 4, 0) → the Quake value 0.998... · (0.6, 0.8).
    const vec3_t q = vec3_normalize_fast(vec3_t{3, 4, 0});
    CHECK(q.x != 0.6f);
    CHECK_NEAR(q.x, 0.6, 1e-3);
    CHECK_NEAR(vec3_length(vec3_t{3e30f, 4e30f, 0}), 5e30, 5e30 * U);
    CHECK_NEAR(vec3_length(vec3_t{3e-40f, 4e-40f, 0}), 5e-40, 1e-45);
}

namespace {

// The libtiny3d report's listings (Task 2), transcribed with std::bit_cast for the
// pointer punning: the global functions must reproduce them bit for bit on ordinary input.
vec3_t report_normalize_fast(vec3_t v) {
    const float squared_length = v.x * v.x + v.y * v.y + v.z * v.z;
    const float x2 = squared_length * 0.5f;
    float y = squared_length;
    std::int32_t i = std::bit_cast<std::int32_t>(y);
    i = 0x5f3759df - (i >> 1);
    y = std::bit_cast<float>(i);
    y = y * (1.5f - (x2 * y * y));
    return {v.x * y, v.y * y, v.z * y};
}

vec3_t report_slerp(vec3_t a, vec3_t b, float t) {
    a = report_normalize_fast(a);
    b = report_normalize_fast(b);
    float dot = a.x * b.x + a.y * b.y + a.z * b.z;
    if (dot > 0.9995f) return report_normalize_fast({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)});
    dot = std::clamp(dot, -1.0f, 1.0f);
    const float theta_0 = std::acos(dot), theta = theta_0 * t;
    const float sin_theta = std::sin(theta), sin_theta_0 = std::sin(theta_0);
    const float s0 = std::cos(theta) - dot * sin_theta / sin_theta_0, s1 = sin_theta / sin_theta_0;
    return {s0 * a.x + s1 * b.x, s0 * a.y + s1 * b.y, s0 * a.z + s1 * b.z};
}

}  // namespace

TEST(global_names_reproduce_the_report_bit_for_bit) {
    std::mt19937 rng(55);
    std::uniform_real_distribution<float> tdist(-0.5f, 1.5f);
    int normalize_mismatch = 0, slerp_mismatch = 0, slerp_compared = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const vec3_t a = random_vec(rng, -10, 10), b = random_vec(rng, -10, 10);
        if (llen(L(a)) < 1e-3L || llen(L(b)) < 1e-3L) continue;
        normalize_mismatch += !(vec3_normalize_fast(a) == report_normalize_fast(a));
        // Outside the near-antipodal band the faithful slerp is the report's code.
        const ld c = ldot(unit_ref(a), unit_ref(b));
        if (c > -0.9L) {
            const float t = tdist(rng);
            slerp_mismatch += !(vec3_slerp(a, b, t) == report_slerp(a, b, t));
            ++slerp_compared;
        }
    }
    CHECK_EQ(normalize_mismatch, 0);
    CHECK_EQ(slerp_mismatch, 0);
    CHECK(slerp_compared > 10000);
}

TEST(any_perpendicular_is_unit_and_perpendicular) {
    std::mt19937 rng(50);
    for (int trial = 0; trial < 1000; ++trial) {
        const vec3_t v = random_scaled_vec(rng);
        const vec3_t p = vec3_any_perpendicular(v);
        CHECK_NEAR(llen(L(p)), 1.0, 2e-7);
        CHECK_NEAR(ldot(L(p), unit_ref(v)), 0.0, 3e-7);
    }
    CHECK(vec3_any_perpendicular(vec3_t{0, 0, 0}) == (vec3_t{1, 0, 0}));
}

// ---- spherical ---------------------------------------------------------------------------

TEST(spherical_known_values_and_conventions) {
    float r, theta, phi;
    vec3_to_spherical(vec3_t{0, 0, 2}, &r, &theta, &phi);
    CHECK_EQ(r, 2.0f);
    CHECK_EQ(theta, 0.0f);
    CHECK_EQ(phi, 0.0f);
    vec3_to_spherical(vec3_t{-0.0f, 0.0f, -3}, &r, &theta, &phi);  // south pole, signed zero
    CHECK_EQ(r, 3.0f);
    CHECK_EQ(theta, 0.0f);
    CHECK_EQ(phi, float(M_PI));
    vec3_to_spherical(vec3_t{0, 0, 0}, &r, &theta, &phi);
    CHECK_EQ(r, 0.0f);
    CHECK_EQ(theta, 0.0f);
    CHECK_EQ(phi, 0.0f);
    vec3_to_spherical(vec3_t{0, 5, 0}, &r, &theta, &phi);
    CHECK_EQ(theta, float(M_PI / 2));
    CHECK_EQ(phi, float(M_PI / 2));
    vec3_to_spherical(vec3_t{-1, -0.0f, 0}, &r, &theta, &phi);  // θ in (−π, π]
    CHECK(std::fabs(theta) == float(M_PI));
    vec3_to_spherical(vec3_t{1, 1, 1}, nullptr, &theta, nullptr);  // null outputs skipped
    CHECK_NEAR(theta, M_PI / 4, 1e-7);
    // x = r sinφ cosθ, y = r sinφ sinθ, z = r cosφ.
    const vec3_t v = vec3_from_spherical(2, float(M_PI / 2), float(M_PI / 2));
    CHECK(max_diff(v, lvec{0, 2, 0}) < 1e-6);
    const vec3_t down = vec3_from_spherical(1, 0.3f, float(M_PI));
    CHECK(max_diff(down, lvec{0, 0, -1}) < 1e-7);
}

TEST(spherical_round_trip_to_float_precision) {
    std::mt19937 rng(51);
    std::vector<vec3_t> cases;
    for (int i = 0; i < 100000; ++i) cases.push_back(random_scaled_vec(rng));
    for (float z : {1.0f, -1.0f, 1e-30f, -7e20f}) cases.push_back({0, 0, z});  // poles
    cases.push_back({1e-40f, -1e-41f, 3e-40f});                                  // denormal
    cases.push_back({0, 0, 0});
    cases.push_back({1e-7f, 0, -1});  // near the south pole
    double worst = 0;
    for (const vec3_t &v : cases) {
        float r, theta, phi;
        vec3_to_spherical(v, &r, &theta, &phi);
        CHECK(r >= 0.0f && theta > -float(M_PI) - 1e-6f && theta <= float(M_PI) && phi >= 0.0f && phi <= float(M_PI));
        const vec3_t back = vec3_from_spherical(r, theta, phi);
        const ld len = llen(L(v));
        const ld err = max_diff(back, L(v));
        if (len == 0) {
            CHECK(back == (vec3_t{0, 0, 0}));
            continue;
        }
        worst = std::max(worst, double(err / len));
        // Float r, θ, φ each rounded once (≤ U relative, ≤ U·π absolute for the angles) plus
        // the final rounding: well inside 4e-7·|v| (stated in math3d.h).
        // (Denormal results may also round by half the smallest denormal.)
        const ld denormal_step = std::numeric_limits<float>::denorm_min();
        CHECK_MSG(err <= 4e-7L * len + denormal_step, std::to_string(double(err / len)));
        // From-spherical itself: each component within 0.5 ulp of the exact value of its
        // float arguments (reference in long double).
        const lvec exact = {ld(r) * std::sin(ld(phi)) * std::cos(ld(theta)), ld(r) * std::sin(ld(phi)) * std::sin(ld(theta)),
                            ld(r) * std::cos(ld(phi))};
        CHECK(max_diff(back, exact) <= U * 1.01 * len + denormal_step);
    }
    CHECK(worst > 0.0);
}

// ---- slerp -------------------------------------------------------------------------------

TEST(slerp_robust_matches_reference_on_random_pairs) {
    std::mt19937 rng(52);
    std::uniform_real_distribution<float> tdist(-0.5f, 1.5f);
    std::uniform_real_distribution<double> logangle(-7, std::log10(M_PI));
    double worst = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        // Angles from 1e-7 rad to π (the upper end includes nearly antipodal pairs) and
        // random non-unit lengths.
        const vec3_t a0 = vec3_normalize(random_vec(rng));
        const vec3_t p = vec3_normalize(vec3_cross(a0, random_vec(rng)));
        if (a0 == vec3_t{0, 0, 0} || p == vec3_t{0, 0, 0}) continue;
        const double angle = std::min(M_PI - 1e-6, std::pow(10.0, logangle(rng)));
        const vec3_t a = a0 * (0.5f + float(trial % 7));
        const vec3_t b = at_angle(a0, p, angle) * (0.25f + float(trial % 5));
        const float t = trial % 10 == 0 ? 0.5f : tdist(rng);
        const lvec ref = slerp_ref(a, b, t);
        const vec3_t got = vec3_slerp_robust(a, b, t);
        const ld scale = std::max(llen(ref), 1e-30L);
        const double err = double(max_diff(got, ref) / std::max(llen(L(a)), llen(L(b))));
        worst = std::max(worst, err);
        CHECK_MSG(err <= 2e-7, std::to_string(err) + " at angle " + std::to_string(angle));
        (void)scale;
    }
    CHECK(worst > 0.0);
}

TEST(slerp_robust_stability_cases) {
    const vec3_t a = vec3_normalize(vec3_t{0.3f, -0.5f, 0.8f});
    const vec3_t p = vec3_any_perpendicular(a);
    // dot = 1: the direction stays a for every t.
    for (float t : {0.0f, 0.25f, 1.0f, -0.5f, 1.5f}) CHECK(max_diff(vec3_slerp_robust(a, a, t), unit_ref(a)) < 1e-7);
    // dot = 1 − 1e-7 and −1 + 1e-7 (θ = acos of those), against the reference.
    for (double cosine : {1.0 - 1e-7, -1.0 + 1e-7}) {
        const vec3_t b = at_angle(a, p, std::acos(cosine));
        for (float t : {0.0f, 0.5f, 1.0f, -0.5f, 1.5f}) {
            const vec3_t got = vec3_slerp_robust(a, b, t);
            CHECK(max_diff(got, slerp_ref(a, b, t)) <= 2e-7);
        }
    }
    // dot = −1 exactly: deterministic, unit, on the circle through the fixed perpendicular.
    const vec3_t minus_a = -a;
    const vec3_t mid = vec3_slerp_robust(a, minus_a, 0.5f);
    CHECK(mid == vec3_slerp_robust(a, minus_a, 0.5f));
    CHECK_NEAR(llen(L(mid)), 1.0, 2e-7);
    CHECK_NEAR(ldot(L(mid), unit_ref(a)), 0.0, 2e-7);
    CHECK(max_diff(mid, L(p)) <= 2e-7);
    CHECK(max_diff(vec3_slerp_robust(a, minus_a, 1.0f), L(minus_a)) <= 2e-7);
    CHECK(max_diff(vec3_slerp_robust(a, minus_a, 0.25f), L(at_angle(a, p, M_PI / 4))) <= 2e-7);
    // Ends and extrapolation: t = 0 → a, t = 1 → b, t = −0.5 and 1.5 continue the circle.
    const vec3_t b = at_angle(a, p, 1.0);
    CHECK(max_diff(vec3_slerp_robust(a, b, 0.0f), L(a)) <= 1e-7);
    CHECK(max_diff(vec3_slerp_robust(a, b, 1.0f), L(b)) <= 1e-7);
    CHECK(max_diff(vec3_slerp_robust(a, b, -0.5f), L(at_angle(a, p, -0.5))) <= 2e-7);
    CHECK(max_diff(vec3_slerp_robust(a, b, 1.5f), L(at_angle(a, p, 1.5))) <= 2e-7);
    // Non-unit inputs: the length is interpolated linearly, clamped at 0.
    const vec3_t m2 = vec3_slerp_robust(vec3_t{2, 0, 0}, vec3_t{0, 3, 0}, 0.5f);
    CHECK(max_diff(m2, lvec{2.5L * std::sqrt(0.5L), 2.5L * std::sqrt(0.5L), 0}) <= 3e-7);
    CHECK_NEAR(llen(L(vec3_slerp_robust(vec3_t{1, 0, 0}, vec3_t{0, 5, 0}, -0.5f))), 0.0, 0.0);
    // Zero inputs take the other direction; non-finite input gives zero.
    CHECK(max_diff(vec3_slerp_robust(vec3_t{0, 0, 0}, vec3_t{0, 4, 0}, 0.5f), lvec{0, 2, 0}) <= 2e-7);
    CHECK(vec3_slerp_robust(vec3_t{0, 0, 0}, vec3_t{0, 0, 0}, 0.5f) == (vec3_t{0, 0, 0}));
    CHECK(vec3_slerp_robust(vec3_t{NAN, 0, 0}, vec3_t{0, 1, 0}, 0.5f) == (vec3_t{0, 0, 0}));
    CHECK(vec3_slerp_robust(vec3_t{1, 0, 0}, vec3_t{0, 1, 0}, NAN) == (vec3_t{0, 0, 0}));
}

TEST(slerp_robust_has_constant_angular_speed) {
    const vec3_t a = {1, 0, 0}, b = vec3_normalize(vec3_t{-0.2f, 0.9f, 0.4f});
    const ld total = std::acos(ldot(unit_ref(a), unit_ref(b)));
    for (int k = -5; k <= 15; ++k) {
        const float t = float(k) / 10.0f;
        const vec3_t r = vec3_slerp_robust(a, b, t);
        // Signed angle from a along the circle: atan2(r·p̂, r·â).
        const lvec n = lcross(unit_ref(a), unit_ref(b));
        const lvec perp = lscale(lcross(n, unit_ref(a)), 1.0L / llen(n));
        const ld angle = std::atan2(ldot(L(r), perp), ldot(L(r), unit_ref(a)));
        CHECK_NEAR(angle, t * total, 3e-7);
    }
}

TEST(slerp_faithful_is_safe_and_within_its_bound) {
    std::mt19937 rng(53);
    std::uniform_real_distribution<float> tdist(0.0f, 1.0f);
    // Bounds stated in math3d.h by angle band: θ ≤ 90°, ≤ 135°, beyond.
    const double band_limit_deg[3] = {90, 135, 180}, band_bound[3] = {1.8e-3, 6e-3, 0.05};
    double worst[3] = {0, 0, 0};
    for (int trial = 0; trial < 30000; ++trial) {
        const vec3_t a = random_vec(rng), b = random_vec(rng);
        if (llen(L(a)) < 1e-3L || llen(L(b)) < 1e-3L) continue;
        const ld angle_deg = std::acos(std::clamp(ldot(unit_ref(a), unit_ref(b)), -1.0L, 1.0L)) * 180 / PI_L;
        if (angle_deg > 179.9L) continue;  // the reference needs a defined plane
        const float t = tdist(rng);
        const lvec ref = slerp_ref(vec3_normalize(a), vec3_normalize(b), t);
        const int band = angle_deg <= 90 ? 0 : angle_deg <= 135 ? 1 : 2;
        worst[band] = std::max(worst[band], double(max_diff(vec3_slerp(a, b, t), ref)));
    }
    for (int band = 0; band < 3; ++band)
        CHECK_MSG(worst[band] <= band_bound[band] && worst[band] > 0.0,
                  "up to " + std::to_string(band_limit_deg[band]) + " deg: " + std::to_string(worst[band]));
    // Stability: antipodal, nearly parallel/antipodal, zero, NaN — unit, finite, no NaN.
    const vec3_t a = vec3_normalize(vec3_t{0.3f, -0.5f, 0.8f});
    const vec3_t p = vec3_any_perpendicular(a);
    for (const vec3_t &b : {-a, a, at_angle(a, p, std::acos(1.0 - 1e-7)), at_angle(a, p, std::acos(-1.0 + 1e-7))})
        for (float t : {0.0f, 0.5f, 1.0f, -0.5f, 1.5f}) {
            const vec3_t r = vec3_slerp(a, b, t);
            CHECK(finite3(r));
            // Inside [0, 1] the Quake inputs' 1.75e-3 (+ the acos path's ≤ 1e-3 bulge when
            // Quake pushes a·a below 0.9995); extrapolating, the report's formula drifts
            // further (4.2e-3 at t = 1.5 for b = a): 1e-2.
            CHECK_NEAR(llen(L(r)), 1.0, t >= 0.0f && t <= 1.0f ? 3e-3 : 1e-2);
        }
    CHECK(max_diff(vec3_slerp(a, -a, 0.5f), L(p)) < 4e-3);
    const vec3_t from_zero = vec3_slerp(vec3_t{0, 0, 0}, vec3_t{0, 2, 0}, 0.3f);
    CHECK(max_diff(from_zero, lvec{0, 1, 0}) < 2e-3);
    CHECK(vec3_slerp(vec3_t{0, 0, 0}, vec3_t{NAN, 0, 0}, 0.3f) == (vec3_t{0, 0, 0}));
}

// ---- quaternions -------------------------------------------------------------------------

TEST(quaternion_multiply_matches_matrix_product) {
    std::mt19937 rng(54);
    std::uniform_real_distribution<float> angle(-6, 6);
    for (int trial = 0; trial < 500; ++trial) {
        const quat a = quat_from_axis_angle(random_vec(rng), angle(rng));
        const quat b = quat_from_axis_angle(random_vec(rng), angle(rng));
        const mat4_t via_quat = quat_to_mat4(quat_multiply(a, b));
        const mat4_t via_mat = mat4_multiply(quat_to_mat4(a), quat_to_mat4(b));
        for (int i = 0; i < 16; ++i) CHECK_NEAR(via_quat.m[i], via_mat.m[i], 6e-7);
        const quat n = quat_normalize(quat{a.x * 3, a.y * 3, a.z * 3, a.w * 3});
        CHECK_NEAR(std::sqrt(ld(n.x) * n.x + ld(n.y) * n.y + ld(n.z) * n.z + ld(n.w) * n.w), 1.0, 2e-7);
    }
    const quat z = quat_normalize(quat{0, 0, 0, 0});
    CHECK(z.w == 1.0f && z.x == 0.0f);
    const quat id = quat_from_axis_angle(vec3_t{0, 0, 0}, 1.0f);
    CHECK(id.w == 1.0f);
}

TEST(quaternion_slerp_takes_short_path_at_constant_speed) {
    const vec3_t axis = {0, 0, 1};
    const quat start = quat_identity();
    const quat end = quat_from_axis_angle(axis, 0.4f);
    const quat end_negated = {-end.x, -end.y, -end.z, -end.w};  // same rotation, other hemisphere
    for (int k = -5; k <= 15; ++k) {
        const float t = float(k) / 10.0f;
        for (const quat &e : {end, end_negated}) {
            const quat q = quat_slerp(start, e, t);
            const ld len = std::sqrt(ld(q.x) * q.x + ld(q.y) * q.y + ld(q.z) * q.z + ld(q.w) * q.w);
            CHECK_NEAR(len, 1.0, 2e-7);
            const vec3_t r = quat_rotate(q, vec3_t{1, 0, 0});
            CHECK_NEAR(std::atan2(ld(r.y), ld(r.x)), 0.4L * t, 3e-7);  // short way, tθ
        }
    }
    // Nearly identical and identical orientations: no NaN, exact ends.
    const quat tiny = quat_from_axis_angle(axis, 1e-7f);
    const quat mid = quat_slerp(start, tiny, 0.5f);
    CHECK(std::isfinite(mid.w) && std::fabs(mid.w - 1.0f) < 1e-7f);
    const quat same = quat_slerp(end, end, 0.3f);
    CHECK_NEAR(same.z, end.z, 1e-7);
}
