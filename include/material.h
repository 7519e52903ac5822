// material.h — surface materials with a Blinn-Phong highlight, and where the viewer is.
// Implementations: src/material/material.cpp (the flat normal shared with src/lighting/).
//
// Model (Blinn 1977), for a point p with unit normal n, lights and ambient from a light_rig
// (lighting.h: L_k towards light k, unit), V the unit vector from p towards the eye:
//     I = clamp01( ambient + Σ_k intensity_k · (kd · max(0, n·L_k) + ks · max(0, n·h_k)^s) )
//     h_k = unit(L_k + V)                                   (the half vector)
// with kd = material::diffuse, ks = material::specular, s = material::shininess. As in
// OpenGL's fixed-function lighting, light k adds nothing (no highlight either) where
// n·L_k ≤ 0, so a surface turned away from a light never catches its highlight.
// The default material (kd = 1, ks = 0) is the lighting module's Lambert model exactly:
// the rasterizer then takes its diffuse-only code, and images are unchanged.
#ifndef TINY3D_MATERIAL_H
#define TINY3D_MATERIAL_H

#include <cmath>

#include "lighting.h"
#include "math3d.h"
#include "tiny3d_result.h"

namespace tiny3d {

struct material {
    float diffuse = 1.0f;     // kd ≥ 0: scales n·L
    float specular = 0.0f;    // ks ≥ 0: the highlight's peak (where n = h), per unit intensity
    float shininess = 32.0f;  // s ≥ 1: the highlight's sharpness; its area shrinks about as 1/s
};

// True when m is the plain Lambert model (kd = 1, ks = 0): nothing but the diffuse term.
inline bool material_is_lambert(const material &m) { return m.diffuse == 1.0f && m.specular == 0.0f; }

// Checks a material: every field finite, diffuse and specular ≥ 0, shininess ≥ 1. The error
// names the field and its value.
status check_material(const material &m);

// Where V points: towards a finite eye position (perspective), or one fixed direction (an
// orthographic view, whose eye is at infinity).
struct viewer {
    vec3_t eye{0, 0, 0};           // world space (perspective)
    vec3_t direction{0, 0, 1};     // unit, towards the viewer (orthographic)
    bool at_infinity = false;

    // Unit V at world point p ((0, 0, 0) at the eye itself).
    vec3_t toward_eye(vec3_t p) const { return at_infinity ? direction : unit_or_zero(eye - p); }
};

// The viewer of a world → clip matrix (projection · view): its centre of projection C is
// the null vector of the matrix's x, y and w rows (the point every view ray passes through,
// Hartley & Zisserman §6.2.1), found in double by cofactors. A finite C is the eye; C at
// infinity (w = 0, an orthographic or other parallel projection) gives the direction, its
// sign chosen so that moving along it lowers the depth (towards the near plane). A singular
// matrix (no unique centre) gives the default viewer: direction (0, 0, 1) at infinity.
viewer viewer_of(const mat4_t &view_projection);

// I above at point p with UNIT normal n ((0, 0, 0): ambient only). Inline: the per-pixel
// core of specular Phong shading.
inline float shade_point_material(const light_rig &rig, const material &mat, const viewer &eye, vec3_t p,
                                  vec3_t unit_normal) {
    const vec3_t v = eye.toward_eye(p);
    float sum = rig.ambient;
    for (int i = 0; i < rig.count; ++i) {
        const light_t &l = rig.lights[i];
        const vec3_t to_light = l.kind == light_kind::point ? unit_or_zero(l.position - p) : l.direction;
        const float cosine = vec3_dot(unit_normal, to_light);
        if (!(cosine > 0.0f)) continue;
        float term = mat.diffuse * cosine;
        const float n_dot_h = vec3_dot(unit_normal, unit_or_zero(to_light + v));
        if (n_dot_h > 0.0f) term += mat.specular * std::pow(n_dot_h, mat.shininess);
        sum += l.intensity * term;
    }
    return clamp01(sum);
}

// Flat: one value per triangle a, b, c (counter-clockwise from the front), with its
// geometric normal at its centroid (V from the centroid); degenerate: ambient only.
float shade_flat_material(const light_rig &rig, const material &mat, const viewer &eye, vec3_t a, vec3_t b, vec3_t c);

}  // namespace tiny3d

#endif
