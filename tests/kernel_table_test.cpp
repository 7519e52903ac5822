// Tests of the kernel tables (src/kernels.h), walking every table this CPU runs:
//  * each table is what it says (its instruction set, its name, a band kernel);
//  * every table draws its family reference's frames bit for bit — at 4×, 8× and 16× the
//    portable table's (the multisample kernels are bit-identical to it), at 1× the SSE2
//    table's (raster.h: the portable 1× kernel may differ in the last bits of depth and
//    intensity; its coverage is compared with a tolerance there) — on Scene S, a bumpy
//    unseen mesh, slivers, triangles far outside the canvas (clipped, huge coordinates) and
//    triangles whose edges lie on band edges, on one and two threads;
//  * the tables' line kernels draw the portable line kernel's image (to float rounding);
//  * the tables' anisotropic tap walks return the portable walk's float bit for bit.
#include "harness.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "canvas.h"
#include "lines.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"
#include "raster_test_util.h"
#include "../src/kernels.h"
#include "../src/raster/texture/texture_walk.h"

using namespace tiny3d;

namespace {

const raster_simd ALL[] = {raster_simd::portable, raster_simd::sse2, raster_simd::avx2, raster_simd::avx512};

// Scene S level 4 displaced by a smooth bump field: an irregular mesh no kernel was tuned on.
raster_mesh bumpy_mesh() {
    mesh m = make_icosphere(4);
    for (vec3_t &p : m.positions) {
        const float r = 1.0f + 0.18f * std::sin(7.0f * p.x + 1.3f) * std::cos(5.0f * p.y) + 0.07f * std::sin(11.0f * p.z);
        p = {p.x * r, p.y * r, p.z * r};
    }
    return raster_test::smooth_raster_mesh(m);
}

// Triangles given directly in object space (z = 0 plane seen by scene_s_params' camera).
raster_mesh soup(const std::vector<vec3_t> &corners) {
    raster_mesh m;
    for (std::size_t k = 0; k < corners.size(); ++k) {
        m.positions.push_back(corners[k]);
        m.normals.push_back(vec3_normalize_fast({0.3f * static_cast<float>(k % 5) - 0.6f, 0.2f, 1.0f}));
        m.uvs.push_back({0, 0});
    }
    for (std::uint32_t k = 0; k + 2 < corners.size(); k += 3) m.triangles.push_back({k, k + 1, k + 2});
    m.bound_center = {0, 0, 0};
    for (const vec3_t &q : corners) m.bound_radius = std::fmax(m.bound_radius, vec3_length(q));
    return m;
}

// Long thin triangles at many angles, some under a pixel wide.
raster_mesh slivers() {
    std::vector<vec3_t> c;
    for (int k = 0; k < 60; ++k) {
        const float a = 0.105f * static_cast<float>(k), w = 0.0005f * static_cast<float>(1 + k % 7);
        const float dx = std::cos(a), dy = std::sin(a);
        c.push_back({-dx, -dy, 0.01f * static_cast<float>(k % 3)});
        c.push_back({dx, dy, 0.0f});
        c.push_back({-dx - w * dy, -dy + w * dx, 0.02f});
    }
    return soup(c);
}

// Triangles reaching far beyond the canvas and the guard band (clipped), and one huge.
raster_mesh huge() {
    return soup({{-4000, -3, 0.1f}, {4000, -2.5f, 0.1f}, {0, 3000, -0.2f},
                 {-0.5f, -0.5f, 0.3f}, {1e5f, 0.2f, 0.0f}, {0.1f, 0.6f, 0.2f},
                 {-2e4f, 1e4f, -0.5f}, {-0.2f, -2e4f, 0.0f}, {3e4f, 3e4f, 0.5f}});
}

// Triangles whose horizontal and vertical edges fall on band edges (32 and 16 rows) and
// pixel centres of a 256² canvas: with scene_s_params' camera one object unit at z = 0 is
// h/2 / tan(22.5°) / 3 px.
raster_mesh band_edges() {
    const float unit = 128.0f / std::tan(static_cast<float>(M_PI) / 8.0f) / 3.0f;  // px per object unit
    auto at = [&](float px, float py) -> vec3_t { return {(px - 128.0f) / unit, (128.0f - py) / unit, 0.0f}; };
    std::vector<vec3_t> c;
    for (int k = 0; k < 6; ++k) {
        const float y0 = 32.0f * static_cast<float>(k + 1), x0 = 10.0f + 37.0f * static_cast<float>(k);
        c.push_back(at(x0, y0)), c.push_back(at(x0, y0 + 16.0f)), c.push_back(at(x0 + 20.5f, y0));
        c.push_back(at(x0 + 20.5f, y0)), c.push_back(at(x0, y0 + 16.0f)), c.push_back(at(x0 + 20.5f, y0 + 16.0f));
        c.push_back(at(x0 + 3.5f, y0 - 0.5f)), c.push_back(at(x0 + 3.5f, y0 + 31.5f)), c.push_back(at(x0 + 24.0f, y0 + 15.5f));
    }
    return soup(c);
}

raster_test::rendered render(raster_simd simd, int threads, canvas_t &c, const raster_mesh &m, const draw_params &p,
                             sample_count n) {
    render_context ctx(threads);
    CHECK(ctx.use_simd(simd));
    CHECK(ctx.begin_frame(c, 0.05f, n).ok());
    ctx.draw(m, p);
    ctx.end_frame();
    return raster_test::capture(ctx, c);
}

}  // namespace

TEST(each_table_is_what_it_names) {
    int running = 0;
    for (raster_simd s : ALL) {
        const detail::kernel_table &k = detail::kernels_for(s);
        CHECK(k.simd == s);
        CHECK(std::string(k.name) == raster_simd_name(s));
        CHECK(k.fill_fast_bins != nullptr);
        CHECK((k.setup_fast_batch == nullptr) == (k.setup_msaa_batch == nullptr));  // both set-ups batched or neither
        // The 8- and 16-sample ones (tiles in rows in every table) both or neither, SSE2's tail.
        CHECK((k.resolve_rows8 == nullptr) == (k.resolve_rows16 == nullptr));
        CHECK(k.resolve_rows8 == nullptr || k.resolve_rows_simd);
        running += detail::kernels_run(s);
        if (!detail::kernels_run(s)) {  // a render context refuses a table this CPU lacks
            render_context ctx;
            CHECK(!ctx.use_simd(s));
        }
    }
    CHECK(detail::kernels_run(raster_simd::portable));
    CHECK(running >= 1);
    CHECK(detail::kernels_run(best_raster_simd()));
    const raster_simd_choice chosen = default_raster_simd();
    CHECK(chosen.simd == best_raster_simd());
    CHECK(chosen.honoured == (!chosen.requested.empty() && chosen.requested == raster_simd_name(chosen.simd)));
    render_context ctx;
    CHECK(ctx.simd_in_use() == best_raster_simd());
}

TEST(every_table_draws_its_family_reference_frames) {
    canvas_ptr c = make_canvas(256, 256).value();
    const raster_mesh sphere = raster_test::smooth_raster_mesh(make_icosphere(5));
    const raster_mesh bumpy = bumpy_mesh(), thin = slivers(), far = huge(), edges = band_edges();
    struct scene {
        const char *name;
        const raster_mesh *mesh;
        draw_params params;
    };
    draw_params flat = raster_test::scene_s_params();
    flat.cull = cull_mode::none;
    flat.model = mat4_identity();
    draw_params turned = raster_test::scene_s_params();
    turned.model = mat4_rotate_y(0.6f);
    const std::vector<scene> scenes = {{"Scene S", &sphere, turned}, {"bumpy", &bumpy, turned},
                                       {"slivers", &thin, flat},    {"huge", &far, flat},
                                       {"band edges", &edges, flat}};
    int compared = 0;
    for (const scene &sc : scenes)
        for (sample_count n : {sample_count::x1, sample_count::x4, sample_count::x8, sample_count::x16}) {
            const bool one = n == sample_count::x1;
            // The family's reference: SSE2's 1× kernels (where the build has them), the
            // portable multisample kernels.
            const raster_simd reference = one && detail::kernels_run(raster_simd::sse2) ? raster_simd::sse2
                                                                                        : raster_simd::portable;
            const raster_test::rendered want = render(reference, 1, *c, *sc.mesh, sc.params, n);
            CHECK_MSG(want.stats.rasterized > 0, sc.name);
            if (sc.mesh == &far) CHECK(want.stats.clipped > 0);  // (the huge triangles reach the clipper)
            for (raster_simd s : ALL) {
                if (!detail::kernels_run(s)) continue;
                for (int threads : {1, 2}) {
                    const raster_test::rendered got = render(s, threads, *c, *sc.mesh, sc.params, n);
                    const std::string what = std::string(sc.name) + ", " + raster_simd_name(s) + ", " +
                                             std::to_string(static_cast<int>(n)) + " samples, " +
                                             std::to_string(threads) + " threads";
                    if (one && s == raster_simd::portable && reference != raster_simd::portable) {
                        // The portable 1× kernel: the same coverage, values to float rounding.
                        CHECK_EQ(got.colour.size(), want.colour.size());
                        int differ = 0;
                        for (std::size_t k = 0; k < got.colour.size() && k < want.colour.size(); ++k) {
                            differ += std::fabs(got.colour[k] - want.colour[k]) > 1e-5f;
                            differ += (got.colour[k] == 0.05f) != (want.colour[k] == 0.05f);
                        }
                        CHECK_MSG(differ == 0, what);
                    } else {
                        CHECK_MSG(raster_test::same_frame(got, want), what);
                    }
                    ++compared;
                }
            }
        }
    CHECK(compared >= 5 * 4 * 2);  // (the portable table at least: the only one of a portable build)
}

TEST(every_line_table_draws_the_portable_lines) {
    canvas_ptr want = make_canvas(96, 80).value(), got = make_canvas(96, 80).value();
    std::vector<line_segment> segments;
    for (int k = 0; k < 40; ++k) {
        const float a = 0.157f * static_cast<float>(k);
        segments.push_back({48.0f + 5.0f * std::cos(a), 40.0f + 5.0f * std::sin(a), 48.0f + 45.0f * std::cos(a),
                            40.0f + 38.0f * std::sin(a), 0.9f});
    }
    line_table table = line_table::make(1.5f).value();
    CHECK(table.use_simd(line_simd::portable));
    draw_lines_tabulated(want.get(), segments.data(), segments.size(), table);
    int compared = 0;
    for (raster_simd s : ALL) {
        if (!detail::kernels_run(s)) continue;
        const line_simd lines = detail::kernels_for(s).lines;
        CHECK(detail::line_kernels_run(lines));
        CHECK(table.use_simd(lines));
        canvas_clear(got.get(), 0.0f);
        draw_lines_tabulated(got.get(), segments.data(), segments.size(), table);
        float worst = 0.0f;
        for (int y = 0; y < 80; ++y)
            for (int x = 0; x < 96; ++x) worst = std::fmax(worst, std::fabs(got->pixels[y][x] - want->pixels[y][x]));
        CHECK_MSG(worst <= 1e-5f, std::string(raster_simd_name(s)) + ": " + std::to_string(worst));
        ++compared;
    }
    CHECK(compared >= 1);
}


TEST(every_tap_walk_returns_the_portable_walks_bits) {
    // The anisotropic filter's tap walks (src/raster/texture/texture_walk.h) on levels of odd
    // and tiny sizes, 1 to 64 taps in every direction, starting anywhere the contract allows
    // (indices within one wrap of the level, so across both edges): every table's kernel
    // returns exactly the portable walk's float.
    std::vector<float> texels;
    std::uint32_t seed = 2024;
    auto next = [&] {  // uniform in [0, 1)
        seed = seed * 1664525u + 1013904223u;
        return static_cast<float>(seed >> 8) / 16777216.0f;
    };
    const int sizes[][2] = {{1, 1}, {2, 1}, {3, 5}, {37, 23}, {64, 64}, {256, 7}};
    int compared = 0;
    for (const auto &size : sizes) {
        const int w = size[0], h = size[1];
        texels.resize(static_cast<std::size_t>(w) * h);
        for (float &t : texels) t = next();
        for (int trial = 0; trial < 300; ++trial) {
            detail::tap_walk walk{texels.data(), w, h, 0, 0, 0, 0, 1 + trial % 64};
            // Taps within the texel-space box [−w/4 − ½, 5w/4 − ½) × (the same in y): the
            // filter's range (a footprint within half the texture about a centre in [0, 1]).
            const float n = static_cast<float>(walk.taps);
            const float span_x = 0.5f * static_cast<float>(w) * next(), span_y = 0.5f * static_cast<float>(h) * next();
            const float angle = 6.2831853f * next();
            walk.sx = span_x * std::cos(angle) / n;
            walk.sy = span_y * std::sin(angle) / n;
            walk.fx0 = static_cast<float>(w) * next() - 0.5f - 0.5f * (n - 1.0f) * walk.sx;
            walk.fy0 = static_cast<float>(h) * next() - 0.5f - 0.5f * (n - 1.0f) * walk.sy;
            const float want = detail::walk_taps_portable(walk);
            for (raster_simd s : ALL) {
                if (!detail::kernels_run(s) || !detail::kernels_for(s).walk_taps) continue;
                const float got = detail::kernels_for(s).walk_taps(walk);
                CHECK_MSG(std::memcmp(&got, &want, sizeof got) == 0,
                          std::string(raster_simd_name(s)) + ": " + std::to_string(got) + " vs " + std::to_string(want));
                ++compared;
            }
        }
    }
    std::printf("  tap walks compared: %d\n", compared);
}
