// projection.cpp — frustum and perspective with their reasons, the look-at view matrix.
#include <cmath>
#include <initializer_list>
#include <string>

#include "math3d.h"

namespace {

tiny3d::error bad_argument(const std::string &function, const std::string &what) {
    return tiny3d::error{"", 0, -1, function + ": " + what};
}

bool all_finite(std::initializer_list<float> values) {
    for (float v : values)
        if (!std::isfinite(v)) return false;
    return true;
}

}  // namespace

namespace tiny3d {

result<mat4_t> frustum_checked(float l, float r, float b, float t, float n, float f) {
    const char *name = "mat4_frustum_asymmetric";
    if (!all_finite({l, r, b, t, n, f})) return bad_argument(name, "an argument is not finite");
    if (r == l) return bad_argument(name, "left equals right (" + std::to_string(l) + ")");
    if (t == b) return bad_argument(name, "bottom equals top (" + std::to_string(b) + ")");
    if (!(n > 0.0f)) return bad_argument(name, "near must be > 0, got " + std::to_string(n));
    if (!(f > n)) return bad_argument(name, "far must be > near, got near " + std::to_string(n) +
                                                " far " + std::to_string(f));
    if (!all_finite({r - l, t - b, f - n})) return bad_argument(name, "the extents overflow float");
    // glFrustum (OpenGL 2.1 reference): x' = (2n x + (r+l) z)/(r−l) etc., w' = −z.
    mat4_t m = {};
    m.m[0] = 2.0f * n / (r - l);
    m.m[5] = 2.0f * n / (t - b);
    m.m[8] = (r + l) / (r - l);
    m.m[9] = (t + b) / (t - b);
    m.m[10] = -(f + n) / (f - n);
    m.m[11] = -1.0f;
    m.m[14] = -2.0f * f * n / (f - n);
    return m;
}

result<mat4_t> perspective_checked(float fovy, float aspect, float n, float f) {
    const char *name = "mat4_perspective";
    if (!all_finite({fovy, aspect, n, f})) return bad_argument(name, "an argument is not finite");
    if (!(fovy > 0.0f) || !(double(fovy) < M_PI))
        return bad_argument(name, "fovy must lie in (0, pi) radians, got " + std::to_string(fovy));
    if (!(aspect > 0.0f)) return bad_argument(name, "aspect must be > 0, got " + std::to_string(aspect));
    const float top = n * float(std::tan(0.5 * double(fovy)));
    const float right = top * aspect;
    return frustum_checked(-right, right, -top, top, n, f);
}

mat4_t mat4_perspective(float fovy, float aspect, float n, float f) {
    result<mat4_t> m = perspective_checked(fovy, aspect, n, f);
    return m ? *m : mat4_identity();
}

mat4_t mat4_look_at(vec3_t eye, vec3_t target, vec3_t up) {
    vec3_t forward = vec3_normalize(target - eye);
    if (forward == vec3_t{0.0f, 0.0f, 0.0f}) forward = {0.0f, 0.0f, -1.0f};
    vec3_t side = vec3_normalize(vec3_cross(forward, up));
    if (side == vec3_t{0.0f, 0.0f, 0.0f}) side = vec3_normalize(vec3_cross(forward, vec3_any_perpendicular(forward)));
    const vec3_t true_up = vec3_cross(side, forward);
    // Rows: side, up, −forward; the translation moves the eye to the origin.
    mat4_t m = mat4_identity();
    m.m[0] = side.x;
    m.m[4] = side.y;
    m.m[8] = side.z;
    m.m[1] = true_up.x;
    m.m[5] = true_up.y;
    m.m[9] = true_up.z;
    m.m[2] = -forward.x;
    m.m[6] = -forward.y;
    m.m[10] = -forward.z;
    m.m[12] = -vec3_dot(side, eye);
    m.m[13] = -vec3_dot(true_up, eye);
    m.m[14] = vec3_dot(forward, eye);
    return m;
}

}  // namespace tiny3d

mat4_t mat4_frustum_asymmetric(float l, float r, float b, float t, float n, float f) {
    tiny3d::result<mat4_t> m = tiny3d::frustum_checked(l, r, b, t, n, f);
    return m ? *m : mat4_identity();
}
