// raster_fill_avx2.cpp — the 1-sample fill's AVX2 kernel (raster_simd::avx2), for CPUs
// without AVX-512: the render context's band loop with the narrow triangles (at most
// NARROW_WIDTH = 16 columns, narrow_fits) drawn two groups of four per 256-bit register,
// where the SSE2 kernel takes one group per register. Every other triangle goes to the
// SSE2 loops (fill_fast_rows).
//
// The same pixels, bit for bit, as the SSE2 narrow kernel (fill_rows_narrow in
// raster_fill.cpp): each group's depth and intensity are formed by its operations in its
// order (the row's value plus the lane offsets, then the group step added once per group
// before it) and only then paired; the span, the depth test (the same ordered or unordered
// compares) and the selects are theirs, eight lanes at once. Tested against it under every
// depth test (tests/raster_threads_test.cpp).
//
// Compiled for AVX2 inside the target region of avx2_region_open.inc; run only on CPUs that
// have it (fill_kernel_runs). No FMA contraction: the float operations rounded step by step.
#include <algorithm>
#include <cstdint>

#include "fill.h"
#include "../../simd_config.h"

#ifdef TINY3D_AVX2
#include <immintrin.h>

#include "../../avx2_region_open.inc"

namespace tiny3d::detail {
namespace {

// The SSE2 kernel's depth compares (cmpltps … cmpneqps) as one predicate of vcmpps: all
// ones where the depth test passes.
template <depth_func Test>
constexpr int depth_predicate() {
    if constexpr (Test == depth_func::less) return _CMP_LT_OS;
    else if constexpr (Test == depth_func::less_equal) return _CMP_LE_OS;
    else if constexpr (Test == depth_func::equal) return _CMP_EQ_OQ;
    else if constexpr (Test == depth_func::greater) return _CMP_GT_OS;
    else if constexpr (Test == depth_func::greater_equal) return _CMP_GE_OS;
    else if constexpr (Test == depth_func::not_equal) return _CMP_NEQ_UQ;
    else if constexpr (Test == depth_func::always) return _CMP_TRUE_UQ;
    else return _CMP_FALSE_OQ;
}

// One row's columns [at, at + 8) relative to min_x as two groups (z_lo, z_hi the groups'
// depths, i_lo, i_hi their intensities): covered where before < column < after, then the
// depth test, and the depth and colour rows written through selects, as the SSE2 kernel
// writes each group.
template <depth_func Test>
inline void draw_pair(float *color, float *zrow, int at, __m256i before, __m256i after, __m128 z_lo, __m128 z_hi,
                      __m128 i_lo, __m128 i_hi) {
    const __m256i column = _mm256_add_epi32(_mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7), _mm256_set1_epi32(at));
    __m256 mask = _mm256_castsi256_ps(_mm256_and_si256(_mm256_cmpgt_epi32(column, before), _mm256_cmpgt_epi32(after, column)));
    const __m256 z = _mm256_set_m128(z_hi, z_lo);
    const __m256 stored = _mm256_loadu_ps(zrow + at);
    mask = _mm256_and_ps(mask, _mm256_cmp_ps(z, stored, depth_predicate<Test>()));
    _mm256_storeu_ps(zrow + at, _mm256_blendv_ps(stored, z, mask));
    const __m256 shade = _mm256_min_ps(_mm256_max_ps(_mm256_set_m128(i_hi, i_lo), _mm256_setzero_ps()), _mm256_set1_ps(1.0f));
    _mm256_storeu_ps(color + at, _mm256_blendv_ps(_mm256_loadu_ps(color + at), shade, mask));
}

// The same for the last group alone (an odd group count), four lanes.
template <depth_func Test>
inline void draw_single(float *color, float *zrow, int at, __m256i before, __m256i after, __m128 z, __m128 in) {
    const __m128i column = _mm_add_epi32(_mm_setr_epi32(0, 1, 2, 3), _mm_set1_epi32(at));
    __m128 mask = _mm_castsi128_ps(_mm_and_si128(_mm_cmpgt_epi32(column, _mm256_castsi256_si128(before)),
                                                 _mm_cmplt_epi32(column, _mm256_castsi256_si128(after))));
    const __m128 stored = _mm_loadu_ps(zrow + at);
    mask = _mm_and_ps(mask, _mm_cmp_ps(z, stored, depth_predicate<Test>()));
    _mm_storeu_ps(zrow + at, _mm_blendv_ps(stored, z, mask));
    const __m128 shade = _mm_min_ps(_mm_max_ps(in, _mm_setzero_ps()), _mm_set1_ps(1.0f));
    _mm_storeu_ps(color + at, _mm_blendv_ps(_mm_loadu_ps(color + at), shade, mask));
}

// A triangle that narrow_fits, with depth written, rows [y0, y1) within f's: every row as
// the same `Groups` groups of four from min_x (fill_rows_narrow's scheme), paired.
template <depth_func Test, int Groups>
void narrow_rows(canvas_t &canvas, zbuffer &depth, const fast_triangle &f, int y0, int y1) {
    const row_spans spans(f);
    const group_planes planes(f);
    const int min_x = f.min_x, min_y = f.min_y;
    for (int y = y0; y < y1; ++y) {
        const int dy = y - min_y;
        int lo, hi;
        spans.at(dy, lo, hi);
        const __m256i before = _mm256_set1_epi32(lo - 1), after = _mm256_set1_epi32(hi + 1);
        __m128 z[Groups], in[Groups];
        planes.first_group(dy, z[0], in[0]);
        for (int g = 1; g < Groups; ++g) z[g] = _mm_add_ps(z[g - 1], planes.zstep), in[g] = _mm_add_ps(in[g - 1], planes.istep);
        float *color = canvas.pixels[y] + min_x;
        float *zrow = depth.row(y) + min_x;
        int g = 0;
        for (; g + 2 <= Groups; g += 2) draw_pair<Test>(color, zrow, 4 * g, before, after, z[g], z[g + 1], in[g], in[g + 1]);
        if constexpr (Groups % 2 == 1) draw_single<Test>(color, zrow, 4 * g, before, after, z[g], in[g]);
    }
}

template <depth_func Test>
void narrow_any(canvas_t &canvas, zbuffer &depth, const fast_triangle &f, int y0, int y1) {
    static_assert(NARROW_WIDTH == 16, "one case per group count below");
    switch ((f.max_x - f.min_x + 4) / 4) {  // ⌈bounding-box width / 4⌉, a constant per case
        case 1: return narrow_rows<Test, 1>(canvas, depth, f, y0, y1);
        case 2: return narrow_rows<Test, 2>(canvas, depth, f, y0, y1);
        case 3: return narrow_rows<Test, 3>(canvas, depth, f, y0, y1);
        default: return narrow_rows<Test, 4>(canvas, depth, f, y0, y1);
    }
}

}  // namespace

void fill_fast_bins_avx2(canvas_t &canvas, zbuffer &depth, const band_bin *bins, int bin_count, depth_func test,
                         int y0, int y1, band_prefetch &ahead) {
    with_depth_test(test, [&](auto t) {
        for_each_bin_triangle(bins, bin_count, ahead, [&](const band_bin &bin, const fast_triangle &f) {
            const int first = std::max(y0, f.min_y), end = std::min(y1, f.max_y + 1);
            if (first >= end) return;
            if (f.wide < 0 && narrow_fits(f, canvas.width)) narrow_any<t.value>(canvas, depth, f, first, end);
            else
                fill_fast_rows_base(canvas, &depth, f, f.wide >= 0 ? &bin.wide[f.wide] : nullptr, test, true, first, end);
        });
    });
}

}  // namespace tiny3d::detail

#include "../../avx512_region_close.inc"
#endif
