// math3d_test.cpp — matrices (product, inverse, transforms, the batch transform), rotations,
// projection (frustum, perspective, look-at) and the report's rotating cube. Vectors,
// normalisation, spherical form, slerp and quaternions: math3d_vector_test.cpp.
//
// Independent references and error bounds: math3d_reference.h (long double, U = 2^-24, γₙ).
#include "harness.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <cfloat>
#include <cmath>
#include <random>
#include <vector>

#include "canvas.h"
#include "lines.h"
#include "math3d.h"
#include "math3d_reference.h"

using namespace tiny3d;
using namespace math3d_ref;

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

TEST(inverse_singularity_threshold_sits_at_1e_12_of_hadamards_bound) {
    // Rows (1, 0, 0, 0), (1, δ, 0, 0), e3, e4: det = δ (analytic), Hadamard's bound
    // Π‖row‖ = √(1 + δ²) ≈ 1, so the ratio the header states is δ / √(1 + δ²). Nearly
    // parallel rows, not a small scale: a decade either side of 1e-12 decides.
    const auto nearly_parallel = [](float delta) {
        mat4_t m = mat4_identity();
        m.m[0 * 4 + 1] = 1.0f;   // row 1, column 0
        m.m[1 * 4 + 1] = delta;  // row 1, column 1
        return m;
    };
    for (const float delta : {1e-13f, 3e-14f, 1e-16f}) {
        const result<mat4_t> inv = mat4_inverse(nearly_parallel(delta));
        CHECK_MSG(!inv.ok(), "a matrix with |det| / Π‖row‖ = " + std::to_string(delta) + " was inverted");
        if (!inv.ok()) CHECK_MSG(inv.message().find("singular") != std::string::npos, inv.message());
    }
    for (const float delta : {1e-11f, 1e-9f, 1e-6f}) {
        const result<mat4_t> inv = mat4_inverse(nearly_parallel(delta));
        CHECK_MSG(inv.ok(), "ratio " + std::to_string(delta) + " refused");
        if (!inv.ok()) continue;
        // Analytic inverse of [[1, 0], [1, δ]]: [[1, 0], [−1/δ, 1/δ]], identity elsewhere.
        const double d = double(delta);  // δ as the float holds it
        double expected[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        expected[0 * 4 + 1] = -1.0 / d;
        expected[1 * 4 + 1] = 1.0 / d;
        for (int k = 0; k < 16; ++k)
            CHECK_NEAR(double(inv.value().m[k]), expected[k], 1e-6 * std::fabs(expected[k]) + 1e-12);
    }
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
