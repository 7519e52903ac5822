// material.cpp — material checks, the viewer of a projection, flat Blinn-Phong shading.
// See include/material.h.
#include "material.h"

#include <cmath>
#include <string>

#include "../lighting/flat_normal.h"

namespace tiny3d {

status check_material(const material &m) {
    auto bad = [](const char *field, float value, const char *wanted) {
        return status(error{"", 0, -1, std::string("material: ") + field + " " + std::to_string(value) + " is not " + wanted});
    };
    if (!std::isfinite(m.diffuse) || m.diffuse < 0.0f) return bad("diffuse", m.diffuse, "a finite value >= 0");
    if (!std::isfinite(m.specular) || m.specular < 0.0f) return bad("specular", m.specular, "a finite value >= 0");
    if (!std::isfinite(m.shininess) || m.shininess < 1.0f) return bad("shininess", m.shininess, "a finite value >= 1");
    return {};
}

viewer viewer_of(const mat4_t &view_projection) {
    // Row r of the matrix as a linear form on homogeneous points (column-major storage).
    auto row = [&](int r, int c) { return double(view_projection.m[c * 4 + r]); };
    const int rows[3] = {0, 1, 3};
    // C_j = (−1)^j det(the 3×3 left when column j is struck out): C is orthogonal to all three.
    double centre[4];
    for (int j = 0; j < 4; ++j) {
        int cols[3], n = 0;
        for (int c = 0; c < 4; ++c)
            if (c != j) cols[n++] = c;
        auto e = [&](int r, int c) { return row(rows[r], cols[c]); };
        const double det = e(0, 0) * (e(1, 1) * e(2, 2) - e(1, 2) * e(2, 1)) -
                           e(0, 1) * (e(1, 0) * e(2, 2) - e(1, 2) * e(2, 0)) +
                           e(0, 2) * (e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0));
        centre[j] = (j % 2 == 0) ? det : -det;
    }
    viewer v;
    const double xyz = std::sqrt(centre[0] * centre[0] + centre[1] * centre[1] + centre[2] * centre[2]);
    if (!(xyz > 0.0) || !std::isfinite(xyz)) {
        if (centre[3] != 0.0 && std::isfinite(centre[3])) v.eye = {0, 0, 0};  // the eye at the origin
        else v.at_infinity = true;
        return v;
    }
    // A centre whose w is tiny against its x, y, z (relative to float rounding) is at infinity.
    if (std::fabs(centre[3]) <= 1e-7 * xyz) {
        double d[3] = {centre[0] / xyz, centre[1] / xyz, centre[2] / xyz};
        // Towards the viewer the clip depth z falls (w stays: a parallel projection).
        const double depth_step = row(2, 0) * d[0] + row(2, 1) * d[1] + row(2, 2) * d[2];
        if (depth_step > 0.0)
            for (double &c : d) c = -c;
        v.at_infinity = true;
        v.direction = {float(d[0]), float(d[1]), float(d[2])};
        return v;
    }
    v.eye = {float(centre[0] / centre[3]), float(centre[1] / centre[3]), float(centre[2] / centre[3])};
    return v;
}

float shade_flat_material(const light_rig &rig, const material &mat, const viewer &eye, vec3_t a, vec3_t b, vec3_t c) {
    return shade_point_material(rig, mat, eye, (a + b + c) * (1.0f / 3.0f), flat_unit_normal(a, b, c));
}

}  // namespace tiny3d
