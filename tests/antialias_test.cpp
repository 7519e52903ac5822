// antialias_test.cpp — the render context's multisample modes against the converged
// reference image (error bounds, per-sample watertightness, thread-count invariance) and
// the multisample kernels. Mipmaps and the reference itself: texture_filter_test.cpp.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <cmath>
#include <cstring>
#include <tuple>
#include <random>
#include <utility>
#include <vector>

#include "../src/raster/msaa/msaa.h"
#include "../src/raster/msaa/msaa_kernels.h"
#include "../src/simd_config.h"
#include "alloc_tracker.h"
#include "harness.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"
#include "raster_test_util.h"

using namespace tiny3d;
using raster_test::constant_light;
using raster_test::clip_quad;
using raster_test::draw_frame;
using raster_test::flat_params;

// ---- multisampling ------------------------------------------------------------------------

namespace {

constexpr sample_count MODES[] = {sample_count::x1, sample_count::x4, sample_count::x8, sample_count::x16};

// Every multisample kernel this build runs on this CPU, the portable reference first.
std::vector<detail::msaa_kernel> msaa_kernels() {
    std::vector<detail::msaa_kernel> out;
    for (detail::msaa_kernel k : {detail::msaa_kernel::portable, detail::msaa_kernel::sse2, detail::msaa_kernel::avx2,
                                  detail::msaa_kernel::avx512})
        if (detail::kernels_run(k)) out.push_back(k);
    return out;
}

// A small Scene S: the icosphere (or any mesh) at the origin, camera at (0, 0, 3), fov 45°,
// Gouraud Lambert with one directional light, turned by `angle` about +y.
struct small_scene {
    raster_mesh mesh;
    draw_params params;
};

small_scene make_small_scene(const mesh &m, float angle) {
    small_scene s;
    s.mesh = make_raster_mesh(m, mesh_vertex_normals(m)).value();
    const light_t light = {{1, 1, 1}, 1.0f};
    s.params.lights = make_light_rig(std::span<const light_t>(&light, 1), 0.1f).value();
    s.params.view_projection = mat4_multiply(mat4_perspective(static_cast<float>(45 * M_PI / 180), 1.0f, 0.1f, 100.0f),
                                             mat4_look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}));
    s.params.model = mat4_rotate_y(angle);
    return s;
}

void render(const small_scene &s, canvas_t &c, sample_count n, int threads, float clear = 0.0f) {
    render_context ctx(threads);
    CHECK(draw_frame(ctx, c, s.mesh, s.params, clear, n).ok());
}

// The several-draws frame of the multisampling tests: a Gouraud sphere, a Phong quad through
// it with `tex` (mipmapped here, trilinear, both sides drawn) and a translucent torus knot.
struct multi_draw_scene {
    small_scene sphere = make_small_scene(make_icosphere(2), 0.4f);
    small_scene knot = make_small_scene(make_torus_knot(2, 3, 40, 6), 0.1f);
    texture tex;
    raster_mesh quad = clip_quad(-2, -0.5f, 2, 0.5f, 0, 0, 0, 8, 2);
    draw_params quad_params = sphere.params;

    explicit multi_draw_scene(texture t) : tex(std::move(t)) {
        knot.params.alpha = 0.5f;
        CHECK(build_mipmaps(tex).ok());
        quad_params.shade = shading::phong;
        quad_params.cull = cull_mode::none;
        quad_params.tex = &tex;
        quad_params.filter = texture_filter::trilinear;
    }
    multi_draw_scene(const multi_draw_scene &) = delete;  // quad_params points at tex
    multi_draw_scene &operator=(const multi_draw_scene &) = delete;
};

struct image_error {
    double all_mean = 0, edge_mean = 0, edge_max = 0;
    int edge_pixels = 0;
};

// Error in grey levels (0–255) against the reference, over all pixels and over the
// silhouette pixels: those whose exact coverage by the object (the reference of the same
// scene drawn flat white on black) is strictly between 0 and 1.
image_error error_against(const canvas_t &image, const canvas_t &reference, const canvas_t &coverage) {
    image_error e;
    const int n = image.width * image.height;
    for (int i = 0; i < n; ++i) {
        const double d = 255.0 * std::fabs(static_cast<double>(image.data[i]) - reference.data[i]);
        e.all_mean += d / n;
        if (coverage.data[i] > 1e-3f && coverage.data[i] < 1 - 1e-3f) {
            e.edge_mean += d;
            e.edge_max = std::max(e.edge_max, d);
            ++e.edge_pixels;
        }
    }
    if (e.edge_pixels) e.edge_mean /= e.edge_pixels;
    return e;
}

}  // namespace

TEST(msaa_error_against_the_reference_per_mode) {
    constexpr int S = 64;
    const small_scene scene = make_small_scene(make_icosphere(3), 0.3f);
    small_scene white = scene;
    white.params.lights = constant_light(1.0f);
    white.params.shade = shading::flat;
    canvas_ptr reference = make_canvas(S, S).value(), coverage = make_canvas(S, S).value();
    const reference_draw d{&scene.mesh, scene.params}, dw{&white.mesh, white.params};
    CHECK(render_reference(*reference, std::span<const reference_draw>(&d, 1), 0.0f, 8).ok());
    CHECK(render_reference(*coverage, std::span<const reference_draw>(&dw, 1), 0.0f, 8).ok());
    // Upper bounds on the silhouette mean (grey levels), measured 1×: 23.2, 4×: 10.5, 8×: 6.0,
    // 16×: 3.65 against this 64-sample reference (whose own error is ~2); the standard
    // 16-sample pattern, off centre by 1/32 px, gave ~4.7.
    const double edge_bound[] = {40, 14, 10, 4.2};
    double previous = 1e9;
    for (int m = 0; m < 4; ++m) {
        canvas_ptr c = make_canvas(S, S).value();
        render(scene, *c, MODES[m], 1);
        const image_error e = error_against(*c, *reference, *coverage);
        CHECK(e.edge_pixels > 100);
        CHECK(e.edge_mean < edge_bound[m]);
        CHECK(e.edge_mean < previous);  // more samples, less error
        CHECK(e.all_mean < edge_bound[m] / 3);
        std::printf("  %2dx: silhouette %.2f (max %.1f, %d px), all %.3f\n", static_cast<int>(MODES[m]), e.edge_mean,
                    e.edge_max, e.edge_pixels, e.all_mean);
        previous = e.edge_mean;
    }
}

TEST(msaa_images_do_not_depend_on_the_thread_count) {
    constexpr int S = 96;
    for (const mesh &m : {make_icosphere(3), make_torus_knot(2, 3, 60, 8)}) {
        const small_scene scene = make_small_scene(m, 0.5f);
        for (sample_count n : MODES) {
            canvas_ptr one = make_canvas(S, S).value();
            render(scene, *one, n, 1, 0.2f);
            for (int threads : {2, 3}) {
                canvas_ptr c = make_canvas(S, S).value();
                render(scene, *c, n, threads, 0.2f);
                int differ = 0;
                for (int i = 0; i < S * S; ++i) differ += c->data[i] != one->data[i];
                CHECK_EQ(differ, 0);
            }
        }
    }
}

// The instruction set of the multisampled frames changes the speed only: every one this CPU
// runs (use_multisample_simd) draws the same image as the portable kernel, in every mode, at
// 1 and 2 threads; the setting is refused during a frame and for what the CPU lacks.
TEST(msaa_images_do_not_depend_on_the_instruction_set) {
    constexpr int S = 96;
    const small_scene scene = make_small_scene(make_torus_knot(2, 3, 60, 8), 0.5f);
    render_context probe(1);
    CHECK(probe.multisample_simd_in_use() == best_multisample_simd());
    CHECK(probe.use_multisample_simd(multisample_simd::portable));
    CHECK(probe.multisample_simd_in_use() == multisample_simd::portable);
    int runs = 0;
    for (multisample_simd simd : {multisample_simd::sse2, multisample_simd::avx2, multisample_simd::avx512})
        runs += probe.use_multisample_simd(simd);
    CHECK(runs >= (best_multisample_simd() == multisample_simd::portable ? 0 : 1));
    canvas_ptr frame = make_canvas(8, 8).value();
    CHECK(probe.begin_frame(*frame, 0.0f, sample_count::x4).ok());
    const multisample_simd during = probe.multisample_simd_in_use();
    CHECK(!probe.use_multisample_simd(multisample_simd::portable));
    CHECK(probe.multisample_simd_in_use() == during);
    probe.end_frame();
    for (sample_count n : {sample_count::x4, sample_count::x8, sample_count::x16})
        for (int threads : {1, 2}) {
            canvas_ptr reference = make_canvas(S, S).value();
            render_context portable(threads);
            CHECK(portable.use_multisample_simd(multisample_simd::portable));
            CHECK(draw_frame(portable, *reference, scene.mesh, scene.params, 0.2f, n).ok());
            for (multisample_simd simd : {multisample_simd::sse2, multisample_simd::avx2, multisample_simd::avx512}) {
                render_context ctx(threads);
                if (!ctx.use_multisample_simd(simd)) continue;
                canvas_ptr c = make_canvas(S, S).value();
                CHECK(draw_frame(ctx, *c, scene.mesh, scene.params, 0.2f, n).ok());
                int differ = 0;
                for (int i = 0; i < S * S; ++i) differ += c->data[i] != reference->data[i];
                CHECK_EQ(differ, 0);
            }
        }
}

// The background keeps the clear intensity's bits in every mode and kernel. The 4× block
// kernels also store (and mark touched) the pixels of a block they cover no sample of,
// which then hold the clear intensity c in every sample: their resolve ((c + c) + (c + c))/4
// must be c exactly, as it is for every c in [0, 1] (begin_frame clamps it there), the
// smallest subnormal included. Against the portable kernel, which stores covered pixels
// only, and against the background of the frame cleared to 0.
TEST(msaa_background_keeps_the_clear_intensity) {
    constexpr int S = 64;
    const small_scene scene = make_small_scene(make_icosphere(2), 0.5f);
    auto bits = [](float v) { return std::bit_cast<std::uint32_t>(v); };
    const float below_one = std::nextafter(1.0f, 0.0f), tiny = std::numeric_limits<float>::denorm_min();
    // (clear intensity passed, the background expected)
    const std::pair<float, float> clears[] = {{0.2f, 0.2f}, {tiny, tiny}, {below_one, below_one}, {1.0f, 1.0f},
                                              {3e38f, 1.0f}, {-std::numeric_limits<float>::infinity(), 0.0f}};
    for (sample_count n : {sample_count::x4, sample_count::x8, sample_count::x16}) {
        canvas_ptr black = make_canvas(S, S).value();
        render(scene, *black, n, 1, 0.0f);
        int background = 0;
        for (int i = 0; i < S * S; ++i) background += bits(black->data[i]) == 0;
        CHECK(background > S * S / 4);  // the sphere leaves a border of background
        for (const auto &[clear, expected] : clears) {
            canvas_ptr reference = make_canvas(S, S).value();
            render_context portable(1);
            CHECK(portable.use_multisample_simd(multisample_simd::portable));
            CHECK(draw_frame(portable, *reference, scene.mesh, scene.params, clear, n).ok());
            for (multisample_simd simd : {multisample_simd::portable, multisample_simd::sse2, multisample_simd::avx2,
                                          multisample_simd::avx512}) {
                render_context ctx(2);
                if (!ctx.use_multisample_simd(simd)) continue;
                canvas_ptr c = make_canvas(S, S).value();
                CHECK(draw_frame(ctx, *c, scene.mesh, scene.params, clear, n).ok());
                int differ = 0, not_clear = 0;
                for (int i = 0; i < S * S; ++i) {
                    differ += bits(c->data[i]) != bits(reference->data[i]);
                    not_clear += bits(black->data[i]) == 0 && bits(c->data[i]) != bits(expected);
                }
                CHECK_EQ(differ, 0);
                CHECK_EQ(not_clear, 0);
            }
        }
    }
}

// A tile is at rest between bands (every sample depth 1 and the clear colour in memory,
// which every multisample kernel relies on): resize puts it there, for the clear colour
// given, whenever the layout or the clear colour changes; and one context drawing frame
// after frame with other clears, sample counts and canvas sizes gives each frame a fresh
// context gives, with every kernel.
TEST(msaa_tile_at_rest_follows_the_clear_the_mode_and_the_size) {
    detail::sample_store store;
    int wrong = 0;
    for (const auto &[width, samples, clear, blocks] :
         {std::tuple{9, 4, 0.3f, false}, std::tuple{9, 4, 0.6f, false}, std::tuple{9, 16, 0.6f, false},
          std::tuple{9, 4, 0.6f, false}, std::tuple{9, 4, 0.6f, true}, std::tuple{40, 4, 0.6f, true},
          std::tuple{40, 4, 0.6f, false}}) {
        store.resize(width, 3, samples, clear, blocks);
        store.start(0, 3);
        CHECK_EQ(store.blocks(), blocks);
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < width; ++x)
                for (int s = 0; s < samples; ++s) {
                    const float *p = store.pixel(x, y);
                    wrong += p[s] != 1.0f;
                    wrong += p[store.colour_offset() + s] != clear;
                }
    }
    CHECK_EQ(wrong, 0);
    const small_scene near_sphere = make_small_scene(make_icosphere(2), 0.3f);
    small_scene far_sphere = make_small_scene(make_icosphere(3), 1.1f);
    far_sphere.params.model = mat4_multiply(mat4_translate(0.4f, -0.2f, -1.0f), far_sphere.params.model);
    struct frame {
        const small_scene *scene;
        int size;
        float clear;
        sample_count n;
    };
    const frame frames[] = {{&near_sphere, 48, 0.1f, sample_count::x4},  {&far_sphere, 48, 0.1f, sample_count::x4},
                            {&near_sphere, 48, 0.7f, sample_count::x4},  {&far_sphere, 48, 0.7f, sample_count::x16},
                            {&near_sphere, 48, 0.7f, sample_count::x4},  {&far_sphere, 64, 0.7f, sample_count::x4},
                            {&near_sphere, 40, 0.0f, sample_count::x8},  {&far_sphere, 40, 0.0f, sample_count::x4}};
    for (multisample_simd simd : {multisample_simd::portable, multisample_simd::sse2, multisample_simd::avx2,
                                  multisample_simd::avx512}) {
        render_context kept(2);
        if (!kept.use_multisample_simd(simd)) continue;
        for (std::size_t k = 0; k < std::size(frames); ++k) {
            const frame &f = frames[k];
            canvas_ptr a = make_canvas(f.size, f.size).value(), b = make_canvas(f.size, f.size).value();
            CHECK(draw_frame(kept, *a, f.scene->mesh, f.scene->params, f.clear, f.n).ok());
            render_context fresh(2);
            CHECK(fresh.use_multisample_simd(simd));
            CHECK(draw_frame(fresh, *b, f.scene->mesh, f.scene->params, f.clear, f.n).ok());
            CHECK_MSG(std::memcmp(a->data, b->data, sizeof(float) * static_cast<std::size_t>(f.size * f.size)) == 0,
                      "frame " + std::to_string(k));
        }
    }
}

// Several draws in one frame (Gouraud sphere, a textured Phong quad through it, a clipped
// quad crossing the near plane, a translucent torus knot): every mode, 1, 2 and 3 threads.
TEST(msaa_multi_draw_frames_do_not_depend_on_the_thread_count) {
    constexpr int S = 72;
    texture checker;
    checker.width = checker.height = 16;
    for (int i = 0; i < 256; ++i) checker.texels.push_back(((i + i / 16) % 2) ? 1.0f : 0.2f);
    const multi_draw_scene scene(std::move(checker));
    const small_scene &sphere = scene.sphere, &knot = scene.knot;
    const raster_mesh &quad = scene.quad;
    draw_params qp = scene.quad_params;
    qp.model = mat4_multiply(mat4_rotate_x(-1.2f), mat4_scale(1, 1, 1));
    draw_params near = qp;  // reaches behind the camera: clipped
    near.model = mat4_multiply(mat4_translate(0, -0.3f, 2.5f), mat4_rotate_x(-1.5f));
    near.filter = texture_filter::bilinear;
    for (sample_count n : MODES) {
        canvas_ptr images[3];
        frame_stats stats[3];
        for (int threads = 1; threads <= 3; ++threads) {
            images[threads - 1] = make_canvas(S, S).value();
            render_context ctx(threads);
            CHECK(ctx.begin_frame(*images[threads - 1], 0.1f, n).ok());
            ctx.draw(sphere.mesh, sphere.params);
            ctx.draw(quad, qp);
            ctx.draw(quad, near);
            ctx.draw(knot.mesh, knot.params);
            ctx.end_frame();
            stats[threads - 1] = ctx.stats();
        }
        for (int k = 1; k < 3; ++k) {  // the counts too
            CHECK_EQ(stats[k].rasterized, stats[0].rasterized);
            CHECK_EQ(stats[k].culled_backface, stats[0].culled_backface);
            CHECK_EQ(stats[k].clipped, stats[0].clipped);
        }
        CHECK(stats[0].clipped > 0);  // the near quad was clipped
        for (int k = 1; k < 3; ++k) {
            int differ = 0;
            for (int i = 0; i < S * S; ++i) differ += images[k]->data[i] != images[0]->data[i];
            CHECK_EQ(differ, 0);
        }
        double sum = 0;
        for (int i = 0; i < S * S; ++i) sum += images[0]->data[i];
        CHECK(sum > 0.2 * S * S);  // something was drawn
    }
}

// The sample store's layouts the SIMD kernels rely on (sample_store), across resizes that
// shrink and grow the width, odd row counts included: rows padded to a multiple of
// STRIDE_PIXELS; every pixel's depths and colours S floats each, disjoint, together filling
// the tile without a gap; pixel_step from column to column; in rows pixel after pixel, each
// row's first on a 64-byte boundary (at 4 samples a pixel pair from an even column one
// aligned 64-byte line); in blocks (4 samples) 2 × 2 pixels from column 0 and the tile's
// origin, 128 bytes each and 64-byte aligned, pixel q = 2r + j at float 4q of the block's
// depths and of its colours 16 floats on (the AVX-512 and AVX2 kernels' lanes: their tables'
// 4× layout). Blocks are asked of 8 and 16 samples too, and not given.
TEST(msaa_sample_store_layout) {
    detail::sample_store store;
    for (int width : {1, 2, 3, 5, 8, 41, 7, 1024})
        for (int samples : {4, 8, 16})
            for (int rows : {3, 4})
            for (bool asked : {false, true}) {
                store.resize(width, rows, samples, 0.0f, asked);
                store.start(11, 11 + rows);
                const bool blocks = asked && samples == 4;
                CHECK_EQ(store.blocks(), blocks);
                CHECK_EQ(detail::sample_store::blocks_for(detail::msaa_kernel::avx512, samples), samples == 4);
                CHECK_EQ(detail::sample_store::blocks_for(detail::msaa_kernel::avx2, samples), samples == 4);
                CHECK(!detail::sample_store::blocks_for(detail::msaa_kernel::sse2, samples));
                CHECK_EQ(store.origin(), 11);
                CHECK(store.stride() >= width);
                CHECK_EQ(store.stride() % detail::sample_store::STRIDE_PIXELS, 0);
                CHECK(store.stride() < width + detail::sample_store::STRIDE_PIXELS);
                const int C = store.colour_offset();
                CHECK_EQ(C, blocks ? 16 : samples);
                std::vector<std::pair<const float *, int>> runs;  // (first float, S): every depth and colour run
                const float *first = store.pixel(0, 11);
                const int padded_rows = blocks ? rows + (rows & 1) : rows;
                for (int y = 11; y < 11 + padded_rows; ++y) {
                    CHECK_EQ(store.touched_row(y) - store.touched_row(11), static_cast<long>(y - 11) * store.stride());
                    for (int x = 0; x < store.stride(); ++x) {
                        const float *p = store.pixel(x, y);
                        runs.push_back({p, samples});
                        runs.push_back({p + C, samples});
                        if (x + 1 < store.stride())
                            CHECK_EQ(store.pixel(x + 1, y) - p, detail::sample_store::pixel_step(samples, blocks, x));
                        if (!blocks) {
                            CHECK_EQ(p - first, (static_cast<long>(y - 11) * store.stride() + x) * 2 * samples);
                            if (x % 2 == 0 && samples == 4) CHECK_EQ(reinterpret_cast<std::uintptr_t>(p) % 64, 0u);
                            continue;
                        }
                        const float *block = store.pixel(x & ~1, y - ((y - 11) & 1));
                        CHECK_EQ(reinterpret_cast<std::uintptr_t>(block) % 64, 0u);
                        CHECK_EQ(block - first, ((static_cast<long>(y - 11) / 2) * store.stride() / 2 + x / 2) * 32);
                        CHECK_EQ(p - block, 4L * (2 * ((y - 11) & 1) + (x & 1)));
                    }
                }
                CHECK_EQ(reinterpret_cast<std::uintptr_t>(first) % 64, 0u);
                std::sort(runs.begin(), runs.end());
                int gaps = 0;
                for (std::size_t k = 0; k < runs.size(); ++k)
                    gaps += runs[k].first != first + static_cast<std::ptrdiff_t>(k) * samples;
                CHECK_EQ(gaps, 0);
            }
}

// No allocation per frame in steady state, multisampled frames included: after one frame
// of each mode (the tiles and triangle lists grow to the largest), frames cycling through
// every mode with several draws (textured, Phong, translucent) allocate nothing.
TEST(msaa_frames_allocate_nothing_in_steady_state) {
    constexpr int S = 64;
    texture grey;
    grey.width = grey.height = 8;
    grey.texels.assign(64, 0.5f);
    const multi_draw_scene scene(std::move(grey));
    canvas_ptr c = make_canvas(S, S).value();
    render_context ctx(2);
    auto frame = [&](sample_count n) {
        CHECK(ctx.begin_frame(*c, 0.1f, n).ok());
        ctx.draw(scene.sphere.mesh, scene.sphere.params);
        ctx.draw(scene.quad, scene.quad_params);
        ctx.draw(scene.knot.mesh, scene.knot.params);
        ctx.end_frame();
    };
    for (sample_count n : MODES) frame(n);
    const std::size_t before = alloc_tracker::allocations();
    for (int k = 0; k < 12; ++k) frame(MODES[(k * 3) % 4]);
    CHECK_EQ(alloc_tracker::allocations() - before, std::size_t{0});
}

TEST(msaa_x1_is_the_aliased_image) {
    constexpr int S = 80;
    const small_scene scene = make_small_scene(make_icosphere(2), 0.2f);
    canvas_ptr a = make_canvas(S, S).value(), b = make_canvas(S, S).value();
    render(scene, *a, sample_count::x1, 1);
    render_context ctx(1);
    CHECK(ctx.begin_frame(*b).ok());  // the default
    ctx.draw(scene.mesh, scene.params);
    ctx.end_frame();
    int differ = 0;
    for (int i = 0; i < S * S; ++i) differ += a->data[i] != b->data[i];
    CHECK_EQ(differ, 0);
}

TEST(sample_count_parsing_and_bad_counts) {
    CHECK(parse_sample_count("4").value() == sample_count::x4);
    CHECK(parse_sample_count("16x").value() == sample_count::x16);
    CHECK(parse_sample_count("1").value() == sample_count::x1);
    CHECK(!parse_sample_count("2").ok());
    CHECK(!parse_sample_count("").ok());
    canvas_ptr c = make_canvas(8, 8).value();
    render_context ctx(1);
    CHECK(!ctx.begin_frame(*c, 0.0f, static_cast<sample_count>(2)).ok());
}

// ---- the multisample kernels (internal API) -----------------------------------------------

namespace {

// A jittered grid of quads over (and beyond) a W × H canvas, split into triangles with both
// windings, as snapped vertices on the grid of 1/2^bits px: jitter in steps of 1/16 px
// (some vertices on sample positions or edges through them exactly), and on a finer grid
// every other vertex off the 1/16 grid by up to 1/32 px.
std::vector<std::array<std::int32_t, 6>> jittered_grid(int W, int H, unsigned seed, int bits) {
    std::mt19937 rng(seed);
    const int scale = 1 << (bits - 4);
    std::uniform_int_distribution<int> jitter(-20, 20), fine(-scale / 2, scale / 2);  // 1/16 px (quads stay convex)
    constexpr int N = 7;
    std::int32_t gx[N + 1][N + 1], gy[N + 1][N + 1];
    for (int j = 0; j <= N; ++j)
        for (int i = 0; i <= N; ++i) {
            const bool border = i == 0 || j == 0 || i == N || j == N;
            const int off = (i + j) % 2;
            gx[j][i] = (-4 + i * (W + 8) / N) * (16 * scale) + (border ? 0 : jitter(rng) * scale + off * fine(rng));
            gy[j][i] = (-4 + j * (H + 8) / N) * (16 * scale) + (border ? 0 : jitter(rng) * scale + off * fine(rng));
        }
    std::vector<std::array<std::int32_t, 6>> tris;
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            const std::int32_t ax = gx[j][i], ay = gy[j][i], bx = gx[j][i + 1], by = gy[j][i + 1];
            const std::int32_t cx = gx[j + 1][i + 1], cy = gy[j + 1][i + 1], dx = gx[j + 1][i], dy = gy[j + 1][i];
            if ((i + j) % 2) {
                tris.push_back({ax, ay, bx, by, cx, cy});
                tris.push_back({ax, ay, dx, dy, cx, cy});  // opposite winding
            } else {
                tris.push_back({ax, ay, bx, by, dx, dy});
                tris.push_back({bx, by, cx, cy, dx, dy});
            }
        }
    return tris;
}

// Fills the triangles in order (or reversed) into a fresh store, all at depth 0.5 with depth
// test LESS, triangle t in intensity (t + 1) / 1024: each sample keeps the FIRST triangle
// covering it, and depth 0.5 once covered.
detail::sample_store fill_all(const std::vector<std::array<std::int32_t, 6>> &tris, int W, int H, int samples,
                              bool reversed, detail::msaa_kernel kernel) {
    detail::sample_store store;
    store.resize(W, H, samples, 0.0f, detail::sample_store::blocks_for(kernel, samples));
    store.start(0, H);
    const detail::sample_pattern &pat = detail::pattern_of(samples);
    for (std::size_t n = 0; n < tris.size(); ++n) {
        const std::size_t t = reversed ? tris.size() - 1 - n : n;
        const std::int32_t X[3] = {tris[t][0], tris[t][2], tris[t][4]}, Y[3] = {tris[t][1], tris[t][3], tris[t][5]};
        const triangle_edges e = detail::triangle_setup_snapped(X, Y, {0, 0, W, H}, cull_mode::none, pat.bits);
        const float depth[3] = {0.5f, 0.5f, 0.5f};
        const float shade = static_cast<float>(t + 1) / 1024, intensity[3] = {shade, shade, shade};
        detail::msaa_triangle f;
        if (e.area2 == 0 ||
            !detail::make_msaa_triangle(X, Y, detail::snapped_area2(X, Y), pat, {0, 0, W, H}, depth, intensity, f))
            continue;
        detail::msaa_fill_for(kernel, pat.count, depth_func::less)(store, f, pat, depth_func::less, 0, H);
    }
    return store;
}

}  // namespace

// A mesh with shared edges covers every sample exactly once: drawn first to last and last to
// first, every sample is covered (depth 0.5) and shows the same triangle both ways (a sample
// covered twice would show the first triangle one way and the other the other way).
TEST(msaa_watertight_per_sample) {
    constexpr int W = 37, H = 29;
    for (unsigned seed : {1u, 2u, 3u})
        for (int samples : {4, 8, 16})
            for (detail::msaa_kernel kernel : msaa_kernels()) {
                const auto tris = jittered_grid(W, H, seed, detail::pattern_of(samples).bits);
                detail::sample_store forward = fill_all(tris, W, H, samples, false, kernel);
                detail::sample_store backward = fill_all(tris, W, H, samples, true, kernel);
                int gaps = 0, doubles = 0;
                for (int y = 0; y < H; ++y)
                    for (int x = 0; x < W; ++x) {
                        const float *f = forward.pixel(x, y), *b = backward.pixel(x, y);
                        // (a tile at rest holds every sample in memory, marked or not: sample_store)
                        for (int s = 0; s < samples; ++s) {
                            gaps += f[s] != 0.5f;
                            const int c = forward.colour_offset() + s;
                            doubles += f[c] != b[c];
                        }
                    }
                CHECK_EQ(gaps, 0);
                CHECK_EQ(doubles, 0);
            }
}

// The 16-sample pattern: on the 1/256 px grid, a 4 × 4 rotated grid of odd multiples of
// 1/32 px, every row and column distinct, centred on the pixel; and the coverage the edge
// functions give equals an independent exact test (the top-left rule at a tie), for random
// triangles of either winding snapped to that grid.
TEST(msaa_16_pattern_is_centred_and_its_coverage_exact) {
    const detail::sample_pattern &pat = detail::pattern_of(16);
    CHECK_EQ(pat.bits, detail::MSAA_16_SUBPIXEL_BITS);
    CHECK_EQ(pat.one(), std::int64_t{256});
    int sum_x = 0, sum_y = 0;
    unsigned columns = 0, rows = 0;
    for (int s = 0; s < 16; ++s) {
        CHECK_EQ(pat.dx[s] % 16, pat.dx[s] < 0 ? -8 : 8);  // odd multiples of 8/256 = 1/32 px
        CHECK_EQ(pat.dy[s] % 16, pat.dy[s] < 0 ? -8 : 8);
        CHECK_EQ(static_cast<double>(pat.fdx[s]), pat.dx[s] / 256.0);
        sum_x += pat.dx[s], sum_y += pat.dy[s];
        columns |= 1u << ((pat.dx[s] / 8 + 15) / 2), rows |= 1u << ((pat.dy[s] / 8 + 15) / 2);
    }
    CHECK_EQ(sum_x, 0);
    CHECK_EQ(sum_y, 0);
    CHECK_EQ(columns, 0xFFFFu);
    CHECK_EQ(rows, 0xFFFFu);
    constexpr int W = 12, H = 10;
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> coord(-320, 12 * 256 + 320);
    int checked = 0, mismatches = 0, ties = 0;
    for (int trial = 0; trial < 300; ++trial) {
        std::int32_t X[3], Y[3];
        for (int k = 0; k < 3; ++k) {
            X[k] = coord(rng), Y[k] = coord(rng);
            if (trial % 3 == 0) X[k] &= ~127, Y[k] &= ~127;  // coarse vertices: many samples on edges
            if (trial % 3 == 1) X[k] = X[k] / 16 * 16 + 8, Y[k] = Y[k] / 16 * 16 + 8;  // on sample rows, columns
        }
        const triangle_edges t = detail::triangle_setup_snapped(X, Y, {0, 0, W, H}, cull_mode::none, pat.bits);
        if (!t.valid) continue;
        const std::int64_t s = t.area2 == detail::snapped_area2(X, Y) ? 1 : -1;
        std::vector<unsigned> masks(W * H, 0);
        detail::for_each_covered_pixel(t, X, Y, pat, {0, 0, W, H},
                                       [&](int x, int y, unsigned m) { masks[y * W + x] = m; });
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                unsigned expect = 0;
                for (int q = 0; q < 16; ++q) {
                    const std::int64_t qx = 256 * x + 128 + pat.dx[q], qy = 256 * y + 128 + pat.dy[q];
                    bool in = true;
                    for (int k = 0; k < 3; ++k) {
                        const int a = (k + 1) % 3, b = (k + 2) % 3;
                        const std::int64_t dx = s * (X[b] - X[a]), dy = s * (Y[b] - Y[a]);
                        const std::int64_t e = dx * (qy - Y[a]) - dy * (qx - X[a]);
                        ties += e == 0;
                        in = in && (e > 0 || (e == 0 && (dy < 0 || (dy == 0 && dx > 0))));
                    }
                    expect |= static_cast<unsigned>(in) << q;
                }
                mismatches += masks[y * W + x] != expect;
                ++checked;
            }
    }
    CHECK(checked > 10000);
    CHECK(ties > 0);
    CHECK_EQ(mismatches, 0);
}

// The SIMD kernels (SSE2, AVX2, AVX-512, as the CPU runs them) against the portable one:
// random overlapping triangles with depth (ties included, every depth test), every sample
// bit-identical; large triangles, small ones (boxes at most 8 columns) and medium ones (up to
// 16: every step count of the 4× box walk), some off the canvas' edges; and wide ones,
// reaching far beyond the canvas (boxes beyond what 32-bit values cover: rows walked in
// chunks, offsets in integers — msaa_kernels.h). Each SIMD kernel in the tile layout the
// render context gives it and in the other one (blocks at 4×: sample_store), samples and
// resolves alike.
TEST(msaa_simd_kernels_match_the_portable_kernel) {
    constexpr int W = 41, H = 33;
    const std::vector<detail::msaa_kernel> kernels = msaa_kernels();
    // The clip: the canvas, or a rectangle inside it from an odd column to an odd column, so
    // that the 4× kernel's 2 × 2 blocks straddle both of its sides.
    const pixel_rect clips[] = {{0, 0, W, H}, {1, 2, W - 2, H - 1}};
    for (std::size_t kernel = 1; kernel < kernels.size(); ++kernel)
    for (const pixel_rect clip : clips)
    for (int size : {0, 1, 2, 3})  // large, small, wide, medium
        for (int samples : {4, 8, 16}) {
            const bool medium = size == 3, small = size == 1 || medium, wide = size == 2;
            std::mt19937 rng(11 + static_cast<unsigned>(samples));
            const detail::sample_pattern &pat = detail::pattern_of(samples);
            const int grid = static_cast<int>(pat.one());  // sub-pixel units per px
            // Wide: vertices up to 3000 px (4×, 8×) or 400 px (16×) off the canvas.
            const int reach = wide ? (pat.bits == RASTER_SUBPIXEL_BITS ? 3000 : 400) : 5;
            std::uniform_int_distribution<int> coord(-reach * grid, (40 + reach) * grid), near(-3 * grid, 3 * grid),
                spread(-8 * grid, 8 * grid);
            std::uniform_real_distribution<float> unit(0.0f, 1.0f);
            detail::sample_store a, b;
            // (a in the layout its kernel is given, blocks for AVX-512 at 4×; other: the same
            // kernel in the other layout, which every kernel takes too)
            detail::sample_store other;
            const bool blocks = detail::sample_store::blocks_for(kernels[kernel], samples);
            a.resize(W, H, samples, 0.25f, blocks), a.start(0, H);
            b.resize(W, H, samples, 0.25f), b.start(0, H);
            other.resize(W, H, samples, 0.25f, !blocks), other.start(0, H);
            int narrow_boxes = 0, drawn = 0, chunked = 0, clipped = 0;
            unsigned step_counts = 0;  // bit n - 1: a box the 4× kernels walk whole in n steps per row
            for (int t = 0; t < (small ? 600 : 60); ++t) {
                std::int32_t X[3] = {coord(rng), coord(rng), coord(rng)}, Y[3] = {coord(rng), coord(rng), coord(rng)};
                if (small)
                    for (int k = 1; k < 3; ++k)
                        X[k] = X[0] + (medium ? spread(rng) : near(rng)), Y[k] = Y[0] + (medium ? spread(rng) : near(rng));
                const triangle_edges e = detail::triangle_setup_snapped(X, Y, clip, cull_mode::none, pat.bits);
                // Every other triangle at a constant depth of 0.25 or 0.5: equal depths, so the
                // depth test's ties are decided too.
                float depth[3] = {unit(rng), unit(rng), unit(rng)};
                if (t % 2) depth[0] = depth[1] = depth[2] = t % 4 == 1 ? 0.25f : 0.5f;
                const float intensity[3] = {unit(rng), unit(rng), unit(rng)};
                detail::msaa_triangle f;
                if (e.area2 == 0 ||
                    !detail::make_msaa_triangle(X, Y, detail::snapped_area2(X, Y), pat, clip, depth, intensity, f))
                    continue;
                CHECK(f.chunkable);
                CHECK(wide || f.narrow);
                chunked += !f.narrow;
                clipped += f.clipped_x;
                ++drawn;
                narrow_boxes += f.max_x - f.min_x < 8;
                if (const int columns = f.max_x - f.min_x + 1; columns <= 16)
                    step_counts |= 1u << ((columns + (f.min_x & 1) + 1) / 2 - 1);
                // Mostly `less`; every seventh triangle another test.
                constexpr depth_func tests[] = {depth_func::less_equal, depth_func::equal, depth_func::greater,
                                                depth_func::greater_equal, depth_func::not_equal, depth_func::always,
                                                depth_func::never};
                const depth_func test = t % 7 ? depth_func::less : tests[(t / 7) % 7];
                detail::msaa_fill_for(kernels[kernel], pat.count, test)(a, f, pat, test, 0, H);
                detail::msaa_fill_for(kernels[kernel], pat.count, test)(other, f, pat, test, 0, H);
                detail::msaa_fill_for(kernels[0], pat.count, test)(b, f, pat, test, 0, H);
            }
            CHECK(medium ? step_counts == 0x1FFu : small ? narrow_boxes == drawn : narrow_boxes < drawn / 4);
            // (small: boxes cut by the clip and boxes not, which the 4× block kernel walks without
            // masking the column past them)
            if (small) CHECK(clipped > 0 && clipped < drawn);
            CHECK(wide ? chunked > drawn / 2 : chunked == 0);
            // Every sample as the stores hold it: in memory, touched or not (the tile is at rest:
            // sample_store).
            // Value s of a pixel's 2·samples: its depths, then its colours.
            auto value = [samples](const detail::sample_store &st, int x, int y, int s) {
                const float *p = st.pixel(x, y);
                return s < samples ? p[s] : p[st.colour_offset() + s - samples];
            };
            int differ = 0, touched = 0;
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x) {
                    touched += b.touched_row(y)[x];
                    for (int s = 0; s < 2 * samples; ++s)
                        differ += (value(a, x, y, s) != value(b, x, y, s)) + (value(other, x, y, s) != value(b, x, y, s));
                }
            CHECK(touched > (clip.x1 - clip.x0) * (clip.y1 - clip.y0) / 2);
            CHECK_EQ(differ, 0);
            // The resolve (SSE2: four pixels at a time, W = 41 leaves a tail) of `a` against the
            // portable loop's of `b` (the same samples), bit-identical, and against the plain
            // mean and minimum, taken before: the resolve puts the samples back at rest.
            std::vector<double> mean(static_cast<std::size_t>(W * H), 0.25);
            std::vector<float> nearest(static_cast<std::size_t>(W * H), 1.0f);
            int untouched = 0;
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x) {
                    const float *px = a.pixel(x, y);
                    const std::size_t i = static_cast<std::size_t>(y * W + x);
                    untouched += !a.touched_row(y)[x];
                    mean[i] = 0;
                    for (int s = 0; s < samples; ++s) mean[i] += value(a, x, y, samples + s) / samples;
                    nearest[i] = *std::min_element(px, px + samples);
                }
            canvas_ptr fast = make_canvas(W, H).value(), plain = make_canvas(W, H).value();
            canvas_ptr in_other = make_canvas(W, H).value();
            zbuffer fast_z, plain_z, other_z;
            CHECK(fast_z.resize(W, H).ok() && plain_z.resize(W, H).ok() && other_z.resize(W, H).ok());
            a.resolve(*fast, fast_z, kernels[kernel]);
            b.resolve(*plain, plain_z, kernels[0]);
            other.resolve(*in_other, other_z, kernels[kernel]);
            int resolve_differ = 0, not_at_rest = 0;
            double worst = 0;
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x) {
                    resolve_differ += fast->pixels[y][x] != plain->pixels[y][x] || fast_z.at(x, y) != plain_z.at(x, y);
                    resolve_differ += in_other->pixels[y][x] != plain->pixels[y][x] || other_z.at(x, y) != plain_z.at(x, y);
                    const std::size_t i = static_cast<std::size_t>(y * W + x);
                    worst = std::max(worst, std::fabs(mean[i] - fast->pixels[y][x]));
                    CHECK_EQ(fast_z.at(x, y), nearest[i]);
                    // At rest again: every sample of every pixel (1, 0.25).
                    for (const detail::sample_store *st : {&a, &b, &other})
                        for (int s = 0; s < 2 * samples; ++s)
                            not_at_rest += value(*st, x, y, s) != (s < samples ? 1.0f : 0.25f);
                }
            CHECK_EQ(resolve_differ, 0);
            CHECK_EQ(not_at_rest, 0);
            CHECK(small && !medium ? untouched > 0 : true);  // (medium boxes cover the canvas)
            CHECK(worst < 1e-6);
            // A tile no triangle touched (the SIMD resolves pass over runs of untouched pixels
            // without reading their samples): the clear values everywhere.
            detail::sample_store empty;
            empty.resize(W, H, samples, 0.25f, detail::sample_store::blocks_for(kernels[kernel], samples));
            empty.start(0, H);
            empty.resolve(*fast, fast_z, kernels[kernel]);
            int not_clear = 0;
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x) not_clear += fast->pixels[y][x] != 0.25f || fast_z.at(x, y) != 1.0f;
            CHECK_EQ(not_clear, 0);
        }
}

#ifdef TINY3D_SSE2
// The SSE2 4× kernel's row spans without divisions (sample_row_spans) against the exact
// ones (edge_extremes::row): every row's span holds the exact one and is at most one column
// wider at each end, for narrow triangles of every size up to the narrow limit (the float
// quotient's error grows with the box) and at every sample pattern on the 1/16 px grid; and
// each row's edge values t are the exact ones at the best sample, e + b·dy + best.
TEST(msaa_row_spans_hold_the_exact_spans) {
    const pixel_rect clip{0, 0, 2100, 2100};
    int rows = 0, wider = 0;
    for (int samples : {4, 8}) {
        const detail::sample_pattern &pat = detail::pattern_of(samples);
        const int grid = static_cast<int>(pat.one());
        std::mt19937 rng(5 + static_cast<unsigned>(samples));
        for (int t = 0; t < 3000; ++t) {
            const int reach = t % 3 == 0 ? 2000 : t % 3 == 1 ? 40 : 4;  // px
            std::uniform_int_distribution<int> base(0, (2040 - reach) * grid), near(0, reach * grid);
            const std::int32_t x0 = base(rng), y0 = base(rng);
            std::int32_t X[3] = {x0 + near(rng), x0 + near(rng), x0 + near(rng)};
            std::int32_t Y[3] = {y0 + near(rng), y0 + near(rng), y0 + near(rng)};
            if (t % 7 == 0) Y[1] = Y[0];  // a horizontal edge (a = 0)
            if (t % 11 == 0) X[2] = X[1];  // a vertical one (b = 0)
            const triangle_edges e = detail::triangle_setup_snapped(X, Y, clip, cull_mode::none, pat.bits);
            const float flat[3] = {0.5f, 0.5f, 0.5f};
            detail::msaa_triangle f;
            if (e.area2 == 0 || !detail::make_msaa_triangle(X, Y, detail::snapped_area2(X, Y), pat, clip, flat, flat, f))
                continue;
            CHECK(f.narrow);
            detail::edge_extremes off;
            std::int64_t best[3];
            for (int k = 0; k < 3; ++k) {
                off.lo[k] = INT64_MAX, off.hi[k] = INT64_MIN;
                for (int s = 0; s < samples; ++s) {
                    const std::int64_t d = detail::sample_edge_offset(f.a[k], f.b[k], pat, s);
                    off.lo[k] = std::min(off.lo[k], d), off.hi[k] = std::max(off.hi[k], d);
                }
                best[k] = off.hi[k];
            }
            detail::sample_row_spans spans;
            spans.start(f, _mm_setr_epi32(static_cast<std::int32_t>(best[0]), static_cast<std::int32_t>(best[1]),
                                          static_cast<std::int32_t>(best[2]), 0), 0);
            alignas(16) std::int32_t first4[4], last4[4], t4[3][4];
            for (int y = f.min_y, r = 4; y <= f.max_y; ++y, ++r) {
                if (r == 4) {
                    __m128i a, b, t[3];
                    spans.next4(a, b, t);
                    _mm_store_si128(reinterpret_cast<__m128i *>(first4), a);
                    _mm_store_si128(reinterpret_cast<__m128i *>(last4), b);
                    for (int k = 0; k < 3; ++k) _mm_store_si128(reinterpret_cast<__m128i *>(t4[k]), t[k]);
                    r = 0;
                }
                const int first = first4[r], last = last4[r];
                for (int k = 0; k < 3; ++k)
                    CHECK(t4[k][r] == static_cast<std::int32_t>(f.e[k] + f.b[k] * (y - f.min_y) + best[k]));
                int lo, hi;
                std::int64_t v[3];
                if (!off.row(f, y, v, lo, hi)) continue;
                ++rows;
                wider += first < lo || last > hi;
                CHECK(first <= lo && first >= lo - 1);
                CHECK(last >= hi && last <= hi + 1);
            }
        }
    }
    CHECK(rows > 100000);
    CHECK(wider > 0);
}
#endif
