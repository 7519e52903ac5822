// line_tabulated_avx512.cpp — the tabulated line's AVX-512 kernel (line_simd::avx512):
// the ends of 8 strokes located in one 16-lane pass, each 4 × 4 end block in one
// register, and 16 pixels at a time in tiles of 4 × 4, 8 × 2 or 16 × 1.
//
// Compiled for AVX-512 inside a target region (below) that GCC and clang both apply, not
// by a per-file -mavx512f: the headers are included before the region opens, so their
// inline functions and templates stay baseline x86-64 (an AVX-512 copy of a shared inline
// function could otherwise be the one the linker keeps, and crash CPUs without it). Run
// only on CPUs that have it (line_kernels_run, src/kernels.cpp). Nothing defined here is called from outside
// but draw_batch_avx512 and prepare8_avx512 (pointer and int arguments only). No FMA
// contraction: the same arithmetic as the SSE2 path, rounding step by step.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "line_tabulated_internal.h"
#include "../simd_config.h"

#ifdef TINY3D_AVX512
#include <immintrin.h>

#include "../avx512_region_open.inc"

namespace tiny3d::tabulated {
namespace {

// Unfolding a 4 × 4 block (unfolded_index) as a permutation: for fold = swap·4 + flip_y·2 +
// flip_x, canvas lane l takes canonical lane kUnfold4[fold][l].
struct alignas(64) lane_indices : std::array<std::int32_t, 16> {};
constexpr std::array<lane_indices, 8> unfold_tables() {
    std::array<lane_indices, 8> out{};
    for (int fold = 0; fold < 8; ++fold)
        for (int b = 0; b < 4; ++b)
            for (int a = 0; a < 4; ++a)
                out[std::size_t(fold)][std::size_t(unfolded_index(fold & 4, fold & 1, fold & 2, 4, a, b))] = b * 4 + a;
    return out;
}
constexpr std::array<lane_indices, 8> kUnfold4 = unfold_tables();

// A 4 × 4 end block in one register, lane r·4 + c = canvas pixel (x0 + c, y0 + r).
struct block16 {
    __m512 values;
    int x0, y0;
    bool live;
};

// The lanes of a tile of W columns × 16/W rows (lane i·W + c = tile pixel (c, i)), and how
// an end block enters such a tile.
template <int W>
struct tile_lanes {
    static constexpr int kRows = 16 / W;
    __m512i row, col, block_base;  // block_base: 4·row + col
    explicit tile_lanes(__m512i iota)
        : row(_mm512_srli_epi32(iota, W == 4 ? 2 : W == 8 ? 3 : 4)),
          col(_mm512_and_si512(iota, _mm512_set1_epi32(W - 1))),
          block_base(_mm512_add_epi32(_mm512_slli_epi32(row, 2), col)) {}
    // cover + block b's values on the pixels it shares with the tile whose first pixel is
    // (x, y): tile lane (i, c) takes block lane 4·(i + y − y0) + (c + x − x0) by one masked
    // permute.
    __m512 add_block(const block16 &b, int x, int y, __m512 cover) const {
        const int dy0 = y - b.y0, dx0 = x - b.x0;
        if (!b.live || dy0 >= 4 || dy0 + kRows <= 0 || dx0 >= 4 || dx0 + W <= 0) return cover;
        const __mmask16 in_rows = _mm512_cmp_epu32_mask(_mm512_add_epi32(row, _mm512_set1_epi32(dy0)), _mm512_set1_epi32(4), _MM_CMPINT_LT);
        const __mmask16 in_cols = _mm512_cmp_epu32_mask(_mm512_add_epi32(col, _mm512_set1_epi32(dx0)), _mm512_set1_epi32(4), _MM_CMPINT_LT);
        const __m512i from = _mm512_add_epi32(block_base, _mm512_set1_epi32(4 * dy0 + dx0));
        return _mm512_add_ps(cover, _mm512_maskz_permutexvar_ps(in_rows & in_cols, from, b.values));
    }
};

// locate_end for up to 16 ends at once (8 strokes: lane 2i end A of stroke i, 2i + 1 its
// end B), in float: the ends' fractional parts are what matter, and float keeps them to
// 2^-24 of the coordinate (6e-5 px at 1000 px). Results per lane: the offset of the
// first of the 8 table blocks, the weights, the fold, the block's first canvas pixel.
struct ends16 {
    alignas(64) std::int32_t offset[16], fold[16], x0[16], y0[16];
    alignas(64) float wx[16], wy[16], wq[16];
};

void locate_ends16(const line_table &t, const float *px, const float *py, const float *ex, const float *ey,
                   ends16 &out) {
    const __m512 zero = _mm512_setzero_ps(), sign = _mm512_set1_ps(-0.0f);
    const __m512 x = _mm512_load_ps(px), y = _mm512_load_ps(py), dx = _mm512_load_ps(ex), dy = _mm512_load_ps(ey);
    const __mmask16 flip_x = _mm512_cmp_ps_mask(dx, zero, _CMP_LT_OQ), flip_y = _mm512_cmp_ps_mask(dy, zero, _CMP_LT_OQ);
    __m512 cx = _mm512_mask_xor_ps(x, flip_x, x, sign), cy = _mm512_mask_xor_ps(y, flip_y, y, sign);
    const __m512 adx = _mm512_andnot_ps(sign, dx), ady = _mm512_andnot_ps(sign, dy);
    const __mmask16 swap = _mm512_cmp_ps_mask(ady, adx, _CMP_GT_OQ);
    const __m512 sx_ = _mm512_mask_mov_ps(cx, swap, cy), sy_ = _mm512_mask_mov_ps(cy, swap, cx);
    cx = sx_;
    cy = sy_;
    const __m512 amax = _mm512_max_ps(adx, ady), amin = _mm512_min_ps(adx, ady);
    constexpr int intervals = line_table::kStampIntervals, cells = line_table::kStampCells;
    const __m512 fq = _mm512_mul_ps(_mm512_div_ps(amin, _mm512_add_ps(amax, amin)), _mm512_set1_ps(2.0f * intervals));
    const __m512i k = _mm512_min_epi32(_mm512_cvttps_epi32(fq), _mm512_set1_epi32(intervals - 1));
    _mm512_store_ps(out.wq, _mm512_sub_ps(fq, _mm512_cvtepi32_ps(k)));
    auto axis = [&](__m512 c, __m512i &cell, __m512i &whole, float *weight) {
        const __m512 f = _mm512_roundscale_ps(c, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
        whole = _mm512_cvtps_epi32(f);
        const __m512 phase = _mm512_mul_ps(_mm512_sub_ps(c, f), _mm512_set1_ps(float(cells)));
        cell = _mm512_min_epi32(_mm512_cvttps_epi32(phase), _mm512_set1_epi32(cells - 1));
        _mm512_store_ps(weight, _mm512_sub_ps(phase, _mm512_cvtepi32_ps(cell)));
    };
    __m512i kx, ky, fx, fy;
    axis(cx, kx, fx, out.wx);
    axis(cy, ky, fy, out.wy);
    const __m512i k4 = _mm512_slli_epi32(k, 2), one = _mm512_set1_epi32(1);
    const int *axes = t.stamp_axes.data();
    const __m512i origin_x = _mm512_i32gather_epi32(k4, axes, 4);
    const __m512i jump_x = _mm512_i32gather_epi32(_mm512_add_epi32(k4, one), axes, 4);
    const __m512i origin_y = _mm512_i32gather_epi32(_mm512_add_epi32(k4, _mm512_set1_epi32(2)), axes, 4);
    const __m512i jump_y = _mm512_i32gather_epi32(_mm512_add_epi32(k4, _mm512_set1_epi32(3)), axes, 4);
    const __mmask16 past_x = _mm512_cmp_epi32_mask(kx, jump_x, _MM_CMPINT_NLT), past_y = _mm512_cmp_epi32_mask(ky, jump_y, _MM_CMPINT_NLT);
    const __m512i sx = _mm512_mask_add_epi32(kx, past_x, kx, one), sy = _mm512_mask_add_epi32(ky, past_y, ky, one);
    constexpr int phases = line_table::kStampPhases;
    const int area = t.stamp_size * t.stamp_size;
    // (((k·2)·phases + sy)·phases + sx)·area
    const __m512i index = _mm512_add_epi32(_mm512_mullo_epi32(_mm512_slli_epi32(k, 1), _mm512_set1_epi32(phases)), sy);
    _mm512_store_si512(out.offset, _mm512_mullo_epi32(_mm512_add_epi32(_mm512_mullo_epi32(index, _mm512_set1_epi32(phases)), sx), _mm512_set1_epi32(area)));
    // The block's canonical first pixel, unswapped and unflipped (locate_end).
    const __m512i cx0 = _mm512_add_epi32(_mm512_add_epi32(fx, origin_x), _mm512_maskz_mov_epi32(past_x, one));
    const __m512i cy0 = _mm512_add_epi32(_mm512_add_epi32(fy, origin_y), _mm512_maskz_mov_epi32(past_y, one));
    const __m512i ux0 = _mm512_mask_mov_epi32(cx0, swap, cy0), uy0 = _mm512_mask_mov_epi32(cy0, swap, cx0);
    const __m512i last = _mm512_set1_epi32(-t.stamp_size);  // −(u0 + size − 1) − 1 = −u0 − size
    _mm512_store_si512(out.x0, _mm512_mask_sub_epi32(ux0, flip_x, last, ux0));
    _mm512_store_si512(out.y0, _mm512_mask_sub_epi32(uy0, flip_y, last, uy0));
    const __m512i fold = _mm512_or_si512(_mm512_maskz_mov_epi32(swap, _mm512_set1_epi32(4)),
                                         _mm512_or_si512(_mm512_maskz_mov_epi32(flip_y, _mm512_set1_epi32(2)),
                                                         _mm512_maskz_mov_epi32(flip_x, one)));
    _mm512_store_si512(out.fold, fold);
}

// End `i` of a located batch as a block in one register.
void make_block16(const line_table &table, const ends16 &e, int i, block16 &out) {
    const std::size_t area = std::size_t(table.stamp_size) * std::size_t(table.stamp_size);
    const std::size_t next_x = area, next_y = line_table::kStampPhases * area, next_q = line_table::kStampPhases * next_y;
    const float *s000 = table.stamps.data() + std::size_t(e.offset[i]);
    const __m512 wx = _mm512_set1_ps(e.wx[i]), wy = _mm512_set1_ps(e.wy[i]), wq = _mm512_set1_ps(e.wq[i]);
    auto lerp = [](__m512 p, __m512 q, __m512 w) { return _mm512_add_ps(p, _mm512_mul_ps(w, _mm512_sub_ps(q, p))); };
    auto bilinear = [&](const float *p) {
        return lerp(lerp(_mm512_load_ps(p), _mm512_load_ps(p + next_x), wx),
                    lerp(_mm512_load_ps(p + next_y), _mm512_load_ps(p + next_y + next_x), wx), wy);
    };
    const __m512 canonical = lerp(bilinear(s000), bilinear(s000 + next_q), wq);
    out.values = _mm512_permutexvar_ps(_mm512_load_si512(kUnfold4[std::size_t(e.fold[i])].data()), canonical);
    out.x0 = e.x0[i];
    out.y0 = e.y0[i];
    out.live = true;
}

void draw_avx512(canvas_t *canvas, const stroke_setup &s, const block16 &block_a, const block16 &block_b) {
    const int width = canvas->width;
    const __m512i iota = _mm512_set_epi32(15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0);
    const __m512 lanes = _mm512_cvtepi32_ps(iota);
    const __m512 lane_du = _mm512_mul_ps(lanes, _mm512_set1_ps(s.du)), lane_dv = _mm512_mul_ps(lanes, _mm512_set1_ps(s.dv));
    const __m512 u_lo = _mm512_set1_ps(s.end_a ? -float(s.reach) : -INFINITY);
    const __m512 u_hi = _mm512_set1_ps(s.end_b ? s.length_f + float(s.reach) : INFINITY);
    // square_cdf::band, 16 lanes (as band_writer::band4).
    const __m512 sign = _mm512_set1_ps(-0.0f), w_lo = _mm512_set1_ps(s.cdf.w_lo), w_hi = _mm512_set1_ps(s.cdf.w_hi);
    const __m512 inv_amax = _mm512_set1_ps(s.cdf.inv_amax), inv_2ab = _mm512_set1_ps(s.cdf.inv_2ab);
    const __m512 half = _mm512_set1_ps(s.half), ink = _mm512_set1_ps(s.ink), one = _mm512_set1_ps(1.0f);
    auto centred = [&](__m512 x) {
        const __m512 t = _mm512_min_ps(_mm512_andnot_ps(sign, x), w_hi);
        const __m512 m = _mm512_max_ps(_mm512_sub_ps(t, w_lo), _mm512_setzero_ps());
        const __m512 h = _mm512_sub_ps(_mm512_mul_ps(t, inv_amax), _mm512_mul_ps(_mm512_mul_ps(m, m), inv_2ab));
        return _mm512_or_ps(h, _mm512_and_ps(sign, x));
    };
    const bool wide = s.half >= s.cdf.w_hi;
    const __m512 saturated = centred(w_hi);
    auto band = [&](__m512 v) {
        const __m512 a = _mm512_andnot_ps(sign, v);
        const __m512 near = centred(_mm512_sub_ps(half, a));
        return _mm512_add_ps(near, wide ? saturated : centred(_mm512_add_ps(half, a)));
    };
    const double ry = s.row_first + 0.5 - s.ay, rx = 0.5 - s.ax;
    auto blend = [&](float *p, __mmask16 keep, __m512 cover) {
        const __m512 c = _mm512_max_ps(_mm512_min_ps(_mm512_mul_ps(ink, cover), one), _mm512_setzero_ps());
        const __m512 old = _mm512_maskz_loadu_ps(keep, p);
        _mm512_mask_storeu_ps(p, keep, _mm512_add_ps(old, _mm512_mul_ps(c, _mm512_sub_ps(one, old))));
    };
    // Short strokes: the pixels within reach of the segment span ≤ 16 columns, so one
    // register per row covers them all, from the same column x_lo on every row (pixels
    // beyond the stroke get coverage 0 or lie beyond a cap: not drawn).
    const double x_max = s.ax + s.length * s.dx;  // dx ≥ 0
    const int x_lo = clamped_ceil(s.ax - s.reach - 0.5, 0.0, width), x_hi = clamped_floor(x_max + s.reach - 0.5, -1.0, width - 1.0);
    // Tiles of 16 pixels: W columns from x_lo × 16/W rows (W = 4, 8 or 16), the narrowest
    // that holds the stroke's columns: a steep stroke 4 columns wide takes a register per 4 rows.
    auto tiles = [&]<int W>() {
        const tile_lanes<W> tile(iota);
        constexpr int rows = tile_lanes<W>::kRows;
        const __m512 col_f = _mm512_cvtepi32_ps(tile.col), row_f = _mm512_cvtepi32_ps(tile.row);
        const __m512 off_u = _mm512_add_ps(_mm512_mul_ps(col_f, _mm512_set1_ps(s.du)), _mm512_mul_ps(row_f, _mm512_set1_ps(float(s.dy))));
        const __m512 off_v = _mm512_add_ps(_mm512_mul_ps(col_f, _mm512_set1_ps(s.dv)), _mm512_mul_ps(row_f, _mm512_set1_ps(float(s.dx))));
        const __mmask16 columns = __mmask16(_mm512_cmp_epi32_mask(tile.col, _mm512_set1_epi32(x_hi - x_lo), _MM_CMPINT_LE));
        const double rx_lo = rx + x_lo;
        const __m128d down = _mm_set_pd(rows * s.dx, rows * s.dy);
        __m128d uv_row = _mm_set_pd(ry * s.dx - rx_lo * s.dy, rx_lo * s.dx + ry * s.dy);  // (u, v) of pixel x_lo
        float *p = canvas->data + std::size_t(s.row_first) * std::size_t(width) + std::size_t(x_lo);
        for (int y = s.row_first; y <= s.row_last; y += rows, uv_row = _mm_add_pd(uv_row, down), p += rows * width) {
            const __m128 uv = _mm_cvtpd_ps(uv_row);
            const __m512 u = _mm512_add_ps(_mm512_broadcastss_ps(uv), off_u);
            const __m512 v = _mm512_add_ps(_mm512_broadcastss_ps(_mm_movehdup_ps(uv)), off_v);
            const __m512 cover = tile.add_block(block_b, x_lo, y, tile.add_block(block_a, x_lo, y, band(v)));
            const int live_rows = std::min(rows, s.row_last - y + 1);
            const __mmask16 keep = __mmask16(_mm512_cmp_ps_mask(u, u_lo, _CMP_GT_OQ) & _mm512_cmp_ps_mask(u, u_hi, _CMP_LT_OQ) &
                                             _mm512_cmp_ps_mask(cover, _mm512_setzero_ps(), _CMP_GT_OQ) & columns &
                                             (0xFFFFu >> (16 - live_rows * W)));
            const __m512 c = _mm512_max_ps(_mm512_min_ps(_mm512_mul_ps(ink, cover), one), _mm512_setzero_ps());
            if constexpr (W == 16) {
                blend(p, keep, cover);
            } else if constexpr (W == 8) {
                const __mmask8 k0 = __mmask8(keep), k1 = __mmask8(keep >> 8);
                float *p1 = live_rows > 1 ? p + width : p;  // no address past the last row
                const __m512 old = _mm512_insertf32x8(_mm512_castps256_ps512(_mm256_maskz_loadu_ps(k0, p)), _mm256_maskz_loadu_ps(k1, p1), 1);
                const __m512 now = _mm512_add_ps(old, _mm512_mul_ps(c, _mm512_sub_ps(one, old)));
                _mm256_mask_storeu_ps(p, k0, _mm512_castps512_ps256(now));
                _mm256_mask_storeu_ps(p1, k1, _mm512_extractf32x8_ps(now, 1));
            } else {
                float *q[4];
                for (int i = 0; i < 4; ++i) q[i] = i < live_rows ? p + i * width : p;
                __m512 old = _mm512_castps128_ps512(_mm_maskz_loadu_ps(__mmask8(keep & 0xF), q[0]));
                old = _mm512_insertf32x4(old, _mm_maskz_loadu_ps(__mmask8((keep >> 4) & 0xF), q[1]), 1);
                old = _mm512_insertf32x4(old, _mm_maskz_loadu_ps(__mmask8((keep >> 8) & 0xF), q[2]), 2);
                old = _mm512_insertf32x4(old, _mm_maskz_loadu_ps(__mmask8((keep >> 12) & 0xF), q[3]), 3);
                const __m512 now = _mm512_add_ps(old, _mm512_mul_ps(c, _mm512_sub_ps(one, old)));
                _mm_mask_storeu_ps(q[0], __mmask8(keep & 0xF), _mm512_castps512_ps128(now));
                _mm_mask_storeu_ps(q[1], __mmask8((keep >> 4) & 0xF), _mm512_extractf32x4_ps(now, 1));
                _mm_mask_storeu_ps(q[2], __mmask8((keep >> 8) & 0xF), _mm512_extractf32x4_ps(now, 2));
                _mm_mask_storeu_ps(q[3], __mmask8((keep >> 12) & 0xF), _mm512_extractf32x4_ps(now, 3));
            }
        }
    };
    if (x_hi < x_lo) return;
    const int span = x_hi - x_lo + 1;
    if (span <= 4 && x_lo + 4 <= width) return tiles.template operator()<4>();
    if (span <= 8 && x_lo + 8 <= width) return tiles.template operator()<8>();
    if (span <= 16) return tiles.template operator()<16>();
    const tile_lanes<16> run(iota);  // a row's run, 16 pixels at a time
    for (row_walk walk(canvas, s); walk.y <= s.row_last; walk.advance()) {
        const int y = walk.y;
        float *const row = walk.row;
        int first, last;
        walk.runs.next(first, last);
        for (int x = first; x <= last; x += 16) {
            float u0, v0;
            walk.uv.at(x, u0, v0);
            const __m512 u = _mm512_add_ps(_mm512_set1_ps(u0), lane_du), v = _mm512_add_ps(_mm512_set1_ps(v0), lane_dv);
            const __m512 cover = run.add_block(block_b, x, y, run.add_block(block_a, x, y, band(v)));
            const int n = std::min(16, last - x + 1);
            const __mmask16 keep = __mmask16(_mm512_cmp_ps_mask(u, u_lo, _CMP_GT_OQ) & _mm512_cmp_ps_mask(u, u_hi, _CMP_LT_OQ) &
                                             (0xFFFFu >> (16 - n)));
            blend(row + x, keep, cover);
        }
    }
}

}  // namespace

namespace {
// D = eight doubles for stroke_math.inc: the set-up arithmetic of prepare_stroke, the
// same operations lane by lane (compiled here, inside the target region).
namespace avx512_lanes {
struct d8 {
    __m512d v;
    d8(__m512d x) : v(x) {}
    d8(double x) : v(_mm512_set1_pd(x)) {}
};
struct m8 {
    __mmask8 k;
};
// (Vector types wrapped, as template arguments keep no attributes.)
struct f8 {
    __m256 v;
};
struct i8 {
    __m256i v;
};
inline d8 operator+(d8 a, d8 b) { return _mm512_add_pd(a.v, b.v); }
inline d8 operator-(d8 a, d8 b) { return _mm512_sub_pd(a.v, b.v); }
inline d8 operator*(d8 a, d8 b) { return _mm512_mul_pd(a.v, b.v); }
inline d8 operator/(d8 a, d8 b) { return _mm512_div_pd(a.v, b.v); }
inline d8 operator-(d8 a) { return _mm512_xor_pd(a.v, _mm512_set1_pd(-0.0)); }
inline m8 operator<(d8 a, d8 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LT_OQ)}; }
inline m8 operator>(d8 a, d8 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GT_OQ)}; }
inline m8 operator<=(d8 a, d8 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LE_OQ)}; }
inline m8 operator>=(d8 a, d8 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GE_OQ)}; }
inline m8 operator&(m8 a, m8 b) { return {__mmask8(a.k & b.k)}; }
inline d8 sqrt_of(d8 a) { return _mm512_sqrt_pd(a.v); }
inline d8 abs_of(d8 a) { return _mm512_andnot_pd(_mm512_set1_pd(-0.0), a.v); }
// std::min(a, b) is b < a ? b : a, and MINPD(x, y) is x < y ? x : y: so MINPD(b, a). Likewise max.
inline d8 min_of(d8 a, d8 b) { return _mm512_min_pd(b.v, a.v); }
inline d8 max_of(d8 a, d8 b) { return _mm512_max_pd(b.v, a.v); }
inline d8 select(m8 m, d8 if_true, d8 if_false) { return _mm512_mask_blend_pd(m.k, if_false.v, if_true.v); }
inline f8 to_float(d8 a) { return {_mm512_cvtpd_ps(a.v)}; }
inline i8 floor_to_lanes(d8 a) {
    return {_mm512_cvttpd_epi32(_mm512_roundscale_pd(a.v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC))};
}
inline i8 ceil_to_lanes(d8 a) { return {_mm256_sub_epi32(_mm256_setzero_si256(), floor_to_lanes(-a).v)}; }
#include "stroke_math.inc"
}  // namespace avx512_lanes
}  // namespace

// prepare_stroke's common case (both ends finite and in the grown canvas, h ≤ L ≤ 64 px,
// intensity > 0) for up to 8 segments at once, through the arithmetic prepare_stroke
// uses (stroke_math.inc), so the set-ups are bit for bit prepare_stroke's. Returns the
// lanes it set up; the caller hands the others to prepare_stroke. The table has blocks
// (stamp_size > 0).
unsigned prepare8_avx512(const canvas_t &canvas, const line_segment *g, int n, const line_table &table,
                         stroke_setup *out) {
    using namespace avx512_lanes;
    alignas(32) float fx0[8] = {}, fy0[8] = {}, fx1[8] = {}, fy1[8] = {}, fink[8] = {};
    for (int i = 0; i < n; ++i) {
        fx0[i] = g[i].x0;
        fy0[i] = g[i].y0;
        fx1[i] = g[i].x1;
        fy1[i] = g[i].y1;
        fink[i] = g[i].intensity;
    }
    __m256 x0 = _mm256_load_ps(fx0), y0 = _mm256_load_ps(fy0), x1 = _mm256_load_ps(fx1), y1 = _mm256_load_ps(fy1);
    const __m256 ink = _mm256_load_ps(fink), zero_f = _mm256_setzero_ps();
    auto finite = [&](__m256 v) { return _mm256_cmp_ps_mask(_mm256_mul_ps(v, zero_f), zero_f, _CMP_EQ_OQ); };
    __mmask8 ok = __mmask8((1u << n) - 1) & finite(x0) & finite(y0) & finite(x1) & finite(y1) & finite(ink) &
                  _mm256_cmp_ps_mask(ink, zero_f, _CMP_GT_OQ);
    // Left to right (as prepare_stroke).
    const __mmask8 swap = _mm256_cmp_ps_mask(x1, x0, _CMP_LT_OQ) |
                          (_mm256_cmp_ps_mask(x1, x0, _CMP_EQ_OQ) & _mm256_cmp_ps_mask(y1, y0, _CMP_LT_OQ));
    const __m256 sx0 = _mm256_mask_blend_ps(swap, x0, x1), sy0 = _mm256_mask_blend_ps(swap, y0, y1);
    x1 = _mm256_mask_blend_ps(swap, x1, x0);
    y1 = _mm256_mask_blend_ps(swap, y1, y0);
    x0 = sx0;
    y0 = sy0;
    const d8 X0 = _mm512_cvtps_pd(x0), Y0 = _mm512_cvtps_pd(y0), X1 = _mm512_cvtps_pd(x1), Y1 = _mm512_cvtps_pd(y1);
    const double h = 0.5 * double(table.thickness());
    const double reach = table.reach, margin = 2.0 * reach + 2.0;
    const double width = canvas.width, height = canvas.height;
    const segment_extent<d8> full = extent_of(X0, Y0, X1, Y1);
    ok &= tabulates(full.length, h, kExactFromLength).k & inside_grown_canvas(X0, Y0, X1, Y1, margin, width, height).k;
    if (!ok) return 0;
    const unit_direction<d8> d = direction_of(full);
    const stroke_span<d8, i8> span = span_of(X0, Y0, X1, Y1, d, reach, height);
    const cdf_factors<f8> cdf = square_cdf_factors(-d.y, d.x);
    alignas(64) double ax[8], ay[8], adx[8], ady[8], alen[8];
    alignas(32) float lo[8], hi[8], ia[8], i2[8], ink_f[8];
    alignas(32) std::int32_t first[8], last[8];
    _mm512_store_pd(ax, X0.v);
    _mm512_store_pd(ay, Y0.v);
    _mm512_store_pd(adx, d.x.v);
    _mm512_store_pd(ady, d.y.v);
    _mm512_store_pd(alen, span.length.v);
    _mm256_store_ps(lo, cdf.w_lo.v);
    _mm256_store_ps(hi, cdf.w_hi.v);
    _mm256_store_ps(ia, cdf.inv_amax.v);
    _mm256_store_ps(i2, cdf.inv_2ab.v);
    _mm256_store_ps(ink_f, _mm256_min_ps(ink, _mm256_set1_ps(1.0f)));
    _mm256_store_si256(reinterpret_cast<__m256i *>(first), span.row_first.v);
    _mm256_store_si256(reinterpret_cast<__m256i *>(last), span.row_last.v);
    for (int i = 0; i < n; ++i) {
        if (!(ok >> i & 1)) continue;
        stroke_setup &s = out[i];
        s.ax = ax[i];
        s.ay = ay[i];
        s.dx = adx[i];
        s.dy = ady[i];
        s.length = alen[i];
        s.reach = reach;
        s.end_a = s.end_b = true;
        s.cdf.w_lo = lo[i];
        s.cdf.w_hi = hi[i];
        s.cdf.inv_amax = ia[i];
        s.cdf.inv_2ab = i2[i];
        s.half = float(h);
        s.length_f = float(alen[i]);
        s.du = float(adx[i]);
        s.dv = float(-ady[i]);
        s.ink = ink_f[i];
        s.row_first = first[i];
        s.row_last = last[i];
    }
    return ok;
}

// Strokes prepared in a batch: all their blocks first (the table reads of several strokes
// overlap instead of each stroke waiting for its own), then their pixels, in order.
void draw_batch_avx512(canvas_t *canvas, const stroke_setup *strokes, int count, const line_table &table) {
    alignas(64) float px[16] = {}, py[16] = {}, ex[16], ey[16];
    std::fill(std::begin(ex), std::end(ex), 1.0f);
    std::fill(std::begin(ey), std::end(ey), 0.0f);
    for (int i = 0; i < count; ++i) {
        const stroke_setup &s = strokes[i];
        px[2 * i] = float(s.ax);
        py[2 * i] = float(s.ay);
        px[2 * i + 1] = float(s.ax + s.length * s.dx);
        py[2 * i + 1] = float(s.ay + s.length * s.dy);
        ex[2 * i] = float(s.dx);
        ey[2 * i] = float(s.dy);
        ex[2 * i + 1] = -float(s.dx);
        ey[2 * i + 1] = -float(s.dy);
    }
    ends16 ends;
    locate_ends16(table, px, py, ex, ey, ends);
    block16 blocks[2 * kBatch];
    for (int i = 0; i < count; ++i) {
        const stroke_setup &s = strokes[i];
        blocks[2 * i] = {_mm512_setzero_ps(), 0, 0, false};
        blocks[2 * i + 1] = {_mm512_setzero_ps(), 0, 0, false};
        if (s.end_a) make_block16(table, ends, 2 * i, blocks[2 * i]);
        if (s.end_b) make_block16(table, ends, 2 * i + 1, blocks[2 * i + 1]);
    }
    for (int i = 0; i < count; ++i) draw_avx512(canvas, strokes[i], blocks[2 * i], blocks[2 * i + 1]);
}

}  // namespace tiny3d::tabulated

#include "../avx512_region_close.inc"
#endif
