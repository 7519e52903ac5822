// math3d_test.cpp — matrices, vectors, spherical form, slerp, quaternions.
#include "harness.h"

#include "math3d.h"

TEST(multiply_applies_right_operand_first) {
    const mat4_t t = mat4_translate(1, 2, 3);
    const mat4_t s = mat4_scale(2, 2, 2);
    const vec3_t p = apply_transform(mat4_multiply(t, s), vec3_t{1, 1, 1});  // scale, then translate
    CHECK_NEAR(p.x, 3.0, 0.0);
    CHECK_NEAR(p.y, 4.0, 0.0);
    CHECK_NEAR(p.z, 5.0, 0.0);
    CHECK_EQ(t.m[12], 1.0f);
}

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
