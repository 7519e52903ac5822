// raster_fill_avx512.cpp — the 1-sample fill's AVX-512 kernels (raster_simd::avx512):
//  * a narrow triangle's row (at most NARROW_WIDTH = 16 columns) as ONE 16-lane register (8
//    lanes, 256 bits, for a triangle at most 8 columns wide), the row's span a lane mask,
//    the depth test a masked compare and the colour and depth writes masked stores (no
//    colour read, no blend), where the SSE2 kernel needs up to four groups of four, each
//    loaded, compared, blended and stored; four rows' spans and plane values computed at
//    once. Every other triangle goes to the SSE2 kernels (fill_fast_rows).
//  * the fast set-up of eight triangles at once (setup_fast_batch_avx512), and the
//    multisampled frames' set-up of eight at once on the 1/16 px grid
//    (setup_msaa_batch_avx512): the same lane edges and planes.
//
// The same results, bit for bit, as the SSE2 kernel and the scalar set-up: the lanes' depth
// and intensity are formed in the SSE2 kernel's operation order (the row's value plus the
// lane's column offset within its group of four, then the group's step added once per group
// before it), the set-up's doubles in the scalar set-up's order, with no FMA contraction
// (avx512_region_open.inc); the triangles the narrow kernel takes are exactly those the SSE2
// narrow kernel takes. Tested against them and the portable kernel
// (tests/raster_threads_test.cpp).
//
// Compiled inside the AVX-512 target region; the headers are included before it opens, so
// their inline functions stay baseline x86-64. Run only on CPUs that have AVX-512 F/VL/DQ/BW
// (fill_kernel_runs).
#include <algorithm>
#include <cstdint>
#include <span>

#include "msaa.h"
#include "raster_internal.h"
#include "../simd_config.h"

#ifdef TINY3D_AVX512
#include <immintrin.h>

#include "../avx512_region_open.inc"

namespace tiny3d::detail {
namespace {

// The narrow kernel's registers: a row of up to 16 columns as 16 lanes, or of up to 8 as 8
// lanes (half the work where a 512-bit operation costs two 256-bit ones, as on AMD Zen 4;
// fewer group steps everywhere). The same operations on either width, lane by lane.
struct lanes16 {
    using vec = __m512;
    using mask = __mmask16;
    static constexpr int count = 16;
    static vec set1(float v) { return _mm512_set1_ps(v); }
    static vec column() { return _mm512_setr_ps(0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3); }
    static vec add(vec a, vec b) { return _mm512_add_ps(a, b); }
    static vec mul(vec a, vec b) { return _mm512_mul_ps(a, b); }
    static vec mask_add(vec src, mask m, vec a, vec b) { return _mm512_mask_add_ps(src, m, a, b); }
    static vec clamp01(vec v) { return _mm512_min_ps(_mm512_max_ps(v, _mm512_setzero_ps()), _mm512_set1_ps(1.0f)); }
    static vec load(mask m, const float *p) { return _mm512_maskz_loadu_ps(m, p); }
    static void store(float *p, mask m, vec v) { _mm512_mask_storeu_ps(p, m, v); }
    template <int Predicate>
    static mask compare(mask m, vec a, vec b) { return _mm512_mask_cmp_ps_mask(m, a, b, Predicate); }
};
struct lanes8 {
    using vec = __m256;
    using mask = __mmask8;
    static constexpr int count = 8;
    static vec set1(float v) { return _mm256_set1_ps(v); }
    static vec column() { return _mm256_setr_ps(0, 1, 2, 3, 0, 1, 2, 3); }
    static vec add(vec a, vec b) { return _mm256_add_ps(a, b); }
    static vec mul(vec a, vec b) { return _mm256_mul_ps(a, b); }
    static vec mask_add(vec src, mask m, vec a, vec b) { return _mm256_mask_add_ps(src, m, a, b); }
    static vec clamp01(vec v) { return _mm256_min_ps(_mm256_max_ps(v, _mm256_setzero_ps()), _mm256_set1_ps(1.0f)); }
    static vec load(mask m, const float *p) { return _mm256_maskz_loadu_ps(m, p); }
    static void store(float *p, mask m, vec v) { _mm256_mask_storeu_ps(p, m, v); }
    template <int Predicate>
    static mask compare(mask m, vec a, vec b) { return _mm256_mask_cmp_ps_mask(m, a, b, Predicate); }
};

template <depth_func Test, class L>
inline typename L::mask depth_pass(typename L::mask cover, typename L::vec z, typename L::vec stored) {
    // The SSE2 kernel's compares (cmpltps … cmpneqps): ordered and signalling but for
    // not_equal, which is true on NaN.
    if constexpr (Test == depth_func::less) return L::template compare<_CMP_LT_OS>(cover, z, stored);
    else if constexpr (Test == depth_func::less_equal) return L::template compare<_CMP_LE_OS>(cover, z, stored);
    else if constexpr (Test == depth_func::equal) return L::template compare<_CMP_EQ_OQ>(cover, z, stored);
    else if constexpr (Test == depth_func::greater) return L::template compare<_CMP_GT_OS>(cover, z, stored);
    else if constexpr (Test == depth_func::greater_equal) return L::template compare<_CMP_GE_OS>(cover, z, stored);
    else if constexpr (Test == depth_func::not_equal) return L::template compare<_CMP_NEQ_UQ>(cover, z, stored);
    else return cover;  // always
}

// The lanes' offsets from the row's value, as the SSE2 kernel forms them: lane l of group
// g = l / 4 is (row + step·(l mod 4)) + 4·step, the group step added g times.
template <class L>
inline typename L::vec lanes_from(float row, typename L::vec within_group, typename L::vec group_step) {
    typename L::vec v = L::add(L::set1(row), within_group);
    for (int g = 1; g < L::count / 4; ++g)  // (unrolled: the lanes of group g and after)
        v = L::mask_add(v, static_cast<typename L::mask>((0xFFFFu << (4 * g)) & 0xFFFFu), v, group_step);
    return v;
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

// A triangle that narrow_fits, rows [y0, y1) within f's, with L's lanes (L::count columns
// from min_x: the triangle is at most that wide).
template <depth_func Test, bool HasDepth, class L>
[[gnu::always_inline]] inline void narrow_rows_with(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, bool depth_write, int y0, int y1) {
    using vec = typename L::vec;
    using mask = typename L::mask;
    const vec column = L::column();
    const vec zoff = L::mul(L::set1(f.zdx), column), ioff = L::mul(L::set1(f.idx), column);
    const vec zstep = L::set1(4.0f * f.zdx), istep = L::set1(4.0f * f.idx);
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
        const vec z = lanes_from<L>(zrow_at[r], zoff, zstep);
        const vec in = lanes_from<L>(irow_at[r], ioff, istep);
        mask pass = static_cast<mask>(cover[r]);  // (the bits beyond L::count are 0: the span is narrower)
        if constexpr (HasDepth) {
            float *zrow = depth->row(y) + min_x;
            pass = depth_pass<Test, L>(pass, z, L::load(pass, zrow));
            if (depth_write) L::store(zrow, pass, z);
        }
        L::store(canvas.pixels[y] + min_x, pass, L::clamp01(in));
    }
}

// narrow_rows_with eight lanes when the triangle is at most eight columns wide, else sixteen.
template <depth_func Test, bool HasDepth>
[[gnu::always_inline]] inline void narrow_rows(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, bool depth_write, int y0, int y1) {
    if (f.max_x - f.min_x < lanes8::count) narrow_rows_with<Test, HasDepth, lanes8>(canvas, depth, f, depth_write, y0, y1);
    else narrow_rows_with<Test, HasDepth, lanes16>(canvas, depth, f, depth_write, y0, y1);
}

}  // namespace

void fill_rows_narrow_avx512(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, depth_func test,
                             bool depth_write, int y0, int y1) {
    if (!depth) return narrow_rows<depth_func::always, false>(canvas, depth, f, false, y0, y1);
    with_depth_test(test, [&](auto t) { narrow_rows<t.value, true>(canvas, depth, f, depth_write, y0, y1); });
}

void fill_fast_bins_avx512(canvas_t &canvas, zbuffer &depth, const band_bin *bins, int bin_count, depth_func test,
                           int y0, int y1, band_prefetch &ahead) {
    constexpr std::size_t TRIANGLES_AHEAD = 6;
    // The set-up triangle TRIANGLES_AHEAD entries on (its two cache lines), into the next
    // bin near a bin's end: a bin skips through its piece's list, which the hardware
    // prefetcher does not follow, and a band's bins are short on many threads (prefetching
    // only within each bin leaves the first triangles of every bin unfetched).
    with_depth_test(test, [&](auto t) {
        for (int j = 0; j < bin_count; ++j) {
            const band_bin &bin = bins[j];
            const band_bin *next = j + 1 < bin_count ? &bins[j + 1] : nullptr;
            for (std::size_t k = 0; k < bin.count; ++k) {
                ahead.step();
                const fast_triangle *later = nullptr;
                if (const std::size_t on = k + TRIANGLES_AHEAD; on < bin.count) later = &bin.triangle(bin.index[on]);
                else if (next && on - bin.count < next->count) later = &next->triangle(next->index[on - bin.count]);
                if (later) {
                    _mm_prefetch(reinterpret_cast<const char *>(later), _MM_HINT_T0);
                    _mm_prefetch(reinterpret_cast<const char *>(later) + sizeof(fast_triangle) - 1, _MM_HINT_T0);
                }
                const fast_triangle &f = bin.triangle(bin.index[k]);
                const int first = std::max(y0, f.min_y), end = std::min(y1, f.max_y + 1);
                if (first >= end) continue;
                if (f.wide < 0 && narrow_fits(f, canvas.width))
                    narrow_rows<t.value, true>(canvas, &depth, f, true, first, end);
                else
                    fill_fast_rows_base(canvas, &depth, f, f.wide >= 0 ? &bin.wide[f.wide] : nullptr, test, true, first, end);
            }
        }
    });
}

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

#include "../avx512_region_close.inc"
#endif
