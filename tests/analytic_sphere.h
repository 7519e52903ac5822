// analytic_sphere.h — the unit sphere at the origin lit with material.h's Blinn-Phong model
// in double precision, seen through a pixel grid: the reference of the material tests
// (tests/material_test.cpp) and of the shading benchmark (tests/bench/shading.cpp).
#ifndef TINY3D_ANALYTIC_SPHERE_H
#define TINY3D_ANALYTIC_SPHERE_H

#include <algorithm>
#include <cmath>

#include "canvas.h"
#include "lighting.h"
#include "material.h"
#include "math3d.h"

namespace analytic_sphere {

struct dvec {
    double x, y, z;
};
inline dvec operator+(dvec a, dvec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline dvec operator-(dvec a, dvec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline dvec operator*(dvec a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(dvec a, dvec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline dvec unit(dvec a) {
    const double l = std::sqrt(dot(a, a));
    return l > 0 ? a * (1.0 / l) : dvec{0, 0, 0};
}
inline dvec wide(vec3_t v) { return {v.x, v.y, v.z}; }

// material.h's formula in double at point p with unit normal n; V towards `eye`, or along
// `eye` itself when at_infinity. Directional and point lights.
inline double blinn_phong(const tiny3d::light_rig &rig, const tiny3d::material &m, dvec eye, bool at_infinity, dvec p,
                          dvec n) {
    const dvec v = at_infinity ? unit(eye) : unit(eye - p);
    double sum = rig.ambient;
    for (int i = 0; i < rig.count; ++i) {
        const light_t &l = rig.lights[i];
        const dvec to_light =
            l.kind == tiny3d::light_kind::point ? unit(wide(l.position) - p) : unit(wide(l.direction));
        const double cosine = dot(n, to_light);
        if (cosine <= 0) continue;
        const double nh = dot(n, unit(to_light + v));
        sum += l.intensity * (m.diffuse * cosine + (nh > 0 ? m.specular * std::pow(nh, m.shininess) : 0.0));
    }
    return std::clamp(sum, 0.0, 1.0);
}

// Where the ray from `eye` through the centre of pixel (x, y) of a size × size image (row 0
// at the top) first meets the unit sphere; false when it misses or passes within `margin`
// (in the discriminant) of the silhouette, where tessellation changes the coverage.
// `inverse` is the inverse of the view-projection matrix.
inline bool sphere_hit(const mat4_t &inverse, dvec eye, int size, int x, int y, double margin, dvec &hit) {
    const double ndc_x = (x + 0.5) / size * 2 - 1, ndc_y = 1 - (y + 0.5) / size * 2;
    const vec4_t far4 = mat4_mul_vec4(inverse, {float(ndc_x), float(ndc_y), 1.0f, 1.0f});
    const dvec far = {far4.x / far4.w, far4.y / far4.w, far4.z / far4.w};
    const dvec d = unit(far - eye);
    const double b = dot(eye, d), c = dot(eye, eye) - 1.0, disc = b * b - c;
    if (disc <= margin) return false;
    hit = eye + d * (-b - std::sqrt(disc));
    return true;
}

struct image_error {
    double mean = 0, max = 0;
    int pixels = 0;
};

// A rendered size × size image of the sphere against the analytic one lit in double, over
// the pixels well inside its silhouette.
inline image_error against_analytic(const canvas_t &c, const mat4_t &view_projection, dvec eye,
                                    const tiny3d::light_rig &rig, const tiny3d::material &m) {
    image_error e;
    const mat4_t inverse = tiny3d::mat4_inverse(view_projection).value();
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x) {
            dvec hit;
            if (!sphere_hit(inverse, eye, c.width, x, y, 0.02, hit)) continue;
            const double d = std::fabs(c.pixels[y][x] - blinn_phong(rig, m, eye, false, hit, hit));
            e.mean += d;
            e.max = std::max(e.max, d);
            ++e.pixels;
        }
    if (e.pixels) e.mean /= e.pixels;
    return e;
}

}  // namespace analytic_sphere

#endif
