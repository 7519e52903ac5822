// wireframe.cpp — Scene S's wireframe variant (documentation/benchmarks.md: the 122,880 unique
// edges of the level-6 icosphere, anti-aliased width 1.5, 1024², colour cleared per frame,
// no depth test; camera at (0, 0, 3), fov 45°, mesh turned 1° about +y per frame) and the
// soccer ball (90 edges, 1024²), each drawn with
//   faithful:  the report's draw_line_f (DDA splats) through render_wireframe,
//   fast:      tiny3d::draw_line_coverage (exact area coverage, "over" combine), and
//              tiny3d::draw_line_tabulated (the ends interpolated from a line_table),
//   other:     the fast path plus the report's far-to-near Z-sort, and draw_line_f at the
//              report's width 1.0,
//   reference: every edge's exact coverage (line_coverage_reference_at, double) combined
//              "over" in double over the same clipped screen segments.
//   other:     "pipeline only" — the same call with ink 0, so every edge is transformed,
//              clipped and listed but no line is drawn: the cost of this module alone,
// Time = ms (Scene S) or µs (soccer ball) per frame: clear + transform + clip + lines;
// median (min–max) of 5 frames after one warm-up, or for the tabulated line and the
// pipeline alone Scene S's protocol: 5 warm-up frames, then 50 timed.
// Error = |pixel − reference| over the pixels either image inks (mean and max).
#include <algorithm>
#include <cmath>
#include <vector>

#include "common/bench.h"
#include "canvas.h"
#include "lines.h"
#include "math3d.h"
#include "mesh.h"
#include "wireframe.h"

namespace {

constexpr int kSide = 1024;
constexpr float kWidth = 1.5f;
constexpr float kReportWidth = 1.0f;
constexpr float kFovY = float(45.0 * M_PI / 180.0);
constexpr float kDegree = float(M_PI / 180.0);
constexpr double kMsPerNs = 1e-6, kUsPerNs = 1e-3;

struct scene {
    const char *name;
    const tiny3d::mesh *m;
    const char *unit;
    double unit_per_ns;
    int repeats;
};

mat4_t frame_matrix(int frame) {
    const mat4_t proj = tiny3d::mat4_perspective(kFovY, 1.0f, 0.1f, 100.0f);
    const mat4_t view = mat4_translate(0, 0, -3);  // camera at (0, 0, 3) looking at the origin
    return mat4_multiply(proj, mat4_multiply(view, tiny3d::mat4_rotate_y(frame * kDegree)));
}

// Exact reference image: every clipped segment's exact coverage, combined "over" in double.
std::vector<double> reference_image(const tiny3d::wireframe_workspace &ws) {
    std::vector<double> img(std::size_t(kSide) * kSide, 0.0);
    const double reach = kWidth * 0.5 + 1.0;
    for (const auto &e : ws.edges) {
        const int x_lo = std::max(0, int(std::floor(std::min(e.x0, e.x1) - reach)));
        const int x_hi = std::min(kSide - 1, int(std::ceil(std::max(e.x0, e.x1) + reach)));
        const int y_lo = std::max(0, int(std::floor(std::min(e.y0, e.y1) - reach)));
        const int y_hi = std::min(kSide - 1, int(std::ceil(std::max(e.y0, e.y1) + reach)));
        for (int y = y_lo; y <= y_hi; ++y)
            for (int x = x_lo; x <= x_hi; ++x) {
                const double c = tiny3d::line_coverage_reference_at(x, y, e.x0, e.y0, e.x1, e.y1, kWidth);
                double &v = img[std::size_t(y) * kSide + x];
                v += c * (1.0 - v);
            }
    }
    return img;
}

struct error_stats {
    double mean, max;
};
error_stats compare(const canvas_t &c, const std::vector<double> &ref) {
    double sum = 0, worst = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
        if (c.data[i] == 0.0f && ref[i] == 0.0) continue;
        const double d = std::fabs(double(c.data[i]) - ref[i]);
        sum += d;
        worst = std::max(worst, d);
        ++n;
    }
    return {n ? sum / double(n) : 0.0, worst};
}

}  // namespace

int main(int argc, char **argv) {
    const bench::options o = bench::parse_options(argc, argv);
    auto canvas = tiny3d::make_canvas(kSide, kSide);
    if (!canvas) return std::fprintf(stderr, "%s\n", canvas.message().c_str()), 1;
    canvas_t &c = **canvas;
    const tiny3d::mesh sphere = tiny3d::make_icosphere(o.quick ? 4 : 6);
    const tiny3d::mesh ball = tiny3d::make_soccer_ball();
    const scene scenes[] = {{"Scene S L6 icosphere", &sphere, "ms/frame", kMsPerNs, o.quick ? 2 : 5},
                            {"soccer ball", &ball, "us/frame", kUsPerNs, o.quick ? 5 : 51}};
    std::vector<bench::row> rows;
    tiny3d::wireframe_workspace ws;
    for (const scene &s : scenes) {
        // The reference of frame 0's segments (the same clipping for every variant).
        tiny3d::wireframe_options base;
        base.depth_sort = false;
        base.frustum_cull = false;
        base.thickness = kWidth;
        base.method = tiny3d::line_method::coverage;
        canvas_clear(&c, 0.0f);
        if (tiny3d::status st = tiny3d::render_wireframe(c, *s.m, frame_matrix(0), base, ws); !st)
            return std::fprintf(stderr, "%s\n", st.message().c_str()), 1;
        std::vector<double> ref;
        const bench::timing ref_time = bench::measure_ns(1, 1.0, [&] { ref = reference_image(ws); });
        rows.push_back({"wireframe", std::string(s.name) + ": exact coverage reference", "reference", s.unit,
                        {ref_time.median * s.unit_per_ns, ref_time.min * s.unit_per_ns, ref_time.max * s.unit_per_ns},
                        0.0, 0.0, "abs intensity", "double, per pixel"});

        struct variant {
            const char *label, *kind;
            tiny3d::line_method method;
            float width;
            bool sort;
            float ink = 1.0f;  // 0: every edge is skipped after clipping (pipeline cost alone)
            bool scene_protocol = false;  // Scene S's 5 warm-up + 50 timed frames (the others: 1 + s.repeats)
        };
        const variant variants[] = {
            {"faithful draw_line_f w1.5", "faithful", tiny3d::line_method::faithful, kWidth, false},
            {"fast coverage line w1.5", "fast", tiny3d::line_method::coverage, kWidth, false},
            {"fast tabulated line w1.5", "fast", tiny3d::line_method::tabulated, kWidth, false, 1.0f, true},
            {"coverage line w1.5 + Z-sort", "other", tiny3d::line_method::coverage, kWidth, true},
            {"faithful draw_line_f w1.0 (report)", "other", tiny3d::line_method::faithful, kReportWidth, false},
            {"pipeline only: transform + clip, no lines", "other", tiny3d::line_method::coverage, kWidth, false, 0.0f, true},
        };
        for (const variant &v : variants) {
            tiny3d::wireframe_options opt = base;
            opt.method = v.method;
            opt.thickness = v.width;
            opt.depth_sort = v.sort;
            opt.intensity = v.ink;
            int frame = 0;
            auto render = [&] {
                canvas_clear(&c, 0.0f);
                const tiny3d::status st = tiny3d::render_wireframe(c, *s.m, frame_matrix(frame++ % 360), opt, ws);
                bench::keep(st);
                bench::keep(c.data[0]);
            };
            const bool protocol = v.scene_protocol && !o.quick;
            if (protocol)
                for (int k = 0; k < 4; ++k) render();  // + measure_ns's own warm-up run = 5
            const bench::timing t = bench::measure_ns(protocol ? 50 : s.repeats, 1.0, render);
            // Error on frame 0, the reference's frame.
            canvas_clear(&c, 0.0f);
            (void)tiny3d::render_wireframe(c, *s.m, frame_matrix(0), opt, ws);
            const error_stats e = v.ink > 0.0f ? compare(c, ref) : error_stats{NAN, NAN};
            rows.push_back({"wireframe", std::string(s.name) + ": " + v.label, v.kind, s.unit,
                            {t.median * s.unit_per_ns, t.min * s.unit_per_ns, t.max * s.unit_per_ns}, e.mean, e.max,
                            "abs intensity", std::to_string(s.m->edges.size()) + " edges, 1024^2"});
        }
    }
    const int result = bench::report(o, "wireframe", rows, "Wireframe: time per frame vs intensity error");
    if (result != 0) return result;
    // One chart per workload (each has its own time unit): wireframe.pgm is Scene S.
    return bench::write_workload_charts(o, rows, {
        {"Scene S L6 icosphere: ", "wireframe", "Wireframe, Scene S L6 icosphere: ms per frame vs error"},
        {"soccer ball: ", "wireframe_soccer", "Wireframe, soccer ball: us per frame vs error"},
    });
}
