// lighting.h — Lambert lighting (per edge and per face), flat / Gouraud / Phong, lights.
//
// Conventions (pinned by tests/lighting_test.cpp):
//  * light_t::direction points FROM the lit surface TOWARDS the light (the L of Lambert's
//    n·L): a light with direction (0, 0, 1) lights a surface whose normal is +z, i.e. it
//    shines down the −z axis. It need not be unit length.
//  * Normals are outward (counter-clockwise faces seen from outside, as in mesh.h).
//  * Diffuse model (Lambert, with an ambient term), for a point p with unit normal n:
//        I(p, n) = clamp01( ambient + Σ_i intensity_i · max(0, n · L_i(p)) )
//    where L_i = unit(direction_i) for a directional light and unit(position_i − p) for a
//    point light (no distance fall-off). Everything is in one space (normally world space:
//    light positions, surface points and normals all in it).
//  * Results are intensities in 0..1; NaN inputs give 0 (never NaN out).
#ifndef TINY3D_LIGHTING_H
#define TINY3D_LIGHTING_H

#include "math3d.h"
#include "tiny3d_result.h"

// From C (C11) this header declares light_t and lambert_intensity (C linkage) only.
#ifdef __cplusplus
#include <cmath>
#include <span>

namespace tiny3d {
enum class light_kind : int {
    directional = 0,  // parallel light from `direction` (the default: zero-initialised)
    point = 1,        // light at `position`, shining in every direction
};
}  // namespace tiny3d
#define TINY3D_LIGHT_KIND_TYPE tiny3d::light_kind
#else
// C: light_t::kind is an int holding one of these (tiny3d::light_kind's values).
enum { TINY3D_LIGHT_DIRECTIONAL = 0, TINY3D_LIGHT_POINT = 1 };
#define TINY3D_LIGHT_KIND_TYPE int
#endif

// A light. Brace-initialise as other libtiny3d programs do — light_t l = {{dx, dy, dz}, i} —
// for a directional light; set kind = tiny3d::light_kind::point and `position` for a point
// light (its `direction` is then ignored). intensity ≥ 0 scales its n·L term. The last two
// fields have default member initialisers, so the two-field form stays warning-free under
// -Wextra (it is still an aggregate).
typedef struct light_t {
    vec3_t direction;        // towards the light (directional lights)
    float intensity TINY3D_DEFAULT(0);  // ≥ 0 (0 by default, so `light_t l = {0};` compiles as C++)
    TINY3D_LIGHT_KIND_TYPE kind TINY3D_DEFAULT(tiny3d::light_kind::directional);
    vec3_t position TINY3D_DEFAULT({0.0f, 0.0f, 0.0f});  // point lights: where the light is
} light_t;

// ---- the libtiny3d report's API --------------------------------------------------------

// The report's per-edge Lambert, kept as its faithful variant:
//     clamp01( unit(end − start) · unit(light_dir) )
// A zero-length edge or zero light direction gives 0 (no NaN). Known flaw, kept on purpose
// (bench `edge_lighting`, row 'lambert_intensity per edge (report)'): an edge direction
// is not a surface normal and has no preferred sign, so under any light about half of a
// wireframe's edges come out black (and an edge lying along the light is fully lit).
// tiny3d::mesh_edge_normals plus tiny3d::shade_edge is the corrected model.
TINY3D_C_BEGIN
float lambert_intensity(vec3_t start, vec3_t end, vec3_t light_dir);
TINY3D_C_END

#ifdef __cplusplus
namespace tiny3d {

// Most lights a rig holds (a fixed array: a rig is a small value, never allocates).
inline constexpr int MAX_LIGHTS = 8;

// A prepared set of lights plus the ambient term, ready for per-pixel use: directional
// lights' directions are stored unit length. Build with make_light_rig; copy freely.
struct light_rig {
    light_t lights[MAX_LIGHTS];
    int count = 0;
    float ambient = 0.0f;  // 0..1, added before clamping
};

// Checks and prepares lights: at most MAX_LIGHTS, finite values, intensity ≥ 0, ambient in
// 0..1, a directional light's direction non-zero. The error names the light (0-based) and
// the problem.
result<light_rig> make_light_rig(std::span<const light_t> lights, float ambient);

// I(p, n) above for a point p and a UNIT normal n (pass (0, 0, 0) for "no normal": ambient
// only). The per-pixel core: inline, no allocation.
inline float shade_point(const light_rig &rig, vec3_t p, vec3_t unit_normal) {
    float sum = rig.ambient;
    for (int i = 0; i < rig.count; ++i) {
        const light_t &l = rig.lights[i];
        const vec3_t to_light = l.kind == light_kind::point
                                    ? unit_or_zero(l.position - p)
                                    : l.direction;
        const float cosine = vec3_dot(unit_normal, to_light);
        if (cosine > 0.0f) sum += l.intensity * cosine;
    }
    return clamp01(sum);
}

// ---- face lighting for filled rendering (the rasterizer calls these) -------------------

// Flat shading: one value per triangle (a, b, c counter-clockwise seen from the front),
// lit with its geometric normal unit((b − a) × (c − a)) at its centroid. A degenerate
// triangle (zero area) gets the ambient term only.
float shade_flat(const light_rig &rig, vec3_t a, vec3_t b, vec3_t c);

// Gouraud shading: the value at one vertex (position p, vertex normal n of any non-zero
// length; it is normalised here). The rasterizer interpolates these across the triangle.
float shade_gouraud_vertex(const light_rig &rig, vec3_t p, vec3_t normal);

// Phong shading: the value at one pixel from the interpolated (not unit) normal and the
// interpolated surface point. Normalises the normal (one sqrt), then shade_point.
inline float shade_phong_pixel(const light_rig &rig, vec3_t p, vec3_t interpolated_normal) {
    return shade_point(rig, p, unit_or_zero(interpolated_normal));
}

// ---- normals under a model transform ---------------------------------------------------

// The matrix that carries normals from model to world space: the cofactor matrix of the
// model's upper 3×3 (= det · inverse-transpose, sign fixed so normals stay outward when
// the model mirrors). Correct for any invertible linear part, including non-uniform scale.
struct normal_transform {
    float m[9];  // row-major 3×3
};
normal_transform make_normal_transform(mat4_t model);
// unit(N·n), or (0, 0, 0) for a zero / non-finite result.
inline vec3_t apply_normal_transform(const normal_transform &t, vec3_t n) {
    const vec3_t r = {t.m[0] * n.x + t.m[1] * n.y + t.m[2] * n.z,
                      t.m[3] * n.x + t.m[4] * n.y + t.m[5] * n.z,
                      t.m[6] * n.x + t.m[7] * n.y + t.m[8] * n.z};
    return unit_or_zero(r);
}

// ---- edge lighting for wireframes ------------------------------------------------------

enum class edge_lighting {
    faithful_lambert,  // the report's lambert_intensity per edge, summed over lights, no ambient
    face_normals,      // corrected: the edge's normal = mean of its adjacent faces' normals
};

// Intensity of the edge a–b (world space) under the corrected model: shade_point at the
// edge's midpoint with its world-space unit normal (mesh_edge_normals, mesh.h, gives the
// model-space ones once per mesh; an edge with no face has (0, 0, 0) and is lit by the
// ambient term only). With ambient > 0 no edge is ever black.
inline float shade_edge(const light_rig &rig, vec3_t a, vec3_t b, vec3_t unit_edge_normal) {
    return shade_point(rig, (a + b) * 0.5f, unit_edge_normal);
}

// The faithful model over a rig: clamp01( Σ_i intensity_i · lambert_intensity(a, b, L_i) )
// with L_i the light's direction (point lights: from the edge midpoint to the light).
// The ambient term is NOT added (the report had none).
float shade_edge_faithful(const light_rig &rig, vec3_t a, vec3_t b);

}  // namespace tiny3d

#include "compat/lighting_alias.h"  // pins light_t's form other libtiny3d programs use
#endif  // __cplusplus

#endif
