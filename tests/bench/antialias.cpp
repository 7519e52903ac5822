// antialias.cpp — anti-aliased filled rendering against the converged image: Scene S
// (Scene S protocol, documentation/benchmarks.md: 1024², camera (0, 0, 3), fov 45°, Gouraud Lambert, depth LESS,
// back-face culling, mesh turned 1° about +y per frame, 5 warm-up + 50 timed frames, the
// multisampled rows' frames in 5 rounds of 10, the configurations in turn) at
// icosphere level 6 and the 3,696-triangle torus knot, rows 1x, 4x, 8x, 16x (samples per
// pixel) with one and two threads (and for Scene S, one thread, 1x-16x with each other
// instruction set the CPU runs: `4x AVX2 kernel`, `4x SSE2 kernel` …, the note giving a
// multisampled frame's time as a multiple of the same set's 1x frame), and
// `analytic` (exact area coverage, a prototype in
// common/analytic_coverage.h; one thread); and a textured plane at a grazing angle, bilinear
// against nearest, trilinear and anisotropic.
//
// Error: the frame at angle 0 against render_reference (raster.h: 16 × 16 = 256
// samples per pixel, depth and shading per sample, box filter; 8 × 8 with --quick), in grey
// levels 0–255. error_mean / error_max: over the SILHOUETTE pixels — those whose exact
// coverage by the object (the reference of the same scene drawn flat white on black) lies
// strictly between 1/1000 and 1 − 1/1000; the note gives the mean over all pixels and the
// silhouette pixel count. The plane rows' error is over all pixels (the plane fills the
// frame; its error is in the texture, not at silhouettes).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "common/analytic_coverage.h"
#include "common/bench.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"
#include "../grazing_plane.h"

using namespace tiny3d;

namespace {

constexpr int SIDE = 1024, PLANE_SIDE = 512;
constexpr int WARMUP_FRAMES = 5, TIMED_FRAMES = 50, ROUNDS = 5;
constexpr double NS_PER_MS = 1e6;
constexpr sample_count MODES[] = {sample_count::x1, sample_count::x4, sample_count::x8, sample_count::x16};

struct scene {
    raster_mesh mesh;
    raster_clusters clusters;
    draw_params params;
};

mat4_t scene_s_view_projection() {
    return mat4_multiply(mat4_perspective(static_cast<float>(45 * M_PI / 180), 1.0f, 0.1f, 100.0f),
                         mat4_look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}));
}

scene make_scene(const mesh &m) {
    scene s;
    s.mesh = make_raster_mesh(m, mesh_vertex_normals(m)).value();
    s.clusters = make_raster_clusters(s.mesh).value();
    const light_t light = {{1, 1, 1}, 1.0f};
    s.params.lights = make_light_rig(std::span<const light_t>(&light, 1), 0.1f).value();
    s.params.view_projection = scene_s_view_projection();
    s.params.model = mat4_identity();
    s.params.clusters = &s.clusters;
    return s;
}

// Times frames drawn by draw() (the mesh turned 1° per frame), then draws the frame at angle 0.
template <class Draw>
bench::timing time_turning(scene &s, int frames, Draw &&draw) {
    int frame = 0;
    auto render = [&] {
        s.params.model = mat4_rotate_y(static_cast<float>(frame++ * M_PI / 180));
        draw();
    };
    for (int k = 0; k < WARMUP_FRAMES - 1; ++k) render();  // measure_ns adds one more
    const bench::timing t = bench::measure_ns(frames, NS_PER_MS, render);
    frame = 0;
    render();
    return t;
}

// One configuration of the multisampled rows: its own context, its own turn of the mesh.
struct config {
    sample_count samples;
    int threads;
    multisample_simd simd;
    std::unique_ptr<render_context> ctx;
    int frame = 0;  // the next frame's angle in degrees
    std::vector<bench::timing> rounds;
    // Draws the next frame of the turn into canvas.
    void draw(scene &s, canvas_t &canvas) {
        s.params.model = mat4_rotate_y(static_cast<float>(frame++ * M_PI / 180));
        if (!ctx->begin_frame(canvas, 0.0f, samples).ok()) return;
        ctx->draw(s.mesh, s.params);
        ctx->end_frame();
    }
    // The frame at angle 0.
    void draw_first(scene &s, canvas_t &canvas) {
        frame = 0;
        draw(s, canvas);
    }
    // The median of the rounds' medians, the fastest and slowest frame of any round.
    bench::timing time() const {
        std::vector<double> medians;
        bench::timing t = rounds.front();
        for (const bench::timing &r : rounds) {
            medians.push_back(r.median);
            t.min = std::min(t.min, r.min), t.max = std::max(t.max, r.max);
        }
        t.median = bench::summarise(std::move(medians)).median;
        return t;
    }
};

struct image_error {
    double all_mean = 0, all_max = 0, edge_mean = 0, edge_max = 0;
    long edge_pixels = 0;
};

// Grey-level error against the reference; silhouette pixels by the coverage image.
image_error error_against(const canvas_t &image, const canvas_t &reference, const canvas_t *coverage) {
    image_error e;
    const long n = static_cast<long>(image.width) * image.height;
    for (long i = 0; i < n; ++i) {
        const double d = 255.0 * std::fabs(static_cast<double>(image.data[i]) - reference.data[i]);
        e.all_mean += d / static_cast<double>(n);
        e.all_max = std::max(e.all_max, d);
        if (coverage && coverage->data[i] > 1e-3f && coverage->data[i] < 1 - 1e-3f) {
            e.edge_mean += d;
            e.edge_max = std::max(e.edge_max, d);
            ++e.edge_pixels;
        }
    }
    if (e.edge_pixels) e.edge_mean /= static_cast<double>(e.edge_pixels);
    return e;
}

bool same_image(const canvas_t &a, const canvas_t &b) {
    return std::equal(a.data, a.data + static_cast<long>(a.width) * a.height, b.data);
}

std::string fixed(double v, int digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, v);
    return text;
}

}  // namespace

int main(int argc, char **argv) {
    const bench::options o = bench::parse_options(argc, argv);
    const int frames = o.quick ? 3 : TIMED_FRAMES;
    const int reference_n = o.quick ? 8 : REFERENCE_SAMPLES_PER_AXIS;
    std::vector<bench::row> rows;
    canvas_ptr reference = make_canvas(SIDE, SIDE).value(), coverage = make_canvas(SIDE, SIDE).value();
    canvas_ptr one = make_canvas(SIDE, SIDE).value(), two = make_canvas(SIDE, SIDE).value();
    struct workload {
        std::string name;
        mesh m;
    };
    const workload loads[] = {{"Scene S L6", make_icosphere(6)}, {"torus knot", make_torus_knot(2, 3, 154, 12)}};
    // The multisample instruction sets this CPU runs besides the best one.
    std::vector<std::pair<multisample_simd, const char *>> other_simds;
    for (const auto &[simd, label] : {std::pair{multisample_simd::avx2, "AVX2"}, std::pair{multisample_simd::sse2, "SSE2"}})
        if (render_context probe(1); simd != best_multisample_simd() && probe.use_multisample_simd(simd))
            other_simds.emplace_back(simd, label);
    std::vector<double> other_x1(other_simds.size(), 1.0);  // each one's 1x median (MODES starts at 1x)
    for (const workload &w : loads) {
        scene s = make_scene(w.m);
        scene white = s;
        white.params.lights = make_light_rig(std::span<const light_t>(), 1.0f).value();
        white.params.shade = shading::flat;
        const reference_draw shaded{&s.mesh, s.params}, flat{&white.mesh, white.params};
        const auto start = std::chrono::steady_clock::now();
        const bool drawn = render_reference(*reference, std::span<const reference_draw>(&shaded, 1), 0.0f, reference_n).ok();
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (!drawn || !render_reference(*coverage, std::span<const reference_draw>(&flat, 1), 0.0f, reference_n)) {
            std::fprintf(stderr, "bench antialias: reference failed\n");
            return 1;
        }
        rows.push_back({"antialias", w.name + " reference " + std::to_string(reference_n * reference_n) + " spp",
                        "reference", "ms/frame", {ms, ms, ms}, 0.0, 0.0, "grey levels", "render_reference, one frame"});
        // Every mode, thread count and (Scene S) instruction set, timed in rounds: a block of
        // frames of each configuration in turn, ROUNDS times, so that a slow spell of the
        // machine falls on every row alike instead of on one; a row's time is the median of
        // its rounds' medians. (--quick: one round, the rows' order, as
        // tests/bench/callgrind.sh expects: a measure_ns call per row.)
        std::vector<config> configs;  // in the rows' order
        for (sample_count n : MODES) {
            configs.push_back({n, 1, best_multisample_simd(), std::make_unique<render_context>(1), 0, {}});
            configs.push_back({n, 2, best_multisample_simd(), std::make_unique<render_context>(2), 0, {}});
            if (w.name == "Scene S L6")
                for (const auto &other : other_simds)
                    configs.push_back({n, 1, other.first, std::make_unique<render_context>(1), 0, {}});
        }
        for (config &c : configs) {
            c.ctx->use_multisample_simd(c.simd);
            for (int k = 0; k < WARMUP_FRAMES - 1; ++k) c.draw(s, *two);  // measure_ns adds one more
        }
        const int rounds = o.quick ? 1 : ROUNDS;
        for (int r = 0; r < rounds; ++r)
            for (config &c : configs)
                c.rounds.push_back(bench::measure_ns(frames / rounds, NS_PER_MS, [&] { c.draw(s, *two); }));
        std::size_t next = 0;
        for (sample_count n : MODES) {
            const std::string mode = std::to_string(static_cast<int>(n)) + "x";
            config &c1 = configs[next++], &c2 = configs[next++];
            c1.draw_first(s, *one);
            c2.draw_first(s, *two);
            const image_error e = error_against(*one, *reference, coverage.get());
            const std::string note = "all pixels: mean " + fixed(e.all_mean, 3) + " max " + fixed(e.all_max, 1) + "; " +
                                     std::to_string(e.edge_pixels) + " silhouette px";
            // On the chart each scene's modes are one line per thread count (one legend entry
            // each), the one-thread points tagged with their mode.
            rows.push_back({"antialias", w.name + " " + mode + " 1 thread", n == sample_count::x1 ? "faithful" : "fast",
                            "ms/frame", c1.time(), e.edge_mean, e.edge_max, "grey levels", note,
                            w.name + ", 1 thread: faithful 1x, fast 4x-16x", mode});
            rows.push_back({"antialias", w.name + " " + mode + " 2 threads", "other", "ms/frame", c2.time(), e.edge_mean,
                            e.edge_max, "grey levels",
                            same_image(*one, *two) ? "image identical to 1 thread" : "IMAGE DIFFERS FROM 1 THREAD",
                            w.name + ", 2 threads, 1x-16x"});
            // Scene S's frames with each other instruction set this CPU runs (one thread; the
            // image checked against the best kernel's, still in `one`): what a CPU without the
            // best one gets, multisampled frames also as a multiple of that set's own 1x frame.
            if (w.name != "Scene S L6") continue;
            for (std::size_t k = 0; k < other_simds.size(); ++k) {
                config &c = configs[next++];
                c.draw_first(s, *two);
                const bench::timing t = c.time();
                if (n == sample_count::x1) other_x1[k] = t.median;
                std::string verdict = same_image(*one, *two) ? "image identical to the best kernel's"
                                                              : "IMAGE DIFFERS FROM THE BEST KERNEL'S";
                if (n != sample_count::x1) verdict += "; " + fixed(t.median / other_x1[k], 2) + "x its own 1x";
                rows.push_back({"antialias", w.name + " " + mode + " " + other_simds[k].second + " kernel 1 thread",
                                "other", "ms/frame", t, e.edge_mean, e.edge_max, "grey levels", verdict,
                                w.name + ", 1 thread, " + other_simds[k].second + " kernel, 1x-16x", mode});
            }
        }
        // The analytic-coverage prototype (common/analytic_coverage.h): exact area per pixel,
        // front to back with saturating coverage; one thread.
        bench::analytic_renderer analytic;
        const bench::timing ta = time_turning(s, frames, [&] { analytic.render(*one, s.mesh, s.params, 0.0f); });
        const image_error ea = error_against(*one, *reference, coverage.get());
        rows.push_back({"antialias", w.name + " analytic 1 thread", "fast", "ms/frame", ta, ea.edge_mean, ea.edge_max,
                        "grey levels",
                        "exact area, front to back saturating; all pixels: mean " + fixed(ea.all_mean, 3) + " max " +
                            fixed(ea.all_max, 1) + "; " + std::to_string(ea.edge_pixels) + " silhouette px; " +
                            std::to_string(analytic.skipped()) + " triangles skipped"});
    }
    // The grazing plane (tests/grazing_plane.h): bilinear (the faithful filter) against
    // nearest, trilinear and anisotropic (8 taps), one sample per pixel.
    grazing_plane::scene plane;
    grazing_plane::make(plane);
    canvas_ptr plane_ref = make_canvas(PLANE_SIDE, PLANE_SIDE).value(), plane_img = make_canvas(PLANE_SIDE, PLANE_SIDE).value();
    const reference_draw pd{&plane.mesh, plane.params};
    if (!render_reference(*plane_ref, std::span<const reference_draw>(&pd, 1), 0.0f, reference_n)) {
        std::fprintf(stderr, "bench antialias: plane reference failed\n");
        return 1;
    }
    const struct {
        texture_filter filter;
        const char *name, *kind;
    } filters[] = {{texture_filter::bilinear, "bilinear", "faithful"},
                   {texture_filter::nearest, "nearest", "other"},
                   {texture_filter::trilinear, "trilinear", "fast"},
                   {texture_filter::anisotropic, "anisotropic 8 taps", "fast"}};
    for (const auto &f : filters) {
        plane.params.filter = f.filter;
        render_context ctx(1);
        auto render = [&] {
            if (!ctx.begin_frame(*plane_img).ok()) return;
            ctx.draw(plane.mesh, plane.params);
            ctx.end_frame();
        };
        for (int k = 0; k < WARMUP_FRAMES - 1; ++k) render();
        const bench::timing t = bench::measure_ns(o.quick ? 3 : 20, NS_PER_MS, render);
        const image_error e = error_against(*plane_img, *plane_ref, nullptr);
        rows.push_back({"antialias", std::string("grazing plane 512^2 ") + f.name + " 1 thread", f.kind, "ms/frame", t,
                        e.all_mean, e.all_max, "grey levels", "error over all pixels",
                        "grazing plane 512^2: texture filters", f.name});
    }
    const int result = bench::report(o, "antialias", rows, "Anti-aliasing: ms per frame vs silhouette error (grey levels)");
    if (result != 0) return result;
    // The texture filters again in a chart of their own, a legend entry each: their error is
    // over every pixel, not the silhouette.
    std::vector<bench::row> filter_rows;
    for (const bench::row &r : rows)
        if (r.variant.rfind("grazing plane 512^2 ", 0) == 0) {
            filter_rows.push_back(r);
            filter_rows.back().series.clear();
            filter_rows.back().tag.clear();
        }
    const std::string path = o.out_dir + "/antialias_texture.pgm";
    if (const tiny3d::status st =
            bench::write_chart(path, filter_rows, "Texture filters, grazing plane 512^2: ms per frame vs mean error");
        !st) {
        std::fprintf(stderr, "bench antialias: %s: %s\n", path.c_str(), st.message().c_str());
        return 1;
    }
    std::printf("wrote %s\n", path.c_str());
    return 0;
}
