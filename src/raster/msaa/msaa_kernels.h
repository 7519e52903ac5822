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

#ifdef TINY3D_SSE2
#include <emmintrin.h>
#endif

namespace tiny3d::detail {

// Per edge: the extremes of the sample offsets over the pattern.
struct edge_extremes {
    std::int64_t lo[3], hi[3];
    // Row y of f: the edge values e[] at column min_x and the columns [lo_x, hi_x] (from
    // min_x) where some sample could pass every edge; false when none. Int may be 32-bit
    // when f.narrow (every value then fits), as a 32-bit division is much cheaper.
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

#ifdef TINY3D_SSE2
// The low 32 bits of x · y lane by lane (SSE2 has no 32-bit multiply).
inline __m128i mullo32(__m128i x, __m128i y) {
    const __m128i even = _mm_mul_epu32(x, y), odd = _mm_mul_epu32(_mm_srli_epi64(x, 32), _mm_srli_epi64(y, 32));
    return _mm_unpacklo_epi32(_mm_shuffle_epi32(even, 0x08), _mm_shuffle_epi32(odd, 0x08));
}

// A narrow triangle's rows' column spans (from min_x) without the divisions of
// edge_extremes::row: per edge (one per lane), the best sample's value t at column 0 of a
// row (exact in 32 bits) times 1/a in float, the pixels where t + a·x ≥ 0 may hold. The
// float's error stays far below the margin EPS over the box (at most 2^11 columns), so a
// span holds every pixel row() gives and at most one more at each end; an edge with a = 0
// bounds nothing. Only which pixels are visited depends on it, never what they get.
class sample_row_spans {
public:
    // Rows from f.min_y + dy0 on; lane k of best (lanes 0 to 2): edge k's greatest sample
    // offset.
    __attribute__((always_inline)) void start(const msaa_triangle &f, __m128i best, int dy0) {
        auto row = [&](int k) { return static_cast<std::int32_t>(f.e[k] + f.b[k] * dy0); };
        t_ = _mm_add_epi32(_mm_setr_epi32(row(0), row(1), row(2), 0), best);  // (32 bits, wrapping)
        down_ = _mm_setr_epi32(static_cast<std::int32_t>(f.b[0]), static_cast<std::int32_t>(f.b[1]),
                               static_cast<std::int32_t>(f.b[2]), 0);
        const __m128 a = _mm_setr_ps(static_cast<float>(f.a[0]), static_cast<float>(f.a[1]),
                                     static_cast<float>(f.a[2]), 0.0f);
        const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f), inf = _mm_set1_ps(__builtin_inff());
        const __m128 inv = _mm_div_ps(one, _mm_or_ps(a, _mm_and_ps(_mm_cmpeq_ps(a, zero), one)));  // (a = 0: 1)
        // a > 0: x ≥ −t/a, the first column −⌊min t/a⌋; a < 0: the last ⌊min t/(−a)⌋;
        // OFFSET keeps both positive for the truncating conversion.
        const __m128 up = _mm_cmpgt_ps(a, zero), down = _mm_cmplt_ps(a, zero);
        const __m128 margin = _mm_set1_ps(EPS + OFFSET);
        up_ = _mm_and_ps(up, inv);
        up_add_ = _mm_or_ps(_mm_and_ps(up, margin), _mm_andnot_ps(up, inf));
        down_mul_ = _mm_and_ps(down, _mm_sub_ps(zero, inv));
        down_add_ = _mm_or_ps(_mm_and_ps(down, margin), _mm_andnot_ps(down, inf));
        const int columns = f.max_x - f.min_x + 1;
        low_ = _mm_setr_ps(static_cast<float>(OFFSET - columns), static_cast<float>(OFFSET - 1), 0.0f, 0.0f);
        high_ = _mm_setr_ps(static_cast<float>(OFFSET), static_cast<float>(OFFSET + columns - 1), 0.0f, 0.0f);
    }
    // The next four rows' spans [first, last], row r in lane r (first > last: no sample of
    // the row is inside); t[k]: edge k's t of the four rows.
    __attribute__((always_inline)) void next4(__m128i &first, __m128i &last, __m128i t[3]) {
        const __m128 rows = _mm_setr_ps(0.0f, 1.0f, 2.0f, 3.0f);
        __m128 lo = _mm_set1_ps(__builtin_inff()), hi = lo;
        auto edge = [&]<int K>(std::integral_constant<int, K>) {
            constexpr int lane = K * 0x55;
            const __m128i down = _mm_shuffle_epi32(down_, lane);
            // (b·r is exact in float: |b| < 2^20)
            t[K] = _mm_add_epi32(_mm_shuffle_epi32(t_, lane), _mm_cvttps_epi32(_mm_mul_ps(_mm_cvtepi32_ps(down), rows)));
            const __m128 tf = _mm_cvtepi32_ps(t[K]);
            lo = _mm_min_ps(lo, _mm_add_ps(_mm_mul_ps(tf, _mm_shuffle_ps(up_, up_, lane)), _mm_shuffle_ps(up_add_, up_add_, lane)));
            hi = _mm_min_ps(hi, _mm_add_ps(_mm_mul_ps(tf, _mm_shuffle_ps(down_mul_, down_mul_, lane)),
                                           _mm_shuffle_ps(down_add_, down_add_, lane)));
        };
        edge(std::integral_constant<int, 0>{}), edge(std::integral_constant<int, 1>{}), edge(std::integral_constant<int, 2>{});
        t_ = _mm_add_epi32(t_, _mm_slli_epi32(down_, 2));  // four rows on
        const __m128i offset = _mm_set1_epi32(OFFSET);
        lo = _mm_min_ps(_mm_max_ps(lo, _mm_shuffle_ps(low_, low_, 0x00)), _mm_shuffle_ps(high_, high_, 0x00));
        hi = _mm_min_ps(_mm_max_ps(hi, _mm_shuffle_ps(low_, low_, 0x55)), _mm_shuffle_ps(high_, high_, 0x55));
        first = _mm_sub_epi32(offset, _mm_cvttps_epi32(lo));
        last = _mm_sub_epi32(_mm_cvttps_epi32(hi), offset);
    }

private:
    static constexpr int OFFSET = 4096;  // > every narrow box's columns
    static constexpr float EPS = 1.0f / 64;
    __m128i t_, down_;
    __m128 up_, up_add_, down_mul_, down_add_, low_, high_;
};
#endif

// A chunkable triangle's row is walked in chunks short enough that every step and offset in
// one moves a value by less than 2^29: a value beyond ±2^30 at the chunk's start keeps its
// sign over it, and so does the clamped one, so every 32-bit test is the exact 64-bit one.
// Narrow triangles: one chunk per row, no clamp.
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

// Edge k's sample offsets in 32 bits, where the float ones are not exact (not f.narrow).
inline void sample_offsets_exact(const msaa_triangle &f, const sample_pattern &pat, int k, std::int32_t *out) {
    for (int s = 0; s < pat.count; ++s) out[s] = static_cast<std::int32_t>(sample_edge_offset(f.a[k], f.b[k], pat, s));
}

// Rows [y0, y1) := those of f among them; false when none are.
inline bool clamp_to_rows(const msaa_triangle &f, int &y0, int &y1) {
    y0 = std::max(y0, f.min_y);
    y1 = std::min(y1, f.max_y + 1);
    return y0 < y1;
}

// choose(S, Test) for samples 4, 8 or 16 and a test (not never), as integral constants.
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

// f drawn by `kernel`'s fill for `samples` (msaa_fill_for), out of line: a SIMD fill that
// hands f on keeps no registers across the call.
void fill_with(msaa_kernel kernel, int samples, sample_store &store, const msaa_triangle &f, const sample_pattern &pat,
               depth_func test, int y0, int y1);

#ifdef TINY3D_SSE2
// The kernel table's multisample fills for 4, 8, 16 samples (test not never), bit-identical
// to the portable kernel. SSE2: where f is chunkable, else the portable one.
msaa_row_fill msaa_fill_sse2(int samples, depth_func test);
#endif

#ifdef TINY3D_AVX2
// AVX2: where f is narrow (at 4× on the block tile), else the SSE2 functions.
msaa_row_fill fill_function_avx2(int samples, depth_func test);
// The 4-sample resolve of a row of blocks' first `pixels` columns (a multiple of 8), in the
// SSE2 resolve's order (same bits), blocks put back at rest; row 1's pointers null when it
// is padding.
void resolve_blocks4_avx2(float *p, const std::uint8_t *touched0, const std::uint8_t *touched1, int pixels,
                          float clear_colour, float *colour0, float *z0, float *colour1, float *z1);
// The 8- and 16-sample resolves of a row's first `pixels` columns (a multiple of 8), in the
// SSE2 resolve's order (same bits), pixels put back at rest.
void resolve_rows8_avx2(float *p, const std::uint8_t *touched, int pixels, float clear_colour, float *colour, float *z);
void resolve_rows16_avx2(float *p, const std::uint8_t *touched, int pixels, float clear_colour, float *colour, float *z);
#endif

#ifdef TINY3D_AVX512
// AVX-512: where f is chunkable, else the portable one.
msaa_row_fill fill_function_avx512(int samples, depth_func test);
// The 4-sample resolve of a row of blocks' first `pixels` columns (a multiple of 8), in the
// SSE2 resolve's order (same bits), blocks put back at rest; row 1's pointers null when it
// is padding.
void resolve_blocks4_avx512(float *p, const std::uint8_t *touched0, const std::uint8_t *touched1, int pixels,
                            float clear_colour, float *colour0, float *z0, float *colour1, float *z1);
#endif

}  // namespace tiny3d::detail

#endif
