// raster_threads_test.cpp — the render context's sharing of a draw between threads and its
// 1-sample fill kernels:
//  * every thread count 1..16 gives the frame of one thread, bit for bit (colour, depth,
//    stats): Scene S (level 4, 256²) with and without clusters, at 1 and 4 samples; a frame
//    of several draws (Gouraud, textured Phong, translucent) at 1 and 8 samples; a mesh of
//    random overlapping triangles, each twice at equal depths, without clusters (shared
//    vertex transform, many pieces: the first copy must win, as on one thread);
//  * every 1-sample kernel this CPU runs (raster_simd) gives the SSE2 kernel's pixels bit
//    for bit under every depth test, and the portable kernel the same coverage with depth
//    and intensity within 2e-6 of them (depth test always), on random triangles of every
//    width (narrow ones with 1–4 groups of four — the AVX-512 kernel's 8- and 16-lane rows —,
//    wide ones, ones at the canvas' right edge);
//  * a context kept over frames (its threads streaming the triangles another thread is
//    expected to draw) gives the one-thread frame in every frame with every kernel, and the
//    streamed list keeps what was appended;
//  * the hand-out (render_bands.h): with 1–16 threads taking at once, every piece and every
//    band goes to exactly one thread; a thread's first piece is the first of its home run,
//    its run is taken front to back and the others' from the back; bands are claimed in the
//    order of the thread's own bin entries;
//  * the AVX-512 set-up of eight triangles at once gives setup_fast_triangle's verdicts and
//    fast triangles bit for bit (random snapped triangles: small, large, too wide, off the
//    clip rectangle, with horizontal edges, either orientation).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <thread>
#include <vector>

#include "harness.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"
#include "raster_test_util.h"
#include "../src/raster/fill/fill.h"
#include "../src/raster/msaa/msaa.h"
#include "../src/raster/schedule/render_bands.h"
#include "../src/simd_config.h"

using namespace tiny3d;

namespace {

using raster_test::rendered;

// Bit-identical frames, stats included (the share culled by cluster too).
bool same(const rendered &a, const rendered &b) { return raster_test::same_frame(a, b, true); }

struct draw_call {
    const raster_mesh *mesh;
    draw_params params;
};

// One frame of `draws` on a fresh context of `threads` threads with `simd` (when it runs).
rendered render(int threads, canvas_t &c, const std::vector<draw_call> &draws, sample_count n,
                raster_simd simd = best_raster_simd()) {
    render_context ctx(threads);
    ctx.use_simd(simd);
    if (!ctx.begin_frame(c, 0.05f, n).ok()) return {};
    for (const draw_call &d : draws) ctx.draw(*d.mesh, d.params);
    ctx.end_frame();
    return raster_test::capture(ctx, c);
}

// Scene S's parameters with the model turned by `angle` about +y.
draw_params scene_s_params(float angle) {
    draw_params p = raster_test::scene_s_params();
    p.model = mat4_rotate_y(angle);
    return p;
}

using raster_test::smooth_raster_mesh;

// `count` random triangles in front of the camera of scene_s_params, each within a box of
// up to `size` (object units) around a random centre in [−1.2, 1.2]² × [−1, 1]: at 256²
// and distance 3 one unit is ~150 px, so size 0.12 gives triangles up to ~18 px wide.
raster_mesh random_triangles(int count, float size, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> centre(-1.2f, 1.2f), depth(-1.0f, 1.0f), offset(-0.5f, 0.5f);
    raster_mesh m;
    for (int t = 0; t < count; ++t) {
        const vec3_t c = {centre(rng), centre(rng), depth(rng)};
        for (int k = 0; k < 3; ++k) {
            m.positions.push_back({c.x + size * offset(rng), c.y + size * offset(rng), c.z + 0.3f * size * offset(rng)});
            m.normals.push_back(vec3_normalize_fast({offset(rng), offset(rng), 1.0f}));
            m.uvs.push_back({0, 0});
        }
        const std::uint32_t v = static_cast<std::uint32_t>(3 * t);
        m.triangles.push_back({v, v + 1, v + 2});
    }
    m.bound_center = {0, 0, 0};
    m.bound_radius = 3;
    return m;
}

// The mesh twice over, the second copy's normals turned: the same depths, other intensities,
// so under depth_func::less every pixel shows the copy drawn first (submission order).
raster_mesh doubled(const raster_mesh &m) {
    raster_mesh d = m;
    const std::uint32_t n = static_cast<std::uint32_t>(m.positions.size());
    for (std::size_t k = 0; k < m.positions.size(); ++k) {
        d.positions.push_back(m.positions[k]);
        d.normals.push_back({-m.normals[k].x, m.normals[k].y, -m.normals[k].z});
        d.uvs.push_back(m.uvs[k]);
    }
    for (const auto &t : m.triangles) d.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
    return d;
}

}  // namespace

TEST(every_thread_count_from_1_to_16_gives_the_one_thread_frame) {
    canvas_ptr c = make_canvas(256, 256).value();
    const raster_mesh sphere = smooth_raster_mesh(make_icosphere(4));
    const raster_clusters clusters = make_raster_clusters(sphere).value();
    draw_params plain = scene_s_params(0.3f), clustered = plain;
    clustered.clusters = &clusters;
    // Several draws in one frame: the sphere, a textured Phong quad across it, a translucent
    // knot in front.
    texture grey;
    grey.width = grey.height = 8;
    for (int k = 0; k < 64; ++k) grey.texels.push_back(0.25f + 0.5f * static_cast<float>((k * 7) % 11) / 11.0f);
    const raster_mesh quad = raster_test::clip_quad(-2, -0.5f, 2, 0.5f, 0, 0, 0, 8, 2);
    draw_params quad_params = scene_s_params(0.0f);
    quad_params.shade = shading::phong;
    quad_params.cull = cull_mode::none;
    quad_params.tex = &grey;
    quad_params.model = mat4_identity();
    const raster_mesh knot = smooth_raster_mesh(make_torus_knot(2, 3, 60, 8));
    draw_params knot_params = scene_s_params(0.7f);
    knot_params.alpha = 0.5f;
    knot_params.model = mat4_multiply(mat4_translate(0, 0, 1.0f), mat4_scale(0.4f, 0.4f, 0.4f));
    const raster_mesh soup = doubled(random_triangles(3000, 0.15f, 7));
    draw_params soup_params = scene_s_params(0.0f);
    soup_params.cull = cull_mode::none;
    struct scene {
        std::vector<draw_call> draws;
        sample_count samples;
    };
    const std::vector<scene> scenes = {
        {{{&sphere, clustered}}, sample_count::x1},
        {{{&sphere, plain}}, sample_count::x1},
        {{{&sphere, clustered}}, sample_count::x4},
        {{{&sphere, clustered}, {&quad, quad_params}, {&knot, knot_params}}, sample_count::x1},
        {{{&sphere, plain}, {&quad, quad_params}, {&knot, knot_params}}, sample_count::x8},
        {{{&soup, soup_params}}, sample_count::x1},
    };
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const rendered one = render(1, *c, scenes[k].draws, scenes[k].samples);
        CHECK(one.stats.rasterized > 0);
        for (int threads = 2; threads <= 16; ++threads)
            CHECK_MSG(same(render(threads, *c, scenes[k].draws, scenes[k].samples), one),
                      "scene " + std::to_string(k) + ", " + std::to_string(threads) + " threads");
    }
}

// A context kept over frames, with streaming stores on and off: streaming, a thread's set-up
// streams the triangles it expects another thread to draw (every one in its first frame,
// those reaching bands it did not draw last frame after that), and the band kernels read
// them from that list; not streaming, nothing is. Scene S turning, on 2, 3 and 5 threads
// with every 1-sample kernel this CPU runs: every frame is the one-thread frame bit for bit.
TEST(frames_of_a_kept_context_give_the_one_thread_frame_with_every_kernel) {
    canvas_ptr c = make_canvas(192, 160).value();
    const raster_mesh sphere = smooth_raster_mesh(make_icosphere(4));
    const raster_clusters clusters = make_raster_clusters(sphere).value();
    int compared = 0;
    for (raster_simd simd : {raster_simd::portable, raster_simd::sse2, raster_simd::avx2, raster_simd::avx512}) {
        if (!detail::kernels_run(simd)) continue;
        for (int threads : {2, 3, 5})
        for (bool streaming : {true, false}) {
            render_context ctx(threads);
            CHECK(ctx.use_simd(simd));
            CHECK(!ctx.streaming_stores());
            CHECK(ctx.use_streaming_stores(streaming));
            CHECK_EQ(ctx.streaming_stores(), streaming);
            for (int frame = 0; frame < 4; ++frame) {
                draw_params p = scene_s_params(0.4f * static_cast<float>(frame));
                p.clusters = frame % 2 ? &clusters : nullptr;
                const rendered one = render(1, *c, {{&sphere, p}}, sample_count::x1, simd);
                CHECK(ctx.begin_frame(*c, 0.05f, sample_count::x1).ok());
                CHECK(!ctx.use_streaming_stores(!streaming));  // (not during a frame)
                ctx.draw(sphere, p);
                ctx.end_frame();
                CHECK_MSG(same(raster_test::capture(ctx, *c), one),
                          std::to_string(threads) + " threads, frame " + std::to_string(frame) +
                              (streaming ? ", streaming" : ""));
                ++compared;
            }
        }
    }
    CHECK(compared >= 24);  // (the portable kernel at least: the only one of a portable build)
}

// The streamed list keeps what was appended, in order, across its growths and a reserve,
// and starts over after clear().
TEST(streamed_triangles_keep_every_appended_triangle) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> any(-1e6f, 1e6f);
    auto random_triangle = [&] {
        detail::fast_triangle f{};
        f.min_x = static_cast<int>(rng() % 1000), f.max_x = f.min_x + 3, f.min_y = static_cast<int>(rng() % 1000);
        f.max_y = f.min_y + 7;
        for (int k = 0; k < 4; ++k) f.cross[k] = any(rng), f.cross_step[k] = any(rng);
        f.z = any(rng), f.zdx = any(rng), f.zdy = any(rng), f.i = any(rng), f.idx = any(rng), f.idy = any(rng);
        f.wide = static_cast<std::int32_t>(rng() % 5) - 1;
        return f;
    };
    detail::streamed_triangles list;
    for (int round = 0; round < 2; ++round) {
        std::vector<detail::fast_triangle> expected;
        list.clear();
        for (int k = 0; k < 300; ++k) {
            if (k == 150) list.reserve(1000);
            expected.push_back(random_triangle());
            CHECK_EQ(list.append(expected.back()), static_cast<std::size_t>(k));
        }
        detail::stream_fence();
        CHECK_EQ(list.size(), expected.size());
        CHECK(std::memcmp(list.data(), expected.data(), expected.size() * sizeof(detail::fast_triangle)) == 0);
        CHECK_EQ(reinterpret_cast<std::uintptr_t>(list.data()) % 16, 0u);
    }
}

TEST(pieces_and_bands_are_each_handed_out_once) {
    using detail::band_affinity;
    using detail::phase_counters;
    // One thread alone: its own run front to back, then the runs before it from the back.
    {
        phase_counters c;
        c.reset(10, 3, 4);  // runs [0, 3), [3, 6), [6, 10)
        std::vector<int> order;
        for (int k; (k = c.take_piece(1, 3)) >= 0;) order.push_back(k);
        CHECK((order == std::vector<int>{3, 4, 5, 2, 1, 0, 9, 8, 7, 6}));
    }
    // Bands in the order of the thread's own entries (most first, ties top first); with the
    // bands it drew last time first (each group so ordered); top to bottom.
    using order = band_affinity::claim_order;
    {
        band_affinity a;
        const std::vector<std::vector<int>> bins = {{1}, {}, {1, 2, 3}, {4}, {5, 6, 7}};
        a.count(bins, 5);
        a.drew[1] = a.drew[3] = 1;
        a.rank(5, order::kept_then_own);
        CHECK((std::vector<int>(a.order, a.order + 5) == std::vector<int>{3, 1, 2, 4, 0}));
        a.rank(5, order::own_entries);
        CHECK((std::vector<int>(a.order, a.order + 5) == std::vector<int>{2, 4, 0, 3, 1}));
        phase_counters c;
        c.reset(0, 2, 5);
        CHECK(c.take_band(a, 5) == 2);
        c.band_taken[4].store(1);  // taken by another thread
        CHECK(c.take_band(a, 5) == 0);
        a.rank(5, order::top_down);
        CHECK((std::vector<int>(a.order, a.order + 5) == std::vector<int>{0, 1, 2, 3, 4}));
        a.forget(5);
        CHECK(a.own[2] == 0u && a.own[4] == 0u);
    }
    // While waiting, a thread claims at most its share of the bands (ceil(count / threads)),
    // in its order, however long the wait; none when the wait is over.
    {
        band_affinity a;
        a.rank(10, order::top_down);
        phase_counters c;
        c.reset(0, 3, 10);
        int claimed[detail::MAX_BANDS], worked = 0;
        const int n = c.claim_while(a, 10, 3, [] { return true; }, [&](int) { ++worked; }, claimed);
        CHECK_EQ(n, 4);
        CHECK_EQ(worked, 4);
        CHECK((std::vector<int>(claimed, claimed + n) == std::vector<int>{0, 1, 2, 3}));
        CHECK_EQ(c.claim_while(a, 10, 3, [] { return false; }, [&](int) { ++worked; }, claimed), 0);
        CHECK_EQ(c.take_band(a, 10), 4);  // the claimed bands stay taken; the next is the fifth
    }
    // Threads taking at once: each piece and band exactly once, whatever the interleaving.
    std::mt19937 rng(29);
    for (int threads = 1; threads <= 16; ++threads) {
        for (int pieces : {0, 1, threads, 8 * threads, 8 * threads + 3}) {
            phase_counters c;
            const int bands = 32;
            c.reset(pieces, threads, bands);
            std::vector<band_affinity> mine(static_cast<std::size_t>(threads));
            std::vector<std::vector<int>> took_pieces(threads), took_bands(threads);
            for (band_affinity &a : mine) {
                std::vector<std::vector<int>> bins(bands);
                for (auto &bin : bins) bin.resize(rng() % 5);
                a.count(bins, bands);
                for (int b = 0; b < bands; ++b) a.drew[b] = rng() % 2;
                a.rank(bands, threads > 1 ? order::kept_then_own : order::top_down);
            }
            std::vector<std::thread> workers;
            for (int t = 0; t < threads; ++t)
                workers.emplace_back([&, t] {
                    for (int k; (k = c.take_piece(t, threads)) >= 0;) took_pieces[t].push_back(k);
                    for (int b; (b = c.take_band(mine[t], bands)) < bands;) took_bands[t].push_back(b);
                });
            for (std::thread &w : workers) w.join();
            std::vector<int> piece_times(pieces, 0), band_times(bands, 0);
            for (int t = 0; t < threads; ++t) {
                for (int k : took_pieces[t]) ++piece_times[k];
                for (int b : took_bands[t]) ++band_times[b];
                // A thread that took any piece took its run's first one first, if it has one.
                const int first = pieces * t / threads, end = pieces * (t + 1) / threads;
                if (first < end && !took_pieces[t].empty() && took_pieces[t][0] >= first && took_pieces[t][0] < end)
                    CHECK(took_pieces[t][0] == first);
            }
            const std::string where = std::to_string(threads) + " threads, " + std::to_string(pieces) + " pieces";
            CHECK_MSG(std::all_of(piece_times.begin(), piece_times.end(), [](int n) { return n == 1; }), where);
            CHECK_MSG(std::all_of(band_times.begin(), band_times.end(), [](int n) { return n == 1; }), where);
        }
    }
}

TEST(one_sample_kernels_give_the_sse2_pixels_and_the_portable_coverage) {
    // 250 × 256: the narrow kernels' groups of four reach past the right edge for triangles
    // that start in the last columns (those take the span loop and its lane-by-lane tail).
    canvas_ptr c = make_canvas(250, 256).value();
    const depth_func tests[] = {depth_func::less,    depth_func::less_equal,    depth_func::equal,
                                depth_func::greater, depth_func::greater_equal, depth_func::not_equal,
                                depth_func::always};
    int compared = 0;
    for (float size : {0.02f, 0.06f, 0.12f, 0.5f}) {
        const raster_mesh soup = doubled(random_triangles(800, size, static_cast<unsigned>(size * 1000)));
        for (depth_func test : tests) {
            draw_params first = scene_s_params(0.0f), p = first;
            first.cull = p.cull = cull_mode::none;
            p.depth = test;
            // Two draws, each with every triangle twice at equal depths: the second tests
            // against the first's depths, and the ties decide every pixel.
            const std::vector<draw_call> draws = {{&soup, first}, {&soup, p}};
            const rendered sse2 = render(1, *c, draws, sample_count::x1, raster_simd::sse2);
            for (raster_simd simd : {raster_simd::avx2, raster_simd::avx512}) {
                if (render_context probe(1); !probe.use_simd(simd)) continue;
                CHECK(same(render(1, *c, draws, sample_count::x1, simd), sse2));
                CHECK(same(render(2, *c, draws, sample_count::x1, simd), sse2));
                ++compared;
            }
            // The portable kernel's depths differ in the last bits, so overlapping triangles may
            // win differently: compared where the last one drawn always wins.
            if (test != depth_func::always) continue;
            const rendered portable = render(1, *c, draws, sample_count::x1, raster_simd::portable);
            int coverage_differs = 0;
            double worst = 0;
            for (std::size_t i = 0; i < sse2.depth.size(); ++i) {
                coverage_differs += (sse2.depth[i] == 1.0f) != (portable.depth[i] == 1.0f);
                worst = std::max({worst, std::fabs(static_cast<double>(sse2.depth[i]) - portable.depth[i]),
                                  std::fabs(static_cast<double>(sse2.colour[i]) - portable.colour[i])});
            }
            CHECK_EQ(coverage_differs, 0);
            CHECK(worst <= 2e-6);
        }
    }
    CHECK(compared >= (best_raster_simd() == raster_simd::avx512 ? 56 : 0));
}

#if defined(TINY3D_AVX512) || defined(TINY3D_AVX2)
// A batch of 1..8 random triangles: vertices on the 1/2^bits px grid around a point of a
// 250 × 200 px rectangle, spans of 2 px to ~2,100 px (past the fast path's limit), some
// rows or columns shared.
detail::setup_batch random_setup_batch(std::mt19937 &rng, int bits = RASTER_SUBPIXEL_BITS) {
    const int scale = 1 << (bits - RASTER_SUBPIXEL_BITS);
    detail::setup_batch batch;
    std::uniform_int_distribution<int> count_of(1, detail::SETUP_BATCH), coin(0, 7);
    const int count = count_of(rng);
    for (int l = 0; l < count; ++l) {
        const int reach = scale * (coin(rng) == 0 ? 34000 : (coin(rng) < 4 ? 200 : 2000));
        std::uniform_int_distribution<int> centre(-400 * scale, 4400 * scale), offset(-reach, reach);
        const int cx = centre(rng), cy = centre(rng);
        std::int32_t X[3], Y[3];
        for (int k = 0; k < 3; ++k) X[k] = cx + offset(rng), Y[k] = cy + offset(rng);
        if (coin(rng) == 0) Y[1] = Y[0];  // a horizontal edge
        if (coin(rng) == 0) X[2] = X[1];  // a vertical one
        std::int64_t area2 = detail::snapped_area2(X, Y);
        if (area2 == 0) X[2] += 16, area2 = detail::snapped_area2(X, Y);
        if (area2 == 0) continue;
        std::uniform_real_distribution<float> value(0.0f, 1.0f);
        const float depth[3] = {value(rng), value(rng), value(rng)}, shade[3] = {value(rng), value(rng), value(rng)};
        batch.add(X, Y, area2, depth, shade);
    }
    return batch;
}
#endif

// The batched set-up of every kernel that has one (AVX-512, AVX2) against setup_fast_triangle.
TEST(batched_setup_gives_the_scalar_setup_bit_for_bit) {
#if defined(TINY3D_AVX512) || defined(TINY3D_AVX2)
  for (const raster_simd kernel : {raster_simd::avx512, raster_simd::avx2}) {
    if (!detail::kernels_run(kernel) || !detail::kernels_for(kernel).setup_fast_batch) continue;
    std::mt19937 rng(20261203);
    const pixel_rect clip{3, 5, 250, 200};
    int compared = 0, scalar = 0, ready = 0;
    for (int round = 0; round < 4000; ++round) {
        const detail::setup_batch batch = random_setup_batch(rng);
    detail::fast_setup verdict[detail::SETUP_BATCH];
        detail::fast_triangle batched[detail::SETUP_BATCH];
        detail::kernels_for(kernel).setup_fast_batch(batch, clip, verdict, batched);
        for (int l = 0; l < batch.count; ++l) {
            std::int32_t X[3], Y[3];
            float depth[3], shade[3];
            batch.lane(l, X, Y, depth, shade);
            detail::fast_triangle one;
            const detail::fast_setup expected = detail::setup_fast_triangle(X, Y, batch.area2[l], clip, depth, shade, one);
            if (verdict[l] == detail::fast_setup::scalar) {  // allowed only for a horizontal edge
                CHECK(X[0] == X[1] || Y[0] == Y[1] || Y[1] == Y[2] || Y[2] == Y[0]);
                ++scalar;
                continue;
            }
            CHECK(verdict[l] == expected);
            ++compared;
            if (expected != detail::fast_setup::ready) continue;
            ++ready;
            const detail::fast_triangle &b = batched[l];
            CHECK(b.min_x == one.min_x && b.max_x == one.max_x && b.min_y == one.min_y && b.max_y == one.max_y);
            CHECK(std::memcmp(b.cross, one.cross, sizeof one.cross) == 0);
            CHECK(std::memcmp(b.cross_step, one.cross_step, sizeof one.cross_step) == 0);
            const float planes_b[6] = {b.z, b.zdx, b.zdy, b.i, b.idx, b.idy};
            const float planes_one[6] = {one.z, one.zdx, one.zdy, one.i, one.idx, one.idy};
            CHECK(std::memcmp(planes_b, planes_one, sizeof planes_b) == 0);
            CHECK(b.wide == one.wide);
        }
    }
    CHECK(ready > 2000);
    CHECK(scalar > 100);
    CHECK(compared > 10000);
  }
#endif
}

// The multisampled frames' batched set-up (4, 8 and 16 samples) against make_msaa_triangle.
TEST(batched_multisample_setup_gives_the_scalar_setup_bit_for_bit) {
#if defined(TINY3D_AVX512) || defined(TINY3D_AVX2)
  for (const raster_simd kernel : {raster_simd::avx512, raster_simd::avx2}) {
    if (!detail::kernels_run(kernel) || !detail::kernels_for(kernel).setup_msaa_batch) continue;
    std::mt19937 rng(20261204);
    const pixel_rect clip{3, 5, 250, 200};
    int ready = 0, empty = 0, scalar = 0, clipped = 0, ready16 = 0;
    for (const int samples : {4, 8, 16}) {
        const detail::sample_pattern &pat = detail::pattern_of(samples);
        const std::int64_t limit = detail::span_limit(pat.bits);
        for (int round = 0; round < 3000; ++round) {
            const detail::setup_batch batch = random_setup_batch(rng, pat.bits);
            detail::fast_setup verdict[detail::SETUP_BATCH];
            detail::msaa_triangle batched[detail::SETUP_BATCH];
            detail::kernels_for(kernel).setup_msaa_batch(batch, pat, clip, verdict, batched);
            for (int l = 0; l < batch.count; ++l) {
                std::int32_t X[3], Y[3];
                float depth[3], shade[3];
                batch.lane(l, X, Y, depth, shade);
                detail::msaa_triangle one;
                const bool made = detail::make_msaa_triangle(X, Y, batch.area2[l], pat, clip, depth, shade, one);
                if (verdict[l] == detail::fast_setup::scalar) {  // allowed only for a box past the fast span
                    CHECK(std::max({X[0], X[1], X[2]}) - std::min({X[0], X[1], X[2]}) >= limit ||
                          std::max({Y[0], Y[1], Y[2]}) - std::min({Y[0], Y[1], Y[2]}) >= limit);
                    ++scalar;
                    continue;
                }
                CHECK_EQ(verdict[l] == detail::fast_setup::ready, made);
                if (!made) {
                    ++empty;
                    continue;
                }
                ++ready;
                ready16 += samples == 16;
                const detail::msaa_triangle &b = batched[l];
                CHECK(b.min_x == one.min_x && b.max_x == one.max_x && b.min_y == one.min_y && b.max_y == one.max_y);
                CHECK(std::memcmp(b.e, one.e, sizeof one.e) == 0);
                CHECK(std::memcmp(b.a, one.a, sizeof one.a) == 0);
                CHECK(std::memcmp(b.b, one.b, sizeof one.b) == 0);
                const float planes_b[6] = {b.z, b.zdx, b.zdy, b.i, b.idx, b.idy};
                const float planes_one[6] = {one.z, one.zdx, one.zdy, one.i, one.idx, one.idy};
                CHECK(std::memcmp(planes_b, planes_one, sizeof planes_b) == 0);
                CHECK(b.narrow == one.narrow && b.chunkable == one.chunkable && b.clipped_x == one.clipped_x);
                clipped += one.clipped_x;
            }
        }
    }
    CHECK(ready > 2000 && ready16 > 600);
    CHECK(empty > 1000);
    CHECK(scalar > 100);
    CHECK(clipped > 100 && clipped < ready);
  }
#endif
}
