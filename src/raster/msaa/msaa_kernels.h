// msaa_kernels.h — internal to the multisample fill: what the kernels of msaa.cpp (portable,
// SSE2), msaa_avx2.cpp and msaa_avx512.cpp share (their SIMD source shared in
// msaa_sse2_fill.inc and msaa_lanes_fill.inc), and the AVX2 and AVX-512 kernels' entry
// points. Included by those files before their target regions open, so everything inline
// here stays baseline.
#ifndef TINY3D_MSAA_KERNELS_H
#define TINY3D_MSAA_KERNELS_H

#include <algorithm>
#include <cstdint>
#include <type_traits>

#include "msaa.h"
#include "../../simd_config.h"

namespace tiny3d::detail {

// Per edge: the extremes over the pattern of the offsets of the edge value at a sample
// from the value at the pixel centre.
struct edge_extremes {
    std::int64_t lo[3], hi[3];
    // Row y of f: the edge values e[] at the centre of its first column (min_x) and the
    // columns [lo_x, hi_x] (relative to min_x) where some sample could pass every edge.
    // False when that span is empty. Int: std::int64_t, or std::int32_t when f.narrow (the
    // best sample's value at column 0 lies where narrow bounds every edge value, below
    // 2^31 − 2^24, and |a| < 2^19; a 32-bit division has a fraction of a 64-bit one's latency).
    template <class Int>
    bool row(const msaa_triangle &f, int y, Int e[3], int &lo_x, int &hi_x) const {
        Int first = 0, last = static_cast<Int>(f.max_x - f.min_x);
        for (int k = 0; k < 3; ++k) {
            e[k] = static_cast<Int>(f.e[k] + f.b[k] * (y - f.min_y));
            const Int top = e[k] + static_cast<Int>(hi[k]);  // the best sample's value at column 0
            const Int a = static_cast<Int>(f.a[k]);
            if (a > 0) first = std::max(first, static_cast<Int>(-floor_div(top, a)));  // top + a·x ≥ 0
            else if (a < 0) last = std::min(last, floor_div(top, static_cast<Int>(-a)));
            else if (top < 0) last = -1;
        }
        lo_x = static_cast<int>(first);
        hi_x = static_cast<int>(std::max<Int>(last, first - 1));
        return lo_x <= hi_x;
    }
};

// The SIMD kernels' walk along a row of a triangle that is not narrow (chunkable): chunks
// of columns short enough that, from a value clamped to ±2^30 at the chunk's first
// column, every step and sample offset in it moves the value by less than 2^29. A value
// beyond ±2^30 therefore keeps its sign over the whole chunk, and so does the clamped one:
// every sample test is the exact 64-bit test, in 32 bits. Narrow triangles: one chunk per
// row, no clamp (their values fit as they are).
inline constexpr std::int64_t CHUNK_CLAMP = std::int64_t{1} << 30;

// Columns per chunk for f with sample offset extremes `off` (≥ 1 when f.chunkable).
inline int chunk_columns(const msaa_triangle &f, const edge_extremes &off) {
    if (f.narrow) return f.max_x - f.min_x + 1;
    std::int64_t columns = f.max_x - f.min_x + 1;
    for (int k = 0; k < 3; ++k) {
        const std::int64_t step = f.a[k] < 0 ? -f.a[k] : f.a[k];
        if (step) columns = std::min(columns, ((CHUNK_CLAMP / 2) - (off.hi[k] - off.lo[k])) / step);
    }
    return static_cast<int>(std::max<std::int64_t>(columns, 1));
}

// An edge's value at a chunk's first column (64 bits) as the kernels' 32 bits.
inline std::int32_t chunk_start(const msaa_triangle &f, std::int64_t v) {
    if (!f.narrow) v = std::clamp(v, -CHUNK_CLAMP, CHUNK_CLAMP);
    return static_cast<std::int32_t>(v);
}

// Edge k's sample offsets (sample_edge_offset) in 32 bits: the SIMD kernels compute them in
// float where that is exact (f.narrow) and take these otherwise.
inline void sample_offsets_exact(const msaa_triangle &f, const sample_pattern &pat, int k, std::int32_t *out) {
    for (int s = 0; s < pat.count; ++s) out[s] = static_cast<std::int32_t>(sample_edge_offset(f.a[k], f.b[k], pat, s));
}

// Rows [y0, y1) := those of f among them; false when none are.
inline bool clamp_to_rows(const msaa_triangle &f, int &y0, int &y1) {
    y0 = std::max(y0, f.min_y);
    y1 = std::min(y1, f.max_y + 1);
    return y0 < y1;
}

// The msaa_row_fill choose(S, Test) returns for samples (4, 8 or 16) and test (not never),
// S and Test as std::integral_constant: one kernel file's functions by sample count and test.
template <class Choose>
msaa_row_fill fill_function(int samples, depth_func test, Choose &&choose) {
    msaa_row_fill chosen = nullptr;
    with_depth_test(test, [&](auto t) {
        if (samples == 4) chosen = choose(std::integral_constant<int, 4>{}, t);
        else if (samples == 8) chosen = choose(std::integral_constant<int, 8>{}, t);
        else chosen = choose(std::integral_constant<int, 16>{}, t);
    });
    return chosen;
}

#ifdef TINY3D_SSE2
// msaa_fill_for's SSE2 functions (samples 4, 8 or 16): the SSE2 kernel where f is
// chunkable, else the portable one.
msaa_row_fill msaa_fill_sse2(int samples, depth_func test);
#endif

#ifdef TINY3D_AVX2
// msaa_fill_for's AVX2 functions (msaa_kernel::avx2; only on CPUs kernels_run() reports
// it for, or avx512), samples 4, 8 or 16, test not never: the AVX2 kernel where f is narrow,
// the SSE2 functions otherwise. The same integer tests and float operations as the portable
// kernel.
msaa_row_fill fill_function_avx2(int samples, depth_func test);
#endif

#ifdef TINY3D_AVX512
// msaa_fill_for's AVX-512 functions (msaa_kernel::avx512; only on CPUs kernels_run()
// reports it for), samples 4, 8 or 16, test not never: the AVX-512 kernels where f is
// chunkable, the portable one otherwise. The same integer tests and float operations as the
// portable kernel.
msaa_row_fill fill_function_avx512(int samples, depth_func test);
// The 4-sample resolve of one row of blocks' first `pixels` columns (a multiple of 8): p at
// its first block, the tile at rest (sample_store), its two rows' touched bytes, canvas
// colours and depths (row 1's all null when the block row's second row is padding):
// colour := ((s0 + s2) + (s1 + s3)) · 1/4, z := min(min(s0, s2), min(s1, s3)) — the SSE2
// resolve's operations in its order, so the same bits — and every block read put back at
// rest. Eight columns whose pixels are all untouched get the clear values without reading
// their samples.
void resolve_blocks4_avx512(float *p, const std::uint8_t *touched0, const std::uint8_t *touched1, int pixels,
                            float clear_colour, float *colour0, float *z0, float *colour1, float *z1);
#endif

}  // namespace tiny3d::detail

#endif
