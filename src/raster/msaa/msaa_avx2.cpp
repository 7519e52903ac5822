// msaa_avx2.cpp — the multisample fill's AVX2 kernels for narrow triangles: msaa_lanes_fill.inc's
// kernels over eight lanes with vector masks (lanes8). 8× and 16×: a pixel's samples in one
// or two registers; 4×: two pixels of a row of the block tile per step, and its resolve.
// Compiled inside avx2_region_open.inc's target region; no FMA contraction, so the samples
// are bit-identical to the portable ones.
#include <algorithm>
#include <cstdint>
#include <cstring>

#include "msaa_kernels.h"
#include "../../simd_config.h"

#ifdef TINY3D_AVX2
#include <immintrin.h>

#include "../../avx2_region_open.inc"

namespace tiny3d::detail {
namespace {

#include "msaa_lanes_fill.inc"  // ymm_lanes, passing, fill_rows_pixels

// The lane trait of msaa_lanes_fill.inc: masks as vectors (vmaskmovps reads the sign bits),
// coverage the OR of the three edge values (sign set: out); narrow triangles, no prefetch.
struct lanes8 : ymm_lanes {
    static constexpr bool wide = false, prefetch_below = false, column_terms = true;
    using mask = __m256;
    using coverage = __m256;
    static void write(float *p, mask m, vf value) { _mm256_maskstore_ps(p, _mm256_castps_si256(m), value); }
    static coverage covered(vi b0, vi b1, vi b2) { return _mm256_castsi256_ps(_mm256_or_si256(_mm256_or_si256(b0, b1), b2)); }
    template <int Predicate>
    static mask compare(coverage in, vf z, vf stored) { return _mm256_andnot_ps(in, _mm256_cmp_ps(z, stored, Predicate)); }
    static mask all(coverage in) { return _mm256_andnot_ps(in, _mm256_castsi256_ps(_mm256_set1_epi32(-1))); }
    // 4× (fill_rows_quads): one row of a 2 × 2 block, its 8 depths and its 8 colours each an
    // aligned 32-byte half of one of the block's lines (no permutes).
    static vi rows(bool, bool) { return _mm256_setzero_si256(); }
    static vi columns_within(vi out, vi column, vi last) {
        return _mm256_or_si256(out, _mm256_or_si256(_mm256_cmpgt_epi32(_mm256_setzero_si256(), column),
                                                    _mm256_cmpgt_epi32(column, last)));
    }
    static coverage covered_within(vi out, vi b0, vi b1, vi b2) {
        return _mm256_castsi256_ps(_mm256_or_si256(_mm256_or_si256(_mm256_or_si256(b0, b1), b2), out));
    }
    // At rest a mark only tells the resolve where to read (any of a block's four pixels: the
    // block resolve reads both rows of a group with one).
    static void mark(std::uint8_t *touched) { *touched = 1; }
};

template <int S, depth_func Test>
void fill_avx2(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, depth_func test, int y0, int y1) {
    if (!f.narrow || (S == 4 && !store.blocks()))  // (lanes8's 4× steps walk the block layout)
        return fill_with(msaa_kernel::sse2, S, store, f, pat, test, y0, y1);
    if (!clamp_to_rows(f, y0, y1)) return;
    if constexpr (S == 4) fill_quads<lanes8, Test>(store, f, pat, y0, y1);
    else fill_rows_pixels<lanes8, S, Test>(store, f, pat, y0, y1);
}

}  // namespace

msaa_row_fill fill_function_avx2(int samples, depth_func test) {
    return fill_function(samples, test, [](auto s, auto t) -> msaa_row_fill { return &fill_avx2<s.value, t.value>; });
}

// S = 8 or 16 (rows layout), eight pixels at a time: per pixel the sums of samples l, l + 4, … (lanes
// l) with pixel j in one register's low half and pixel j + 4 in its high half, then the
// SSE2 resolve's transpose on both halves at once (per pixel (l0 + l2) + (l1 + l3), the
// nearest sample): its operations in its order (same bits). The tile is at rest
// (sample_store): eight unmarked pixels get the clear values unread, otherwise all eight
// are read (an unmarked one sums to exactly S·clear, nearest 1: no select) and put back at
// rest.
template <int S>
void resolve_rows_avx2(float *p, const std::uint8_t *touched, int pixels, float clear_colour, float *colour, float *z) {
    const __m256 inv = _mm256_set1_ps(1.0f / S), clear = _mm256_set1_ps(clear_colour), far = _mm256_set1_ps(1.0f);
    for (int x = 0; x < pixels; x += 8, p += 8 * 2 * S) {
        std::uint64_t t8;
        std::memcpy(&t8, touched + x, sizeof t8);
        if (t8 == 0) {
            _mm256_storeu_ps(colour + x, clear), _mm256_storeu_ps(z + x, far);
            continue;
        }
        // Pixels j and j + 4: op over their groups of four at `offset` (c[l], c[l + 4], … in turn).
        auto group = [p](int j, int offset, auto op) {
            const float *a = p + 2 * S * j + offset, *b = p + 2 * S * (j + 4) + offset;
            const __m256 u = _mm256_loadu_ps(a), v = _mm256_loadu_ps(b);
            __m256 r = op(_mm256_permute2f128_ps(u, v, 0x20), _mm256_permute2f128_ps(u, v, 0x31));
            if constexpr (S == 16) {
                const __m256 u2 = _mm256_loadu_ps(a + 8), v2 = _mm256_loadu_ps(b + 8);
                r = op(op(r, _mm256_permute2f128_ps(u2, v2, 0x20)), _mm256_permute2f128_ps(u2, v2, 0x31));
            }
            return r;
        };
        auto reduce = [&](int offset, auto op) {
            const __m256 q0 = group(0, offset, op), q1 = group(1, offset, op), q2 = group(2, offset, op),
                         q3 = group(3, offset, op);
            const __m256 v01 = op(_mm256_unpacklo_ps(q0, q1), _mm256_unpackhi_ps(q0, q1));
            const __m256 v23 = op(_mm256_unpacklo_ps(q2, q3), _mm256_unpackhi_ps(q2, q3));
            return op(_mm256_castpd_ps(_mm256_unpacklo_pd(_mm256_castps_pd(v01), _mm256_castps_pd(v23))),
                      _mm256_castpd_ps(_mm256_unpackhi_pd(_mm256_castps_pd(v01), _mm256_castps_pd(v23))));
        };
        __m256 c = _mm256_mul_ps(reduce(S, [](__m256 u, __m256 v) { return _mm256_add_ps(u, v); }), inv);
        __m256 d = reduce(0, [](__m256 u, __m256 v) { return _mm256_min_ps(u, v); });
        _mm256_storeu_ps(colour + x, c), _mm256_storeu_ps(z + x, d);
#pragma GCC unroll 8
        for (int j = 0; j < 8 * 2 * S; j += 2 * S)
#pragma GCC unroll 2
            for (int g = 0; g < S; g += 8) _mm256_store_ps(p + j + g, far), _mm256_store_ps(p + j + S + g, clear);
    }
}

// Eight columns of a row of blocks (four blocks) at a time, each of its two rows as the
// SSE2 resolve's transpose on both 128-bit halves (the four blocks' columns 0 and 1 of the
// row), then one permute into column order: its operations in its order (same bits). At rest
// an unmarked pixel sums to exactly 4·clear with minimum 1: no select.
void resolve_blocks4_avx2(float *p, const std::uint8_t *touched0, const std::uint8_t *touched1, int pixels,
                          float clear_colour, float *colour0, float *z0, float *colour1, float *z1) {
    const __m256 far = _mm256_set1_ps(1.0f), clear = _mm256_set1_ps(clear_colour), quarter = _mm256_set1_ps(0.25f);
    // Lane i: column i (block i/2, pixel i%2, which the transpose leaves in lane 4·(i%2) + i/2).
    const __m256i column_order = _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7);
    for (int x = 0; x < pixels; x += 8, p += 4 * 32) {
        std::uint64_t t0, t1 = 0;
        std::memcpy(&t0, touched0 + x, sizeof t0);
        if (touched1) std::memcpy(&t1, touched1 + x, sizeof t1);
        if ((t0 | t1) == 0) {
            _mm256_storeu_ps(colour0 + x, clear), _mm256_storeu_ps(z0 + x, far);
            if (colour1) _mm256_storeu_ps(colour1 + x, clear), _mm256_storeu_ps(z1 + x, far);
            continue;
        }
        // (s0 + s2) + (s1 + s3) by op of one row's eight pixels, at `offset` (depths 8r, colours 16 + 8r).
        auto reduce = [p, column_order](int offset, auto op) {
            const __m256 b0 = _mm256_load_ps(p + offset), b1 = _mm256_load_ps(p + 32 + offset);
            const __m256 b2 = _mm256_load_ps(p + 64 + offset), b3 = _mm256_load_ps(p + 96 + offset);
            const __m256 v01 = op(_mm256_unpacklo_ps(b0, b1), _mm256_unpackhi_ps(b0, b1));
            const __m256 v23 = op(_mm256_unpacklo_ps(b2, b3), _mm256_unpackhi_ps(b2, b3));
            const __m256 r = op(_mm256_castpd_ps(_mm256_unpacklo_pd(_mm256_castps_pd(v01), _mm256_castps_pd(v23))),
                                _mm256_castpd_ps(_mm256_unpackhi_pd(_mm256_castps_pd(v01), _mm256_castps_pd(v23))));
            return _mm256_permutevar8x32_ps(r, column_order);
        };
        const auto add = [](__m256 u, __m256 v) { return _mm256_add_ps(u, v); };
        const auto min = [](__m256 u, __m256 v) { return _mm256_min_ps(u, v); };
        _mm256_storeu_ps(colour0 + x, _mm256_mul_ps(reduce(16, add), quarter)), _mm256_storeu_ps(z0 + x, reduce(0, min));
        if (colour1) _mm256_storeu_ps(colour1 + x, _mm256_mul_ps(reduce(24, add), quarter)), _mm256_storeu_ps(z1 + x, reduce(8, min));
#pragma GCC unroll 4
        for (int k = 0; k < 4; ++k)
            _mm256_store_ps(p + 32 * k, far), _mm256_store_ps(p + 32 * k + 8, far), _mm256_store_ps(p + 32 * k + 16, clear),
                _mm256_store_ps(p + 32 * k + 24, clear);
    }
}

void resolve_rows8_avx2(float *p, const std::uint8_t *touched, int pixels, float clear_colour, float *colour, float *z) {
    resolve_rows_avx2<8>(p, touched, pixels, clear_colour, colour, z);
}

void resolve_rows16_avx2(float *p, const std::uint8_t *touched, int pixels, float clear_colour, float *colour, float *z) {
    resolve_rows_avx2<16>(p, touched, pixels, clear_colour, colour, z);
}

}  // namespace tiny3d::detail

#include "../../avx512_region_close.inc"

#endif  // TINY3D_AVX2
