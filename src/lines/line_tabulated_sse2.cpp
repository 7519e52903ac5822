// line_tabulated_sse2.cpp — the tabulated line's SSE2 kernel (line_simd::sse2, every
// x86-64 CPU): the portable kernel's arithmetic four pixels at a time.
#include <algorithm>
#include <cmath>

#include "line_tabulated_internal.h"
#include "../simd_config.h"

#ifdef TINY3D_SSE2
#include <emmintrin.h>
#include <xmmintrin.h>

namespace tiny3d::tabulated {
namespace {

// fill_block_portable with SSE2, for a block of Size × Size (a multiple of 4): the same
// blend 4 elements at a time, then unfolded 4 × 4 tile by tile (swap = transpose, flips =
// reversed order).
template <int Size>
void fill_block_sse2(const end_source &e, end_block &block) {
    constexpr int stride = end_block::kStride, tiles = Size / 4;
    alignas(16) float canonical[Size * Size];
    const __m128 wx = _mm_set1_ps(e.wx), wy = _mm_set1_ps(e.wy), wq = _mm_set1_ps(e.wq);
    auto lerp = [](__m128 p, __m128 q, __m128 w) { return _mm_add_ps(p, _mm_mul_ps(w, _mm_sub_ps(q, p))); };
    auto bilinear = [&](const float *p) {
        return lerp(lerp(_mm_loadu_ps(p), _mm_loadu_ps(p + e.next_x), wx),
                    lerp(_mm_loadu_ps(p + e.next_y), _mm_loadu_ps(p + e.next_y + e.next_x), wx), wy);
    };
    for (int i = 0; i < Size * Size; i += 4)
        _mm_store_ps(canonical + i, lerp(bilinear(e.s000 + i), bilinear(e.s000 + e.next_q + i), wq));
    block.x0 = e.x0;
    block.y0 = e.y0;
    block.size = Size;
    const __m128 zero = _mm_setzero_ps();
    for (int r = 0; r < Size; ++r) {
        _mm_store_ps(block.rows + r * stride, zero);
        _mm_store_ps(block.rows + r * stride + end_block::kPad + Size, zero);
    }
    for (int tb = 0; tb < tiles; ++tb)
        for (int ta = 0; ta < tiles; ++ta) {
            const float *src = canonical + (tb * Size + ta) * 4;
            __m128 r0 = _mm_load_ps(src), r1 = _mm_load_ps(src + Size), r2 = _mm_load_ps(src + 2 * Size),
                   r3 = _mm_load_ps(src + 3 * Size);
            int tx = ta, ty = tb;  // the tile's place after unswapping
            if (e.swap) {
                _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
                std::swap(tx, ty);
            }
            if (e.flip_x) {
                r0 = _mm_shuffle_ps(r0, r0, _MM_SHUFFLE(0, 1, 2, 3));
                r1 = _mm_shuffle_ps(r1, r1, _MM_SHUFFLE(0, 1, 2, 3));
                r2 = _mm_shuffle_ps(r2, r2, _MM_SHUFFLE(0, 1, 2, 3));
                r3 = _mm_shuffle_ps(r3, r3, _MM_SHUFFLE(0, 1, 2, 3));
                tx = tiles - 1 - tx;
            }
            if (e.flip_y) {
                std::swap(r0, r3);
                std::swap(r1, r2);
                ty = tiles - 1 - ty;
            }
            float *dst = block.rows + ty * 4 * stride + end_block::kPad + tx * 4;
            _mm_store_ps(dst, r0);
            _mm_store_ps(dst + stride, r1);
            _mm_store_ps(dst + 2 * stride, r2);
            _mm_store_ps(dst + 3 * stride, r3);
        }
}

}  // namespace

// Four pixels at a time along each row's run: coverage (1), the band in closed form and
// each end's correction read from its block where the group overlaps it.
void draw_sse2(canvas_t *canvas, const stroke_setup &s, const line_table &table) {
    const int width = canvas->width;
    const detail::band_writer body(s.cdf, s.half, s.ink, s.dv);
    end_block block_a, block_b;
    auto fill = [&](end_block &block, double px, double py, double ex, double ey) {
        const end_source e = locate_end(table, px, py, ex, ey);
        if (table.stamp_size == 4) fill_block_sse2<4>(e, block);
        else fill_block_sse2<8>(e, block);
    };
    if (s.end_a) fill(block_a, s.ax, s.ay, s.dx, s.dy);
    if (s.end_b) fill(block_b, s.ax + s.length * s.dx, s.ay + s.length * s.dy, -s.dx, -s.dy);
    const __m128 lanes = _mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f);
    const __m128 lane_du = _mm_mul_ps(lanes, _mm_set1_ps(s.du)), lane_dv = _mm_mul_ps(lanes, _mm_set1_ps(s.dv));
    // Pixels beyond a cap's reach (u ≤ −R, u ≥ L + R) are not drawn: (1) holds only within.
    const __m128 u_lo = _mm_set1_ps(s.end_a ? -float(s.reach) : -INFINITY);
    const __m128 u_hi = _mm_set1_ps(s.end_b ? s.length_f + float(s.reach) : INFINITY);
    // The blocks' placement in registers (as far as the compiler knows, canvas stores may
    // change the blocks).
    const int ya = block_a.y0, xa = block_a.x0, yb = block_b.y0, xb = block_b.x0;
    const unsigned size_a = unsigned(block_a.size), size_b = unsigned(block_b.size);
    for_each_run(canvas, s, [&](float *row, int y, int first, int last, const row_frame &uv) {
        // Each block's row (rows[.. + kPad] = its pixel x0), or null.
        const float *row_a = unsigned(y - ya) < size_a ? block_a.rows + (y - ya) * end_block::kStride + end_block::kPad : nullptr;
        const float *row_b = unsigned(y - yb) < size_b ? block_b.rows + (y - yb) * end_block::kStride + end_block::kPad : nullptr;
        float u0, v0;
        for (int i = first; i <= last; i += 4) {
            const int x = std::min(i, width - 4);  // the row's end: the last group moved back inside
            uv.at(x, u0, v0);
            const __m128 u = _mm_add_ps(_mm_set1_ps(u0), lane_du), v = _mm_add_ps(_mm_set1_ps(v0), lane_dv);
            __m128 cover = body.band4(v);
            // Groups overlapping a block's columns: −4 < x − x0 < size.
            if (row_a && unsigned(x - xa + 3) < size_a + 3) cover = _mm_add_ps(cover, _mm_loadu_ps(row_a + (x - xa)));
            if (row_b && unsigned(x - xb + 3) < size_b + 3) cover = _mm_add_ps(cover, _mm_loadu_ps(row_b + (x - xb)));
            __m128 keep = _mm_and_ps(_mm_cmpgt_ps(u, u_lo), _mm_cmplt_ps(u, u_hi));
            if (x != i) keep = _mm_andnot_ps(_mm_cmplt_ps(lanes, _mm_set1_ps(float(i - x))), keep);  // done lanes
            body.blend4(row + x, _mm_and_ps(keep, cover));
        }
    });
}

}  // namespace tiny3d::tabulated
#endif
