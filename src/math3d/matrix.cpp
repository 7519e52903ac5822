// matrix.cpp — the report's mat4 builders and products (column-major, m[col*4 + row]).
#include <cmath>

#include "math3d.h"
#include "rows3.h"

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

mat4_t mat4_rotate_x(float angle) { return mat4_rotate_xyz(angle, 0.0f, 0.0f); }
mat4_t mat4_rotate_y(float angle) { return mat4_rotate_xyz(0.0f, angle, 0.0f); }
mat4_t mat4_rotate_z(float angle) { return mat4_rotate_xyz(0.0f, 0.0f, angle); }

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

vec4_t vec4_from_vec3(vec3_t v, float w) { return {v.x, v.y, v.z, w}; }

vec4_t mat4_mul_vec4(mat4_t m, vec4_t v) {
    return {m.m[0] * v.x + m.m[4] * v.y + m.m[8] * v.z + m.m[12] * v.w,
            m.m[1] * v.x + m.m[5] * v.y + m.m[9] * v.z + m.m[13] * v.w,
            m.m[2] * v.x + m.m[6] * v.y + m.m[10] * v.z + m.m[14] * v.w,
            m.m[3] * v.x + m.m[7] * v.y + m.m[11] * v.z + m.m[15] * v.w};
}

// ---- libtiny3d additions: rotations ------------------------------------------------------
namespace tiny3d {

// Rodrigues: R = cos α·I + sin α·[k]× + (1 − cos α)·k kᵀ for the unit axis k.
mat4_t mat4_rotate_axis(vec3_t axis, float angle) {
    const double ax = axis.x, ay = axis.y, az = axis.z;
    const double len = std::sqrt(ax * ax + ay * ay + az * az);
    if (!(len > 0.0) || !std::isfinite(len) || !std::isfinite(angle)) return mat4_identity();
    const double k[3] = {ax / len, ay / len, az / len};
    const double c = std::cos(double(angle)), s = std::sin(double(angle)), t = 1.0 - c;
    const double r[3][3] = {
        {c + t * k[0] * k[0], t * k[0] * k[1] - s * k[2], t * k[0] * k[2] + s * k[1]},
        {t * k[1] * k[0] + s * k[2], c + t * k[1] * k[1], t * k[1] * k[2] - s * k[0]},
        {t * k[2] * k[0] - s * k[1], t * k[2] * k[1] + s * k[0], c + t * k[2] * k[2]},
    };
    return detail::from_rows3(r);
}

mat4_t mat4_transpose(mat4_t m) {
    mat4_t t = {};
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) t.m[row * 4 + col] = m.m[col * 4 + row];
    return t;
}

}  // namespace tiny3d
