// vertex_transform.cpp — the render context's vertex stage (see vertex_transform.h): the
// one place that chooses between the portable reference kernels and the SSE2 ones.
#include "vertex_transform.h"

#include "vertex_kernels_sse2.h"  // the SIMD kernels (nothing without SSE2)
#include "../../simd_config.h"

namespace tiny3d::detail {

namespace {

bool directional_only(const light_rig &rig) {
    for (int k = 0; k < rig.count; ++k)
        if (rig.lights[k].kind != light_kind::directional) return false;
    return true;
}

// Position part: project_x4 four vertices at a time where SSE2 is available, project_one
// for the rest.
void project_vertices(const raster_mesh &m, const vertex_job &job, float guard, vertex_set set, xvertex *vertices,
                      vec4_t *clip) {
    std::size_t first = 0;
#ifdef TINY3D_SSE2
    for (; first + 4 <= set.count; first += 4) {
        const std::uint32_t index[4] = {set[first], set[first + 1], set[first + 2], set[first + 3]};
        project_x4(job.mvp, m.positions.data(), index, guard, job.width, job.height, job.subpixel_bits, vertices, clip);
    }
#endif
    for (std::size_t k = first; k < set.count; ++k) {
        const std::uint32_t i = set[k];
        project_one(job.mvp, m.positions[i], guard, job.width, job.height, job.subpixel_bits, vertices[i], clip[i]);
    }
}

// Gouraud with directional lights only: shade_gouraud_x4 four vertices at a time where SSE2
// is available, shade_directional_one for the rest.
void shade_directional(const raster_mesh &m, const draw_params &p, const vertex_job &job, vertex_set set,
                       xvertex *vertices) {
    std::size_t first = 0;
#ifdef TINY3D_SSE2
    for (; first + 4 <= set.count; first += 4) {
        const std::uint32_t index[4] = {set[first], set[first + 1], set[first + 2], set[first + 3]};
        alignas(16) float shade[4];
        shade_gouraud_x4(p.lights, job.nt, m.normals.data(), index, shade);
        for (int l = 0; l < 4; ++l) vertices[index[l]].shade = shade[l];
    }
#endif
    for (std::size_t k = first; k < set.count; ++k)
        vertices[set[k]].shade = shade_directional_one(p.lights, job.nt, m.normals[set[k]]);
}

// Every other shading (flat: 0 here; Gouraud with point lights), and the per-pixel path's
// attributes (world position, unit normal, uv, Gouraud intensity).
void shade_general(const raster_mesh &m, const draw_params &p, const vertex_job &job, vertex_set set,
                   xvertex *vertices, float *vertex_attr) {
    for (std::size_t k = 0; k < set.count; ++k) {
        const std::uint32_t i = set[k];
        xvertex &x = vertices[i];
        vec3_t world{0, 0, 0}, normal{0, 0, 0};
        if (job.gouraud || job.generic) {
            const vec4_t h = mul_point_scalar(p.model, m.positions[i]);
            world = {h.x, h.y, h.z};
            normal = apply_normal_transform(job.nt, m.normals[i]);
        }
        if (!job.gouraud) x.shade = 0.0f;
        else if (job.material_lit) x.shade = shade_point_material(p.lights, p.surface, job.eye, world, unit_or_zero(normal));
        else x.shade = shade_gouraud_vertex(p.lights, world, normal);
        if (job.generic) {
            float *a = &vertex_attr[i * ATTR_COUNT];
            a[ATTR_PX] = world.x, a[ATTR_PY] = world.y, a[ATTR_PZ] = world.z;
            a[ATTR_NX] = normal.x, a[ATTR_NY] = normal.y, a[ATTR_NZ] = normal.z;
            a[ATTR_U] = m.uvs[i].x, a[ATTR_V] = m.uvs[i].y;
            a[ATTR_SHADE] = x.shade;
        }
    }
}

}  // namespace

vertex_job make_vertex_job(const draw_params &p, const mat4_t &mvp, bool generic, int width, int height,
                           int subpixel_bits) {
    vertex_job job;
    job.mvp = mvp;
    job.nt = make_normal_transform(p.model);
    job.width = width;
    job.height = height;
    job.subpixel_bits = subpixel_bits;
    job.gouraud = p.shade == shading::gouraud;
    job.generic = generic;
    job.material_lit = job.gouraud && !material_is_lambert(p.surface);
    job.eye = job.material_lit ? viewer_of(p.view_projection) : viewer{};
    job.directional_gouraud = job.gouraud && !generic && !job.material_lit && directional_only(p.lights);
    return job;
}

void transform_vertices(const raster_mesh &m, const draw_params &p, const vertex_job &job, float guard, vertex_set set,
                        xvertex *vertices, vec4_t *clip, float *vertex_attr) {
    project_vertices(m, job, guard, set, vertices, clip);
    if (job.directional_gouraud) shade_directional(m, p, job, set, vertices);
    else shade_general(m, p, job, set, vertices, vertex_attr);
}

}  // namespace tiny3d::detail
