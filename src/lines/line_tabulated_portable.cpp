// line_tabulated_portable.cpp — the tabulated line's portable reference kernel
// (line_simd::portable): plain C++, one pixel at a time. The SSE2 and AVX-512 kernels are
// tested against it (tests/line_tabulated_test.cpp).
#include <algorithm>
#include <cmath>
#include <iterator>

#include "line_tabulated_internal.h"

namespace tiny3d::tabulated {
namespace {

// The block in canonical order: trilinear blend of the 8 table blocks, element by element.
void blend_blocks(const end_source &e, int size, float *canonical) {
    const int area = size * size;
    for (int i = 0; i < area; ++i) {
        auto bilinear = [&](const float *p) {
            const float bottom = p[0] + e.wx * (p[e.next_x] - p[0]);
            const float top = p[e.next_y] + e.wx * (p[e.next_y + e.next_x] - p[e.next_y]);
            return bottom + e.wy * (top - bottom);
        };
        const float d0 = bilinear(e.s000 + i), d1 = bilinear(e.s000 + e.next_q + i);
        canonical[i] = d0 + e.wq * (d1 - d0);
    }
}

void fill_block_portable(const end_source &e, int size, end_block &block) {
    float canonical[kMaxBlock * kMaxBlock];
    blend_blocks(e, size, canonical);
    block.x0 = e.x0;
    block.y0 = e.y0;
    block.size = size;
    std::fill(std::begin(block.rows), std::end(block.rows), 0.0f);
    for (int b = 0; b < size; ++b)
        for (int a = 0; a < size; ++a) {
            const int at = unfolded_index(e.swap, e.flip_x, e.flip_y, size, a, b);
            block.rows[(at / size) * end_block::kStride + end_block::kPad + at % size] = canonical[b * size + a];
        }
}

}  // namespace

// One pixel at a time (no SSE2, or canvases narrower than 4 pixels).
void draw_portable(canvas_t *canvas, const stroke_setup &s, const line_table &table) {
    end_block block_a, block_b;
    if (s.end_a) fill_block_portable(locate_end(table, s.ax, s.ay, s.dx, s.dy), table.stamp_size, block_a);
    if (s.end_b)
        fill_block_portable(locate_end(table, s.ax + s.length * s.dx, s.ay + s.length * s.dy, -s.dx, -s.dy),
                            table.stamp_size, block_b);
    const float u_lo = s.end_a ? -float(s.reach) : -INFINITY, u_hi = s.end_b ? s.length_f + float(s.reach) : INFINITY;
    auto correction = [](const end_block &b, int x, int y) {
        const unsigned r = unsigned(y - b.y0), c = unsigned(x - b.x0);
        return r < unsigned(b.size) && c < unsigned(b.size) ? b.rows[r * end_block::kStride + end_block::kPad + c] : 0.0f;
    };
    for_each_run(canvas, s, [&](float *row, int y, int first, int last, const row_frame &uv) {
        for (int i = first; i <= last; ++i) {
            float u, v;
            uv.at(i, u, v);
            if (!(u > u_lo && u < u_hi)) continue;
            const float cover = s.cdf.band(v, s.half) + correction(block_a, i, y) + correction(block_b, i, y);
            detail::combine_over(row[i], s.ink * cover);
        }
    });
}

}  // namespace tiny3d::tabulated
