// vertex_transform.h — the render context's vertex stage (internal). In: a vertex_job, plain
// data (the mesh's positions, normals and uvs, the matrices, the lights). Out: every vertex
// to clip space, outcode, snapped screen point (screen_snap.h), window depth and shading (the
// per-pixel path's attributes too). Called by the render context's set-up loop
// (raster/schedule/raster_context.cpp, which makes the job from a draw: make_vertex_job)
// before the raster set-up stage. Not installed. The kernels: a portable reference
// (vertex_transform.cpp) and SSE2 ones (vertex_kernels_sse2.h), chosen in transform_vertices.
#ifndef TINY3D_VERTEX_TRANSFORM_H
#define TINY3D_VERTEX_TRANSFORM_H

#include <cstddef>
#include <cstdint>

#include "lighting.h"
#include "material.h"
#include "pipeline.h"
#include "screen_snap.h"

namespace tiny3d::detail {

// A transformed vertex: what the triangle walk reads, 20 bytes (the clip-space position,
// which only clipping needs, is kept in an array of its own, so that the walk's vertex
// reads and the transform's writes are 2.6× smaller).
struct xvertex {
    std::int32_t snapped_x, snapped_y;  // screen position in 1/2^job.subpixel_bits px, valid when `snapped`
    float depth;                        // window depth (z/w + 1)/2, valid when `snapped`
    float shade;                        // Gouraud intensity (or 0)
    std::uint8_t outcode;
    bool snapped;                       // screen position usable (snap_screen_point succeeded)
};

// Per-vertex attributes of the generic (per-pixel) path, in clip_vertex::attr order.
enum attr_slot { ATTR_PX, ATTR_PY, ATTR_PZ, ATTR_NX, ATTR_NY, ATTR_NZ, ATTR_U, ATTR_V, ATTR_SHADE, ATTR_COUNT };
static_assert(ATTR_COUNT <= CLIP_MAX_ATTRIBUTES);

// One draw's vertex work, as plain data (the vertex stage knows no raster types): the mesh's
// arrays, one entry per vertex (normals and uvs read only when the shading or the per-pixel
// path needs them), and the per-draw constants. The screen points go to transform_vertices'
// arrays.
struct vertex_job {
    const vec3_t *positions;
    const vec3_t *normals;
    const vec2 *uvs;
    mat4_t mvp;           // object → clip (view_projection · model)
    mat4_t model;         // object → world (Gouraud with point lights, the per-pixel path)
    normal_transform nt;  // the model's, for normals
    const light_rig *lights;
    const material *surface;
    int width, height;  // the target's, in pixels
    int subpixel_bits;  // the snapping grid, 1/2^bits px: the frame's sample pattern's (msaa.h)
    bool gouraud, generic;
    bool directional_gouraud;  // Gouraud with directional lights only (no position needed)
    bool material_lit;         // a non-default material: Blinn-Phong per vertex (material.h)
    viewer eye;                // V's origin for material_lit
};

// The vertices one transform() call handles: first..first + count − 1, or list[0..count).
struct vertex_set {
    const std::uint32_t *list;
    std::size_t count;
    std::uint32_t first = 0;
    std::uint32_t operator[](std::size_t k) const { return list ? list[k] : first + static_cast<std::uint32_t>(k); }
};

// ---- the portable reference kernels (the SSE2 ones match them bit for bit) ----

// One vertex: clip = M·p, clip_outcode, and for a vertex not outside the near plane its
// window depth and snapped screen position (clip_to_screen, snap_screen_point).
inline void project_one(const mat4_t &m, vec3_t position, float guard, int width, int height, int subpixel_bits,
                        xvertex &x, vec4_t &clip) {
    clip = mul_point_scalar(m, position);
    x.outcode = static_cast<std::uint8_t>(clip_outcode(clip, guard));
    x.snapped = false;
    if (!(x.outcode & clip_near)) {
        const screen_point p = clip_to_screen(clip, width, height);
        x.depth = p.depth;
        x.snapped = !p.behind && snap_screen_point(p.x, p.y, subpixel_bits, x.snapped_x, x.snapped_y);
    }
}

// The world position of a model-space point (the xyz part of model·(p, 1)): the vertex's for
// lighting, and the flat shading's corners (the render context's set-up).
inline vec3_t world_of(const mat4_t &model, vec3_t p) {
    const vec4_t h = mul_point_scalar(model, p);
    return {h.x, h.y, h.z};
}

// Gouraud intensity of one vertex lit by directional lights only (no position needed).
inline float shade_directional_one(const light_rig &rig, const normal_transform &nt, vec3_t normal) {
    return shade_gouraud_vertex(rig, {0, 0, 0}, apply_normal_transform(nt, normal));
}

// Transforms the vertices `set` of the job: writes vertices[i] and clip[i] (clip-space
// position) for each i of the set, and vertex_attr[i·ATTR_COUNT ..] when job.generic; x/y
// planes of the outcode at |x|, |y| ≤ guard·w. Arrays sized for the mesh's vertex count.
void transform_vertices(const vertex_job &job, float guard, vertex_set set, xvertex *vertices, vec4_t *clip,
                        float *vertex_attr);

}  // namespace tiny3d::detail

#endif
