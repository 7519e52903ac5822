// setup_batch_avx512.cpp — the set-up stage's AVX-512 batches (kernel_table::setup_fast_batch,
// setup_msaa_batch for raster_simd::avx512): eight triangles' snapped vertices in, their
// fast_triangles (1 sample) or msaa_triangles (4 and 8 samples) out, the same bits as the
// scalar set-up (setup/triangle_setup.cpp, msaa/msaa.cpp). Called by the render context's
// set-up loop through its kernel table. Compiled inside the AVX-512 target region (the
// headers before it opens stay baseline); run only on CPUs that have it (kernels_run).
#include <algorithm>
#include <cstdint>
#include <span>

#include "setup.h"
#include "../msaa/msaa.h"
#include "../../simd_config.h"

#ifdef TINY3D_AVX512
#include <immintrin.h>

#include "../../avx512_region_open.inc"

namespace tiny3d::detail {

// ---- eight triangles' set-up at once ----------------------------------------------------

namespace {

inline __m512i widen(__m256i v) { return _mm512_cvtepi32_epi64(v); }
inline __m512d to_double(__m256i v) { return _mm512_cvtepi32_pd(v); }
inline __m512d negate(__m512d v) { return _mm512_xor_pd(v, _mm512_set1_pd(-0.0)); }  // −x, as the scalar −x

// Edge k of setup_fast_triangle (snapped_edge_at at the centre (cx, cy)), eight lanes: its
// dx, dy (32 bits: the fast path's boxes are < 2^15) and value e (64 bits).
struct lane_edges {
    __m256i dx, dy;
    __m512i e;
};
inline lane_edges edge_at(__m256i s, __m256i xa, __m256i ya, __m256i xb, __m256i yb, __m256i cx, __m256i cy) {
    lane_edges g;
    g.dx = _mm256_mullo_epi32(s, _mm256_sub_epi32(xb, xa));
    g.dy = _mm256_mullo_epi32(s, _mm256_sub_epi32(yb, ya));
    const __m512i e = _mm512_sub_epi64(_mm512_mul_epi32(widen(g.dx), widen(_mm256_sub_epi32(cy, ya))),
                                       _mm512_mul_epi32(widen(g.dy), widen(_mm256_sub_epi32(cx, xa))));
    // top_left_edge: dy < 0, or dy = 0 and dx > 0: bias 0, else 1.
    const __m256i zero = _mm256_setzero_si256();
    const __mmask8 top_left = static_cast<__mmask8>(_mm256_cmplt_epi32_mask(g.dy, zero) |
                                                    (_mm256_cmpeq_epi32_mask(g.dy, zero) & _mm256_cmpgt_epi32_mask(g.dx, zero)));
    g.e = _mm512_mask_sub_epi64(e, static_cast<__mmask8>(~top_left), e, _mm512_set1_epi64(1));
    return g;
}

// set_crossing's value and step for edge g (not horizontal): sign·(−e/a), sign·(−b/a) with
// a = −16·dy, b = 16·dx, sign = +1 for a left edge (a > 0), −1 for a right one.
inline void crossing_of(const lane_edges &g, __m512d &cross, __m512d &step) {
    const __m512d a = to_double(_mm256_mullo_epi32(g.dy, _mm256_set1_epi32(-RASTER_SUBPIXEL_ONE)));
    const __m512d b = to_double(_mm256_mullo_epi32(g.dx, _mm256_set1_epi32(RASTER_SUBPIXEL_ONE)));
    const __m512d inv_a = _mm512_div_pd(_mm512_set1_pd(1.0), a);
    const __mmask8 left = _mm256_cmplt_epi32_mask(g.dy, _mm256_setzero_si256());
    const __m512d sign = _mm512_mask_blend_pd(left, _mm512_set1_pd(-1.0), _mm512_set1_pd(1.0));
    cross = _mm512_mul_pd(sign, _mm512_mul_pd(negate(_mm512_cvtepi64_pd(g.e)), inv_a));
    step = _mm512_mul_pd(sign, _mm512_mul_pd(negate(b), inv_a));
}

// attribute_plane: the plane of f at the reference centre, its steps.
inline void plane_of(const float *f0, const float *f1, const float *f2, __m512d d1x, __m512d d1y, __m512d d2x,
                     __m512d d2y, __m512d inv_det, __m512d ref_dx, __m512d ref_dy, __m256 &at, __m256 &gx_f,
                     __m256 &gy_f) {
    const __m512d v0 = _mm512_cvtps_pd(_mm256_load_ps(f0));
    const __m512d a1 = _mm512_sub_pd(_mm512_cvtps_pd(_mm256_load_ps(f1)), v0);
    const __m512d a2 = _mm512_sub_pd(_mm512_cvtps_pd(_mm256_load_ps(f2)), v0);
    const __m512d gx = _mm512_mul_pd(_mm512_sub_pd(_mm512_mul_pd(a1, d2y), _mm512_mul_pd(a2, d1y)), inv_det);
    const __m512d gy = _mm512_mul_pd(_mm512_sub_pd(_mm512_mul_pd(a2, d1x), _mm512_mul_pd(a1, d2x)), inv_det);
    const __m512d ref = _mm512_add_pd(_mm512_add_pd(v0, _mm512_mul_pd(gx, ref_dx)), _mm512_mul_pd(gy, ref_dy));
    at = _mm512_cvtpd_ps(ref);
    gx_f = _mm512_cvtpd_ps(gx);
    gy_f = _mm512_cvtpd_ps(gy);
}

#include "setup_batch_lanes.inc"  // lane_bits, lane_vertices, lane_bounds

// The three edges (snapped_edge_at, oriented by s = sign(area2)) at the centre of pixel
// (min_x, min_y): edge k from vertex k + 1 to vertex k − 1.
inline void lane_edges_at(const setup_batch &in, const lane_vertices &v, __m256i min_x, __m256i min_y, lane_edges g[3]) {
    const __m256i half = _mm256_set1_epi32(RASTER_SUBPIXEL_ONE / 2);
    const __mmask8 positive = _mm512_cmpgt_epi64_mask(_mm512_load_si512(in.area2), _mm512_setzero_si512());
    const __m256i s = _mm256_mask_blend_epi32(positive, _mm256_set1_epi32(-1), _mm256_set1_epi32(1));
    const __m256i cx = _mm256_add_epi32(_mm256_slli_epi32(min_x, RASTER_SUBPIXEL_BITS), half);
    const __m256i cy = _mm256_add_epi32(_mm256_slli_epi32(min_y, RASTER_SUBPIXEL_BITS), half);
    g[0] = edge_at(s, v.X[1], v.Y[1], v.X[2], v.Y[2], cx, cy);
    g[1] = edge_at(s, v.X[2], v.Y[2], v.X[0], v.Y[0], cx, cy);
    g[2] = edge_at(s, v.X[0], v.Y[0], v.X[1], v.Y[1], cx, cy);
}

// The depth and intensity planes through the snapped vertices (px) at the centre of pixel
// (min_x, min_y), per lane: attribute_planes_at's doubles in its order. planes[0..5] =
// depth, its x and y steps, intensity, its x and y steps.
// (Inlined: called out of line, it returned without clearing the vector registers' upper
// halves (vzeroupper), and its caller, which uses no 256-bit register after the call, then
// returned without it too; the baseline SSE code after the batch, the vertex transform,
// then paid the penalty of mixing dirty upper halves with SSE instructions.)
[[gnu::always_inline]] inline void lane_planes(const setup_batch &in, const lane_vertices &v, __m256i min_x,
                                               __m256i min_y, float planes[6][SETUP_BATCH]) {
    const __m512d step = _mm512_set1_pd(1.0 / RASTER_SUBPIXEL_ONE);
    const __m512d x0 = _mm512_mul_pd(to_double(v.X[0]), step), x1 = _mm512_mul_pd(to_double(v.X[1]), step);
    const __m512d x2 = _mm512_mul_pd(to_double(v.X[2]), step), y0 = _mm512_mul_pd(to_double(v.Y[0]), step);
    const __m512d y1 = _mm512_mul_pd(to_double(v.Y[1]), step), y2 = _mm512_mul_pd(to_double(v.Y[2]), step);
    const __m512d d1x = _mm512_sub_pd(x1, x0), d1y = _mm512_sub_pd(y1, y0);
    const __m512d d2x = _mm512_sub_pd(x2, x0), d2y = _mm512_sub_pd(y2, y0);
    const __m512d inv_det = _mm512_div_pd(_mm512_set1_pd(1.0), _mm512_sub_pd(_mm512_mul_pd(d1x, d2y), _mm512_mul_pd(d2x, d1y)));
    const __m512d ref_dx = _mm512_sub_pd(_mm512_add_pd(to_double(min_x), _mm512_set1_pd(0.5)), x0);
    const __m512d ref_dy = _mm512_sub_pd(_mm512_add_pd(to_double(min_y), _mm512_set1_pd(0.5)), y0);
    __m256 at, gx, gy;
    plane_of(in.depth[0], in.depth[1], in.depth[2], d1x, d1y, d2x, d2y, inv_det, ref_dx, ref_dy, at, gx, gy);
    _mm256_storeu_ps(planes[0], at), _mm256_storeu_ps(planes[1], gx), _mm256_storeu_ps(planes[2], gy);
    plane_of(in.shade[0], in.shade[1], in.shade[2], d1x, d1y, d2x, d2y, inv_det, ref_dx, ref_dy, at, gx, gy);
    _mm256_storeu_ps(planes[3], at), _mm256_storeu_ps(planes[4], gx), _mm256_storeu_ps(planes[5], gy);
}

}  // namespace

void setup_fast_batch_avx512(const setup_batch &in, pixel_rect clip, fast_setup verdict[SETUP_BATCH],
                             fast_triangle out[SETUP_BATCH]) {
    const lane_vertices v(in);
    batch_lanes lanes;
    const lane_bounds box(v, 0, 0, 0, 0, clip, lanes);
    lane_edges g[3];
    lane_edges_at(in, v, box.min_x, box.min_y, g);
    const __m256i zero = _mm256_setzero_si256();
    const __mmask8 horizontal = static_cast<__mmask8>(
        _mm256_cmpeq_epi32_mask(g[0].dy, zero) | _mm256_cmpeq_epi32_mask(g[1].dy, zero) | _mm256_cmpeq_epi32_mask(g[2].dy, zero));
    // The crossings, in set_crossing's slots: left edges (dy < 0) to 0 then 2, right ones to
    // 1 then 3, in edge order; the slot no edge takes holds NO_EDGE (clear_crossings).
    __m512d c0, s0, c1, s1, c2, s2;
    crossing_of(g[0], c0, s0);
    crossing_of(g[1], c1, s1);
    crossing_of(g[2], c2, s2);
    const __mmask8 L0 = _mm256_cmplt_epi32_mask(g[0].dy, zero), L1 = _mm256_cmplt_epi32_mask(g[1].dy, zero);
    const __mmask8 L2 = _mm256_cmplt_epi32_mask(g[2].dy, zero);
    const __mmask8 slot_of[4][3] = {
        {L0, static_cast<__mmask8>(L1 & ~L0), static_cast<__mmask8>(L2 & ~L0 & ~L1)},
        {static_cast<__mmask8>(~L0), static_cast<__mmask8>(~L1 & L0), static_cast<__mmask8>(~L2 & L0 & L1)},
        {0, static_cast<__mmask8>(L1 & L0), static_cast<__mmask8>(L2 & (L0 ^ L1))},
        {0, static_cast<__mmask8>(~L1 & ~L0), static_cast<__mmask8>(~L2 & (L0 ^ L1))},
    };
    constexpr double NO_EDGE = -1e30;
    alignas(64) double cross[4][SETUP_BATCH], cross_step[4][SETUP_BATCH];
    for (int j = 0; j < 4; ++j) {
        __m512d c = _mm512_set1_pd(NO_EDGE), st = _mm512_setzero_pd();
        c = _mm512_mask_blend_pd(slot_of[j][0], c, c0), st = _mm512_mask_blend_pd(slot_of[j][0], st, s0);
        c = _mm512_mask_blend_pd(slot_of[j][1], c, c1), st = _mm512_mask_blend_pd(slot_of[j][1], st, s1);
        c = _mm512_mask_blend_pd(slot_of[j][2], c, c2), st = _mm512_mask_blend_pd(slot_of[j][2], st, s2);
        _mm512_store_pd(cross[j], c);
        _mm512_store_pd(cross_step[j], st);
    }
    lane_planes(in, v, box.min_x, box.min_y, lanes.planes);
    lanes.finish_fast(in.count, horizontal, cross, cross_step, verdict, out);
}

void setup_msaa_batch_avx512(const setup_batch &in, const sample_pattern &pat, pixel_rect clip,
                             fast_setup verdict[SETUP_BATCH], msaa_triangle out[SETUP_BATCH]) {
    const lane_vertices v(in);
    batch_lanes lanes;
    const lane_bounds box(v, pat.min_dx, pat.max_dx, pat.min_dy, pat.max_dy, clip, lanes);
    lane_edges g[3];
    lane_edges_at(in, v, box.min_x, box.min_y, g);
    // a = −dy·16, b = dx·16 (64 bits, as msaa_triangle holds them; |·| < 2^19 here).
    alignas(64) std::int64_t e[3][SETUP_BATCH], a[3][SETUP_BATCH], b[3][SETUP_BATCH];
    for (int k = 0; k < 3; ++k) {
        _mm512_store_si512(e[k], g[k].e);
        _mm512_store_si512(a[k], widen(_mm256_mullo_epi32(g[k].dy, _mm256_set1_epi32(-RASTER_SUBPIXEL_ONE))));
        _mm512_store_si512(b[k], widen(_mm256_mullo_epi32(g[k].dx, _mm256_set1_epi32(RASTER_SUBPIXEL_ONE))));
    }
    lane_planes(in, v, box.min_x, box.min_y, lanes.planes);
    finish_msaa_batch(lanes, in.count, e, a, b, verdict, out);
}

}  // namespace tiny3d::detail

#include "../../avx512_region_close.inc"
#endif
