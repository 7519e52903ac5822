// raster_context_test.cpp — the render context's filled drawing: perspective-correct uv
// against the analytic value, back-face culling, near-plane clipping against a
// double-precision ray cast, thread-count invariance, texture sampling, transparency.
#include <cmath>
#include <cstring>
#include <new>
#include <random>
#include <thread>
#include <vector>

#include "harness.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "pipeline.h"
#include "raster.h"
#include "raster_test_util.h"

using namespace tiny3d;
using raster_test::constant_light;
using raster_test::draw_frame;
using raster_test::slanted_quad;

TEST(perspective_correct_uv_matches_the_analytic_value) {
    constexpr int S = 256;
    const slanted_quad quad;
    double worst_persp = 0, worst_affine = 0;
    int samples = 0;
    for (bool perspective : {true, false}) {
        canvas_ptr c = make_canvas(S, S).value();
        render_context ctx(1);
        CHECK(draw_frame(ctx, *c, quad.mesh, quad.params(perspective)).ok());
        for (int y = 4; y < S - 4; y += 5)
            for (int x = 4; x < S - 4; x += 5) {
                double u;
                if (!slanted_quad::exact_u(x, y, S, 0.95, u)) continue;  // keep off the quad's edges
                const double err = std::fabs(c->pixels[y][x] - u);
                if (perspective) {
                    worst_persp = std::max(worst_persp, err);
                    ++samples;
                } else {
                    worst_affine = std::max(worst_affine, err);
                }
            }
    }
    CHECK(samples > 100);
    CHECK_NEAR(worst_persp, 0.0, 1e-3);
    CHECK(worst_affine > 0.05);  // affine mapping is visibly wrong on this slanted quad
}

TEST(backface_culling_removes_exactly_the_clockwise_ones) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> pos(-1.0f, 1.0f);
    raster_mesh m;
    int clockwise = 0;
    for (int k = 0; k < 200; ++k) {
        vec3_t a{pos(rng), pos(rng), -3}, b{pos(rng), pos(rng), -3}, c{pos(rng), pos(rng), -3};
        // Orientation as seen by the camera (x right, y up): cross z of (b − a) × (c − a).
        const double cz = static_cast<double>(b.x - a.x) * (c.y - a.y) - static_cast<double>(b.y - a.y) * (c.x - a.x);
        if (std::fabs(cz) < 1e-3) continue;  // keep clear of degenerate snapping
        clockwise += cz < 0;
        const std::uint32_t i = static_cast<std::uint32_t>(m.positions.size());
        m.positions.insert(m.positions.end(), {a, b, c});
        m.triangles.push_back({i, i + 1, i + 2});
    }
    m.normals.assign(m.positions.size(), {0, 0, 1});
    m.uvs.assign(m.positions.size(), {0, 0});
    m.bound_center = {0, 0, -3};
    m.bound_radius = 2;
    canvas_ptr c = make_canvas(256, 256).value();
    render_context ctx(1);
    draw_params p;
    p.model = mat4_identity();
    p.view_projection = mat4_perspective(static_cast<float>(M_PI / 2), 1.0f, 0.1f, 100.0f);
    p.lights = constant_light(0.5f);
    CHECK(draw_frame(ctx, *c, m, p).ok());
    CHECK_EQ(ctx.stats().culled_backface, static_cast<std::size_t>(clockwise));
    CHECK_EQ(ctx.stats().rasterized, m.triangles.size() - clockwise);
}

TEST(vertex_behind_the_camera_renders_only_the_visible_part) {
    constexpr int S = 96;
    const double near_plane = 0.1;
    raster_mesh m;
    // One vertex far in front, two behind the camera (z > 0), one of them off to the side.
    m.positions = {{0.0f, -0.5f, -4.0f}, {1.5f, 0.8f, 2.0f}, {-1.0f, 0.3f, 1.0f}};
    m.normals.assign(3, {0, 0, 1});
    m.uvs.assign(3, {0, 0});
    m.triangles = {{0, 1, 2}};
    m.bound_center = {0, 0, 0};
    m.bound_radius = 5;
    canvas_ptr c = make_canvas(S, S).value();
    render_context ctx(1);
    draw_params p;
    p.model = mat4_identity();
    p.view_projection = mat4_perspective(static_cast<float>(M_PI / 2), 1.0f, static_cast<float>(near_plane), 100.0f);
    p.lights = constant_light(1.0f);
    p.cull = cull_mode::none;
    CHECK(draw_frame(ctx, *c, m, p).ok());
    CHECK_EQ(ctx.stats().clipped, std::size_t{1});
    // Double-precision ray cast (Möller–Trumbore) per pixel centre: hit with −z ≥ near.
    auto sub = [](vec3_t a, vec3_t b) { return std::array<double, 3>{a.x - b.x + 0.0, a.y - b.y + 0.0, a.z - b.z + 0.0}; };
    auto crs = [](std::array<double, 3> a, std::array<double, 3> b) {
        return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    auto dt = [](std::array<double, 3> a, std::array<double, 3> b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    const auto e1 = sub(m.positions[1], m.positions[0]), e2 = sub(m.positions[2], m.positions[0]);
    int covered = 0, wrong = 0;
    for (int y = 0; y < S; ++y)
        for (int x = 0; x < S; ++x) {
            const std::array<double, 3> d{(x + 0.5) / S * 2 - 1, 1 - (y + 0.5) / S * 2, -1};
            const auto pv = crs(d, e2);
            const double det = dt(e1, pv);
            const std::array<double, 3> o{-m.positions[0].x + 0.0, -m.positions[0].y + 0.0, -m.positions[0].z + 0.0};
            const double u = dt(o, pv) / det;
            const auto q = crs(o, e1);
            const double v = dt(d, q) / det, t = dt(e2, q) / det;
            constexpr double MARGIN = 0.02;  // barycentric margin: keep off the edges
            const bool inside = u > MARGIN && v > MARGIN && u + v < 1 - MARGIN && t > near_plane * 1.05;
            const bool outside = u < -MARGIN || v < -MARGIN || u + v > 1 + MARGIN || t < near_plane * 0.95;
            const bool drawn = c->pixels[y][x] > 0.5f;
            covered += drawn;
            if ((inside && !drawn) || (outside && drawn)) ++wrong;
        }
    CHECK(covered > 200);
    CHECK_EQ(wrong, 0);
}

TEST(clip_polygon_against_the_near_plane) {
    clip_vertex in[3];
    in[0].position = {0, 0, 0.5f, 1};    // inside
    in[1].position = {1, 0, -3, -1};     // behind (z < −w)
    in[2].position = {0, 1, 0.5f, 1};    // inside
    for (int k = 0; k < 3; ++k) in[k].attr.fill(static_cast<float>(k));
    clip_vertex out[CLIP_MAX_VERTICES];
    const int n = clip_polygon(in, 3, clip_near, 1.0f, 1, out);
    CHECK_EQ(n, 4);
    for (int k = 0; k < n; ++k) CHECK(out[k].position.z + out[k].position.w >= -1e-6f);
    // Crossing on edge 0→1: d0 = 1.5, d1 = −4 → t = 1.5/5.5.
    CHECK_NEAR(out[1].attr[0], 1.5 / 5.5, 1e-6);
    CHECK_EQ(clip_outcode({NAN, 0, 0, 1}, 1.0f) != 0u, true);
    // All behind: nothing left.
    for (auto &v : in) v.position = {0, 0, -2, -1};
    CHECK_EQ(clip_polygon(in, 3, clip_near, 1.0f, 0, out), 0);
}

TEST(crease_normals_at_180_draw_todays_image_bit_for_bit) {
    // What render draws (per-corner crease normals, --crease 180) against what it drew before
    // (shared vertices with per-position normals), on meshes without repeated positions.
    for (const mesh &m : {make_torus(1.0f, 0.35f, 40, 20), make_icosphere(3)}) {
        mesh plain = m;
        plain.corner_uvs.clear();
        const raster_mesh shared = make_raster_mesh(plain, mesh_vertex_normals(plain)).value();
        plain.corner_normals = mesh_crease_normals(plain, 180.0f);
        const raster_mesh cornered = make_raster_mesh(plain, {}).value();
        for (shading level : {shading::gouraud, shading::phong}) {
            draw_params p = raster_test::scene_s_params();
            p.model = mat4_rotate_xyz(0.7f, 0.3f, 0);
            p.shade = level;
            canvas_ptr a = make_canvas(160, 120).value(), b = make_canvas(160, 120).value();
            render_context ctx(1);
            CHECK(draw_frame(ctx, *a, shared, p).ok());
            CHECK(draw_frame(ctx, *b, cornered, p).ok());
            int differing = 0, lit = 0;
            for (int y = 0; y < 120; ++y)
                for (int x = 0; x < 160; ++x) {
                    differing += a->pixels[y][x] != b->pixels[y][x];
                    lit += a->pixels[y][x] > 0.2f;
                }
            CHECK_EQ(differing, 0);
            CHECK(lit > 1000);
        }
    }
}

// Progress reports (render_context::report_progress): one call per band the caller's thread
// draws, on that thread, counting every thread's bands; the pass ends at its band total; the
// image is the one drawn without reports.
struct progress_log {
    std::thread::id caller = std::this_thread::get_id();
    int calls = 0, last_done = 0, total = 0, off_thread = 0, not_increasing = 0;
    std::size_t triangles = 0;
    static void report(const render_context::progress &p, void *self) {
        progress_log &log = *static_cast<progress_log *>(self);
        log.off_thread += std::this_thread::get_id() != log.caller;
        log.not_increasing += p.bands_done <= log.last_done;
        log.last_done = p.bands_done;
        log.total = p.bands_total;
        log.triangles = p.triangles;
        ++log.calls;
    }
};

TEST(progress_is_reported_per_band_on_the_callers_thread_and_changes_no_pixel) {
    const raster_mesh sphere = make_raster_mesh(make_icosphere(3), {}).value();
    draw_params p = raster_test::scene_s_params();
    for (sample_count samples : {sample_count::x1, sample_count::x4})
        for (int threads : {1, 2}) {
            canvas_ptr quiet = make_canvas(96, 200).value(), reported = make_canvas(96, 200).value();
            render_context plain(threads), watched(threads);
            progress_log log;
            watched.report_progress(&progress_log::report, &log);
            CHECK(draw_frame(plain, *quiet, sphere, p, 0.0f, samples).ok());
            CHECK(draw_frame(watched, *reported, sphere, p, 0.0f, samples).ok());
            int differing = 0;
            for (int y = 0; y < 200; ++y)
                for (int x = 0; x < 96; ++x) differing += quiet->pixels[y][x] != reported->pixels[y][x];
            CHECK_EQ(differing, 0);
            CHECK(log.calls >= 1);
            CHECK(log.total >= 2);  // 200 rows make several bands
            CHECK(log.calls <= log.total + 1);
            if (threads == 1) CHECK_EQ(log.calls, log.total);  // every band is the caller's
            CHECK_EQ(log.off_thread, 0);
            CHECK_EQ(log.not_increasing, 0);
            CHECK_MSG(log.triangles == sphere.triangles.size(), std::to_string(log.triangles) + " triangles reported");
            CHECK_EQ(log.last_done, log.total);  // the pass's end is reported, whoever drew the last band
        }
}

TEST(two_threads_give_the_same_image_as_one) {
    mesh torus = make_torus(1.0f, 0.35f, 40, 20);
    const std::vector<vec3_t> normals = mesh_vertex_normals(torus);
    tiny3d::mesh plain = torus;
    plain.corner_uvs.clear();
    const raster_mesh shared = make_raster_mesh(plain, normals).value();
    const raster_mesh cornered = make_raster_mesh(torus, {}).value();
    texture checker;
    checker.width = checker.height = 8;
    for (int i = 0; i < 64; ++i) checker.texels.push_back(((i + i / 8) % 2) ? 1.0f : 0.3f);
    light_t lights[2] = {{{1, 1, 1}, 0.8f}, {{-1, 0, 0.5f}, 0.3f}};
    const light_rig rig = make_light_rig(lights, 0.1f).value();
    std::vector<float> images[3];
    frame_stats stats[3];
    for (int threads = 1; threads <= 3; ++threads) {
        canvas_ptr c = make_canvas(257, 193).value();
        render_context ctx(threads);
        for (int frame = 0; frame < 2; ++frame) {
            CHECK(ctx.begin_frame(*c, 0.05f).ok());
            draw_params p;
            p.view_projection = mat4_multiply(mat4_perspective(0.8f, 257.0f / 193, 0.1f, 50),
                                              mat4_look_at({0, 0.5f, 3}, {0, 0, 0}, {0, 1, 0}));
            p.lights = rig;
            const shading levels[3] = {shading::flat, shading::gouraud, shading::phong};
            for (int k = 0; k < 3; ++k) {
                p.model = mat4_multiply(mat4_translate(-1.2f + 1.2f * k, 0, -0.5f * k), mat4_rotate_xyz(0.7f, 0.3f * frame, 0));
                p.shade = levels[k];
                ctx.draw(shared, p);
            }
            p.model = mat4_multiply(mat4_translate(0, 0.6f, 0.8f), mat4_rotate_xyz(1.2f, 0, 0));
            p.tex = &checker;
            p.shade = shading::gouraud;
            ctx.draw(cornered, p);
            p.alpha = 0.5f;
            p.model = mat4_multiply(mat4_translate(0.3f, -0.4f, 1.2f), mat4_rotate_xyz(0.2f, 0.5f, 0));
            ctx.draw(cornered, p);
            // Through the near plane and beyond the guard band: clipped triangles.
            p.tex = nullptr;
            p.alpha = 1.0f;
            p.model = mat4_multiply(mat4_translate(0.2f, 0, 2.6f), mat4_rotate_xyz(1.4f, 0.2f * frame, 0));
            ctx.draw(shared, p);
            ctx.end_frame();
        }
        images[threads - 1].assign(c->data, c->data + 257 * 193);
        stats[threads - 1] = ctx.stats();
    }
    CHECK(images[0] == images[1]);
    CHECK(images[0] == images[2]);
    CHECK(stats[0].clipped > 0);
    for (int k = 1; k < 3; ++k) {  // every triangle counted once, whatever thread handled it
        CHECK_EQ(stats[k].triangles_in, stats[0].triangles_in);
        CHECK_EQ(stats[k].culled_backface, stats[0].culled_backface);
        CHECK_EQ(stats[k].clipped, stats[0].clipped);
        CHECK_EQ(stats[k].rasterized, stats[0].rasterized);
    }
    double sum = 0;
    for (float v : images[0]) sum += v;
    CHECK(sum > 257 * 193 * 0.1);  // something was drawn
}

TEST(translucent_layers_blend_back_to_front) {
    raster_mesh quad;
    quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    quad.normals.assign(4, {0, 0, 1});
    quad.uvs.assign(4, {0, 0});
    quad.triangles = {{0, 1, 2}, {0, 2, 3}};
    quad.bound_radius = 1.5f;
    canvas_ptr c = make_canvas(32, 32).value();
    render_context ctx(2);
    CHECK(ctx.begin_frame(*c, 0.2f).ok());
    draw_params p;
    p.view_projection = mat4_perspective(static_cast<float>(M_PI / 2), 1, 0.1f, 10);
    p.alpha = 0.5f;
    // Submitted front first: the back one must still be blended first.
    p.model = mat4_translate(0, 0, -2);
    p.lights = constant_light(1.0f);
    ctx.draw(quad, p);
    p.model = mat4_translate(0, 0, -3);
    p.lights = constant_light(0.6f);
    ctx.draw(quad, p);
    ctx.end_frame();
    const double back = 0.5 * 0.6 + 0.5 * 0.2, front = 0.5 * 1.0 + 0.5 * back;
    CHECK_NEAR(c->pixels[16][16], front, 1e-6);
    CHECK_NEAR(ctx.depth().at(16, 16), 1.0, 0.0);  // translucent draws do not write depth
}

TEST(texture_sampling_nearest_bilinear_wrap_clamp) {
    texture t;
    t.width = 2;
    t.height = 2;
    t.texels = {0.0f, 1.0f, 0.5f, 0.25f};
    CHECK_EQ(texture_sample(t, 0.25f, 0.25f, texture_filter::nearest, texture_wrap::repeat), 0.0f);
    CHECK_EQ(texture_sample(t, 0.75f, 0.75f, texture_filter::nearest, texture_wrap::repeat), 0.25f);
    CHECK_EQ(texture_sample(t, 1.75f, -0.25f, texture_filter::nearest, texture_wrap::repeat), 0.25f);
    CHECK_EQ(texture_sample(t, 5.0f, 0.25f, texture_filter::nearest, texture_wrap::clamp), 1.0f);
    // Bilinear at the centre of the four texel centres: their mean.
    CHECK_NEAR(texture_sample(t, 0.5f, 0.5f, texture_filter::bilinear, texture_wrap::clamp), 0.4375, 1e-6);
    // Clamp: left of the first centre holds the edge texels; repeat wraps to the far column.
    CHECK_NEAR(texture_sample(t, 0.0f, 0.25f, texture_filter::bilinear, texture_wrap::clamp), 0.0, 1e-6);
    CHECK_NEAR(texture_sample(t, 0.0f, 0.25f, texture_filter::bilinear, texture_wrap::repeat), 0.5, 1e-6);
    CHECK_EQ(texture_sample(t, NAN, 0.5f, texture_filter::bilinear, texture_wrap::repeat), 0.0f);
    CHECK_EQ(texture_sample(t, 1e30f, 0.5f, texture_filter::nearest, texture_wrap::repeat) >= 0.0f, true);
}

// `draw_params p;` must not leave the matrices to whatever the memory held: a draw that sets
// only view_projection draws the mesh where it is (a default model of garbage drew a
// different frame now and then, which tests/alloc_failure_test.cpp caught).
TEST(draw_params_default_to_identity_matrices) {
    alignas(tiny3d::draw_params) unsigned char memory[sizeof(tiny3d::draw_params)];
    std::memset(memory, 0x7f, sizeof memory);
    tiny3d::draw_params *p = new (memory) tiny3d::draw_params;  // default-initialised
    for (int i = 0; i < 16; ++i) {
        const float identity = i % 5 == 0 ? 1.0f : 0.0f;  // column-major diagonal: 0, 5, 10, 15
        CHECK(p->model.m[i] == identity);
        CHECK(p->view_projection.m[i] == identity);
    }
    p->~draw_params();
}
