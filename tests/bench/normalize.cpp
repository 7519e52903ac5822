// normalize.cpp — vector normalisation: the report's Quake inverse square root (faithful,
// the global vec3_normalize_fast), the fast accurate variant (1/std::sqrt in float), the
// exact one (double), and two rejected candidates built here for the record (SSE rsqrtss
// + one Newton step; rsqrtss + a second-order correction). Time per call over 4096
// vectors of mixed scale (2^±20); error = max over components of |result − exact unit
// vector| (long double reference), i.e. relative to the length.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "common/bench.h"
#include "math3d.h"
#include "../../src/simd_config.h"

#ifdef TINY3D_SSE2
#include <xmmintrin.h>
#endif

namespace {

constexpr int kTimedVectors = 4096;
constexpr float kScaleExponent = 20.0f;

using normalize_fn = vec3_t (*)(vec3_t);

vec3_t quake_global(vec3_t v) { return vec3_normalize_fast(v); }

#ifdef TINY3D_SSE2
float rsqrt_estimate(float x) { return _mm_cvtss_f32(_mm_rsqrt_ss(_mm_set_ss(x))); }

// Candidates are kept out of line like the library's functions (a fair call cost), but
// without the library's range check: normal-range inputs only.
// rsqrtss (12 bits) + one Newton step y·(1.5 − x/2·y²).
[[gnu::noinline]] vec3_t rsqrt_newton(vec3_t v) {
    const float sq = v.x * v.x + v.y * v.y + v.z * v.z;
    float y = rsqrt_estimate(sq);
    y = y * (1.5f - 0.5f * sq * y * y);
    return v * y;
}

// rsqrtss + y·(1 + r/2 + 3r²/8), r = 1 − x·y² (third-order convergence).
[[gnu::noinline]] vec3_t rsqrt_second_order(vec3_t v) {
    const float sq = v.x * v.x + v.y * v.y + v.z * v.z;
    const float y = rsqrt_estimate(sq);
    const float r = 1.0f - sq * y * y;
    return v * (y + y * (r * (0.5f + 0.375f * r)));
}
#endif

std::vector<vec3_t> random_vectors(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1, 1), e(-kScaleExponent, kScaleExponent);
    std::vector<vec3_t> v(std::size_t(count), vec3_t{0, 0, 0});
    for (vec3_t &p : v) {
        while (p == vec3_t{0, 0, 0}) p = vec3_t{u(rng), u(rng), u(rng)} * std::exp2(e(rng));
    }
    return v;
}

struct errors {
    double mean, max;
};

errors measure_error(normalize_fn f, const std::vector<vec3_t> &inputs) {
    double sum = 0, worst = 0;
    for (const vec3_t &v : inputs) {
        const long double x = v.x, y = v.y, z = v.z, len = std::sqrt(x * x + y * y + z * z);
        const vec3_t r = f(v);
        const double e = double(std::max({std::fabs(r.x - x / len), std::fabs(r.y - y / len), std::fabs(r.z - z / len)}));
        sum += e;
        worst = std::max(worst, e);
    }
    return {sum / double(inputs.size()), worst};
}

}  // namespace

int main(int argc, char **argv) {
    const bench::options o = bench::parse_options(argc, argv);
    const int repeats = o.quick ? 3 : 31;
    const std::vector<vec3_t> timed = random_vectors(kTimedVectors, 1);
    const std::vector<vec3_t> checked = random_vectors(o.quick ? 20000 : 1000000, 2);
    std::vector<vec3_t> out(timed.size());

    struct variant {
        const char *name, *kind;
        normalize_fn fn;
        const char *note;
    };
    std::vector<variant> variants = {
        {"Quake 0x5f3759df + 1 Newton (vec3_normalize_fast)", "faithful", quake_global, "the report's; safe prescale"},
        {"1/sqrtf (vec3_normalize_fast_accurate)", "fast", tiny3d::vec3_normalize_fast_accurate, "chosen fast path"},
        {"double sqrt (vec3_normalize)", "reference", tiny3d::vec3_normalize, "exact: one rounding"},
    };
#ifdef TINY3D_SSE2
    variants.push_back({"rsqrtss + 1 Newton (candidate)", "other", rsqrt_newton, "candidate, no range check"});
    variants.push_back({"rsqrtss + 2nd-order (candidate)", "other", rsqrt_second_order, "candidate, no range check"});
#endif
    std::vector<bench::row> rows;
    for (const variant &v : variants) {
        const bench::timing t = bench::measure_ns(repeats, double(timed.size()), [&] {
            for (std::size_t i = 0; i < timed.size(); ++i) out[i] = v.fn(timed[i]);
            bench::keep(out);
        });
        const errors e = measure_error(v.fn, checked);
        rows.push_back({"normalize", v.name, v.kind, "ns/call", t, e.mean, e.max, "max abs component (unit)", v.note});
    }
    return bench::report(o, "normalize", rows, "vec3 normalize: time per call vs error");
}
