// slerp.cpp — direction slerp: the report's acos form with Quake-normalised inputs
// (faithful, global vec3_slerp), the robust atan2 / great-circle form in double
// (tiny3d::vec3_slerp_robust), and a long double reference (Rodrigues rotation of â about
// â×b̂ by t·acos(â·b̂)). Inputs: unit pairs at angles spread log-uniformly from 1e-6 rad
// to π − 1e-4 (so near-parallel and near-antipodal pairs are in), t in [0, 1].
// Error = max component difference from the reference (unit results).
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "common/bench.h"
#include "math3d.h"

namespace {

constexpr int kPairs = 4096;
constexpr double kMinAngle = 1e-6, kAntipodalMargin = 1e-4;

struct pair_case {
    vec3_t a, b;
    float t;
};

using ld = long double;
struct lvec {
    ld x, y, z;
};

lvec reference(const pair_case &c) {
    const lvec a = {c.a.x, c.a.y, c.a.z}, b = {c.b.x, c.b.y, c.b.z};
    const ld la = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z), lb = std::sqrt(b.x * b.x + b.y * b.y + b.z * b.z);
    const lvec ua = {a.x / la, a.y / la, a.z / la}, ub = {b.x / lb, b.y / lb, b.z / lb};
    lvec n = {ua.y * ub.z - ua.z * ub.y, ua.z * ub.x - ua.x * ub.z, ua.x * ub.y - ua.y * ub.x};
    const ld ln = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    n = {n.x / ln, n.y / ln, n.z / ln};
    const lvec perp = {n.y * ua.z - n.z * ua.y, n.z * ua.x - n.x * ua.z, n.x * ua.y - n.y * ua.x};
    const ld cosine = std::clamp(ua.x * ub.x + ua.y * ub.y + ua.z * ub.z, ld(-1), ld(1));
    const ld angle = std::acos(cosine) * c.t;
    return {ua.x * std::cos(angle) + perp.x * std::sin(angle), ua.y * std::cos(angle) + perp.y * std::sin(angle),
            ua.z * std::cos(angle) + perp.z * std::sin(angle)};
}

std::vector<pair_case> random_pairs(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1, 1), t(0, 1);
    std::uniform_real_distribution<double> log_angle(std::log(kMinAngle), std::log(M_PI - kAntipodalMargin));
    std::vector<pair_case> pairs;
    while (int(pairs.size()) < count) {
        const vec3_t a = tiny3d::vec3_normalize(vec3_t{u(rng), u(rng), u(rng)});
        const vec3_t p = tiny3d::vec3_normalize(tiny3d::vec3_cross(a, vec3_t{u(rng), u(rng), u(rng)}));
        if (a == vec3_t{0, 0, 0} || p == vec3_t{0, 0, 0}) continue;
        const double angle = std::exp(log_angle(rng));
        const vec3_t b = {float(a.x * std::cos(angle) + p.x * std::sin(angle)),
                          float(a.y * std::cos(angle) + p.y * std::sin(angle)),
                          float(a.z * std::cos(angle) + p.z * std::sin(angle))};
        pairs.push_back({a, b, t(rng)});
    }
    return pairs;
}

}  // namespace

int main(int argc, char **argv) {
    const bench::options o = bench::parse_options(argc, argv);
    const int repeats = o.quick ? 3 : 21;
    const std::vector<pair_case> pairs = random_pairs(o.quick ? 1024 : kPairs, 3);
    std::vector<lvec> exact(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i) exact[i] = reference(pairs[i]);

    std::vector<bench::row> rows;
    using slerp_fn = vec3_t (*)(vec3_t, vec3_t, float);
    struct variant {
        const char *name, *kind;
        slerp_fn fn;
        const char *note;
    };
    const variant variants[] = {
        {"acos + Quake (vec3_slerp)", "faithful", vec3_slerp, "the report's; near-antipodal pairs go robust"},
        {"atan2 great circle, double (vec3_slerp_robust)", "fast", tiny3d::vec3_slerp_robust, "every input"},
    };
    std::vector<vec3_t> out(pairs.size());
    for (const variant &v : variants) {
        const bench::timing t = bench::measure_ns(repeats, double(pairs.size()), [&] {
            for (std::size_t i = 0; i < pairs.size(); ++i) out[i] = v.fn(pairs[i].a, pairs[i].b, pairs[i].t);
            bench::keep(out);
        });
        double sum = 0, worst = 0;
        for (std::size_t i = 0; i < pairs.size(); ++i) {
            const vec3_t r = v.fn(pairs[i].a, pairs[i].b, pairs[i].t);
            const double e = double(std::max({std::fabs(r.x - exact[i].x), std::fabs(r.y - exact[i].y),
                                              std::fabs(r.z - exact[i].z)}));
            sum += e;
            worst = std::max(worst, e);
        }
        rows.push_back({"slerp", v.name, v.kind, "ns/call", t, sum / double(pairs.size()), worst,
                        "max abs component (unit)", v.note});
    }
    std::vector<lvec> sink(pairs.size());
    const bench::timing t = bench::measure_ns(o.quick ? 1 : 5, double(pairs.size()), [&] {
        for (std::size_t i = 0; i < pairs.size(); ++i) sink[i] = reference(pairs[i]);
        bench::keep(sink);
    });
    rows.push_back({"slerp", "Rodrigues, long double (reference)", "reference", "ns/call", t, 0.0, 0.0,
                    "max abs component (unit)", "acos in long double"});
    return bench::report(o, "slerp", rows, "vec3 slerp: time per call vs error");
}
