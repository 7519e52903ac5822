// shading.cpp — the cost of the Blinn-Phong specular term (material.h) against its accuracy:
// a smooth uv sphere (48 × 24 segments) filling a 512² frame, one key light, drawn flat,
// Gouraud (per vertex) and Phong (per pixel), diffuse only (the default material) and with
// a plastic highlight (kd 0.8, ks 0.5, s 30). Time per frame (one thread, median of the
// repeats); error against the analytic sphere lit with the same model in double
// (tests/analytic_sphere.h), in intensity 0..1, over the pixels well inside the
// silhouette. Per-vertex highlights are cheap but smeared across the triangles; per-pixel
// ones follow the surface.
#include <string>
#include <vector>

#include "common/bench.h"
#include "canvas.h"
#include "lighting.h"
#include "material.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"
#include "../analytic_sphere.h"

using namespace tiny3d;

namespace {

constexpr int SIDE = 512;
const analytic_sphere::dvec kEye = {0.4, 0.6, 3.2};

draw_params sphere_params(shading level, const material &m) {
    draw_params p;
    p.model = mat4_identity();
    p.view_projection = mat4_multiply(mat4_perspective(0.8f, 1.0f, 0.5f, 10.0f),
                                      mat4_look_at({float(kEye.x), float(kEye.y), float(kEye.z)}, {0, 0, 0}, {0, 1, 0}));
    const light_t key = {{-0.5f, 0.7f, 1.0f}, 0.8f};
    p.lights = make_light_rig(std::span<const light_t>(&key, 1), 0.1f).value();
    p.shade = level;
    p.surface = m;
    return p;
}

}  // namespace

int main(int argc, char **argv) {
    const bench::options o = bench::parse_options(argc, argv);
    const int repeats = o.quick ? 3 : 41;
    const mesh sphere = make_uv_sphere(48, 24);
    const raster_mesh shape = make_raster_mesh(sphere, mesh_vertex_normals(sphere)).value();
    canvas_ptr frame = make_canvas(SIDE, SIDE).value();
    render_context ctx(1);
    const material plastic = {0.8f, 0.5f, 30.0f};
    struct variant {
        const char *name, *kind;
        shading level;
        material surface;
        const char *note;
    };
    const variant variants[] = {
        {"Gouraud, diffuse only", "faithful", shading::gouraud, material{}, "the default material"},
        {"Phong, diffuse only", "other", shading::phong, material{}, "the default material"},
        {"flat, specular (face centre)", "other", shading::flat, plastic, "faceted"},
        {"Gouraud, specular per vertex", "fast", shading::gouraud, plastic, "highlight smeared"},
        {"Phong, specular per pixel", "fast", shading::phong, plastic, "render's default level"},
    };
    std::vector<bench::row> rows;
    for (const variant &v : variants) {
        const draw_params p = sphere_params(v.level, v.surface);
        const bench::timing t = bench::measure_ns(repeats, 1e6, [&] {
            ctx.begin_frame(*frame, 0.0f).ok();
            ctx.draw(shape, p);
            ctx.end_frame();
            bench::keep(frame->pixels[SIDE / 2][SIDE / 2]);
        });
        const analytic_sphere::image_error e =
            analytic_sphere::against_analytic(*frame, p.view_projection, kEye, p.lights, p.surface);
        rows.push_back({"shading", v.name, v.kind, "ms/frame", t, e.mean, e.max, "abs intensity vs analytic sphere",
                        v.note});
    }
    return bench::report(o, "shading", rows, "Shading a 512^2 sphere: ms per frame vs intensity error");
}
