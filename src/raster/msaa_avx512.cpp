// msaa_avx512.cpp — the multisample fill's AVX-512 kernel (msaa_kernel::avx512): one pixel's
// 8 or 16 samples in one register. Per pixel: the three edge values at every sample stepped
// by one add each, coverage as a mask register (the sign bits of their OR), the depth test
// as a masked compare and the depth and colour writes as masked stores — where the SSE2
// kernel needs two or four groups of four, each with a select per store.
//
// Compiled for AVX-512 inside a target region that GCC and clang both apply (as
// line_tabulated_avx512.cpp is): the headers are included before the region opens, so
// their inline functions stay baseline x86-64. Run only on CPUs that have it
// (best_msaa_kernel). No FMA contraction: the portable kernel's float operations, rounded
// step by step, lane by lane.
#include <algorithm>
#include <cstdint>

#include "msaa_kernels.h"
#include "../simd_config.h"

#ifdef TINY3D_AVX512
#include <emmintrin.h>
#include <immintrin.h>

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx512f,avx512vl,avx512dq,avx512bw"))), apply_to = function)
#pragma clang fp contract(off)
#else
#pragma GCC push_options
#pragma GCC target("avx512f,avx512vl,avx512dq,avx512bw")
#pragma GCC optimize("fp-contract=off")
// GCC 12's AVX-512 intrinsics pass _mm512_undefined_ps() (self-initialised) as the unused
// merge source, which -W(maybe-)uninitialized reports once inlined (GCC bug 105593).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif

namespace tiny3d::detail {
namespace {

// 4×: the SSE2 kernel's source, compiled here for AVX-512 (msaa_sse2_fill.inc).
#include "msaa_sse2_fill.inc"

// The depth test on sixteen lanes, as depth_passes decides it per sample (a NaN depth
// passes only not_equal and always), limited to the lanes of `in`.
template <depth_func Test>
inline __mmask16 passing(__mmask16 in, __m512 z, __m512 stored) {
    if constexpr (Test == depth_func::never) return 0;
    else if constexpr (Test == depth_func::less) return _mm512_mask_cmp_ps_mask(in, z, stored, _CMP_LT_OQ);
    else if constexpr (Test == depth_func::less_equal) return _mm512_mask_cmp_ps_mask(in, z, stored, _CMP_LE_OQ);
    else if constexpr (Test == depth_func::equal) return _mm512_mask_cmp_ps_mask(in, z, stored, _CMP_EQ_OQ);
    else if constexpr (Test == depth_func::greater) return _mm512_mask_cmp_ps_mask(in, z, stored, _CMP_GT_OQ);
    else if constexpr (Test == depth_func::greater_equal) return _mm512_mask_cmp_ps_mask(in, z, stored, _CMP_GE_OQ);
    else if constexpr (Test == depth_func::not_equal) return _mm512_mask_cmp_ps_mask(in, z, stored, _CMP_NEQ_UQ);
    else return in;
}

// Sixteen lanes of the low 32 bits of v (narrow edge values: the wrap is exact).
inline __m512i lanes(std::int64_t v) { return _mm512_set1_epi32(static_cast<std::int32_t>(v)); }

// S = 8 or 16 samples in lanes [0, S) of one register; the other lanes are never loaded or
// stored (`live`).
template <int S, depth_func Test>
void fill_rows(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, bool depth_write,
               float clear_colour, int y0, int y1) {
    constexpr __mmask16 live = static_cast<__mmask16>((1u << S) - 1);
    // The edge offsets a/16·dx + b/16·dy per sample, in float: a·(dx/16) is the integer
    // −Δy·dx, |·| < 2^18, so every product and sum is exact and converts to the portable
    // kernel's integers; the depth offsets are the portable kernel's float operations.
    const __m512 ox = _mm512_maskz_loadu_ps(live, pat.fdx), oy = _mm512_maskz_loadu_ps(live, pat.fdy);
    edge_extremes off;
    __m512i d[3];
    for (int k = 0; k < 3; ++k) {
        const __m512 v = _mm512_add_ps(_mm512_mul_ps(_mm512_set1_ps(static_cast<float>(f.a[k])), ox),
                                       _mm512_mul_ps(_mm512_set1_ps(static_cast<float>(f.b[k])), oy));
        d[k] = _mm512_cvtps_epi32(v);
        off.lo[k] = static_cast<std::int64_t>(_mm512_mask_reduce_min_ps(live, v));
        off.hi[k] = static_cast<std::int64_t>(_mm512_mask_reduce_max_ps(live, v));
    }
    const __m512 dz = _mm512_add_ps(_mm512_mul_ps(_mm512_set1_ps(f.zdx), ox), _mm512_mul_ps(_mm512_set1_ps(f.zdy), oy));
    const __m512i step0 = _mm512_set1_epi32(static_cast<std::int32_t>(f.a[0]));
    const __m512i step1 = _mm512_set1_epi32(static_cast<std::int32_t>(f.a[1]));
    const __m512i step2 = _mm512_set1_epi32(static_cast<std::int32_t>(f.a[2]));
    const __m512 ones = _mm512_set1_ps(1.0f), clear = _mm512_set1_ps(clear_colour);
    // Depth in lane 0, intensity in lane 1: both planes' row value plus step · column in one
    // multiply and add (the portable kernel's float operations, lane by lane).
    const __m128 plane0 = _mm_setr_ps(f.z, f.i, 0.0f, 0.0f), plane_dy = _mm_setr_ps(f.zdy, f.idy, 0.0f, 0.0f);
    const __m128 plane_dx = _mm_setr_ps(f.zdx, f.idx, 0.0f, 0.0f);
    const __m128 one = _mm_set1_ps(1.0f), zero = _mm_setzero_ps();
    for (int y = y0; y < y1; ++y) {
        std::int32_t e[3];
        int lo, hi;
        if (!off.row(f, y, e, lo, hi)) continue;  // narrow: 32 bits
        // The samples' edge values at column lo (narrow: 32 bits), stepped by a per column.
        __m512i b0 = _mm512_add_epi32(lanes(e[0] + f.a[0] * lo), d[0]);
        __m512i b1 = _mm512_add_epi32(lanes(e[1] + f.a[1] * lo), d[1]);
        __m512i b2 = _mm512_add_epi32(lanes(e[2] + f.a[2] * lo), d[2]);
        std::uint8_t *touched = store.touched_row(y) + f.min_x + lo;
        float *p = store.pixel(f.min_x + lo, y);
        const __m128 plane_row = _mm_add_ps(plane0, _mm_mul_ps(plane_dy, _mm_set1_ps(static_cast<float>(y - f.min_y))));
        __m128 column = _mm_set1_ps(static_cast<float>(lo));  // exactly (< 2^24)
        for (int x = lo; x <= hi; ++x, p += 2 * S, ++touched, column = _mm_add_ps(column, one)) {
            // A sample is in when all three edge values are ≥ 0: their OR's sign bit is clear.
            const __mmask16 in = static_cast<__mmask16>(
                ~_mm512_movepi32_mask(_mm512_ternarylogic_epi32(b0, b1, b2, 0xFE)) & live);  // 0xFE: b0 | b1 | b2
            b0 = _mm512_add_epi32(b0, step0), b1 = _mm512_add_epi32(b1, step1), b2 = _mm512_add_epi32(b2, step2);
            if (!in) continue;
            const __m128 at = _mm_add_ps(plane_row, _mm_mul_ps(plane_dx, column));
            const __m128 shade = _mm_min_ps(_mm_max_ps(_mm_shuffle_ps(at, at, 0x55), zero), one);  // clamp01
            const __m512 z = _mm512_add_ps(_mm512_broadcastss_ps(at), dz);
            // Until its first touch this frame a pixel's samples hold depth 1 and the clear
            // colour: read as such (a load with no lane set reads no memory), no branch.
            const __mmask16 held = static_cast<__mmask16>(live & (0u - static_cast<unsigned>(*touched)));
            *touched = 1;
            const __m512 stored = _mm512_mask_loadu_ps(ones, held, p);
            const __mmask16 pass = passing<Test>(in, z, stored);
            if (depth_write) _mm512_mask_storeu_ps(p, live, _mm512_mask_blend_ps(pass, stored, z));
            else _mm512_mask_storeu_ps(p, static_cast<__mmask16>(live & ~held), ones);
            _mm512_mask_storeu_ps(p + S, live, _mm512_mask_blend_ps(pass, _mm512_mask_loadu_ps(clear, held, p + S),
                                                                   _mm512_broadcastss_ps(shade)));
        }
    }
}

template <int S>
void fill_rows_dispatch(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, depth_func test,
                        bool depth_write, float clear_colour, int y0, int y1) {
    switch (test) {
        case depth_func::never: return;
        case depth_func::less: return fill_rows<S, depth_func::less>(store, f, pat, depth_write, clear_colour, y0, y1);
        case depth_func::less_equal:
            return fill_rows<S, depth_func::less_equal>(store, f, pat, depth_write, clear_colour, y0, y1);
        case depth_func::equal: return fill_rows<S, depth_func::equal>(store, f, pat, depth_write, clear_colour, y0, y1);
        case depth_func::greater: return fill_rows<S, depth_func::greater>(store, f, pat, depth_write, clear_colour, y0, y1);
        case depth_func::greater_equal:
            return fill_rows<S, depth_func::greater_equal>(store, f, pat, depth_write, clear_colour, y0, y1);
        case depth_func::not_equal:
            return fill_rows<S, depth_func::not_equal>(store, f, pat, depth_write, clear_colour, y0, y1);
        case depth_func::always: return fill_rows<S, depth_func::always>(store, f, pat, depth_write, clear_colour, y0, y1);
    }
}

}  // namespace

void fill_rows_avx512(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, depth_func test,
                      bool depth_write, float clear_colour, int y0, int y1) {
    if (pat.count == 4) return fill_rows_sse2_dispatch<4>(store, f, pat, test, depth_write, clear_colour, y0, y1);
    if (pat.count == 16) return fill_rows_dispatch<16>(store, f, pat, test, depth_write, clear_colour, y0, y1);
    return fill_rows_dispatch<8>(store, f, pat, test, depth_write, clear_colour, y0, y1);
}

}  // namespace tiny3d::detail

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC diagnostic pop
#pragma GCC pop_options
#endif

#endif  // TINY3D_AVX512
