// matrix.cpp — the report's mat4 builders and products (column-major, m[col*4 + row]).
#include <cmath>

#include "math3d.h"

mat4_t mat4_identity(void) {
    mat4_t m = {};
    m.m[0] = m.m[5] = m.m[10] = m.m[15] = 1.0f;
    return m;
}

mat4_t mat4_multiply(mat4_t a, mat4_t b) {
    mat4_t r = {};
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) {
            float sum = 0.0f;
            for (int k = 0; k < 4; ++k) sum += a.m[k * 4 + row] * b.m[col * 4 + k];
            r.m[col * 4 + row] = sum;
        }
    return r;
}

mat4_t mat4_translate(float tx, float ty, float tz) {
    mat4_t m = mat4_identity();
    m.m[12] = tx;
    m.m[13] = ty;
    m.m[14] = tz;
    return m;
}

mat4_t mat4_scale(float sx, float sy, float sz) {
    mat4_t m = {};
    m.m[0] = sx;
    m.m[5] = sy;
    m.m[10] = sz;
    m.m[15] = 1.0f;
    return m;
}

mat4_t mat4_rotate_xyz(float rx, float ry, float rz) {
    const float cx = std::cos(rx), sx = std::sin(rx);
    const float cy = std::cos(ry), sy = std::sin(ry);
    const float cz = std::cos(rz), sz = std::sin(rz);
    // R = Rz·Ry·Rx, written out (row r, column c at m[c*4 + r]).
    mat4_t m = mat4_identity();
    m.m[0] = cz * cy;
    m.m[1] = sz * cy;
    m.m[2] = -sy;
    m.m[4] = cz * sy * sx - sz * cx;
    m.m[5] = sz * sy * sx + cz * cx;
    m.m[6] = cy * sx;
    m.m[8] = cz * sy * cx + sz * sx;
    m.m[9] = sz * sy * cx - cz * sx;
    m.m[10] = cy * cx;
    return m;
}

mat4_t mat4_frustum_asymmetric(float l, float r, float b, float t, float n, float f) {
    if (!(r != l) || !(t != b) || !(n > 0.0f) || !(f > n)) return mat4_identity();
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

vec4_t vec4_from_vec3(vec3_t v, float w) { return {v.x, v.y, v.z, w}; }

vec4_t mat4_mul_vec4(mat4_t m, vec4_t v) {
    return {m.m[0] * v.x + m.m[4] * v.y + m.m[8] * v.z + m.m[12] * v.w,
            m.m[1] * v.x + m.m[5] * v.y + m.m[9] * v.z + m.m[13] * v.w,
            m.m[2] * v.x + m.m[6] * v.y + m.m[10] * v.z + m.m[14] * v.w,
            m.m[3] * v.x + m.m[7] * v.y + m.m[11] * v.z + m.m[15] * v.w};
}

vec3_t apply_transform(mat4_t m, vec3_t v) {
    const vec4_t p = mat4_mul_vec4(m, vec4_from_vec3(v, 1.0f));
    if (p.w != 0.0f && p.w != 1.0f) return {p.x / p.w, p.y / p.w, p.z / p.w};
    return {p.x, p.y, p.z};
}
