// raster_fill_avx2.cpp — the 1-sample fill's AVX2 kernel (raster_simd::avx2), for CPUs
// without AVX-512: the band loop with the narrow triangles (narrow_fits) drawn by
// narrow_rows.inc two groups of four per 256-bit register (SSE2's instance: one); every other
// triangle goes to the SSE2 loops (fill_fast_rows). The same pixels bit for bit: each group
// is formed as SSE2 forms it and only then paired, the compares and selects are SSE2's on
// eight lanes (tests/raster_threads_test.cpp, every depth test). Inside avx2_region_open.inc's
// target region (no FMA contraction); run only where kernels_run.
#include <algorithm>

#include "fill.h"
#include "../../simd_config.h"

#ifdef TINY3D_AVX2
#include <immintrin.h>

#include "../../avx2_region_open.inc"

namespace tiny3d::detail {
namespace {

#include "narrow_rows.inc"

// The narrow rows kernel's lanes (narrow_rows.inc): two groups of four per 256-bit register,
// a lone last group in a 128-bit one; the SSE2 kernel's compares as vcmpps predicates and its
// and/andnot/or selects as blends.
struct lanes4_avx : lanes4 {
    template <depth_func Test>
    static vec depth_mask(vec z, vec stored) { return _mm_cmp_ps(z, stored, depth_predicate<Test>()); }
    static vec select(vec mask, vec a, vec b) { return _mm_blendv_ps(b, a, mask); }
};
struct lanes8_avx2 {
    using vec = __m256;
    using ivec = __m256i;
    using half = lanes4_avx;
    static constexpr int groups = 2;
    static ivec splat(int v) { return _mm256_set1_epi32(v); }
    static __m128i low(ivec v) { return _mm256_castsi256_si128(v); }
    static ivec columns() { return _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7); }
    static ivec advance(ivec column) { return _mm256_add_epi32(column, _mm256_set1_epi32(8)); }
    static vec cover(ivec column, ivec before, ivec after) {
        return _mm256_castsi256_ps(_mm256_and_si256(_mm256_cmpgt_epi32(column, before), _mm256_cmpgt_epi32(after, column)));
    }
    static vec join(const __m128 *g) { return _mm256_set_m128(g[1], g[0]); }
    template <depth_func Test>
    static vec depth_mask(vec z, vec stored) { return _mm256_cmp_ps(z, stored, depth_predicate<Test>()); }
    static vec mask_and(vec a, vec b) { return _mm256_and_ps(a, b); }
    static vec select(vec mask, vec a, vec b) { return _mm256_blendv_ps(b, a, mask); }
    static vec clamp01(vec v) { return _mm256_min_ps(_mm256_max_ps(v, _mm256_setzero_ps()), _mm256_set1_ps(1.0f)); }
    static vec load(const float *p) { return _mm256_loadu_ps(p); }
    static void store(float *p, vec v) { _mm256_storeu_ps(p, v); }
};

}  // namespace

void fill_fast_bins_avx2(canvas_t &canvas, zbuffer &depth, const band_bin *bins, int bin_count, depth_func test,
                         int y0, int y1, band_prefetch &ahead) {
    with_depth_test(test, [&](auto t) {
        for_each_bin_triangle(bins, bin_count, ahead, [&](const band_bin &bin, const fast_triangle &f) {
            const int first = std::max(y0, f.min_y), end = std::min(y1, f.max_y + 1);
            if (first >= end) return;
            if (f.wide < 0 && narrow_fits(f, canvas.width))
                narrow_rows_any<lanes8_avx2, t.value, true>(canvas, &depth, f, std::true_type{}, first, end);
            else
                fill_fast_rows(canvas, &depth, f, f.wide >= 0 ? &bin.wide[f.wide] : nullptr, test, true, first, end);
        });
    });
}

}  // namespace tiny3d::detail

#include "../../avx512_region_close.inc"
#endif
