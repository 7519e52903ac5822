// transform.cpp — transforming points by a projective 4×4 (the report's cube MVP turned a
// little): the report's per-point apply_transform (faithful), the batch
// tiny3d::transform_points (SSE2, bit-identical to apply_transform), the batch to clip
// space without the divide, and a long double reference. Time per point over 4096 points
// (48 KiB in, 48 KiB out); error = max over components |result − exact| / |exact point|.
// Target: the batch at ≥ 150 M points/s (≤ 6.7 ns/point) on one core.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "common/bench.h"
#include "math3d.h"

namespace {

constexpr int kPoints = 4096;

using ld = long double;

struct lpoint {
    ld x, y, z;
};

lpoint reference(const mat4_t &m, vec3_t p) {
    const ld in[4] = {p.x, p.y, p.z, 1};
    ld h[4] = {0, 0, 0, 0};
    for (int row = 0; row < 4; ++row)
        for (int k = 0; k < 4; ++k) h[row] += ld(m.m[k * 4 + row]) * in[k];
    const bool divide = h[3] != 0 && h[3] != 1;
    return divide ? lpoint{h[0] / h[3], h[1] / h[3], h[2] / h[3]} : lpoint{h[0], h[1], h[2]};
}

struct errors {
    double mean, max;
};

errors relative_error(const std::vector<vec3_t> &got, const std::vector<lpoint> &exact) {
    double sum = 0, worst = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
        const lpoint &e = exact[i];
        const ld scale = std::max(std::sqrt(e.x * e.x + e.y * e.y + e.z * e.z), ld(1e-30));
        const double err = double(
            std::max({std::fabs(got[i].x - e.x), std::fabs(got[i].y - e.y), std::fabs(got[i].z - e.z)}) / scale);
        sum += err;
        worst = std::max(worst, err);
    }
    return {sum / double(got.size()), worst};
}

std::string points_per_second(const bench::timing &t) {
    char note[64];
    std::snprintf(note, sizeof note, "%.0f M points/s", 1e3 / t.median);
    return note;
}

}  // namespace

int main(int argc, char **argv) {
    const bench::options o = bench::parse_options(argc, argv);
    const int repeats = o.quick ? 3 : 31;
    const mat4_t model = mat4_multiply(mat4_translate(0, 0, -5), mat4_rotate_xyz(0.3f, 0.7f, 0.1f));
    const mat4_t mvp = mat4_multiply(mat4_frustum_asymmetric(-1, 1, -1, 1, 1, 10), model);

    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(-1, 1);
    std::vector<vec3_t> in(kPoints);
    for (vec3_t &p : in) p = {u(rng), u(rng), u(rng)};
    std::vector<lpoint> exact(in.size());
    for (std::size_t i = 0; i < in.size(); ++i) exact[i] = reference(mvp, in[i]);
    std::vector<vec3_t> out(in.size());
    std::vector<vec4_t> clip(in.size());
    std::vector<bench::row> rows;
    const std::string unit = "ns/point", err_unit = "rel to |point|";

    const bench::timing faithful = bench::measure_ns(repeats, double(in.size()), [&] {
        for (std::size_t i = 0; i < in.size(); ++i) out[i] = apply_transform(mvp, in[i]);
        bench::keep(out);
    });
    const errors fe = relative_error(out, exact);
    rows.push_back({"transform", "apply_transform per point", "faithful", unit, faithful, fe.mean, fe.max, err_unit,
                    points_per_second(faithful)});

    const bench::timing batch = bench::measure_ns(repeats, double(in.size()), [&] {
        bench::keep(tiny3d::transform_points(mvp, in, out));
        bench::keep(out);
    });
    const errors be = relative_error(out, exact);
    rows.push_back({"transform", "transform_points (SSE2 batch)", "fast", unit, batch, be.mean, be.max, err_unit,
                    points_per_second(batch) + ", bit-identical"});

    const bench::timing homogeneous = bench::measure_ns(repeats, double(in.size()), [&] {
        bench::keep(tiny3d::transform_points_homogeneous(mvp, in, clip));
        bench::keep(clip);
    });
    for (std::size_t i = 0; i < in.size(); ++i) out[i] = {clip[i].x / clip[i].w, clip[i].y / clip[i].w, clip[i].z / clip[i].w};
    const errors he = relative_error(out, exact);
    rows.push_back({"transform", "transform_points_homogeneous (clip space)", "other", unit, homogeneous, he.mean, he.max,
                    err_unit, points_per_second(homogeneous) + ", no divide; error after dividing"});

    std::vector<lpoint> sink(in.size());
    const bench::timing ref = bench::measure_ns(o.quick ? 1 : 5, double(in.size()), [&] {
        for (std::size_t i = 0; i < in.size(); ++i) sink[i] = reference(mvp, in[i]);
        bench::keep(sink);
    });
    rows.push_back({"transform", "long double reference", "reference", unit, ref, 0.0, 0.0, err_unit,
                    points_per_second(ref)});
    return bench::report(o, "transform", rows, "Point transform: time per point vs error");
}
