// setup_batch_avx2.cpp — the set-up stage's AVX2 batches (kernel_table::setup_fast_batch,
// setup_msaa_batch for raster_simd::avx2): eight triangles' snapped vertices in, their
// fast_triangles (1 sample) or msaa_triangles (4 and 8 samples) out, the same bits as the
// scalar set-up (setup/triangle_setup.cpp, msaa/msaa.cpp). Called by the render context's
// set-up loop through its kernel table. Compiled inside the AVX2 target region (the
// headers before it opens stay baseline); run only on CPUs that have it (kernels_run).
#include <algorithm>
#include <cstdint>

#include "setup.h"
#include "../msaa/msaa.h"
#include "../../simd_config.h"

#ifdef TINY3D_AVX2
#include <immintrin.h>

#include "../../avx2_region_open.inc"

namespace tiny3d::detail {

// ---- eight triangles' set-up at once ----------------------------------------------------
//
// The AVX-512 batch's operations (setup_batch_avx512.cpp) on AVX2 registers: the integer
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

#include "../../avx512_region_close.inc"
#endif
