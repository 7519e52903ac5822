// soak_test.cpp — thousands of frames of seeded random scenes through the wireframe path
// (tiny3d::render_wireframe with its workspace) and the filled path (render_context), under
// ASan + UBSan with leak checking in `make test`'s second pass.
//
// Asserted:
//  * every frame succeeds and every pixel stays in 0..1 (finite);
//  * NO allocation per frame in steady state: allocations are counted with the replaced
//    global operator new of alloc_tracker.h; after warm-up (every scene mesh once, then 300
//    random frames: the buffers grow to the largest mesh), 1500 frames per path allocate
//    nothing (at most MAX_LATE_GROWTHS buffer growths, never one per frame);
//  * resident memory flat after warm-up (within RSS_SLACK_BYTES);
//  * the frames are not empty (a soak that draws nothing tests nothing);
//  * leaks: ASan's leak checker at exit (detect_leaks=1 in tests/run_tests.sh).
// Scenes: generator meshes (icosphere, UV sphere, torus, torus knot, cube, soccer ball)
// jittered, plus meshes with a degenerate face, a NaN position and a 1e30 position; random
// rotation, camera distance (sometimes inside the near plane), field of view, line method,
// thickness, depth cue, circular viewport, back-edge hiding, shading, culling, translucency.
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "alloc_tracker.h"
#include "harness.h"
#include "tiny3d.h"

namespace {

constexpr int SIDE = 128;              // px
constexpr int FRAMES_PER_PATH = 1500;  // after warm-up, per path
constexpr int WARMUP_FRAMES = 300;
// Reused buffers may still grow a few times after warm-up when the random scene first hits
// a new largest combination of mesh and options. Anything allocating per frame, even on a
// path taken by a tenth of the frames, makes 150+ allocations.
constexpr std::size_t MAX_LATE_GROWTHS = 4;
constexpr unsigned SEED = 20261123;
constexpr long RSS_SLACK_BYTES = 2L << 20;
constexpr float JITTER = 0.02f;

// One scene mesh, prepared once for both paths (as an application would).
struct scene_mesh {
    tiny3d::mesh mesh;
    tiny3d::edge_adjacency adjacency;
    tiny3d::bounding_sphere bounds;
    tiny3d::raster_mesh raster;
};

scene_mesh prepare(tiny3d::mesh m) {
    tiny3d::mesh_derive_edges(m);
    scene_mesh s;
    s.adjacency = tiny3d::mesh_edge_faces(m);
    s.bounds = tiny3d::mesh_bounding_sphere(m);
    tiny3d::result<tiny3d::raster_mesh> r = tiny3d::make_raster_mesh(m, tiny3d::mesh_vertex_normals(m));
    CHECK_MSG(r.ok(), r.message());
    if (r.ok()) s.raster = std::move(r.value());
    s.mesh = std::move(m);
    return s;
}

std::vector<scene_mesh> make_scene_meshes(std::mt19937 &rng) {
    std::uniform_real_distribution<float> jitter(-JITTER, JITTER);
    std::vector<tiny3d::mesh> base = {tiny3d::make_icosphere(2),          tiny3d::make_uv_sphere(16, 10),
                                      tiny3d::make_torus(1.0f, 0.35f, 18, 8), tiny3d::make_torus_knot(2, 3, 40, 6),
                                      tiny3d::make_cube(),                  tiny3d::make_soccer_ball()};
    for (tiny3d::mesh &m : base)
        for (vec3_t &p : m.positions) p += vec3_t{jitter(rng), jitter(rng), jitter(rng)};
    // Hostile variants: a degenerate face (repeated corner), a NaN and a far-off position.
    tiny3d::mesh degenerate = tiny3d::make_icosphere(1);
    degenerate.add_face({0, 0, 1});
    degenerate.add_face({2, 3, 2});
    tiny3d::mesh with_nan = tiny3d::make_uv_sphere(12, 8);
    with_nan.positions[5].y = std::numeric_limits<float>::quiet_NaN();
    tiny3d::mesh with_huge = tiny3d::make_torus(1.0f, 0.3f, 12, 6);
    with_huge.positions[7] = {1e30f, -1e30f, 1e30f};
    base.push_back(std::move(degenerate));
    base.push_back(std::move(with_nan));
    base.push_back(std::move(with_huge));
    std::vector<scene_mesh> out;
    for (tiny3d::mesh &m : base) out.push_back(prepare(std::move(m)));
    return out;
}

// A random camera: view · projection for a mesh at the origin.
mat4_t random_view_projection(std::mt19937 &rng) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float distance = 0.3f + 6.0f * unit(rng);  // sometimes inside the mesh / near plane
    const float theta = 6.2831853f * unit(rng), phi = 0.2f + 2.7f * unit(rng);
    const vec3_t eye = vec3_from_spherical(distance, theta, phi);
    const mat4_t view = tiny3d::mat4_look_at(eye, {0, 0, 0}, {0, 0, 1});
    const mat4_t proj = tiny3d::mat4_perspective(0.5f + 1.2f * unit(rng), 1.0f, 0.1f + 0.4f * unit(rng), 30.0f);
    return mat4_multiply(proj, view);
}

mat4_t random_model(std::mt19937 &rng) {
    std::uniform_real_distribution<float> angle(-3.1415927f, 3.1415927f), scale(0.5f, 1.5f);
    const float s = scale(rng);
    return mat4_multiply(mat4_rotate_xyz(angle(rng), angle(rng), angle(rng)), mat4_scale(s, s, s));
}

bool pixels_in_range(const canvas_t &c) {
    for (int i = 0; i < c.width * c.height; ++i)
        if (!(c.data[i] >= 0.0f && c.data[i] <= 1.0f)) return false;
    return true;
}

double ink(const canvas_t &c) {
    double s = 0;
    for (int i = 0; i < c.width * c.height; ++i) s += c.data[i];
    return s;
}

long resident_bytes() {
    std::ifstream statm("/proc/self/statm");
    long pages_total = 0, pages_resident = 0;
    statm >> pages_total >> pages_resident;
    return pages_resident * ::sysconf(_SC_PAGESIZE);
}

// Runs warm-up (every mesh once) then `frames` random frames of `render(mesh, rng)`;
// checks each frame and the allocation count of the steady state.
template <class Render>
void soak(const char *path, std::vector<scene_mesh> &meshes, canvas_t &canvas, Render &&render) {
    std::mt19937 rng(SEED);
    std::uniform_int_distribution<std::size_t> pick(0, meshes.size() - 1);
    // Warm-up: every mesh once, then random frames until every option combination has met
    // the largest meshes (buffers grow to their final size here, once).
    for (scene_mesh &m : meshes) CHECK_MSG(render(m, rng), std::string(path) + ": warm-up frame failed");
    for (int f = 0; f < WARMUP_FRAMES; ++f) CHECK(render(meshes[pick(rng)], rng));
    const long rss_before = resident_bytes();  // (reading /proc allocates: outside the count)
    const std::size_t allocations_before = alloc_tracker::allocations();
    int failed = 0, out_of_range = 0, empty = 0, allocating_frames = 0;
    for (int f = 0; f < FRAMES_PER_PATH; ++f) {
        const std::size_t before = alloc_tracker::allocations();
        const std::size_t mesh_index = pick(rng);
        failed += !render(meshes[mesh_index], rng);
        if (alloc_tracker::allocations() != before && allocating_frames++ < 3)
            std::printf("%s: frame %d (mesh %zu) allocated %zu times\n", path, f, mesh_index,
                        alloc_tracker::allocations() - before);
        out_of_range += !pixels_in_range(canvas);
        empty += ink(canvas) == 0.0;
    }
    const std::size_t allocations = alloc_tracker::allocations() - allocations_before;
    const long rss_growth = resident_bytes() - rss_before;
    std::printf("%s: %d frames, %zu allocations after warm-up, %d empty frames, RSS growth %ld bytes\n", path,
                FRAMES_PER_PATH, allocations, empty, rss_growth);
    CHECK_EQ(failed, 0);
    CHECK_EQ(out_of_range, 0);
    CHECK_MSG(allocations <= MAX_LATE_GROWTHS, std::to_string(allocations) + " allocations in steady state");
    CHECK_MSG(rss_growth < RSS_SLACK_BYTES, std::to_string(rss_growth) + " bytes of RSS growth");
    CHECK_MSG(empty < FRAMES_PER_PATH / 2, std::to_string(empty) + " empty frames");
}

}  // namespace

TEST(wireframe_path_soak_without_allocation) {
    std::mt19937 scene_rng(SEED);
    std::vector<scene_mesh> meshes = make_scene_meshes(scene_rng);
    tiny3d::canvas_ptr canvas = std::move(tiny3d::make_canvas(SIDE, SIDE).value());
    tiny3d::wireframe_workspace workspace;
    soak("wireframe", meshes, *canvas, [&](const scene_mesh &m, std::mt19937 &rng) {
        std::uniform_int_distribution<int> coin(0, 1), three(0, 2);
        canvas_clear(canvas.get(), 0.0f);
        tiny3d::wireframe_options o;
        const int pick = three(rng);  // tabulated: the workspace keeps one table per thickness
        o.method = pick == 0   ? tiny3d::line_method::coverage
                   : pick == 1 ? tiny3d::line_method::tabulated
                               : tiny3d::line_method::faithful;
        o.thickness = three(rng) == 0 ? 1.0f : three(rng) == 1 ? 1.5f : 2.5f;
        o.depth_cue = coin(rng);
        o.circular_viewport = coin(rng);
        o.hide_back_edges = coin(rng);
        o.adjacency = &m.adjacency;
        o.bounds = &m.bounds;
        const mat4_t mvp = mat4_multiply(random_view_projection(rng), random_model(rng));
        tiny3d::wireframe_stats stats;
        return tiny3d::render_wireframe(*canvas, m.mesh, mvp, o, workspace, &stats).ok();
    });
}

TEST(filled_path_soak_without_allocation) {
    std::mt19937 scene_rng(SEED + 1);
    std::vector<scene_mesh> meshes = make_scene_meshes(scene_rng);
    tiny3d::canvas_ptr canvas = std::move(tiny3d::make_canvas(SIDE, SIDE).value());
    const light_t lights[2] = {{{0.3f, 0.4f, 1.0f}, 0.7f},
                               {{0, 0, 0}, 0.5f, tiny3d::light_kind::point, {2.0f, -1.0f, 3.0f}}};
    const tiny3d::light_rig rig = tiny3d::make_light_rig(lights, 0.1f).value();
    for (int threads : {1, 2}) {
        tiny3d::render_context ctx(threads);
        soak(threads == 1 ? "filled, 1 thread" : "filled, 2 threads", meshes, *canvas,
             [&](const scene_mesh &m, std::mt19937 &rng) {
                 std::uniform_int_distribution<int> three(0, 2), four(0, 3);
                 if (!ctx.begin_frame(*canvas, 0.0f)) return false;
                 tiny3d::draw_params p{};
                 p.model = random_model(rng);
                 p.view_projection = random_view_projection(rng);
                 p.lights = rig;
                 p.shade = three(rng) == 0 ? tiny3d::shading::flat
                                           : (three(rng) == 1 ? tiny3d::shading::gouraud : tiny3d::shading::phong);
                 p.cull = three(rng) == 0 ? tiny3d::cull_mode::none : tiny3d::cull_mode::back;
                 p.alpha = four(rng) == 0 ? 0.5f : 1.0f;
                 ctx.draw(m.raster, p);
                 ctx.end_frame();
                 return true;
             });
    }
}
