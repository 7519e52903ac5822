// grazing_plane.h — a textured plane seen at a grazing angle, where texture filters differ
// most: a 40 × 40 quad at y = −0.5 under a camera at (0, 0, 0) looking along −z and slightly
// down (60° field of view, square), a 256² checker of 2-texel cells (0.1 and 0.9) repeated
// 20 times (u, v ∈ [0, 20]), with its mipmaps; ambient light 1, flat, no culling. Used by
// tests/texture_filter_test.cpp and the texture rows of tests/bench/antialias.cpp.
#ifndef TINY3D_GRAZING_PLANE_H
#define TINY3D_GRAZING_PLANE_H

#include <cmath>
#include <span>

#include "lighting.h"
#include "math3d.h"
#include "raster.h"

namespace grazing_plane {

struct scene {
    tiny3d::raster_mesh mesh;
    tiny3d::texture tex;
    tiny3d::draw_params params;  // params.tex points at tex: do not copy or move a scene
    scene() = default;
    scene(const scene &) = delete;
    scene &operator=(const scene &) = delete;
};

inline void make(scene &s) {
    constexpr float HALF = 20.0f, REPEAT = 20.0f;
    s.mesh.positions = {{-HALF, -0.5f, 1}, {HALF, -0.5f, 1}, {HALF, -0.5f, 1 - 2 * HALF}, {-HALF, -0.5f, 1 - 2 * HALF}};
    s.mesh.normals.assign(4, vec3_t{0, 1, 0});
    s.mesh.uvs = {{0, 0}, {REPEAT, 0}, {REPEAT, REPEAT}, {0, REPEAT}};
    s.mesh.triangles = {{0, 2, 1}, {0, 3, 2}};  // counter-clockwise seen from above
    s.mesh.bound_center = {0, -0.5f, 1 - HALF};
    s.mesh.bound_radius = HALF * 1.5f;
    s.tex.width = s.tex.height = 256;
    s.tex.texels.clear();
    for (int j = 0; j < 256; ++j)
        for (int i = 0; i < 256; ++i) s.tex.texels.push_back(((i / 2 + j / 2) % 2) ? 0.9f : 0.1f);
    (void)tiny3d::build_mipmaps(s.tex);
    s.params.model = mat4_identity();
    s.params.view_projection =
        mat4_multiply(tiny3d::mat4_perspective(static_cast<float>(60 * M_PI / 180), 1.0f, 0.1f, 100.0f),
                      tiny3d::mat4_look_at({0, 0, 0}, {0, -0.25f, -1}, {0, 1, 0}));
    s.params.lights = tiny3d::make_light_rig(std::span<const light_t>(), 1.0f).value();
    s.params.shade = tiny3d::shading::flat;
    s.params.cull = tiny3d::cull_mode::none;
    s.params.tex = &s.tex;
}

}  // namespace grazing_plane

#endif
