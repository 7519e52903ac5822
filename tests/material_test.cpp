// material_test.cpp — Blinn-Phong materials (material.h): the viewer found from a
// projection, the per-point formula against a double-precision evaluation, rendered
// spheres against the analytic sphere lit in double (per pixel, per vertex, per face), the
// highlight where n = h and its area shrinking as 1/s, the default material being the
// Lambert model exactly, and bad materials refused.
#include <cmath>
#include <random>
#include <vector>

#include "harness.h"
#include "canvas.h"
#include "lighting.h"
#include "material.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"
#include "raster_test_util.h"
#include "analytic_sphere.h"

using namespace tiny3d;

namespace {

using namespace analytic_sphere;

constexpr int S = 160;
const dvec camera_eye = {0.4, 0.6, 3.2};

draw_params sphere_view(shading level, const material &m, const light_rig &rig) {
    draw_params p;
    p.model = mat4_identity();
    p.view_projection = mat4_multiply(mat4_perspective(0.8f, 1.0f, 0.5f, 10.0f),
                                      mat4_look_at({float(camera_eye.x), float(camera_eye.y), float(camera_eye.z)},
                                                   {0, 0, 0}, {0, 1, 0}));
    p.lights = rig;
    p.shade = level;
    p.surface = m;
    p.cull = cull_mode::back;
    return p;
}

light_rig key_light(float ambient) {
    const light_t l = {{-0.5f, 0.7f, 1.0f}, 0.8f};
    return make_light_rig(std::span<const light_t>(&l, 1), ambient).value();
}

bool sphere_hit(const mat4_t &view_projection, int x, int y, double margin, dvec &hit) {
    return analytic_sphere::sphere_hit(mat4_inverse(view_projection).value(), camera_eye, S, x, y, margin, hit);
}

image_error against_analytic(const canvas_t &c, const draw_params &p) {
    return analytic_sphere::against_analytic(c, p.view_projection, camera_eye, p.lights, p.surface);
}

canvas_ptr draw_sphere(const raster_mesh &sphere, const draw_params &p) {
    canvas_ptr c = make_canvas(S, S).value();
    render_context ctx(1);
    CHECK(raster_test::draw_frame(ctx, *c, sphere, p).ok());
    return c;
}

}  // namespace

TEST(viewer_of_finds_the_eye_and_the_parallel_direction) {
    const vec3_t eye = {1.5f, -2.0f, 3.0f};
    const mat4_t view = mat4_look_at(eye, {0.2f, 0.1f, -0.3f}, {0, 1, 0});
    const viewer v = viewer_of(mat4_multiply(mat4_perspective(0.9f, 1.3f, 0.1f, 100.0f), view));
    CHECK(!v.at_infinity);
    CHECK_NEAR(v.eye.x, 1.5, 1e-4);
    CHECK_NEAR(v.eye.y, -2.0, 1e-4);
    CHECK_NEAR(v.eye.z, 3.0, 1e-4);
    // glOrtho-style box: V is the direction from the target back to the eye, everywhere.
    mat4_t ortho = mat4_identity();
    ortho.m[0] = 0.5f, ortho.m[5] = 0.5f, ortho.m[10] = -0.2f, ortho.m[14] = -1.0f;
    const viewer o = viewer_of(mat4_multiply(ortho, view));
    CHECK(o.at_infinity);
    const dvec back = unit(wide(eye) - dvec{0.2, 0.1, -0.3});
    CHECK_NEAR(dot(wide(o.direction), back), 1.0, 1e-6);
    CHECK_NEAR(dot(wide(o.toward_eye({5, 5, 5})), back), 1.0, 1e-6);
    // Singular: no centre at all.
    mat4_t zero{};
    CHECK(viewer_of(zero).at_infinity);
}

TEST(shade_point_material_matches_double_precision) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1, 1);
    light_t lights[3] = {{{-0.5f, 0.7f, 1.0f}, 0.5f}, {{1, 0.2f, 0.3f}, 0.3f}, {{0, 0, 0}, 0.4f}};
    lights[2].kind = light_kind::point;
    lights[2].position = {2, 3, 4};
    const light_rig rig = make_light_rig(lights, 0.05f).value();
    const viewer eye = {{0.3f, 0.4f, 3.0f}, {0, 0, 1}, false};
    int lit = 0;
    for (const material m : {material{0.7f, 0.5f, 8.0f}, material{1.0f, 0.3f, 64.0f}, material{0.2f, 1.0f, 500.0f}}) {
        double worst = 0;
        for (int i = 0; i < 20000; ++i) {
            const vec3_t n = vec3_normalize({u(rng), u(rng), u(rng)});  // on the unit sphere
            const float got = shade_point_material(rig, m, eye, n, n);
            const double want = blinn_phong(rig, m, wide(eye.eye), false, wide(n), wide(n));
            worst = std::max(worst, std::fabs(got - want));
            lit += want > 0.06;
        }
        // Float rounding of n·h (a few 1e-8) grows s-fold in (n·h)^s.
        const double bound = 2e-6 + 1e-7 * m.shininess;
        CHECK_MSG(worst < bound, "s " + std::to_string(m.shininess) + ": " + std::to_string(worst * 1e6) + "e-6");
    }
    CHECK(lit > 20000);
}

TEST(the_default_material_is_the_lambert_model_bit_for_bit) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-2, 2);
    light_t lights[2] = {{{-0.5f, 0.7f, 1.0f}, 0.6f}, {{0, 0, 0}, 0.4f}};
    lights[1].kind = light_kind::point;
    lights[1].position = {1, 3, 2};
    const light_rig rig = make_light_rig(lights, 0.1f).value();
    const viewer eye = {{0, 0, 5}, {0, 0, 1}, false};
    int differing = 0;
    for (int i = 0; i < 10000; ++i) {
        const vec3_t p = {u(rng), u(rng), u(rng)}, n = vec3_normalize({u(rng), u(rng), u(rng)});
        differing += shade_point_material(rig, material{}, eye, p, n) != shade_point(rig, p, n);
    }
    CHECK_EQ(differing, 0);
    CHECK(material_is_lambert(material{}));
    CHECK(!material_is_lambert(material{1.0f, 0.1f, 32.0f}));
    CHECK(!material_is_lambert(material{0.5f, 0.0f, 32.0f}));
}

TEST(phong_gouraud_flat_spheres_against_the_analytic_sphere) {
    // A finely tessellated sphere, smooth normals; the highlight (s = 30) and the diffuse
    // term against the exact sphere lit in double. Per pixel is close; per vertex smears
    // the highlight; per face is faceted. Bounds: about twice the measured mean / max
    // (intensity 0..1): per pixel 0.00046 / 0.0036, per vertex 0.00096 / 0.030, per face
    // 0.0073 / 0.064.
    const raster_mesh sphere = raster_test::smooth_raster_mesh(make_uv_sphere(96, 48));
    const material plastic = {0.8f, 0.6f, 30.0f};
    const struct {
        shading level;
        double mean_bound, max_bound;
    } cases[] = {{shading::phong, 0.001, 0.008}, {shading::gouraud, 0.002, 0.06}, {shading::flat, 0.015, 0.13}};
    for (const auto &c : cases) {
        const draw_params p = sphere_view(c.level, plastic, key_light(0.1f));
        const canvas_ptr img = draw_sphere(sphere, p);
        const image_error e = against_analytic(*img, p);
        CHECK(e.pixels > S * S / 8);
        CHECK_MSG(e.mean < c.mean_bound && e.max < c.max_bound,
                  "level " + std::to_string(int(c.level)) + ": mean " + std::to_string(e.mean) + " max " + std::to_string(e.max));
    }
    // The same view lit as if the eye were straight ahead (a wrong V) is far off: the test
    // tells where V points.
    draw_params wrong = sphere_view(shading::phong, plastic, key_light(0.1f));
    const canvas_ptr img = draw_sphere(sphere, wrong);
    double far_off = 0;
    for (int y = 0; y < S; ++y)
        for (int x = 0; x < S; ++x) {
            dvec hit;
            if (!sphere_hit(wrong.view_projection, x, y, 0.02, hit)) continue;
            far_off = std::max(far_off, std::fabs(img->pixels[y][x] -
                                                  blinn_phong(wrong.lights, plastic, {0, 0, 1}, true, hit, hit)));
        }
    CHECK(far_off > 0.1);
}

TEST(the_highlight_is_where_n_equals_h_and_shrinks_as_one_over_s) {
    const raster_mesh sphere = raster_test::smooth_raster_mesh(make_uv_sphere(128, 64));
    double previous_area = 0;
    for (float s : {25.0f, 50.0f, 100.0f, 200.0f}) {
        const draw_params p = sphere_view(shading::phong, material{0.0f, 1.0f, s}, key_light(0.0f));
        const canvas_ptr img = draw_sphere(sphere, p);
        // The brightest pixel: there the sphere's normal is the half vector.
        int bx = 0, by = 0, area = 0;
        for (int y = 0; y < S; ++y)
            for (int x = 0; x < S; ++x) {
                if (img->pixels[y][x] > img->pixels[by][bx]) bx = x, by = y;
                area += img->pixels[y][x] >= 0.5f * 0.8f;  // at least half the peak (intensity 0.8)
            }
        dvec hit;
        CHECK(sphere_hit(p.view_projection, bx, by, 0.0, hit));
        const dvec h = unit(unit(wide(p.lights.lights[0].direction)) + unit(camera_eye - hit));
        const double degrees = std::acos(std::min(1.0, dot(hit, h))) * 180 / M_PI;
        CHECK_MSG(degrees < 1.5, std::to_string(degrees) + " degrees from n = h");
        CHECK_NEAR(img->pixels[by][bx], 0.8, 0.01);
        // Half-peak cap: cos^s θ ≥ 1/2 ⇔ θ² ≈ 2 ln 2 / s, so the area halves as s doubles.
        if (previous_area > 0) CHECK_MSG(previous_area / area > 1.6 && previous_area / area < 2.5,
                                         std::to_string(previous_area) + " -> " + std::to_string(area));
        CHECK(area > 10);
        previous_area = area;
    }
}

TEST(the_context_matches_the_reference_with_a_material) {
    // Every level, the fast and per-pixel paths against render_reference (double precision).
    const raster_mesh sphere = raster_test::smooth_raster_mesh(make_icosphere(3));
    for (shading level : {shading::flat, shading::gouraud, shading::phong}) {
        const draw_params p = sphere_view(level, material{0.9f, 0.5f, 20.0f}, key_light(0.1f));
        const canvas_ptr img = draw_sphere(sphere, p);
        canvas_ptr ref = make_canvas(S, S).value();
        const reference_draw d{&sphere, p};
        CHECK(render_reference(*ref, std::span<const reference_draw>(&d, 1), 0.0f, 1).ok());
        double mean = 0;
        for (int y = 0; y < S; ++y)
            for (int x = 0; x < S; ++x) mean += std::fabs(img->pixels[y][x] - ref->pixels[y][x]);
        mean /= S * S;
        CHECK_MSG(mean < 0.002, std::to_string(mean));
    }
}

TEST(bad_materials_are_refused_and_draw_nothing) {
    CHECK(check_material(material{}).ok());
    const material bad[] = {{-1.0f, 0.0f, 32.0f}, {1.0f, NAN, 32.0f}, {1.0f, 0.5f, 0.5f}, {1.0f, 0.5f, INFINITY}};
    const raster_mesh sphere = raster_test::smooth_raster_mesh(make_icosphere(2));
    for (const material &m : bad) {
        const status s = check_material(m);
        CHECK(!s.ok());
        CHECK(s.message().find("material") != std::string::npos);
        const canvas_ptr img = draw_sphere(sphere, sphere_view(shading::phong, m, key_light(0.1f)));
        int inked = 0;
        for (int y = 0; y < S; ++y)
            for (int x = 0; x < S; ++x) inked += img->pixels[y][x] != 0.0f;
        CHECK_EQ(inked, 0);
        canvas_ptr ref = make_canvas(S, S).value();
        const reference_draw d{&sphere, sphere_view(shading::phong, m, key_light(0.1f))};
        CHECK(!render_reference(*ref, std::span<const reference_draw>(&d, 1)).ok());
    }
}
