// msaa_avx512.cpp — the multisample fill's AVX-512 kernels: msaa_lanes_fill.inc's kernels
// over mask registers (samples, below). 8× and 16×: one pixel's depths in one register and
// its colours in another; 4×: a 2 × 2 block of pixels per register for narrow triangles,
// else the SSE2 kernel's source compiled here (msaa_sse2_fill.inc), with 32 registers.
// Inside avx512_region_open.inc's target region (no FMA contraction: the portable kernel's
// float operations lane by lane, the same bits); run only where kernels_run allows.
#include <algorithm>
#include <cstdint>
#include <cstring>

#include "msaa_kernels.h"
#include "../../simd_config.h"

#ifdef TINY3D_AVX512
#include <emmintrin.h>
#include <immintrin.h>

#include "../../avx512_region_open.inc"

namespace tiny3d::detail {
namespace {

#include "msaa_sse2_fill.inc"
#include "msaa_lanes_fill.inc"  // ymm_lanes, passing, fill_rows_pixels

// One register of S samples (zmm for 16×, ymm for 8×): a pixel's depths or colours exactly
// (a wider access would reach into the floats after them). Masks: mask registers, bit s =
// sample s.
template <int S>
struct registers;

template <>
struct registers<16> {
    static constexpr int lanes = 16;
    using vf = __m512;
    using vi = __m512i;
    using mask = __mmask16;
    using coverage = __mmask16;
    static vf set(float v) { return _mm512_set1_ps(v); }
    static vi set_int(std::int64_t v) { return _mm512_set1_epi32(static_cast<std::int32_t>(v)); }
    static vi load_int(const std::int32_t *p) { return _mm512_load_si512(p); }
    static void store_int(std::int32_t *p, vi v) { _mm512_store_si512(p, v); }
    static vf load(const float *p) { return _mm512_loadu_ps(p); }
    static void store(float *p, vf v) { _mm512_storeu_ps(p, v); }
    static void write(float *p, mask m, vf value) { _mm512_mask_storeu_ps(p, m, value); }
    static vf add(vf a, vf b) { return _mm512_add_ps(a, b); }
    static vf mul(vf a, vf b) { return _mm512_mul_ps(a, b); }
    static vi add(vi a, vi b) { return _mm512_add_epi32(a, b); }
    static vi to_int(vf v) { return _mm512_cvtps_epi32(v); }
    static vf broadcast(__m128 v) { return _mm512_broadcastss_ps(v); }
    static vf broadcast4(const float *p) { return _mm512_broadcast_f32x4(_mm_load_ps(p)); }
    static vf to_float(vi v) { return _mm512_cvtepi32_ps(v); }
    static vf min(vf a, vf b) { return _mm512_min_ps(a, b); }
    static vf max(vf a, vf b) { return _mm512_max_ps(a, b); }
    // In: not a sign bit of b0 | b1 | b2 (a test into the mask register, not a mask inverted
    // through a general register).
    static coverage covered(vi b0, vi b1, vi b2) {
        return _mm512_testn_epi32_mask(_mm512_ternarylogic_epi32(b0, b1, b2, 0xFE), _mm512_set1_epi32(INT32_MIN));
    }
    template <int Predicate>
    static mask compare(coverage in, vf a, vf b) { return _mm512_mask_cmp_ps_mask(in, a, b, Predicate); }
    // 4× (fill_rows_quads): a 2 × 2 block of the tile per register (lanes 0–7 its upper row):
    // for small triangles fewer steps and row starts than four pixels of a row.
    static mask rows(bool upper, bool lower) { return static_cast<mask>((upper ? 0x00FF : 0) | (lower ? 0xFF00 : 0)); }
    static mask columns_within(mask inside, vi column, vi last) { return _mm512_mask_cmple_epu32_mask(inside, column, last); }
    static coverage covered_within(mask inside, vi b0, vi b1, vi b2) {
        return _mm512_mask_testn_epi32_mask(inside, _mm512_ternarylogic_epi32(b0, b1, b2, 0xFE), _mm512_set1_epi32(INT32_MIN));
    }
    // At rest a mark only tells the resolve where to read: one per block, unconditionally.
    static void mark(std::uint8_t *touched) { *touched = 1; }
};

template <>
struct registers<8> : ymm_lanes {
    using mask = __mmask8;
    using coverage = __mmask8;
    static void write(float *p, mask m, vf value) { _mm256_mask_storeu_ps(p, m, value); }
    static coverage covered(vi b0, vi b1, vi b2) {
        return _mm256_testn_epi32_mask(_mm256_ternarylogic_epi32(b0, b1, b2, 0xFE), _mm256_set1_epi32(INT32_MIN));
    }
    template <int Predicate>
    static mask compare(coverage in, vf a, vf b) { return _mm256_mask_cmp_ps_mask(in, a, b, Predicate); }
};

// The lane trait of msaa_lanes_fill.inc: chunkable triangles too, the next row prefetched.
template <int S>
struct samples : registers<S> {
    static constexpr bool wide = true, prefetch_below = true;
    // The column terms and edge offsets not from arrays: more 64-byte loads per step cost more
    // (measured; the box walk's multiplies are hoisted out of its unrolled rows anyway).
    static constexpr bool column_terms = false;
    using V = registers<S>;
    using mask = typename V::mask;
    static mask all(mask in) { return in; }
};

template <int S, depth_func Test>
void fill_avx512(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, depth_func test, int y0,
                 int y1) {
    if (!f.chunkable) return fill_with(msaa_kernel::portable, S, store, f, pat, test, y0, y1);
    if (!clamp_to_rows(f, y0, y1)) return;
    if constexpr (S == 4) {
        if (!store.blocks()) fill_rows_sse2<4, Test, false>(store, f, pat, y0, y1);
        else if (f.narrow) fill_quads<samples<16>, Test>(store, f, pat, y0, y1);
        else fill_rows_sse2<4, Test, true>(store, f, pat, y0, y1);
    } else {
        fill_rows_pixels<samples<S>, S, Test>(store, f, pat, y0, y1);
    }
}

}  // namespace

msaa_row_fill fill_function_avx512(int samples, depth_func test) {
    return fill_function(samples, test, [](auto s, auto t) -> msaa_row_fill { return &fill_avx512<s.value, t.value>; });
}

// Eight columns of a row of blocks at a time: the SSE2 resolve's transpose on all four
// 128-bit lanes, then one permute into column order (row 0 low half, row 1 high). At rest an
// untouched pixel sums to exactly 4·clear with minimum 1: no select.
void resolve_blocks4_avx512(float *p, const std::uint8_t *touched0, const std::uint8_t *touched1, int pixels,
                            float clear_colour, float *colour0, float *z0, float *colour1, float *z1) {
    const __m512 far = _mm512_set1_ps(1.0f), clear = _mm512_set1_ps(clear_colour), quarter = _mm512_set1_ps(0.25f);
    // Lane i < 8: column i of row 0 (block i/2, pixel i%2: lane 4·(i%2) + i/2); lanes 8..15 row 1.
    const __m512i column_order = _mm512_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7, 8, 12, 9, 13, 10, 14, 11, 15);
    for (int x = 0; x < pixels; x += 8, p += 4 * 32) {
        auto put = [&](__m512 colours, __m512 depths) {
            _mm256_storeu_ps(colour0 + x, _mm512_castps512_ps256(colours));
            _mm256_storeu_ps(z0 + x, _mm512_castps512_ps256(depths));
            if (!colour1) return;
            _mm256_storeu_ps(colour1 + x, _mm512_extractf32x8_ps(colours, 1));
            _mm256_storeu_ps(z1 + x, _mm512_extractf32x8_ps(depths, 1));
        };
        std::uint64_t t0, t1 = 0;
        std::memcpy(&t0, touched0 + x, sizeof t0);
        if (touched1) std::memcpy(&t1, touched1 + x, sizeof t1);
        if ((t0 | t1) == 0) {
            put(clear, far);
            continue;
        }
        // (s0 + s2) + (s1 + s3) by op of every pixel, at `offset` (depths 0, colours 16).
        auto reduce = [p](int offset, auto op) {
            const __m512 b0 = _mm512_load_ps(p + offset), b1 = _mm512_load_ps(p + 32 + offset);
            const __m512 b2 = _mm512_load_ps(p + 64 + offset), b3 = _mm512_load_ps(p + 96 + offset);
            // Per lane: (s0 + s2, s0' + s2', s1 + s3, s1' + s3') of blocks 0 and 1 (2 and 3).
            const __m512 v01 = op(_mm512_unpacklo_ps(b0, b1), _mm512_unpackhi_ps(b0, b1));
            const __m512 v23 = op(_mm512_unpacklo_ps(b2, b3), _mm512_unpackhi_ps(b2, b3));
            return op(_mm512_shuffle_ps(v01, v23, _MM_SHUFFLE(1, 0, 1, 0)),
                      _mm512_shuffle_ps(v01, v23, _MM_SHUFFLE(3, 2, 3, 2)));
        };
        const __m512 colours = _mm512_mul_ps(
            _mm512_permutexvar_ps(column_order, reduce(16, [](__m512 u, __m512 v) { return _mm512_add_ps(u, v); })), quarter);
        const __m512 depths =
            _mm512_permutexvar_ps(column_order, reduce(0, [](__m512 u, __m512 v) { return _mm512_min_ps(u, v); }));
        put(colours, depths);
        for (int k = 0; k < 4; ++k) _mm512_store_ps(p + 32 * k, far), _mm512_store_ps(p + 32 * k + 16, clear);
    }
}

}  // namespace tiny3d::detail

#include "../../avx512_region_close.inc"

#endif  // TINY3D_AVX512
