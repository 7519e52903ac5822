// lines.cpp — speed against accuracy of the line drawers, per thickness T:
//   faithful  draw_line_f (the report's DDA of 0.5 px steps, a disc of splats each step)
//   reference line_coverage_reference (exact area per pixel, double precision)
//   fast      draw_line_coverage (closed-form exact coverage)
//   other     draw_line_tabulated (the ends from a line_table built once per T, outside the
//             timing), 16×16 supersampled stroke, Xiaolin Wu (thin), Bresenham (integer, thin)
// Time: ns per pixel of line length, median (min, max) over repeats of drawing a seeded
// set of segments (lengths 5–300 px, any angle, sub-pixel ends) on a 512×512 canvas.
// Error: |value − exact coverage| over the pixels either image touches, per segment on a
// clean canvas, mean and max over a subset of the segments.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "canvas.h"
#include "lines.h"
#include "common/bench.h"

namespace {

constexpr int kCanvasSize = 512;
constexpr int kSegments = 100;        // timed set
constexpr int kSlowSegments = 12;     // timed set for the reference and supersampling
constexpr int kErrorSegments = 25;    // error is measured on this many
constexpr int kSupersamples = 16;     // per axis
constexpr double kPi = 3.14159265358979323846;

struct segment {
    float x0, y0, x1, y1;
    double length() const { return std::hypot(double(x1) - x0, double(y1) - y0); }
};

std::vector<segment> make_segments(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double margin = 12.0;  // keeps every stroke (T ≤ 8) on the canvas
    std::vector<segment> out;
    while (int(out.size()) < count) {
        const double length = 5.0 + 295.0 * unit(rng), angle = 2.0 * kPi * unit(rng);
        const double x0 = margin + (kCanvasSize - 2 * margin) * unit(rng);
        const double y0 = margin + (kCanvasSize - 2 * margin) * unit(rng);
        const double x1 = x0 + length * std::cos(angle), y1 = y0 + length * std::sin(angle);
        if (x1 < margin || y1 < margin || x1 > kCanvasSize - margin || y1 > kCanvasSize - margin) continue;
        out.push_back({float(x0), float(y0), float(x1), float(y1)});
    }
    return out;
}

using draw_fn = std::function<void(canvas_t *, const segment &)>;

struct method {
    std::string name, kind;
    draw_fn draw;
    bool slow;
};

std::vector<method> methods_for(float t) {
    // Built once per thickness, as a program drawing many lines of one width would.
    const auto table = std::make_shared<tiny3d::line_table>(std::move(tiny3d::line_table::make(t).value()));
    return {
        // draw_line_f takes the report's coordinates (integer = pixel centre): the segment's
        // library coordinates minus 0.5, so it is measured against the same exact stroke.
        {"faithful DDA splat", "faithful",
         [t](canvas_t *c, const segment &s) { draw_line_f(c, s.x0 - 0.5f, s.y0 - 0.5f, s.x1 - 0.5f, s.y1 - 0.5f, t); },
         false},
        {"exact reference", "reference",
         [t](canvas_t *c, const segment &s) {
             // The reference writes doubles; the timed work includes copying them out.
             thread_local std::vector<double> cov;
             tiny3d::line_coverage_reference(cov, c->width, c->height, s.x0, s.y0, s.x1, s.y1, t);
             for (std::size_t i = 0; i < cov.size(); ++i)
                 if (cov[i] > 0) c->data[i] = float(cov[i]);
         },
         true},
        {"fast coverage", "fast", [t](canvas_t *c, const segment &s) { tiny3d::draw_line_coverage(c, s.x0, s.y0, s.x1, s.y1, t); }, false},
        {"tabulated coverage", "other",
         [table](canvas_t *c, const segment &s) { tiny3d::draw_line_tabulated(c, s.x0, s.y0, s.x1, s.y1, *table); },
         false},
        {"supersampled 16x16", "other",
         [t](canvas_t *c, const segment &s) { tiny3d::draw_line_supersampled(c, s.x0, s.y0, s.x1, s.y1, t, kSupersamples); },
         true},
        {"Xiaolin Wu (thin)", "other", [](canvas_t *c, const segment &s) { tiny3d::draw_line_wu(c, s.x0, s.y0, s.x1, s.y1); }, false},
        {"Bresenham (thin)", "other",
         [](canvas_t *c, const segment &s) {
             tiny3d::draw_line_bresenham(c, int(std::floor(s.x0)), int(std::floor(s.y0)), int(std::floor(s.x1)),
                                         int(std::floor(s.y1)));
         },
         false},
    };
}

struct errors {
    double mean, max;
};

// Mean and max |drawn − exact| over the pixels either touches, each segment alone.
errors measure_error(const draw_fn &draw, const std::vector<segment> &segs, float t, canvas_t *c,
                     std::vector<std::vector<double>> &refs) {
    double sum = 0, worst = 0;
    long n = 0;
    for (std::size_t k = 0; k < segs.size(); ++k) {
        const segment &s = segs[k];
        if (refs.size() <= k) {
            refs.emplace_back();
            tiny3d::line_coverage_reference(refs.back(), c->width, c->height, s.x0, s.y0, s.x1, s.y1, t);
        }
        canvas_clear(c, 0.0f);
        draw(c, s);
        const std::vector<double> &ref = refs[k];
        for (std::size_t i = 0; i < ref.size(); ++i) {
            if (c->data[i] == 0.0f && ref[i] == 0.0) continue;
            const double d = std::fabs(double(c->data[i]) - ref[i]);
            sum += d;
            worst = std::max(worst, d);
            ++n;
        }
    }
    return {n ? sum / double(n) : 0.0, worst};
}

std::string note_for(const method &m) {
    if (m.kind == "reference")
        return "timed on " + std::to_string(kSlowSegments) + " segments; includes filling a canvas-sized double image per segment";
    if (m.slow) return "timed on " + std::to_string(kSlowSegments) + " segments";
    return "";
}

std::string thickness_label(float t) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "T=%g", double(t));
    return buf;
}

}  // namespace

int main(int argc, char **argv) {
    const bench::options o = bench::parse_options(argc, argv);
    const std::vector<segment> segs = make_segments(kSegments, 2024u);
    const std::vector<segment> error_segs(segs.begin(), segs.begin() + kErrorSegments);
    const std::vector<segment> slow_segs(segs.begin(), segs.begin() + kSlowSegments);
    auto total_length = [](const std::vector<segment> &v) {
        double sum = 0;
        for (const segment &s : v) sum += s.length();
        return sum;
    };
    tiny3d::result<tiny3d::canvas_ptr> made = tiny3d::make_canvas(kCanvasSize, kCanvasSize);
    if (!made) {
        std::fprintf(stderr, "lines: %s\n", made.message().c_str());
        return 1;
    }
    canvas_t *canvas = made->get();
    const int repeats = o.quick ? 2 : 9, slow_repeats = o.quick ? 1 : 3;

    std::vector<bench::row> rows;
    for (float t : {0.5f, 1.0f, 1.5f, 3.0f, 8.0f}) {
        std::vector<std::vector<double>> refs;  // exact coverage of error_segs at this T
        const std::string label = thickness_label(t);
        for (const method &m : methods_for(t)) {
            const std::vector<segment> &timed = m.slow ? slow_segs : segs;
            canvas_clear(canvas, 0.0f);
            const bench::timing time = bench::measure_ns(m.slow ? slow_repeats : repeats, total_length(timed), [&] {
                for (const segment &s : timed) m.draw(canvas, s);
                bench::keep(canvas->data[0]);
            });
            const errors e = m.kind == "reference" ? errors{0.0, 0.0} : measure_error(m.draw, error_segs, t, canvas, refs);
            rows.push_back({"lines", m.name + " " + label, m.kind, "ns/px " + label, time, e.mean, e.max,
                            "abs intensity", note_for(m), m.name, label});
        }
    }
    return bench::report(o, "lines", rows, "Lines: ns per px of length vs mean abs error");
}
