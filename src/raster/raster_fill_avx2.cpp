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

#include "msaa.h"
#include "raster_internal.h"
#include "../simd_config.h"

#ifdef TINY3D_AVX2
#include <immintrin.h>

#include "../avx2_region_open.inc"

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

// ---- eight triangles' set-up at once ----------------------------------------------------
//
// The AVX-512 batch's operations (raster_fill_avx512.cpp) on AVX2 registers: the integer
// work on eight 32-bit lanes, the 64-bit edge values and every double in two halves of
// four lanes. The same operations in the same order as the scalar set-up, so the same
// triangles bit for bit (tested against it).

namespace {

inline __m128i half_of(__m256i v, int h) { return h ? _mm256_extracti128_si256(v, 1) : _mm256_castsi256_si128(v); }
inline __m256d half_double(__m256i v, int h) { return _mm256_cvtepi32_pd(half_of(v, h)); }
inline __m256i half_widen(__m256i v, int h) { return _mm256_cvtepi32_epi64(half_of(v, h)); }

#include "setup_batch_lanes.inc"  // lane_bits, lane_vertices, lane_bounds

// Edge k (snapped_edge_at at the centre (cx, cy)): dx, dy on 32-bit lanes, the value e in
// two halves of 64-bit lanes.
struct edge8 {
    __m256i dx, dy, e[2];
};
inline edge8 edge_at8(__m256i s, __m256i xa, __m256i ya, __m256i xb, __m256i yb, __m256i cx, __m256i cy) {
    edge8 g;
    g.dx = _mm256_mullo_epi32(s, _mm256_sub_epi32(xb, xa));
    g.dy = _mm256_mullo_epi32(s, _mm256_sub_epi32(yb, ya));
    const __m256i zero = _mm256_setzero_si256();
    // top_left_edge: dy < 0, or dy = 0 and dx > 0: bias 0, else 1.
    const __m256i top_left = _mm256_or_si256(_mm256_cmpgt_epi32(zero, g.dy),
                                             _mm256_and_si256(_mm256_cmpeq_epi32(g.dy, zero), _mm256_cmpgt_epi32(g.dx, zero)));
    const __m256i p = _mm256_sub_epi32(cy, ya), q = _mm256_sub_epi32(cx, xa);
    for (int h = 0; h < 2; ++h) {
        const __m256i e = _mm256_sub_epi64(_mm256_mul_epi32(half_widen(g.dx, h), half_widen(p, h)),
                                           _mm256_mul_epi32(half_widen(g.dy, h), half_widen(q, h)));
        g.e[h] = _mm256_sub_epi64(e, _mm256_andnot_si256(half_widen(top_left, h), _mm256_set1_epi64x(1)));
    }
    return g;
}

// The three edges at the centre of pixel (min_x, min_y), oriented by s = sign(area2).
inline void edges_at8(const setup_batch &in, const lane_vertices &v, __m256i min_x, __m256i min_y, edge8 g[3]) {
    alignas(32) std::int32_t sign[SETUP_BATCH];
    for (int l = 0; l < SETUP_BATCH; ++l) sign[l] = in.area2[l] > 0 ? 1 : -1;
    const __m256i s = _mm256_load_si256(reinterpret_cast<const __m256i *>(sign));
    const __m256i half = _mm256_set1_epi32(RASTER_SUBPIXEL_ONE / 2);
    const __m256i cx = _mm256_add_epi32(_mm256_slli_epi32(min_x, RASTER_SUBPIXEL_BITS), half);
    const __m256i cy = _mm256_add_epi32(_mm256_slli_epi32(min_y, RASTER_SUBPIXEL_BITS), half);
    g[0] = edge_at8(s, v.X[1], v.Y[1], v.X[2], v.Y[2], cx, cy);
    g[1] = edge_at8(s, v.X[2], v.Y[2], v.X[0], v.Y[0], cx, cy);
    g[2] = edge_at8(s, v.X[0], v.Y[0], v.X[1], v.Y[1], cx, cy);
}

// attribute_plane of f for the half h of the lanes (the scalar doubles in their order).
inline void plane_half(const float *const f[3], int h, __m256d d1x, __m256d d1y, __m256d d2x, __m256d d2y,
                       __m256d inv_det, __m256d ref_dx, __m256d ref_dy, float *at, float *gx_out, float *gy_out) {
    const __m256d v0 = _mm256_cvtps_pd(_mm_load_ps(f[0] + 4 * h));
    const __m256d a1 = _mm256_sub_pd(_mm256_cvtps_pd(_mm_load_ps(f[1] + 4 * h)), v0);
    const __m256d a2 = _mm256_sub_pd(_mm256_cvtps_pd(_mm_load_ps(f[2] + 4 * h)), v0);
    const __m256d gx = _mm256_mul_pd(_mm256_sub_pd(_mm256_mul_pd(a1, d2y), _mm256_mul_pd(a2, d1y)), inv_det);
    const __m256d gy = _mm256_mul_pd(_mm256_sub_pd(_mm256_mul_pd(a2, d1x), _mm256_mul_pd(a1, d2x)), inv_det);
    const __m256d ref = _mm256_add_pd(_mm256_add_pd(v0, _mm256_mul_pd(gx, ref_dx)), _mm256_mul_pd(gy, ref_dy));
    _mm_storeu_ps(at + 4 * h, _mm256_cvtpd_ps(ref));
    _mm_storeu_ps(gx_out + 4 * h, _mm256_cvtpd_ps(gx));
    _mm_storeu_ps(gy_out + 4 * h, _mm256_cvtpd_ps(gy));
}

// The depth and intensity planes at the centre of pixel (min_x, min_y): planes[0..5] =
// depth, its x and y steps, intensity, its x and y steps.
// (Inlined, as the AVX-512 batch's lane_planes is, and for the same reason: see there.)
[[gnu::always_inline]] inline void planes8(const setup_batch &in, const lane_vertices &v, __m256i min_x,
                                           __m256i min_y, float planes[6][SETUP_BATCH]) {
    const __m256d step = _mm256_set1_pd(1.0 / RASTER_SUBPIXEL_ONE);
    const float *const depth[3] = {in.depth[0], in.depth[1], in.depth[2]};
    const float *const shade[3] = {in.shade[0], in.shade[1], in.shade[2]};
    for (int h = 0; h < 2; ++h) {
        const __m256d x0 = _mm256_mul_pd(half_double(v.X[0], h), step), x1 = _mm256_mul_pd(half_double(v.X[1], h), step);
        const __m256d x2 = _mm256_mul_pd(half_double(v.X[2], h), step), y0 = _mm256_mul_pd(half_double(v.Y[0], h), step);
        const __m256d y1 = _mm256_mul_pd(half_double(v.Y[1], h), step), y2 = _mm256_mul_pd(half_double(v.Y[2], h), step);
        const __m256d d1x = _mm256_sub_pd(x1, x0), d1y = _mm256_sub_pd(y1, y0);
        const __m256d d2x = _mm256_sub_pd(x2, x0), d2y = _mm256_sub_pd(y2, y0);
        const __m256d inv_det = _mm256_div_pd(_mm256_set1_pd(1.0), _mm256_sub_pd(_mm256_mul_pd(d1x, d2y), _mm256_mul_pd(d2x, d1y)));
        const __m256d ref_dx = _mm256_sub_pd(_mm256_add_pd(half_double(min_x, h), _mm256_set1_pd(0.5)), x0);
        const __m256d ref_dy = _mm256_sub_pd(_mm256_add_pd(half_double(min_y, h), _mm256_set1_pd(0.5)), y0);
        plane_half(depth, h, d1x, d1y, d2x, d2y, inv_det, ref_dx, ref_dy, planes[0], planes[1], planes[2]);
        plane_half(shade, h, d1x, d1y, d2x, d2y, inv_det, ref_dx, ref_dy, planes[3], planes[4], planes[5]);
    }
}

}  // namespace

void setup_fast_batch_avx2(const setup_batch &in, pixel_rect clip, fast_setup verdict[SETUP_BATCH],
                           fast_triangle out[SETUP_BATCH]) {
    const lane_vertices v(in);
    batch_lanes lanes;
    const lane_bounds box(v, 0, 0, 0, 0, clip, lanes);
    edge8 g[3];
    edges_at8(in, v, box.min_x, box.min_y, g);
    const __m256i zero = _mm256_setzero_si256();
    const unsigned horizontal = lane_bits(_mm256_or_si256(_mm256_or_si256(_mm256_cmpeq_epi32(g[0].dy, zero), _mm256_cmpeq_epi32(g[1].dy, zero)),
                                                     _mm256_cmpeq_epi32(g[2].dy, zero)));
    // The crossings in set_crossing's slots (as the AVX-512 batch: left edges to 0 then 2,
    // right ones to 1 then 3, in edge order; a slot no edge takes holds NO_EDGE).
    const __m256i L0 = _mm256_cmpgt_epi32(zero, g[0].dy), L1 = _mm256_cmpgt_epi32(zero, g[1].dy);
    const __m256i L2 = _mm256_cmpgt_epi32(zero, g[2].dy);
    const __m256i ones = _mm256_set1_epi32(-1);
    auto nt = [&](__m256i m) { return _mm256_xor_si256(m, ones); };
    auto both = [](__m256i a, __m256i b) { return _mm256_and_si256(a, b); };
    const __m256i slot_of[4][3] = {
        {L0, both(L1, nt(L0)), both(L2, both(nt(L0), nt(L1)))},
        {nt(L0), both(nt(L1), L0), both(nt(L2), both(L0, L1))},
        {zero, both(L1, L0), both(L2, _mm256_xor_si256(L0, L1))},
        {zero, both(nt(L1), nt(L0)), both(nt(L2), _mm256_xor_si256(L0, L1))},
    };
    constexpr double NO_EDGE = -1e30;
    alignas(32) double cross[4][SETUP_BATCH], cross_step[4][SETUP_BATCH];
    const __m256i low_dwords = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
    for (int h = 0; h < 2; ++h) {
        __m256d c[3], st[3];
        for (int k = 0; k < 3; ++k) {  // set_crossing's value and step (edges that are not horizontal)
            const __m256d a = half_double(_mm256_mullo_epi32(g[k].dy, _mm256_set1_epi32(-RASTER_SUBPIXEL_ONE)), h);
            const __m256d b = half_double(_mm256_mullo_epi32(g[k].dx, _mm256_set1_epi32(RASTER_SUBPIXEL_ONE)), h);
            const __m256d inv_a = _mm256_div_pd(_mm256_set1_pd(1.0), a);
            const __m256d left = _mm256_castsi256_pd(half_widen(_mm256_cmpgt_epi32(zero, g[k].dy), h));
            const __m256d sign = _mm256_blendv_pd(_mm256_set1_pd(-1.0), _mm256_set1_pd(1.0), left);
            // e exactly (|e| < 2^31 where the lane is ready: its low 32 bits).
            const __m256d e = _mm256_cvtepi32_pd(_mm256_castsi256_si128(_mm256_permutevar8x32_epi32(g[k].e[h], low_dwords)));
            const __m256d minus = _mm256_set1_pd(-0.0);
            c[k] = _mm256_mul_pd(sign, _mm256_mul_pd(_mm256_xor_pd(e, minus), inv_a));
            st[k] = _mm256_mul_pd(sign, _mm256_mul_pd(_mm256_xor_pd(b, minus), inv_a));
        }
        for (int j = 0; j < 4; ++j) {
            __m256d cj = _mm256_set1_pd(NO_EDGE), sj = _mm256_setzero_pd();
            for (int k = 0; k < 3; ++k) {
                const __m256d m = _mm256_castsi256_pd(half_widen(slot_of[j][k], h));
                cj = _mm256_blendv_pd(cj, c[k], m), sj = _mm256_blendv_pd(sj, st[k], m);
            }
            _mm256_store_pd(cross[j] + 4 * h, cj);
            _mm256_store_pd(cross_step[j] + 4 * h, sj);
        }
    }
    planes8(in, v, box.min_x, box.min_y, lanes.planes);
    lanes.finish_fast(in.count, horizontal, cross, cross_step, verdict, out);
}

void setup_msaa_batch_avx2(const setup_batch &in, const sample_pattern &pat, pixel_rect clip,
                           fast_setup verdict[SETUP_BATCH], msaa_triangle out[SETUP_BATCH]) {
    const lane_vertices v(in);
    batch_lanes lanes;
    const lane_bounds box(v, pat.min_dx, pat.max_dx, pat.min_dy, pat.max_dy, clip, lanes);
    edge8 g[3];
    edges_at8(in, v, box.min_x, box.min_y, g);
    // a = −dy·16, b = dx·16 (64 bits, as msaa_triangle holds them; |·| < 2^19 here).
    alignas(32) std::int64_t e[3][SETUP_BATCH], a[3][SETUP_BATCH], b[3][SETUP_BATCH];
    for (int k = 0; k < 3; ++k) {
        const __m256i ak = _mm256_mullo_epi32(g[k].dy, _mm256_set1_epi32(-RASTER_SUBPIXEL_ONE));
        const __m256i bk = _mm256_mullo_epi32(g[k].dx, _mm256_set1_epi32(RASTER_SUBPIXEL_ONE));
        for (int h = 0; h < 2; ++h) {
            _mm256_store_si256(reinterpret_cast<__m256i *>(e[k] + 4 * h), g[k].e[h]);
            _mm256_store_si256(reinterpret_cast<__m256i *>(a[k] + 4 * h), half_widen(ak, h));
            _mm256_store_si256(reinterpret_cast<__m256i *>(b[k] + 4 * h), half_widen(bk, h));
        }
    }
    planes8(in, v, box.min_x, box.min_y, lanes.planes);
    finish_msaa_batch(lanes, in.count, e, a, b, verdict, out);
}

}  // namespace tiny3d::detail

#include "../avx512_region_close.inc"
#endif
