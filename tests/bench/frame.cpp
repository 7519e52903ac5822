// frame.cpp — Scene S (documentation/benchmarks.md): whole frames at 1024², unit icosphere levels
// 5 and 6 and the 3,696-triangle torus knot, camera (0, 0, 3), fov 45°, near 0.1, far 100,
// Gouraud Lambert (ambient 0.1, light towards (1, 1, 1)), depth LESS, back-face culling,
// colour and depth cleared every frame, mesh turned 1° about +y per frame; 5 warm-up and 50
// timed frames (median, min, max ms); one and two threads, with cluster culling
// (make_raster_clusters, built once before timing) and, for comparison, without, and with
// the SSE2 fill forced on a CPU that has a faster one (what CPUs without AVX-512 get); level 6
// on one thread while another context renders on the other core (the machine's penalty on
// two busy cores); level 6 on one and on two threads with their frames interleaved (the
// two-thread ratio measured in the same seconds); frame time against triangle count for
// levels 3–7. Only what this program
// measures is printed; other renderers' figures are in documentation/other_renderers.md,
// with their source and date.
// Error column: fraction of pixels where the two-thread frame differs from the one-thread
// frame, or the frame without clusters from the frame with them (must be 0).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "common/bench.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"

namespace {

// A workload's short name for a chart tag: "icosphere L6 (81,920 tris)" → "L6",
// "torus knot (3,696 tris)" → "knot".
std::string short_name(const std::string &workload) {
    if (workload.rfind("icosphere ", 0) == 0) return workload.substr(10, workload.find(' ', 10) - 10);
    if (workload.rfind("torus knot", 0) == 0) return "knot";
    return workload;
}

constexpr int SIDE = 1024;
constexpr int WARMUP_FRAMES = 5, TIMED_FRAMES = 50;
constexpr double NS_PER_MS = 1e6;

struct scene {
    tiny3d::raster_mesh mesh;
    tiny3d::raster_clusters clusters;
    tiny3d::draw_params params;
};

scene make_scene(const tiny3d::mesh &m) {
    scene s;
    s.mesh = tiny3d::make_raster_mesh(m, tiny3d::mesh_vertex_normals(m)).value();
    s.clusters = tiny3d::make_raster_clusters(s.mesh).value();
    const light_t light = {{1, 1, 1}, 1.0f};
    s.params.lights = tiny3d::make_light_rig(std::span<const light_t>(&light, 1), 0.1f).value();
    s.params.view_projection = mat4_multiply(tiny3d::mat4_perspective(static_cast<float>(45 * M_PI / 180), 1.0f, 0.1f, 100.0f),
                                             tiny3d::mat4_look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}));
    return s;
}

// One frame of `mesh` with `params`, the mesh turned `frame` degrees about +y.
void render_frame(tiny3d::render_context &ctx, canvas_t &canvas, const tiny3d::raster_mesh &mesh,
                  tiny3d::draw_params &params, int frame) {
    params.model = tiny3d::mat4_rotate_y(static_cast<float>(frame * M_PI / 180));
    if (!ctx.begin_frame(canvas).ok()) return;
    ctx.draw(mesh, params);
    ctx.end_frame();
}

// Times frames of the scene with `threads`, with or without its clusters, filled with the
// instruction set `simd`; the last frame stays in `canvas`.
bench::timing time_frames(scene &s, int threads, canvas_t &canvas, int frames, bool clusters = true,
                          tiny3d::raster_simd simd = tiny3d::best_raster_simd()) {
    tiny3d::render_context ctx(threads);
    ctx.use_simd(simd);
    s.params.clusters = clusters ? &s.clusters : nullptr;
    int frame = 0;
    auto render = [&] { render_frame(ctx, canvas, s.mesh, s.params, frame++); };
    for (int k = 0; k < WARMUP_FRAMES - 1; ++k) render();  // measure_ns adds one more
    const bench::timing t = bench::measure_ns(frames, NS_PER_MS, render);
    bench::keep(canvas.data[SIDE * SIDE / 2]);
    return t;
}

// Times one-thread frames as time_frames does while a second one-thread context renders the
// same scene on another thread without pause: what a core's frame costs when the other core
// works too (they share the last-level cache, the memory bus and, on many machines, the
// clock). Its ratio to the one-thread frame is the machine's penalty on two busy cores,
// which two threads sharing one frame pay as well: part of why their frame is not half.
bench::timing time_frames_beside_another(scene &s, canvas_t &canvas, int frames) {
    std::atomic<bool> done{false};
    tiny3d::draw_params params = s.params;  // (copied here: time_frames changes s.params)
    params.clusters = &s.clusters;
    std::thread other([&done, &s, params] {
        tiny3d::canvas_ptr own = tiny3d::make_canvas(SIDE, SIDE).value();
        tiny3d::render_context ctx(1);
        tiny3d::draw_params p = params;
        for (int frame = 0; !done.load(std::memory_order_relaxed); ++frame) render_frame(ctx, *own, s.mesh, p, frame);
    });
    const bench::timing t = time_frames(s, 1, canvas, frames);
    done.store(true, std::memory_order_relaxed);
    other.join();
    return t;
}

// One- and two-thread frames of the scene timed in alternating blocks of BLOCK_FRAMES frames,
// the first frame of each block untimed (the other context's worker has gone to sleep
// meanwhile and wakes up then), until each has `frames` timed frames: both see the machine
// in the same seconds, so their ratio is the two-thread speed-up without the drift of a
// shared machine between two measurements made one after the other.
constexpr int BLOCK_FRAMES = 5;
struct paired_timing {
    bench::timing one, two;
};
paired_timing time_frames_interleaved(scene &s, canvas_t &one_canvas, canvas_t &two_canvas, int frames) {
    tiny3d::render_context one(1), two(2);
    s.params.clusters = &s.clusters;
    auto render_ms = [&](tiny3d::render_context &ctx, canvas_t &canvas, int frame) {
        const auto start = std::chrono::steady_clock::now();
        render_frame(ctx, canvas, s.mesh, s.params, frame);
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    };
    for (int k = 0; k < WARMUP_FRAMES; ++k) render_ms(one, one_canvas, k), render_ms(two, two_canvas, k);
    std::vector<double> ms_one, ms_two;
    for (int first = 0; static_cast<int>(ms_one.size()) < frames; first += BLOCK_FRAMES) {
        for (int k = 0; k < BLOCK_FRAMES; ++k)
            if (const double t = render_ms(one, one_canvas, first + k); k > 0) ms_one.push_back(t);
        for (int k = 0; k < BLOCK_FRAMES; ++k)
            if (const double t = render_ms(two, two_canvas, first + k); k > 0) ms_two.push_back(t);
    }
    bench::keep(one_canvas.data[SIDE * SIDE / 2]);
    bench::keep(two_canvas.data[SIDE * SIDE / 2]);
    return {bench::summarise(ms_one), bench::summarise(ms_two)};
}

double differing_fraction(const canvas_t &a, const canvas_t &b) {
    long n = 0;
    for (long i = 0; i < static_cast<long>(a.width) * a.height; ++i) n += a.data[i] != b.data[i];
    return static_cast<double>(n) / (static_cast<double>(a.width) * a.height);
}

}  // namespace

int main(int argc, char **argv) {
    const bench::options o = bench::parse_options(argc, argv);
    const int frames = o.quick ? 5 : TIMED_FRAMES;
    tiny3d::canvas_ptr one = tiny3d::make_canvas(SIDE, SIDE).value(), two = tiny3d::make_canvas(SIDE, SIDE).value();
    tiny3d::canvas_ptr plain = tiny3d::make_canvas(SIDE, SIDE).value();
    std::vector<bench::row> rows;
    struct workload {
        std::string name;
        tiny3d::mesh mesh;
    };
    std::vector<workload> loads;
    std::map<std::string, double> workload_triangles;  // chart tag → triangle count
    // Frame time against triangle count (one thread, levels 3–7, and the torus knot),
    // log-log, so equal slopes mean equal growth.
    tiny3d::chart_spec scaling;
    scaling.title = "Scene S: frame time vs triangle count";
    scaling.x_title = "triangles in the mesh";
    scaling.y_title = "ms per frame (median; bar: min-max)";
    // One series per renderer, its points tagged with the mesh.
    auto add_point = [&](double triangles, const bench::timing &t, const std::string &series, const std::string &tag) {
        tiny3d::chart_point p;
        p.x = triangles;
        p.y = t.median;
        p.y_lo = t.min;
        p.y_hi = t.max;
        p.series = series;
        p.tag = tag;
        scaling.points.push_back(std::move(p));
    };
    loads.push_back({"icosphere L6 (81,920 tris)", tiny3d::make_icosphere(6)});
    loads.push_back({"icosphere L5 (20,480 tris)", tiny3d::make_icosphere(5)});
    loads.push_back({"torus knot (3,696 tris)", tiny3d::make_torus_knot(2, 3, 154, 12)});
    for (workload &w : loads) {
        scene s = make_scene(w.mesh);
        const bench::timing t1 = time_frames(s, 1, *one, frames);
        const bench::timing t2 = time_frames(s, 2, *two, frames);
        const double diff = differing_fraction(*one, *two);
        const bench::timing t1_plain = time_frames(s, 1, *plain, frames, false);
        const double diff1_plain = differing_fraction(*one, *plain);
        const bench::timing t2_plain = time_frames(s, 2, *plain, frames, false);
        const double diff2_plain = differing_fraction(*one, *plain);
        const double triangles = static_cast<double>(s.mesh.triangles.size());
        const std::string tag = short_name(w.name);
        workload_triangles[tag] = triangles;
        // (our icospheres are the levels 3–7 points below)
        if (w.name.rfind("icosphere", 0) != 0) add_point(triangles, t1, "libtiny3d 1 thread", tag);
        rows.push_back({"frame", w.name + " libtiny3d 1 thread", "fast", "ms/frame", t1, 0.0, 0.0, "px fraction", "",
                        "libtiny3d 1 thread", tag});
        rows.push_back({"frame", w.name + " libtiny3d 2 threads", "fast", "ms/frame", t2, diff, diff, "px fraction",
                        "error = pixels differing from 1 thread", "libtiny3d 2 threads", tag});
        if (tag == "L6") {  // one and two threads in the same seconds
            tiny3d::canvas_ptr other = tiny3d::make_canvas(SIDE, SIDE).value();
            const paired_timing paired = time_frames_interleaved(s, *plain, *other, frames);
            const double diff_paired = differing_fraction(*plain, *other);
            char note[96];
            std::snprintf(note, sizeof note, "2 threads / 1 thread, frames interleaved: %.3f (medians)",
                          paired.two.median / paired.one.median);
            rows.push_back({"frame", w.name + " libtiny3d 1 thread, frames interleaved with 2 threads", "other",
                            "ms/frame", paired.one, 0.0, 0.0, "px fraction", note, "libtiny3d 1 thread, interleaved",
                            tag});
            rows.push_back({"frame", w.name + " libtiny3d 2 threads, frames interleaved with 1 thread", "other",
                            "ms/frame", paired.two, diff_paired, diff_paired, "px fraction",
                            std::string(note) + "; error = pixels differing from 1 thread",
                            "libtiny3d 2 threads, interleaved", tag});
        }
        if (tag == "L6") {  // the machine's penalty on two busy cores
            const bench::timing beside = time_frames_beside_another(s, *plain, frames);
            const double diff_beside = differing_fraction(*one, *plain);
            rows.push_back({"frame", w.name + " libtiny3d 1 thread, another on the other core", "other", "ms/frame",
                            beside, diff_beside, diff_beside, "px fraction",
                            "the slowdown of a core while the other works; error = pixels differing from 1 thread",
                            "libtiny3d 1 thread beside another", tag});
        }
        rows.push_back({"frame", w.name + " libtiny3d 1 thread, no clusters", "other", "ms/frame", t1_plain, diff1_plain,
                        diff1_plain, "px fraction", "error = pixels differing from the frame with clusters",
                        "libtiny3d 1 thread, no clusters", tag});
        rows.push_back({"frame", w.name + " libtiny3d 2 threads, no clusters", "other", "ms/frame", t2_plain, diff2_plain,
                        diff2_plain, "px fraction", "error = pixels differing from the 1-thread frame with clusters",
                        "libtiny3d 2 threads, no clusters", tag});
        // What CPUs without AVX-512 get: the AVX2 fill (CPUs with AVX2) and the SSE2 fill (the
        // others), each forced where the CPU has a faster one.
        const struct {
            tiny3d::raster_simd simd;
            const char *label, *series;
        } slower[] = {{tiny3d::raster_simd::avx2, ", AVX2 kernel (CPUs with AVX2, without AVX-512)", ", AVX2 kernel"},
                      {tiny3d::raster_simd::sse2, ", SSE2 kernel (CPUs without AVX2)", ", SSE2 kernel"}};
        for (const auto &k : slower) {
            tiny3d::render_context probe(1);
            // (raster_simd lists the kernels slowest first: only those slower than the best)
            if (k.simd >= tiny3d::best_raster_simd() || !probe.use_simd(k.simd)) continue;
            for (int threads : {1, 2}) {
                const bench::timing t = time_frames(s, threads, *plain, frames, true, k.simd);
                const double diff = differing_fraction(*one, *plain);
                const std::string name = " libtiny3d " + std::to_string(threads) + (threads == 1 ? " thread" : " threads");
                rows.push_back({"frame", w.name + name + k.label, "other", "ms/frame", t, diff, diff, "px fraction",
                                "error = pixels differing from the frame of the best kernel", name.substr(1) + k.series,
                                tag});
            }
        }
    }
    // Frame time against triangle count (one thread).
    std::printf("frame time vs triangle count (1 thread, median ms):\n");
    for (int level = 3; level <= 7; ++level) {
        scene s = make_scene(tiny3d::make_icosphere(level));
        const bench::timing t = time_frames(s, 1, *one, o.quick ? 3 : (level == 7 ? 20 : TIMED_FRAMES));
        std::printf("  level %d  %7zu tris  %8.3f ms\n", level, s.mesh.triangles.size(), t.median);
        add_point(static_cast<double>(s.mesh.triangles.size()), t, "libtiny3d 1 thread", "L" + std::to_string(level));
        rows.push_back({"frame", "icosphere L" + std::to_string(level) + " 1 thread (" +
                                     std::to_string(s.mesh.triangles.size()) + " tris)",
                        "other", "ms/frame", t, NAN, NAN, "px fraction", "scaling series",
                        "libtiny3d 1 thread, icosphere levels (no error measured)", "L" + std::to_string(level)});
    }
    // Each series joined in order of triangle count.
    std::stable_sort(scaling.points.begin(), scaling.points.end(),
                     [](const tiny3d::chart_point &a, const tiny3d::chart_point &b) { return a.x < b.x; });
    const std::string scaling_path = o.out_dir + "/frame_scaling.pgm";
    const int result = bench::report(o, "frame", rows, "Scene S: ms per frame (1024^2, Gouraud, depth, culling)");
    if (result != 0) return result;
    // Every variant's error is 0 or a pixel fraction near it, so the family's chart shows
    // time against the mesh instead: one line per renderer over the three workloads.
    tiny3d::chart_spec by_renderer;
    by_renderer.title = "Scene S: ms per frame by renderer (1024^2, Gouraud, depth, culling)";
    by_renderer.x_title = "triangles in the mesh (L6 icosphere, L5 icosphere, torus knot)";
    by_renderer.y_title = "ms per frame (median; bar: min-max)";
    for (const bench::row &r : rows) {
        const auto found = workload_triangles.find(r.tag);
        if (found == workload_triangles.end() || r.note == "scaling series") continue;
        tiny3d::chart_point p;
        p.x = found->second;
        p.y = r.time.median;
        p.y_lo = r.time.min;
        p.y_hi = r.time.max;
        p.series = r.series;
        p.tag = r.series == "libtiny3d 1 thread" ? r.tag : "";
        by_renderer.points.push_back(std::move(p));
    }
    std::stable_sort(by_renderer.points.begin(), by_renderer.points.end(),
                     [](const tiny3d::chart_point &a, const tiny3d::chart_point &b) { return a.x < b.x; });
    if (const tiny3d::status st = bench::write_chart(o.out_dir + "/frame.pgm", by_renderer); !st) {
        std::fprintf(stderr, "bench frame: %s\n", st.message().c_str());
        return 1;
    }
    if (const tiny3d::status st = bench::write_chart(scaling_path, scaling); !st) {
        std::fprintf(stderr, "bench frame: %s\n", st.message().c_str());
        return 1;
    }
    std::printf("wrote %s\n", scaling_path.c_str());
    return 0;
}
