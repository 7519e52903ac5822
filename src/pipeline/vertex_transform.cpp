// vertex_transform.cpp — the render context's vertex stage (see vertex_transform.h): the
// one place that chooses between the portable reference kernels and the SSE2 ones.
#include "vertex_transform.h"

#include "vertex_kernels_sse2.h"  // the SIMD kernels (nothing without SSE2)
#include "../simd_config.h"

namespace tiny3d::detail {

namespace {

// Position part: project_x4 four vertices at a time where SSE2 is available, project_one
// for the rest.
void project_vertices(const vertex_job &job, float guard, vertex_set set, xvertex *vertices, vec4_t *clip) {
    std::size_t first = 0;
#ifdef TINY3D_SSE2
    for (; first + 4 <= set.count; first += 4) {
        const std::uint32_t index[4] = {set[first], set[first + 1], set[first + 2], set[first + 3]};
        project_x4(job.mvp, job.positions, index, guard, job.width, job.height, job.subpixel_bits, vertices, clip);
    }
#endif
    for (std::size_t k = first; k < set.count; ++k) {
        const std::uint32_t i = set[k];
        project_one(job.mvp, job.positions[i], guard, job.width, job.height, job.subpixel_bits, vertices[i], clip[i]);
    }
}

// Gouraud with directional lights only: shade_gouraud_x4 four vertices at a time where SSE2
// is available, shade_directional_one for the rest.
void shade_directional(const vertex_job &job, vertex_set set, xvertex *vertices) {
    std::size_t first = 0;
#ifdef TINY3D_SSE2
    for (; first + 4 <= set.count; first += 4) {
        const std::uint32_t index[4] = {set[first], set[first + 1], set[first + 2], set[first + 3]};
        alignas(16) float shade[4];
        shade_gouraud_x4(*job.lights, job.nt, job.normals, index, shade);
        for (int l = 0; l < 4; ++l) vertices[index[l]].shade = shade[l];
    }
#endif
    for (std::size_t k = first; k < set.count; ++k)
        vertices[set[k]].shade = shade_directional_one(*job.lights, job.nt, job.normals[set[k]]);
}

// Every other shading (flat: 0 here; Gouraud with point lights), and the per-pixel path's
// attributes (world position, unit normal, uv, Gouraud intensity).
void shade_general(const vertex_job &job, vertex_set set, xvertex *vertices, float *vertex_attr) {
    for (std::size_t k = 0; k < set.count; ++k) {
        const std::uint32_t i = set[k];
        xvertex &x = vertices[i];
        vec3_t world{0, 0, 0}, normal{0, 0, 0};
        if (job.gouraud || job.generic) {
            world = world_of(job.model, job.positions[i]);
            normal = apply_normal_transform(job.nt, job.normals[i]);
        }
        if (!job.gouraud) x.shade = 0.0f;
        else if (job.material_lit) x.shade = shade_point_material(*job.lights, *job.surface, job.eye, world, unit_or_zero(normal));
        else x.shade = shade_gouraud_vertex(*job.lights, world, normal);
        if (job.generic) {
            float *a = &vertex_attr[i * ATTR_COUNT];
            a[ATTR_PX] = world.x, a[ATTR_PY] = world.y, a[ATTR_PZ] = world.z;
            a[ATTR_NX] = normal.x, a[ATTR_NY] = normal.y, a[ATTR_NZ] = normal.z;
            a[ATTR_U] = job.uvs[i].x, a[ATTR_V] = job.uvs[i].y;
            a[ATTR_SHADE] = x.shade;
        }
    }
}

}  // namespace

void transform_vertices(const vertex_job &job, float guard, vertex_set set, xvertex *vertices, vec4_t *clip,
                        float *vertex_attr) {
    project_vertices(job, guard, set, vertices, clip);
    if (job.directional_gouraud) shade_directional(job, set, vertices);
    else shade_general(job, set, vertices, vertex_attr);
}

}  // namespace tiny3d::detail
