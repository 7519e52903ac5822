// raster_fill_avx512.cpp — the 1-sample fill's AVX-512 kernel (fill_simd::avx512): a
// narrow triangle's row (at most NARROW_WIDTH = 16 columns) as ONE 16-lane register, the
// row's span a lane mask, the depth test a masked compare and the colour and depth writes
// masked stores (no colour read, no blend), where the SSE2 kernel needs up to four groups of
// four, each loaded, compared, blended and stored. Every other triangle goes to the SSE2
// kernels (fill_fast_rows).
//
// The same pixels, bit for bit, as the SSE2 kernel: the lanes' depth and intensity are
// formed in its operation order (the row's value plus the lane's column offset within its
// group of four, then the group's step added once per group before it), with no FMA
// contraction (avx512_region_open.inc), and the triangles it takes are exactly those the
// SSE2 narrow kernel takes. Tested against it and the portable kernel
// (tests/raster_rules_test.cpp).
//
// Compiled inside the AVX-512 target region; the headers are included before it opens, so
// their inline functions stay baseline x86-64. Run only on CPUs that have AVX-512 F/VL/DQ/BW
// (fill_simd_runs).
#include <algorithm>
#include <cstdint>

#include "raster_internal.h"
#include "../simd_config.h"

#ifdef TINY3D_AVX512
#include <immintrin.h>

#include "../avx512_region_open.inc"

namespace tiny3d::detail {
namespace {

template <depth_func Test>
inline __mmask16 depth_pass(__mmask16 cover, __m512 z, __m512 stored) {
    // The SSE2 kernel's compares (cmpltps … cmpneqps): ordered and signalling but for
    // not_equal, which is true on NaN.
    if constexpr (Test == depth_func::less) return _mm512_mask_cmp_ps_mask(cover, z, stored, _CMP_LT_OS);
    else if constexpr (Test == depth_func::less_equal) return _mm512_mask_cmp_ps_mask(cover, z, stored, _CMP_LE_OS);
    else if constexpr (Test == depth_func::equal) return _mm512_mask_cmp_ps_mask(cover, z, stored, _CMP_EQ_OQ);
    else if constexpr (Test == depth_func::greater) return _mm512_mask_cmp_ps_mask(cover, z, stored, _CMP_GT_OS);
    else if constexpr (Test == depth_func::greater_equal) return _mm512_mask_cmp_ps_mask(cover, z, stored, _CMP_GE_OS);
    else if constexpr (Test == depth_func::not_equal) return _mm512_mask_cmp_ps_mask(cover, z, stored, _CMP_NEQ_UQ);
    else return cover;  // always
}

// The lanes' offsets from the row's value, as the SSE2 kernel forms them: lane l of group
// g = l / 4 is (row + step·(l mod 4)) + 4·step, the group step added g times.
inline __m512 lanes_from(float row, __m512 within_group, __m512 group_step) {
    __m512 v = _mm512_add_ps(_mm512_set1_ps(row), within_group);
    v = _mm512_mask_add_ps(v, 0xFFF0, v, group_step);
    v = _mm512_mask_add_ps(v, 0xFF00, v, group_step);
    return _mm512_mask_add_ps(v, 0xF000, v, group_step);
}

// The covered columns of four rows dy .. dy + 3 as four 16-bit lane masks (bit x: column
// min_x + x), in the low 16 bits of out[0..3]: row_spans::at's operations for the four rows
// at once, lane pair (2r, 2r + 1) = row r's (lo, hi) pair — the same doubles, rounded the
// same way — then mask = bits lo..hi.
struct span_batch {
    __m512d a, a_step, b, b_step, low, high;
    explicit span_batch(const fast_triangle &f) {
        const double w = f.max_x - f.min_x;
        a = _mm512_broadcast_f64x2(_mm_loadu_pd(f.cross));
        a_step = _mm512_broadcast_f64x2(_mm_loadu_pd(f.cross_step));
        b = _mm512_broadcast_f64x2(_mm_loadu_pd(f.cross + 2));
        b_step = _mm512_broadcast_f64x2(_mm_loadu_pd(f.cross_step + 2));
        low = _mm512_broadcast_f64x2(_mm_setr_pd(-0.5, -w - 0.5));
        high = _mm512_broadcast_f64x2(_mm_setr_pd(w + 0.5, 0.5));
    }
    void masks(int dy, std::uint64_t out[4]) const {
        constexpr double K = 1 << 20;  // row_spans' offset: ceil(v) = K − trunc(K − v)
        const __m512d d = _mm512_cvtepi32_pd(_mm256_add_epi32(_mm256_set1_epi32(dy), _mm256_setr_epi32(0, 0, 1, 1, 2, 2, 3, 3)));
        const __m512d va = _mm512_add_pd(a, _mm512_mul_pd(a_step, d)), vb = _mm512_add_pd(b, _mm512_mul_pd(b_step, d));
        const __m512d u = _mm512_min_pd(_mm512_max_pd(_mm512_sub_pd(_mm512_max_pd(va, vb), _mm512_set1_pd(CROSS_EPS)), low), high);
        const __m256i t = _mm512_cvttpd_epi32(_mm512_sub_pd(_mm512_set1_pd(K), u));
        // Even lanes: lo = K − t, odd lanes: hi + 1 = t − K + 1; then (1 << n) − 1 in each.
        const __m256i ik = _mm256_set1_epi32(static_cast<int>(K));
        const __m256i n = _mm256_mask_sub_epi32(_mm256_sub_epi32(ik, t), 0xAA, t, _mm256_sub_epi32(ik, _mm256_set1_epi32(1)));
        const __m256i below = _mm256_sub_epi32(_mm256_sllv_epi32(_mm256_set1_epi32(1), n), _mm256_set1_epi32(1));
        // Per row (64-bit lane): the hi bits (odd dword, moved down) without the lo bits.
        _mm256_storeu_si256(reinterpret_cast<__m256i *>(out), _mm256_andnot_si256(below, _mm256_srli_epi64(below, 32)));
    }
};

template <depth_func Test, bool HasDepth>
[[gnu::always_inline]] inline void narrow_rows(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, bool depth_write, int y0, int y1) {
    const __m512 column = _mm512_setr_ps(0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3);
    const __m512 zoff = _mm512_mul_ps(_mm512_set1_ps(f.zdx), column);
    const __m512 ioff = _mm512_mul_ps(_mm512_set1_ps(f.idx), column);
    const __m512 zstep = _mm512_set1_ps(4.0f * f.zdx), istep = _mm512_set1_ps(4.0f * f.idx);
    const __m512 zero = _mm512_setzero_ps(), one = _mm512_set1_ps(1.0f);
    const span_batch spans(f);
    const float z0 = f.z, zdy = f.zdy, i0 = f.i, idy = f.idy;  // locals: the stores could alias f
    const int min_x = f.min_x, min_y = f.min_y;
    const __m128 z0v = _mm_set1_ps(z0), zdyv = _mm_set1_ps(zdy), i0v = _mm_set1_ps(i0), idyv = _mm_set1_ps(idy);
    alignas(32) std::uint64_t cover[4];
    alignas(16) float zrow_at[4], irow_at[4];  // the four rows' plane values z0 + zdy·dy, i0 + idy·dy
    for (int y = y0; y < y1; ++y) {
        const int r = (y - y0) & 3;
        if (r == 0) {
            const int dy = y - min_y;
            spans.masks(dy, cover);
            const __m128 dy_f = _mm_cvtepi32_ps(_mm_add_epi32(_mm_set1_epi32(dy), _mm_setr_epi32(0, 1, 2, 3)));
            _mm_store_ps(zrow_at, _mm_add_ps(z0v, _mm_mul_ps(zdyv, dy_f)));
            _mm_store_ps(irow_at, _mm_add_ps(i0v, _mm_mul_ps(idyv, dy_f)));
        }
        const __m512 z = lanes_from(zrow_at[r], zoff, zstep);
        const __m512 in = lanes_from(irow_at[r], ioff, istep);
        __mmask16 pass = _cvtu32_mask16(static_cast<unsigned>(cover[r]));
        if constexpr (HasDepth) {
            float *zrow = depth->row(y) + min_x;
            pass = depth_pass<Test>(pass, z, _mm512_maskz_loadu_ps(pass, zrow));
            if (depth_write) _mm512_mask_storeu_ps(zrow, pass, z);
        }
        _mm512_mask_storeu_ps(canvas.pixels[y] + min_x, pass, _mm512_min_ps(_mm512_max_ps(in, zero), one));
    }
}

}  // namespace

void fill_rows_narrow_avx512(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, depth_func test,
                             bool depth_write, int y0, int y1) {
    if (!depth) return narrow_rows<depth_func::always, false>(canvas, depth, f, false, y0, y1);
    with_depth_test(test, [&](auto t) { narrow_rows<t.value, true>(canvas, depth, f, depth_write, y0, y1); });
}

void fill_fast_bin_avx512(canvas_t &canvas, zbuffer &depth, const fast_triangle *tris, const triangle_edges *wide,
                          const std::uint32_t *bin, std::size_t count, depth_func test, int y0, int y1,
                          band_prefetch &ahead) {
    with_depth_test(test, [&](auto t) {
        for (std::size_t k = 0; k < count; ++k) {
            ahead.step();
            const fast_triangle &f = tris[bin[k]];
            if (k + 6 < count) {
                _mm_prefetch(reinterpret_cast<const char *>(&tris[bin[k + 6]]), _MM_HINT_T0);
                _mm_prefetch(reinterpret_cast<const char *>(&tris[bin[k + 6]]) + 64, _MM_HINT_T0);
            }
            const int first = std::max(y0, f.min_y), end = std::min(y1, f.max_y + 1);
            if (first >= end) continue;
            if (f.wide < 0 && narrow_fits(f, canvas.width)) narrow_rows<t.value, true>(canvas, &depth, f, true, first, end);
            else fill_fast_rows(canvas, &depth, f, f.wide >= 0 ? &wide[f.wide] : nullptr, test, true, first, end, fill_kernel::sse2);
        }
    });
}

}  // namespace tiny3d::detail

#include "../avx512_region_close.inc"
#endif
