// math3d_test.cpp — matrices, vectors, spherical form, slerp, quaternions.
//
// Independent references: long double arithmetic (64-bit mantissa) written here from the
// textbook formulas, never by calling the function under test. Error bounds use the unit
// roundoff of float, U = 2^-24, and the usual dot-product bound γₙ = n·U/(1 − n·U)
// (Higham, "Accuracy and Stability of Numerical Algorithms", §3.1).
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

#include "canvas.h"
#include "math3d.h"

using namespace tiny3d;

namespace {

using ld = long double;
constexpr double U = 0x1p-24;  // float unit roundoff
constexpr double gamma_n(int n) { return n * U / (1.0 - n * U); }
constexpr ld PI_L = 3.141592653589793238462643383279502884L;

struct lvec {
    ld x, y, z;
};
lvec L(vec3_t v) { return {v.x, v.y, v.z}; }
ld ldot(lvec a, lvec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
lvec lcross(lvec a, lvec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
ld llen(lvec a) { return std::sqrt(ldot(a, a)); }
lvec lscale(lvec a, ld s) { return {a.x * s, a.y * s, a.z * s}; }
lvec ladd(lvec a, lvec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
// Largest component difference between a float result and a long double reference.
ld max_diff(vec3_t a, lvec b) {
    return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}
bool finite3(vec3_t v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

ld entry(const mat4_t &m, int row, int col) { return m.m[col * 4 + row]; }

mat4_t random_matrix(std::mt19937 &rng, float lo = -1.0f, float hi = 1.0f) {
    std::uniform_real_distribution<float> u(lo, hi);
    mat4_t m;
    for (float &v : m.m) v = u(rng);
    return m;
}

vec3_t random_vec(std::mt19937 &rng, float lo = -1.0f, float hi = 1.0f) {
    std::uniform_real_distribution<float> u(lo, hi);
    return {u(rng), u(rng), u(rng)};
}

// Random vector with a random scale 2^[-60, 60] and random direction.
vec3_t random_scaled_vec(std::mt19937 &rng) {
    std::uniform_real_distribution<float> e(-60.0f, 60.0f);
    return random_vec(rng) * std::exp2(e(rng));
}

// The reference unit vector.
lvec unit_ref(vec3_t v) { return lscale(L(v), 1.0L / llen(L(v))); }

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

// ---- matrices ----------------------------------------------------------------------------

TEST(multiply_applies_right_operand_first) {
    const mat4_t t = mat4_translate(1, 2, 3);
    const mat4_t s = mat4_scale(2, 2, 2);
    const vec3_t p = apply_transform(mat4_multiply(t, s), vec3_t{1, 1, 1});  // scale, then translate
    CHECK_NEAR(p.x, 3.0, 0.0);
    CHECK_NEAR(p.y, 4.0, 0.0);
    CHECK_NEAR(p.z, 5.0, 0.0);
    CHECK_EQ(t.m[12], 1.0f);
}

TEST(multiply_matches_double_reference_within_gamma4) {
    std::mt19937 rng(41);
    for (int trial = 0; trial < 2000; ++trial) {
        const mat4_t a = random_matrix(rng, -100, 100), b = random_matrix(rng, -1e-3f, 1e-3f);
        const mat4_t c = mat4_multiply(a, b);
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 4; ++col) {
                ld exact = 0, magnitude = 0;
                for (int k = 0; k < 4; ++k) {
                    exact += entry(a, row, k) * entry(b, k, col);
                    magnitude += std::fabs(entry(a, row, k) * entry(b, k, col));
                }
                // Float dot product of length 4: |error| ≤ γ₄·Σ|aᵢbᵢ| (plus 0.5 ulp of the sum).
                CHECK_NEAR(entry(c, row, col), exact, gamma_n(5) * magnitude);
            }
    }
}

TEST(inverse_times_matrix_is_identity_within_bound) {
    std::mt19937 rng(42);
    int checked = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const mat4_t m = random_matrix(rng, -10, 10);
        const result<mat4_t> inv = mat4_inverse(m);
        if (!CHECK_MSG(inv.ok(), inv.message())) continue;
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 4; ++col) {
                ld product = 0, magnitude = 0;
                for (int k = 0; k < 4; ++k) {
                    product += entry(m, row, k) * entry(*inv, k, col);
                    magnitude += std::fabs(entry(m, row, k) * entry(*inv, k, col));
                }
                // M⁻¹ is rounded once from a double inverse: |M·M⁻¹ − I| ≤ U·(|M||M⁻¹|) (+ the
                // double inverse's own error, far below; 1% and 1e-12 slack).
                CHECK_NEAR(product, row == col ? 1.0 : 0.0, 1.01 * U * magnitude + 1e-12);
            }
        ++checked;
    }
    CHECK_EQ(checked, 2000);
}

TEST(inverse_of_rigid_transform_and_frustum) {
    const mat4_t rigid = mat4_multiply(mat4_translate(3, -2, 7), mat4_rotate_axis(vec3_t{1, 2, 3}, 0.9f));
    const result<mat4_t> inv = mat4_inverse(rigid);
    CHECK(inv.ok());
    // Analytic inverse of [R t; 0 1] is [Rᵀ −Rᵀt; 0 1].
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) CHECK_NEAR(entry(*inv, row, col), entry(rigid, col, row), 2e-7);
        ld rt = 0;
        for (int k = 0; k < 3; ++k) rt += entry(rigid, k, row) * entry(rigid, k, 3);
        CHECK_NEAR(entry(*inv, row, 3), -rt, 2e-6);
    }
    const result<mat4_t> finv = mat4_inverse(mat4_frustum_asymmetric(-1, 1, -1, 1, 1, 10));
    CHECK(finv.ok());
    // Unprojecting NDC (0, 0, −1) gives the near-plane centre (0, 0, −1).
    const vec3_t p = apply_transform(*finv, vec3_t{0, 0, -1});
    CHECK_NEAR(p.z, -1.0, 1e-6);
    CHECK(std::fabs(mat4_determinant(mat4_scale(2, 3, 4)) - 24.0) < 1e-12);
}

TEST(inverse_reports_singular_matrices) {
    mat4_t repeated = mat4_identity();
    repeated.m[1] = 1.0f;  // column 0 = (1, 1, 0, 0)
    repeated.m[4] = 1.0f;  // column 1 = (1, 1, 0, 0)
    mat4_t dependent = {};  // rows are multiples of (0.1, 0.2, 0.3, 0.4)
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) dependent.m[col * 4 + row] = float(row + 1) * 0.1f * float(col + 1);
    mat4_t with_nan = mat4_identity();
    with_nan.m[6] = NAN;
    mat4_t zero = {};
    for (const mat4_t &m : {mat4_scale(1, 0, 1), repeated, dependent, with_nan, zero}) {
        const result<mat4_t> inv = mat4_inverse(m);
        CHECK(!inv.ok());
        if (!inv.ok()) CHECK_MSG(inv.message().find("singular") != std::string::npos, inv.message());
    }
    // Tiny but well-conditioned is not singular.
    CHECK(mat4_inverse(mat4_scale(1e-20f, 1e-20f, 1e-20f)).ok());
    // An inverse beyond FLT_MAX is reported, not returned as inf.
    CHECK(!mat4_inverse(mat4_scale(1e-39f, 1e-39f, 1e-39f)).ok());
}

TEST(transpose_swaps_rows_and_columns) {
    std::mt19937 rng(43);
    const mat4_t m = random_matrix(rng);
    const mat4_t t = mat4_transpose(m);
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) CHECK_EQ(entry(t, row, col), entry(m, col, row));
}

TEST(apply_transform_matches_double_reference) {
    std::mt19937 rng(44);
    for (int trial = 0; trial < 5000; ++trial) {
        const mat4_t m = random_matrix(rng, -4, 4);
        const vec3_t p = random_vec(rng, -50, 50);
        const ld in[4] = {p.x, p.y, p.z, 1};
        ld h[4], mag[4];
        for (int row = 0; row < 4; ++row) {
            h[row] = mag[row] = 0;
            for (int k = 0; k < 4; ++k) {
                h[row] += entry(m, row, k) * in[k];
                mag[row] += std::fabs(entry(m, row, k) * in[k]);
            }
        }
        const vec4_t hv = mat4_mul_vec4(m, vec4_from_vec3(p, 1));
        const float hf[4] = {hv.x, hv.y, hv.z, hv.w};
        for (int row = 0; row < 4; ++row) CHECK_NEAR(hf[row], h[row], gamma_n(5) * mag[row]);
        if (std::fabs(h[3]) < 1e-2L) continue;  // the division's error bound needs |w| away from 0
        const transformed_point tp = transform_point(m, p);
        CHECK(tp.divided_by_w);
        CHECK_EQ(tp.w, hv.w);
        const float out[3] = {tp.point.x, tp.point.y, tp.point.z};
        for (int row = 0; row < 3; ++row) {
            const ld exact = h[row] / h[3];
            // (x + εx)/(w + εw) rounded: |err| ≤ (εx + |x/w|·εw)/|w| + U·|x/w| (first order).
            const ld bound = (gamma_n(5) * mag[row] + std::fabs(exact) * gamma_n(5) * mag[3]) / std::fabs(h[3]) +
                             U * std::fabs(exact);
            CHECK_NEAR(out[row], exact, 1.01 * bound);
        }
    }
}

TEST(transform_point_reports_division) {
    const transformed_point affine = transform_point(mat4_translate(1, 2, 3), vec3_t{1, 1, 1});
    CHECK(!affine.divided_by_w);
    CHECK_EQ(affine.w, 1.0f);
    CHECK(affine.point == (vec3_t{2, 3, 4}));
    mat4_t to_infinity = mat4_identity();
    to_infinity.m[15] = 0.0f;  // w = 0: returned undivided
    const transformed_point inf = transform_point(to_infinity, vec3_t{5, 6, 7});
    CHECK(!inf.divided_by_w);
    CHECK(inf.point == (vec3_t{5, 6, 7}));
    const transformed_point proj = transform_point(mat4_frustum_asymmetric(-1, 1, -1, 1, 1, 10), vec3_t{0, 0, -2});
    CHECK(proj.divided_by_w);
    CHECK_EQ(proj.w, 2.0f);
    CHECK(transform_direction(mat4_translate(9, 9, 9), vec3_t{1, 2, 3}) == (vec3_t{1, 2, 3}));
}

TEST(batch_transform_is_bit_identical_to_apply_transform) {
    std::mt19937 rng(45);
    std::vector<vec3_t> in(1001);
    for (vec3_t &p : in) p = random_vec(rng, -20, 20);
    in[3] = {NAN, 1, 2};
    in[4] = {INFINITY, 0, 0};
    mat4_t projective = mat4_multiply(mat4_frustum_asymmetric(-1, 2, -1, 1, 0.5f, 50), mat4_rotate_axis(vec3_t{1, 1, 0}, 0.3f));
    mat4_t w_zero_or_one = mat4_identity();  // w = z: hits w = 0 and w = 1 exactly
    w_zero_or_one.m[11] = 1.0f;
    w_zero_or_one.m[15] = 0.0f;
    in[5] = {1, 2, 0};
    in[6] = {1, 2, 1};
    for (const mat4_t &m : {projective, w_zero_or_one, random_matrix(rng), mat4_translate(1, 2, 3)}) {
        std::vector<vec3_t> out(in.size());
        CHECK(transform_points(m, in, out).ok());
        std::vector<vec4_t> clip(in.size());
        CHECK(transform_points_homogeneous(m, in, clip).ok());
        int mismatches = 0;
        for (std::size_t i = 0; i < in.size(); ++i) {
            const vec3_t e = apply_transform(m, in[i]);
            const vec4_t h = mat4_mul_vec4(m, vec4_from_vec3(in[i], 1));
            const auto same = [](float a, float b) { return a == b || (std::isnan(a) && std::isnan(b)); };
            if (!same(out[i].x, e.x) || !same(out[i].y, e.y) || !same(out[i].z, e.z)) ++mismatches;
            if (!same(clip[i].x, h.x) || !same(clip[i].y, h.y) || !same(clip[i].z, h.z) || !same(clip[i].w, h.w))
                ++mismatches;
        }
        CHECK_EQ(mismatches, 0);
        // In place gives the same.
        std::vector<vec3_t> inplace = in;
        CHECK(transform_points(m, inplace, inplace).ok());
        CHECK(std::equal(inplace.begin() + 7, inplace.end(), out.begin() + 7));
    }
    std::vector<vec3_t> small(3);
    const status s = transform_points(mat4_identity(), in, small);
    CHECK(!s.ok());
    CHECK(!transform_points_homogeneous(mat4_identity(), in, std::span<vec4_t>()).ok());
    CHECK(transform_points(mat4_identity(), std::span<const vec3_t>(), std::span<vec3_t>()).ok());
}

TEST(behind_camera_and_huge_points_transform_without_surprises) {
    const mat4_t proj = mat4_frustum_asymmetric(-1, 1, -1, 1, 1, 10);
    // Behind the camera (z > 0): w = −z < 0, divided (the caller clips on w, see
    // transform_points_homogeneous); the point is mirrored through the eye.
    const transformed_point behind = transform_point(proj, vec3_t{0.5f, 0.25f, 2});
    CHECK(behind.w < 0.0f);
    CHECK(behind.divided_by_w);
    CHECK_NEAR(behind.point.x, -0.25, 1e-7);
    // In the eye plane (z = 0): w = 0, returned undivided, finite.
    const transformed_point eye_plane = transform_point(proj, vec3_t{0.5f, 0.25f, 0});
    CHECK(!eye_plane.divided_by_w);
    CHECK(finite3(eye_plane.point));
    // Huge coordinates: the projective divide keeps them finite when w is finite.
    const transformed_point far_away = transform_point(proj, vec3_t{1e30f, -1e30f, -1e30f});
    CHECK(finite3(far_away.point));
    CHECK_NEAR(far_away.point.x, 1.0, 1e-6);
    std::vector<vec4_t> clip(1);
    const vec3_t huge[1] = {{FLT_MAX, FLT_MAX, -FLT_MAX}};
    CHECK(transform_points_homogeneous(proj, huge, clip).ok());
    CHECK(clip[0].w == FLT_MAX);
}

// ---- rotations ---------------------------------------------------------------------------

TEST(rotations_are_orthonormal_with_det_one) {
    std::mt19937 rng(46);
    std::uniform_real_distribution<float> angle(-10, 10);
    for (int trial = 0; trial < 500; ++trial) {
        const mat4_t rs[] = {mat4_rotate_x(angle(rng)), mat4_rotate_y(angle(rng)), mat4_rotate_z(angle(rng)),
                             mat4_rotate_xyz(angle(rng), angle(rng), angle(rng)),
                             mat4_rotate_axis(random_vec(rng), angle(rng)),
                             quat_to_mat4(quat_from_axis_angle(random_vec(rng), angle(rng)))};
        for (const mat4_t &r : rs) {
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) {
                    ld d = 0;
                    for (int k = 0; k < 3; ++k) d += entry(r, k, i) * entry(r, k, j);
                    CHECK_NEAR(d, i == j ? 1.0 : 0.0, 4e-7);  // a few roundings of entries ≤ 1
                }
            CHECK_NEAR(mat4_determinant(r), 1.0, 1e-6);
            CHECK_EQ(r.m[15], 1.0f);
            CHECK_EQ(r.m[12], 0.0f);
            CHECK_EQ(r.m[3], 0.0f);
        }
    }
}

TEST(rotations_send_axes_where_the_header_says) {
    const float quarter = float(M_PI / 2);
    const auto near = [](vec3_t a, vec3_t b) { return max_diff(a, L(b)) < 1e-7; };
    CHECK(near(apply_transform(mat4_rotate_z(quarter), vec3_t{1, 0, 0}), vec3_t{0, 1, 0}));
    CHECK(near(apply_transform(mat4_rotate_x(quarter), vec3_t{0, 1, 0}), vec3_t{0, 0, 1}));
    CHECK(near(apply_transform(mat4_rotate_y(quarter), vec3_t{0, 0, 1}), vec3_t{1, 0, 0}));
    CHECK(near(apply_transform(mat4_rotate_axis(vec3_t{0, 0, 5}, quarter), vec3_t{1, 0, 0}), vec3_t{0, 1, 0}));
    // 120° about (1,1,1) cycles the axes x → y → z.
    const mat4_t cyc = mat4_rotate_axis(vec3_t{1, 1, 1}, float(2 * M_PI / 3));
    CHECK(near(apply_transform(cyc, vec3_t{1, 0, 0}), vec3_t{0, 1, 0}));
    CHECK(near(apply_transform(cyc, vec3_t{0, 1, 0}), vec3_t{0, 0, 1}));
    // Zero axis: identity.
    const mat4_t id = mat4_rotate_axis(vec3_t{0, 0, 0}, 1.0f);
    CHECK(std::equal(id.m, id.m + 16, mat4_identity().m));
}

TEST(rotate_xyz_order_is_rz_ry_rx) {
    std::mt19937 rng(47);
    std::uniform_real_distribution<float> angle(-4, 4);
    for (int trial = 0; trial < 200; ++trial) {
        const float rx = angle(rng), ry = angle(rng), rz = angle(rng);
        const mat4_t direct = mat4_rotate_xyz(rx, ry, rz);
        const mat4_t composed = mat4_multiply(mat4_rotate_z(rz), mat4_multiply(mat4_rotate_y(ry), mat4_rotate_x(rx)));
        for (int i = 0; i < 16; ++i) CHECK_NEAR(direct.m[i], composed.m[i], 3e-7);
    }
    // Order pinned on a concrete vector: x-rotation first. Rx(90°) sends y to z, then
    // Ry(90°) sends z to x.
    const vec3_t p = apply_transform(mat4_rotate_xyz(float(M_PI / 2), float(M_PI / 2), 0), vec3_t{0, 1, 0});
    CHECK(max_diff(p, lvec{1, 0, 0}) < 1e-7);
}

TEST(rotate_axis_matches_rodrigues_reference) {
    std::mt19937 rng(48);
    std::uniform_real_distribution<float> angle(-7, 7);
    for (int trial = 0; trial < 2000; ++trial) {
        const vec3_t axis = random_vec(rng), v = random_vec(rng);
        const float a = angle(rng);
        if (llen(L(axis)) < 1e-3L) continue;
        const lvec k = unit_ref(axis), lv = L(v);
        // v cos + (k×v) sin + k (k·v)(1 − cos)
        const lvec exact = ladd(ladd(lscale(lv, std::cos(ld(a))), lscale(lcross(k, lv), std::sin(ld(a)))),
                                lscale(k, ldot(k, lv) * (1 - std::cos(ld(a)))));
        const vec3_t got = apply_transform(mat4_rotate_axis(axis, a), v);
        CHECK(max_diff(got, exact) <= 6 * U * llen(lv) * 1.8);  // entries rounded (U), 3-term sums
        const vec3_t via_quat = quat_rotate(quat_from_axis_angle(axis, a), v);
        CHECK(max_diff(via_quat, exact) <= 6 * U * llen(lv) * 1.8);
    }
}

// ---- projection --------------------------------------------------------------------------

TEST(frustum_maps_near_corners_to_ndc) {
    const mat4_t f = mat4_frustum_asymmetric(-1, 2, -0.5f, 1.5f, 1, 10);
    const vec3_t a = apply_transform(f, vec3_t{-1, -0.5f, -1});
    const vec3_t b = apply_transform(f, vec3_t{2 * 10.0f, 1.5f * 10.0f, -10});
    CHECK_NEAR(a.x, -1.0, 1e-6);
    CHECK_NEAR(a.y, -1.0, 1e-6);
    CHECK_NEAR(a.z, -1.0, 1e-6);
    CHECK_NEAR(b.x, 1.0, 1e-6);
    CHECK_NEAR(b.y, 1.0, 1e-6);
    CHECK_NEAR(b.z, 1.0, 1e-6);
}

TEST(frustum_corners_near_and_far_planes) {
    const float l = -0.7f, r = 1.3f, b = -0.4f, t = 0.9f, n = 0.5f, f = 40.0f;
    const mat4_t m = mat4_frustum_asymmetric(l, r, b, t, n, f);
    for (float x : {l, r})
        for (float y : {b, t})
            for (float depth : {n, f}) {
                const float s = depth / n;  // the far corners lie on the same rays
                const transformed_point p = transform_point(m, vec3_t{x * s, y * s, -depth});
                CHECK_NEAR(p.point.x, x == l ? -1.0 : 1.0, 1e-6);
                CHECK_NEAR(p.point.y, y == b ? -1.0 : 1.0, 1e-6);
                CHECK_NEAR(p.point.z, depth == n ? -1.0 : 1.0, 1e-6);
                CHECK_NEAR(p.w, depth, 1e-6 * depth);  // w = −z > 0 in front
            }
    // Bad arguments: identity from the report's name, a reason from the checked one.
    const mat4_t bad = mat4_frustum_asymmetric(1, 1, -1, 1, 1, 10);
    CHECK(std::equal(bad.m, bad.m + 16, mat4_identity().m));
    CHECK(!frustum_checked(-1, 1, -1, 1, 0, 10).ok());
    CHECK(!frustum_checked(-1, 1, -1, 1, 2, 1).ok());
    CHECK(!frustum_checked(-1, 1, 1, 1, 1, 10).ok());
    CHECK(!frustum_checked(-1, NAN, -1, 1, 1, 10).ok());
    const result<mat4_t> why = frustum_checked(-1, 1, -1, 1, -1, 10);
    CHECK_MSG(!why.ok() && why.message().find("near") != std::string::npos, why.message());
}

TEST(perspective_field_of_view_and_depth) {
    const float fovy = 1.1f, aspect = 16.0f / 9.0f, n = 0.1f, f = 100.0f;
    const mat4_t m = mat4_perspective(fovy, aspect, n, f);
    const double half = std::tan(0.5 * fovy);
    // A point on the top edge of the view at depth 7 → NDC y = 1; right edge → x = 1.
    const vec3_t top = apply_transform(m, vec3_t{0, float(7 * half), -7});
    const vec3_t right = apply_transform(m, vec3_t{float(7 * half * aspect), 0, -7});
    CHECK_NEAR(top.y, 1.0, 1e-6);
    CHECK_NEAR(right.x, 1.0, 1e-6);
    CHECK_NEAR(apply_transform(m, vec3_t{0, 0, -n}).z, -1.0, 1e-6);
    CHECK_NEAR(apply_transform(m, vec3_t{0, 0, -f}).z, 1.0, 1e-5);
    CHECK(!perspective_checked(0, 1, 1, 2).ok());
    CHECK(!perspective_checked(4, 1, 1, 2).ok());
    CHECK(!perspective_checked(1, -1, 1, 2).ok());
    CHECK(!perspective_checked(1, 1, 1, 1).ok());
}

TEST(look_at_places_eye_and_target) {
    const vec3_t eye = {3, 4, 5}, target = {-1, 0.5f, 2}, up = {0, 1, 0};
    const mat4_t v = mat4_look_at(eye, target, up);
    const vec3_t e = apply_transform(v, eye);
    CHECK(max_diff(e, lvec{0, 0, 0}) < 1e-5);
    const vec3_t t = apply_transform(v, target);
    const ld dist = llen(ladd(L(target), lscale(L(eye), -1)));
    CHECK(max_diff(t, lvec{0, 0, -dist}) < 1e-5);
    // Up projects to +y (x stays 0).
    const vec3_t u = transform_direction(v, up);
    CHECK(u.y > 0.0f);
    CHECK_NEAR(u.x, 0.0, 1e-6);
    // Degenerate: up parallel to the view direction, eye == target — still a rotation.
    for (const mat4_t &m : {mat4_look_at(vec3_t{0, 0, 0}, vec3_t{0, 5, 0}, vec3_t{0, 1, 0}),
                            mat4_look_at(vec3_t{1, 2, 3}, vec3_t{1, 2, 3}, vec3_t{0, 1, 0}),
                            mat4_look_at(vec3_t{0, 0, 0}, vec3_t{0, 0, -1}, vec3_t{0, 0, 0})}) {
        CHECK_NEAR(mat4_determinant(m), 1.0, 1e-6);
        for (float x : m.m) CHECK(std::isfinite(x));
    }
}

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

// The report's listings (seed 000, Task 2), transcribed with std::bit_cast for the
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

// ---- the report's rotating cube ------------------------------------------------------------

namespace {

// The report's Task 2 frame, as in demo/cube.cpp: ±1 cube, mat4_scale(1,1,1), rotation
// about y, translate (0,0,−5), frustum(−1,1,−1,1,1,10), NDC → pixels, 12 edges at 1.2 px.
void render_report_cube(canvas_t *c, float angle) {
    const vec3_t cube[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                            {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                              {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    const mat4_t model = mat4_multiply(mat4_translate(0, 0, -5), mat4_multiply(mat4_rotate_xyz(0, angle, 0), mat4_scale(1, 1, 1)));
    const mat4_t mvp = mat4_multiply(mat4_frustum_asymmetric(-1, 1, -1, 1, 1, 10), model);
    vec3_t projected[8];
    for (int i = 0; i < 8; ++i) {
        vec3_t p = apply_transform(mvp, cube[i]);
        p.x = (p.x + 1.0f) * 0.5f * float(c->width);
        p.y = (1.0f - (p.y + 1.0f) * 0.5f) * float(c->height);
        projected[i] = p;
    }
    for (const auto &e : edges)
        draw_line_f(c, projected[e[0]].x, projected[e[0]].y, projected[e[1]].x, projected[e[1]].y, 1.2f);
}

}  // namespace

TEST(cube_frame_zero_equals_frame_one_turn_later) {
    const int size = 128;
    canvas_t *first = create_canvas(size, size), *later = create_canvas(size, size), *quarter = create_canvas(size, size);
    render_report_cube(first, 0.0f);
    // Frame 60 of 60 by the report's formula angle = 2π·k/60, unreduced: sin(2π) in float
    // is 1.7e-7, far below one 8-bit step of any pixel.
    render_report_cube(later, float(2.0 * M_PI * 60 / 60));
    render_report_cube(quarter, float(M_PI / 2));  // a cube turned 90° looks the same too
    int differing = 0, ink = 0;
    double largest = 0;
    for (int i = 0; i < size * size; ++i) {
        const auto q = [](float v) { return std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f); };
        differing += q(first->data[i]) != q(later->data[i]);
        largest = std::max(largest, double(std::fabs(first->data[i] - later->data[i])));
        ink += first->data[i] > 0.5f;
        CHECK_NEAR(first->data[i], quarter->data[i], 1e-4);
    }
    CHECK_EQ(differing, 0);
    CHECK(largest < 1e-4);
    CHECK(ink > 100);  // the cube was drawn
    destroy_canvas(first);
    destroy_canvas(later);
    destroy_canvas(quarter);
}
