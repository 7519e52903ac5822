// raster_test_util.h — helpers shared by the raster tests (and tests/bench/fill.cpp): a
// light rig of ambient light only, Scene S's camera and light, a raster mesh with smooth
// normals, a frame holding one draw, a captured frame and its comparison, and the slanted
// textured quad whose exact u at every pixel centre is known in closed form; a quad
// straight in clip space and flat, constant-light draw parameters for it.
#ifndef TINY3D_RASTER_TEST_UTIL_H
#define TINY3D_RASTER_TEST_UTIL_H

#include <cmath>
#include <cstring>
#include <span>
#include <vector>

#include "mesh.h"
#include "raster.h"

namespace raster_test {

// Shade = ambient everywhere (no directional light).
inline tiny3d::light_rig constant_light(float ambient) {
    return tiny3d::make_light_rig(std::span<const light_t>(), ambient).value();
}

// Scene S's draw parameters (documentation/benchmarks.md): one light towards (1, 1, 1),
// ambient 0.1, a 45° square perspective from (0, 0, 3) looking at the origin; model identity.
inline tiny3d::draw_params scene_s_params() {
    tiny3d::draw_params p;
    const light_t light = {{1, 1, 1}, 1.0f};
    p.lights = tiny3d::make_light_rig(std::span<const light_t>(&light, 1), 0.1f).value();
    p.view_projection = mat4_multiply(tiny3d::mat4_perspective(static_cast<float>(M_PI / 4), 1.0f, 0.1f, 100.0f),
                                      tiny3d::mat4_look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}));
    return p;
}

// m as a raster mesh with its smooth vertex normals.
inline tiny3d::raster_mesh smooth_raster_mesh(const tiny3d::mesh &m) {
    return tiny3d::make_raster_mesh(m, tiny3d::mesh_vertex_normals(m)).value();
}

// One frame with one draw: begin_frame (cleared to `clear_intensity`, `samples` per pixel),
// draw, end_frame. The status is begin_frame's; nothing is drawn when it fails.
inline tiny3d::status draw_frame(tiny3d::render_context &ctx, canvas_t &target, const tiny3d::raster_mesh &mesh,
                                 const tiny3d::draw_params &params, float clear_intensity = 0.0f,
                                 tiny3d::sample_count samples = tiny3d::sample_count::x1) {
    tiny3d::status s = ctx.begin_frame(target, clear_intensity, samples);
    if (!s) return s;
    ctx.draw(mesh, params);
    ctx.end_frame();
    return s;
}

// A quad facing the camera (at the origin looking down −z, 90° field of view, aspect 1):
// y = −1 at z = −1.5, y = 1 at z = −6, x in [−1, 1]; u runs along the depth, u = (y + 1)/2.
// Its texture is a ramp whose bilinear sample is u itself (texel i holds (i + 0.5)/4096)
// and the light is ambient 1, so each pixel shows the u the pipeline interpolated.
struct slanted_quad {
    tiny3d::texture ramp;
    tiny3d::raster_mesh mesh;

    slanted_quad() {
        ramp.width = 4096;
        ramp.height = 1;
        for (int i = 0; i < ramp.width; ++i) ramp.texels.push_back((i + 0.5f) / ramp.width);
        mesh.positions = {{-1, -1, -1.5f}, {1, -1, -1.5f}, {1, 1, -6}, {-1, 1, -6}};
        mesh.normals.assign(4, {0, 0, 1});
        mesh.uvs = {{0, 0}, {0, 0}, {1, 0}, {1, 0}};
        mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
        mesh.bound_center = {0, 0, -3.75f};
        mesh.bound_radius = 3;
    }
    slanted_quad(const slanted_quad &) = delete;  // params() points at this ramp
    slanted_quad &operator=(const slanted_quad &) = delete;

    // Flat shading, the ramp clamped, uv perspective-correct or affine.
    tiny3d::draw_params params(bool perspective_correct) const {
        tiny3d::draw_params p;
        p.model = mat4_identity();
        p.view_projection = tiny3d::mat4_perspective(static_cast<float>(M_PI / 2), 1.0f, 0.1f, 100.0f);
        p.lights = constant_light(1.0f);
        p.shade = tiny3d::shading::flat;
        p.tex = &ramp;
        p.wrap = tiny3d::texture_wrap::clamp;
        p.perspective_correct = perspective_correct;
        return p;
    }

    // The exact u at the centre of pixel (x, y) of a side × side frame: the ray through the
    // centre (direction (dx, dy, −1), tan 45° = 1) meets the quad's plane z = −3.75 − 2.25·y
    // at t = 3.75 / (1 − 2.25·dy). False where the hit lies within 1 − margin of the quad's
    // edges (|x| or |y| > margin) or off it.
    static bool exact_u(int x, int y, int side, double margin, double &u) {
        const double dx = (x + 0.5) / side * 2 - 1, dy = 1 - (y + 0.5) / side * 2;
        const double t = 3.75 / (1 - 2.25 * dy);
        const double hx = t * dx, hy = t * dy;
        if (std::fabs(hx) > margin || std::fabs(hy) > margin) return false;
        u = (hy + 1) / 2;
        return true;
    }
};

// A raster mesh straight in clip space (identity matrices, w = 1): quads over x, y ∈ [x0, x1]
// × [y0, y1] at depth z, uv = (u0 + du·s, v0 + dv·t) for s, t ∈ [0, 1].
inline tiny3d::raster_mesh clip_quad(float x0, float y0, float x1, float y1, float z, float u0, float v0, float du,
                                     float dv) {
    tiny3d::raster_mesh m;
    m.positions = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
    m.normals.assign(4, vec3_t{0, 0, 1});
    m.uvs = {{u0, v0}, {u0 + du, v0}, {u0 + du, v0 + dv}, {u0, v0 + dv}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};  // counter-clockwise seen from +z
    m.bound_center = {(x0 + x1) / 2, (y0 + y1) / 2, z};
    m.bound_radius = std::hypot(x1 - x0, y1 - y0);
    return m;
}

// Flat, constant-light parameters with identity matrices (positions are clip coordinates).
inline tiny3d::draw_params flat_params(float intensity) {
    tiny3d::draw_params p;
    p.model = mat4_identity();
    p.view_projection = mat4_identity();
    p.lights = constant_light(intensity);
    p.shade = tiny3d::shading::flat;
    return p;
}

// A rendered frame: colour, depth and stats.
struct rendered {
    std::vector<float> colour, depth;
    tiny3d::frame_stats stats;
};

// The frame `ctx` last drew into `c`.
inline rendered capture(const tiny3d::render_context &ctx, const canvas_t &c) {
    rendered r;
    const std::size_t n = static_cast<std::size_t>(c.width) * c.height;
    r.colour.assign(c.data, c.data + n);
    r.depth.assign(ctx.depth().row(0), ctx.depth().row(0) + n);
    r.stats = ctx.stats();
    return r;
}

// Bit-identical pixels and depths and equal stats (with `cluster_share`, also the share
// of back faces culled by cluster).
inline bool same_frame(const rendered &a, const rendered &b, bool cluster_share = false) {
    auto bits_equal = [](const std::vector<float> &x, const std::vector<float> &y) {
        return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(float)) == 0;
    };
    return bits_equal(a.colour, b.colour) && bits_equal(a.depth, b.depth) && a.stats.triangles_in == b.stats.triangles_in &&
           a.stats.culled_frustum == b.stats.culled_frustum && a.stats.culled_backface == b.stats.culled_backface &&
           a.stats.clipped == b.stats.clipped && a.stats.rasterized == b.stats.rasterized &&
           (!cluster_share || a.stats.backface_by_cluster == b.stats.backface_by_cluster);
}

}  // namespace raster_test

#endif
