// raster_cluster_test.cpp — cluster culling (raster_clusters): the stored bounds hold for
// every triangle, and a frame drawn with clusters is bit-identical to the frame without
// them, for any thread count, mesh, camera and projection; a vertex index out of range.
#include <cmath>
#include <cstring>
#include <random>
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

namespace {

using raster_test::rendered;
using raster_test::same_frame;

rendered render_frame(render_context &ctx, canvas_t &c, const raster_mesh &m, const draw_params &p) {
    if (!raster_test::draw_frame(ctx, c, m, p, 0.05f).ok()) return {};
    return raster_test::capture(ctx, c);
}

using raster_test::scene_s_params;
using raster_test::smooth_raster_mesh;

}  // namespace

TEST(cluster_bounds_hold_for_every_triangle) {
    const raster_mesh m = smooth_raster_mesh(make_icosphere(4));
    CHECK(!make_raster_clusters(m, 0).ok());
    raster_mesh bad = m;
    bad.triangles[7][1] = static_cast<std::uint32_t>(m.positions.size());
    CHECK(!make_raster_clusters(bad, 64).ok());
    const raster_clusters cl = make_raster_clusters(m, 64).value();
    CHECK_EQ(cl.clusters().size(), std::size_t{5120 / 64});
    CHECK_EQ(cl.triangle_count(), m.triangles.size());
    std::size_t next = 0, with_cone = 0;
    for (const raster_cluster &c : cl.clusters()) {
        CHECK_EQ(std::size_t{c.first}, next);  // in order, no gap
        next = c.first + c.count;
        with_cone += c.cone_valid;
        for (std::uint32_t i = c.first; i < c.first + c.count; ++i) {
            // Recomputed independently in long double.
            long double p[3][3];
            for (int k = 0; k < 3; ++k) {
                const vec3_t v = m.positions[m.triangles[i][k]];
                p[k][0] = v.x, p[k][1] = v.y, p[k][2] = v.z;
                const long double d = std::sqrt((p[k][0] - c.center[0]) * (p[k][0] - c.center[0]) +
                                                (p[k][1] - c.center[1]) * (p[k][1] - c.center[1]) +
                                                (p[k][2] - c.center[2]) * (p[k][2] - c.center[2]));
                CHECK(d <= c.radius);
            }
            const long double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
            const long double v[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
            const long double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
            const long double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            CHECK(len >= c.min_double_area);
            const long double edges = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) + std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            CHECK(edges / len <= c.edge_ratio);
            if (!c.cone_valid) continue;
            const long double along = (n[0] * c.axis[0] + n[1] * c.axis[1] + n[2] * c.axis[2]) / len;
            CHECK(along >= c.cone_cos);
            const long double behind = (n[0] * (p[0][0] - c.apex[0]) + n[1] * (p[0][1] - c.apex[1]) + n[2] * (p[0][2] - c.apex[2])) / len;
            CHECK(behind >= c.apex_margin);
        }
    }
    CHECK_EQ(next, m.triangles.size());
    CHECK_EQ(with_cone, cl.clusters().size());  // every level-4 chunk of 64 is a small smooth patch
    CHECK(cl.clusters()[3].cone_cos > 0.9);
}

TEST(clusters_give_the_same_scene_s_frames_for_any_thread_count) {
    const raster_mesh m = smooth_raster_mesh(make_icosphere(6));
    const raster_clusters cl = make_raster_clusters(m, RASTER_CLUSTER_TRIANGLES).value();
    canvas_ptr c = make_canvas(1024, 1024).value();
    draw_params p = scene_s_params();
    rendered first_with[3];
    for (int threads = 1; threads <= 3; ++threads) {
        render_context ctx(threads);
        for (int degrees : {0, 37, 90}) {
            p.model = mat4_rotate_y(static_cast<float>(degrees * M_PI / 180));
            p.clusters = nullptr;
            const rendered plain = render_frame(ctx, *c, m, p);
            p.clusters = &cl;
            const rendered with = render_frame(ctx, *c, m, p);
            CHECK(same_frame(plain, with));
            CHECK_EQ(plain.stats.backface_by_cluster, std::size_t{0});
            // Two thirds of the sphere face away from a camera at distance 3; most of them
            // lie in chunks the cone proves back-facing (90.6 % at level 6, chunks of 64).
            CHECK(with.stats.culled_backface > m.triangles.size() / 2);
            CHECK(with.stats.backface_by_cluster > with.stats.culled_backface * 85 / 100);
            if (degrees == 0) first_with[threads - 1] = with;
        }
    }
    for (int k = 1; k < 3; ++k) {
        CHECK(same_frame(first_with[0], first_with[k]));
        CHECK_EQ(first_with[k].stats.backface_by_cluster, first_with[0].stats.backface_by_cluster);
    }
}

TEST(clusters_never_change_a_frame_random_meshes_cameras_and_projections) {
    std::mt19937 rng(2026);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * unit(rng); };
    // Meshes: coherent (bumpy icospheres, a torus knot) and incoherent (a random soup).
    std::vector<raster_mesh> meshes;
    for (float bump : {0.0f, 0.05f, 0.3f}) {
        mesh s = make_icosphere(3);
        for (vec3_t &v : s.positions) v = v * (1.0f + bump * (unit(rng) - 0.5f));
        meshes.push_back(smooth_raster_mesh(s));
    }
    meshes.push_back(smooth_raster_mesh(make_torus_knot(2, 3, 60, 8)));
    raster_mesh soup;
    for (int k = 0; k < 300; ++k) {
        const vec3_t a{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        const std::uint32_t i = static_cast<std::uint32_t>(soup.positions.size());
        soup.positions.insert(soup.positions.end(), {a, a + vec3_t{uniform(-0.2f, 0.2f), uniform(-0.2f, 0.2f), uniform(-0.2f, 0.2f)},
                                                     a + vec3_t{uniform(-0.2f, 0.2f), uniform(-0.2f, 0.2f), uniform(-0.2f, 0.2f)}});
        soup.triangles.push_back({i, i + 1, i + 2});
    }
    soup.normals.assign(soup.positions.size(), {0, 0, 1});
    soup.uvs.assign(soup.positions.size(), {0, 0});
    soup.bound_radius = 2;
    meshes.push_back(soup);
    const int cluster_sizes[4] = {1, 5, 64, 256};
    std::size_t by_cluster = 0, cases = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const raster_mesh &m = meshes[trial % meshes.size()];
        const raster_clusters cl = make_raster_clusters(m, cluster_sizes[(trial / 5) % 4]).value();
        const int w = 40 + static_cast<int>(unit(rng) * 260), h = 40 + static_cast<int>(unit(rng) * 260);
        canvas_ptr c = make_canvas(w, h).value();
        draw_params p = scene_s_params();
        p.shade = trial % 3 == 0 ? shading::flat : shading::gouraud;
        p.cull = trial % 7 == 3 ? cull_mode::front : (trial % 7 == 5 ? cull_mode::none : cull_mode::back);
        // Camera from inside the mesh (distance 0.3) to far away; fields of view from 1° to
        // 160°; near planes from 1e-3 to 0.5.
        const float distance = std::exp(uniform(std::log(0.3f), std::log(60.0f)));
        const float yaw = uniform(0, 6.3f), pitch = uniform(-1.5f, 1.5f);
        const vec3_t eye{distance * std::cos(pitch) * std::cos(yaw), distance * std::sin(pitch), distance * std::cos(pitch) * std::sin(yaw)};
        const vec3_t look{uniform(-0.8f, 0.8f), uniform(-0.8f, 0.8f), uniform(-0.8f, 0.8f)};
        const float fov = std::exp(uniform(std::log(0.0175f), std::log(2.8f)));
        p.view_projection = mat4_multiply(mat4_perspective(fov, static_cast<float>(w) / h, std::exp(uniform(std::log(1e-3f), std::log(0.5f))), 1000.0f),
                                          mat4_look_at(eye, look, {0, 1, 0}));
        // Rotations, non-uniform and (every 11th) mirroring scales, offsets.
        const float mirror = trial % 11 == 4 ? -1.0f : 1.0f;
        p.model = mat4_multiply(mat4_translate(uniform(-0.5f, 0.5f), uniform(-0.5f, 0.5f), uniform(-0.5f, 0.5f)),
                                mat4_multiply(mat4_rotate_xyz(uniform(0, 6.3f), uniform(0, 6.3f), uniform(0, 6.3f)),
                                              mat4_scale(mirror * uniform(0.5f, 1.5f), uniform(0.5f, 1.5f), uniform(0.5f, 1.5f))));
        for (int threads : {1, 2, 3}) {
            render_context ctx(threads);
            p.clusters = nullptr;
            const rendered plain = render_frame(ctx, *c, m, p);
            p.clusters = &cl;
            const rendered with = render_frame(ctx, *c, m, p);
            CHECK_MSG(same_frame(plain, with), "trial " + std::to_string(trial) + ", " + std::to_string(threads) + " threads");
            if (p.cull != cull_mode::back || mirror < 0) CHECK_EQ(with.stats.backface_by_cluster, std::size_t{0});
            by_cluster += with.stats.backface_by_cluster;
            ++cases;
        }
    }
    CHECK(by_cluster > 0);  // the skip path was taken
    CHECK_EQ(cases, std::size_t{180});
}

TEST(clusters_near_the_silhouette_and_close_cameras) {
    // Grazing chunks: a camera just outside the sphere sees most triangles nearly edge-on;
    // every tenth of a degree of rotation moves the silhouette through the chunks.
    const raster_mesh m = smooth_raster_mesh(make_icosphere(4));
    const raster_clusters small = make_raster_clusters(m, 4).value(), large = make_raster_clusters(m, 64).value();
    canvas_ptr c = make_canvas(160, 120).value();
    render_context one(1), two(2);
    std::size_t by_cluster = 0;
    for (float distance : {1.02f, 1.1f, 1.5f, 3.0f, 40.0f}) {
        draw_params p = scene_s_params();
        p.view_projection = mat4_multiply(mat4_perspective(2.0f * std::atan(1.2f / distance), 160.0f / 120, 0.01f, 100.0f),
                                          mat4_look_at({0, 0, distance}, {0, 0, 0}, {0, 1, 0}));
        for (int step = 0; step < 12; ++step) {
            p.model = mat4_rotate_xyz(0.0017f * step, 0.1f * step, 0);
            for (const raster_clusters *cl : {&small, &large}) {
                for (render_context *ctx : {&one, &two}) {
                    p.clusters = nullptr;
                    const rendered plain = render_frame(*ctx, *c, m, p);
                    p.clusters = cl;
                    const rendered with = render_frame(*ctx, *c, m, p);
                    CHECK(same_frame(plain, with));
                    by_cluster += with.stats.backface_by_cluster;
                }
            }
        }
    }
    CHECK(by_cluster > 0);
}

TEST(clusters_with_several_draws_of_one_mesh_in_a_frame) {
    // A thread transforms each vertex of the walked chunks once per draw (a vertex shared by
    // two chunks is not transformed again): the second draw of the same mesh, under another
    // model matrix, must transform every vertex anew, in 1- and multisampled frames alike.
    const raster_mesh m = smooth_raster_mesh(make_icosphere(4));
    const raster_clusters cl = make_raster_clusters(m, 64).value();
    canvas_ptr c = make_canvas(200, 150).value();
    draw_params p = scene_s_params();
    const mat4_t models[3] = {mat4_rotate_y(0.3f), mat4_multiply(mat4_translate(0.4f, 0.1f, 0.5f), mat4_rotate_xyz(1.0f, 0.2f, 0)),
                              mat4_multiply(mat4_translate(-0.5f, -0.2f, -0.3f), mat4_scale(0.6f, 0.6f, 0.6f))};
    auto frame = [&](render_context &ctx, sample_count samples, const raster_clusters *clusters) {
        p.clusters = clusters;
        CHECK(ctx.begin_frame(*c, 0.05f, samples).ok());
        for (const mat4_t &model : models) {
            p.model = model;
            ctx.draw(m, p);
        }
        ctx.end_frame();
        return raster_test::capture(ctx, *c);
    };
    for (int threads : {1, 2, 3}) {
        render_context ctx(threads);
        for (sample_count samples : {sample_count::x1, sample_count::x4}) {
            const rendered plain = frame(ctx, samples, nullptr);
            for (int repeat = 0; repeat < 2; ++repeat) {  // (the same context again: stamps of the last frame)
                const rendered with = frame(ctx, samples, &cl);
                CHECK_MSG(same_frame(plain, with), std::to_string(threads) + " threads, " +
                                                       std::to_string(static_cast<int>(samples)) + " samples");
                CHECK(with.stats.backface_by_cluster > 0);
            }
        }
    }
}

TEST(clusters_of_another_mesh_are_ignored) {
    const raster_mesh m = smooth_raster_mesh(make_icosphere(4)), other = smooth_raster_mesh(make_icosphere(3));
    const raster_clusters stale = make_raster_clusters(other, 64).value();
    canvas_ptr c = make_canvas(128, 128).value();
    render_context ctx(2);
    draw_params p = scene_s_params();
    p.model = mat4_identity();
    const rendered plain = render_frame(ctx, *c, m, p);
    p.clusters = &stale;
    const rendered with = render_frame(ctx, *c, m, p);
    CHECK(same_frame(plain, with));
    CHECK_EQ(with.stats.backface_by_cluster, std::size_t{0});
}

TEST(clusters_with_hostile_vertices_and_matrices) {
    // Non-finite, huge, denormal and coincident vertices, degenerate triangles, and matrices
    // with NaN or a zero row: every chunk test must fail safe (walk the chunk), never skip
    // wrongly, and the frame must equal the frame without clusters.
    raster_mesh m = smooth_raster_mesh(make_icosphere(3));
    m.positions[5] = {NAN, 0, 0};
    m.positions[40] = {1e30f, -1e30f, 0};
    m.positions[77] = {1e-40f, 1e-41f, -1e-40f};
    m.positions[90] = m.positions[91];
    m.triangles[300] = {7, 7, 8};
    m.triangles[301] = {9, 10, 9};
    const raster_clusters cl = make_raster_clusters(m, 16).value();
    std::size_t without_cone = 0;
    for (const raster_cluster &c : cl.clusters()) without_cone += !c.cone_valid;
    CHECK(without_cone >= 3);  // the chunks holding the NaN, the 1e30 and the degenerate triangles
    canvas_ptr c = make_canvas(96, 80).value();
    render_context ctx(2);
    draw_params p = scene_s_params();
    mat4_t nan_matrix = p.view_projection, flat_matrix = p.view_projection;
    nan_matrix.m[5] = NAN;
    for (int col = 0; col < 4; ++col) flat_matrix.m[col * 4 + 3] = 0.0f;  // w row zero
    std::size_t by_cluster = 0;
    for (const mat4_t &vp : {p.view_projection, nan_matrix, flat_matrix}) {
        p.view_projection = vp;
        for (float angle : {0.0f, 1.0f, 2.5f}) {
            p.model = mat4_rotate_xyz(angle, 0.3f * angle, 0);
            p.clusters = nullptr;
            const rendered plain = render_frame(ctx, *c, m, p);
            p.clusters = &cl;
            const rendered with = render_frame(ctx, *c, m, p);
            CHECK(same_frame(plain, with));
            by_cluster += with.stats.backface_by_cluster;
        }
    }
    CHECK(by_cluster > 0);  // the finite, regular chunks still cull under the ordinary matrix
}

TEST(a_vertex_index_out_of_range_draws_nothing) {
    // The index check runs four indices at a time: put the bad one in the vector part, in the
    // scalar tail, at the boundary value and at the top of the unsigned range.
    const raster_mesh good = smooth_raster_mesh(make_icosphere(2));  // 320 triangles = 960 indices
    const std::uint32_t count = static_cast<std::uint32_t>(good.positions.size());
    canvas_ptr c = make_canvas(64, 64).value();
    render_context ctx(2);
    draw_params p = scene_s_params();
    p.model = mat4_identity();
    CHECK(render_frame(ctx, *c, good, p).stats.rasterized > 0);
    for (std::size_t at : {std::size_t{5}, std::size_t{319}}) {
        for (std::uint32_t bad : {count, count + 1, 0xffffffffu}) {
            raster_mesh m = good;
            m.triangles[at][at % 3] = bad;
            const rendered r = render_frame(ctx, *c, m, p);
            CHECK_EQ(r.stats.rasterized, std::size_t{0});
            CHECK_EQ(r.stats.triangles_in, m.triangles.size());
        }
    }
    raster_mesh tail = good;
    tail.triangles.push_back({0, 1, count});  // 963 indices: the last one in the scalar tail
    CHECK_EQ(render_frame(ctx, *c, tail, p).stats.rasterized, std::size_t{0});
    tail.triangles.back() = {0, 1, count - 1};
    CHECK(render_frame(ctx, *c, tail, p).stats.rasterized > 0);
}
