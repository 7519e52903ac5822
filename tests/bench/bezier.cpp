// bezier.cpp — constant-speed motion along a cubic Bezier: plain t (the report's use of
// vec3_bezier), an exact reference (Newton on the arc length, double precision) and
// arc-length tables of several sizes. Time per position lookup and the speed error
// |speed / constant − 1| at 1000 points; each table row notes its one-off build cost.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "animation.h"
#include "math3d.h"
#include "common/bench.h"

namespace {

// A segment whose speed |B'| varies about 10× along t (the test's S curve).
const tiny3d::cubic_bezier CURVE = {{0, 0, 0}, {0.2f, 3, 0}, {4, -2, 1}, {5, 0.5f, 0.2f}};
constexpr int QUERIES = 1000;

double speed(double u) {  // |B'(u)| in double
    const auto &c = CURVE;
    const double v = 1 - u, w0 = 3 * v * v, w1 = 6 * v * u, w2 = 3 * u * u;
    const double x = w0 * (c.p1.x - c.p0.x) + w1 * (c.p2.x - c.p1.x) + w2 * (c.p3.x - c.p2.x);
    const double y = w0 * (c.p1.y - c.p0.y) + w1 * (c.p2.y - c.p1.y) + w2 * (c.p3.y - c.p2.y);
    const double z = w0 * (c.p1.z - c.p0.z) + w1 * (c.p2.z - c.p1.z) + w2 * (c.p3.z - c.p2.z);
    return std::sqrt(x * x + y * y + z * z);
}

// ∫_0^u |B'| by composite Simpson with 2·PANELS panels (double).
double length_to(double u) {
    constexpr int PANELS = 512;
    const double h = u / (2 * PANELS);
    double sum = speed(0) + speed(u);
    for (int i = 1; i < 2 * PANELS; ++i) sum += (i % 2 ? 4 : 2) * speed(i * h);
    return sum * h / 3;
}

// Reference inverse: Newton on length_to(u) = s (derivative |B'(u)|), bracketed.
double reference_parameter(double s, double total) {
    double u = s / total, lo = 0, hi = 1;
    for (int it = 0; it < 30; ++it) {
        const double f = length_to(u) - s;
        if (std::fabs(f) < 1e-12 * total) break;
        (f > 0 ? hi : lo) = u;
        const double next = u - f / speed(u);
        u = next > lo && next < hi ? next : 0.5 * (lo + hi);
    }
    return u;
}

struct errors {
    double mean, max;
};
// Speed error of a distance → parameter map: |B'(u)|·du/ds − 1 (du/ds by central difference).
template <class Map>
errors speed_error(Map &&param_at, double total) {
    double sum = 0, worst = 0;
    for (int i = 0; i < QUERIES; ++i) {
        const double s = total * (i + 0.5) / QUERIES, ds = total * 1e-6;
        const double du_ds = (param_at(s + ds) - param_at(s - ds)) / (2 * ds);
        const double e = std::fabs(speed(param_at(s)) * du_ds - 1.0);
        sum += e;
        worst = std::max(worst, e);
    }
    return {sum / QUERIES, worst};
}

}  // namespace

int main(int argc, char **argv) {
    const bench::options o = bench::parse_options(argc, argv);
    const int repeats = o.quick ? 3 : 15;
    const double total = length_to(1.0);
    std::vector<bench::row> rows;
    const std::string unit = "ns/lookup", err_unit = "rel speed";

    // Faithful: plain t proportional to the distance wanted, then vec3_bezier.
    {
        vec3_t sink{};
        const auto t = bench::measure_ns(repeats, QUERIES, [&] {
            for (int i = 0; i < QUERIES; ++i) {
                const float u = (i + 0.5f) / QUERIES;
                sink += vec3_bezier(CURVE.p0, CURVE.p1, CURVE.p2, CURVE.p3, u);
            }
            bench::keep(sink);
        });
        const errors e = speed_error([&](double s) { return s / total; }, total);
        rows.push_back({"bezier", "plain t (vec3_bezier)", "faithful", unit, t, e.mean, e.max, err_unit, "no table"});
    }
    // Reference: Newton on the exact arc length, per lookup.
    {
        double sink = 0;
        const int ref_queries = o.quick ? 10 : 50;
        const auto t = bench::measure_ns(o.quick ? 1 : 3, ref_queries, [&] {
            for (int i = 0; i < ref_queries; ++i) sink += reference_parameter(total * (i + 0.5) / ref_queries, total);
            bench::keep(sink);
        });
        const errors e = speed_error([&](double s) { return reference_parameter(s, total); }, total);
        rows.push_back({"bezier", "Newton on exact arc length (double)", "reference", unit, t, e.mean, e.max, err_unit,
                        "Simpson 1024 panels per evaluation"});
    }
    // Tables of several sizes: lookup = binary search + Hermite inverse + vec3_bezier.
    for (int samples : {2, 4, 8, 16, 32, 64, 256}) {
        const auto table = tiny3d::arc_length_table::build(std::span(&CURVE, 1), samples);
        if (!table) {
            std::fprintf(stderr, "bezier: %s\n", table.message().c_str());
            return 1;
        }
        const auto build = bench::measure_ns(repeats, 1, [&] {
            auto again = tiny3d::arc_length_table::build(std::span(&CURVE, 1), samples);
            bench::keep(again);
        });
        vec3_t sink{};
        const auto t = bench::measure_ns(repeats, QUERIES, [&] {
            for (int i = 0; i < QUERIES; ++i) {
                const double u = table->parameter_at_length(total * (i + 0.5) / QUERIES);
                sink += tiny3d::bezier_point(CURVE, static_cast<float>(u));
            }
            bench::keep(sink);
        });
        const errors e = speed_error([&](double s) { return table->parameter_at_length(s); }, total);
        char note[96];
        std::snprintf(note, sizeof note, "build %.0f ns once, %zu stations", build.median, table->station_count());
        rows.push_back({"bezier", "arc-length table " + std::to_string(samples) + " samples", "fast", unit, t, e.mean,
                        e.max, err_unit, note, "arc-length table (samples per segment)", std::to_string(samples)});
    }
    return bench::report(o, "bezier", rows, "Constant-speed Bezier: time per lookup vs speed error");
}
