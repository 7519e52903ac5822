// msaa.h — the multisample stage (internal). In: a multisampled frame's triangles (the
// scalar set-up here, make_msaa_triangle; the batches in setup/) and a band's rows. Out:
// per-sample colour and depth in a band's tile (sample_store), resolved into the canvas
// and the depth buffer. Here: the sample patterns, the store, the per-triangle setup, the
// row fill (portable 64-bit kernel, SSE2 32-bit beside it; AVX2 and AVX-512 in their files)
// and the box resolve, chosen through the kernel table. Called by the schedule's
// multisampled band loop (schedule/raster_multisample.cpp). The contract is in raster.h
// (render_context::begin_frame) and documentation/antialias.md.
#ifndef TINY3D_MSAA_H
#define TINY3D_MSAA_H

#include <cstdint>
#include <vector>

#include "../fill/fill.h"
#include "../setup/setup.h"
#include "../../simd_config.h"

namespace tiny3d::detail {

inline constexpr int MSAA_MAX_SAMPLES = 16;

// The 16-sample frames' sub-pixel grid (1/256 px): on the 1/16 px grid the snap alone
// moves a silhouette by up to 1/32 px, over their error target; the other modes keep 1/16,
// where the 32-bit kernels take far larger triangles.
inline constexpr int MSAA_16_SUBPIXEL_BITS = 8;

// Sample offsets from the pixel centre in 1/2^bits px (y down), on the grid the frame's
// vertices snap to, so every sample's edge values are exact integers: the standard 4- and
// 8-sample patterns (Direct3D 10.1 / Vulkan) on 1/16 px; for 16 a 4 × 4 grid rotated by
// atan(1/4) on 1/256 px, centred on the pixel (the standard 16-sample pattern is not).
struct sample_pattern {
    int count = 1;
    int bits = RASTER_SUBPIXEL_BITS;  // the grid: 1/2^bits px
    std::int16_t dx[MSAA_MAX_SAMPLES] = {}, dy[MSAA_MAX_SAMPLES] = {};
    alignas(16) float fdx[MSAA_MAX_SAMPLES] = {}, fdy[MSAA_MAX_SAMPLES] = {};  // dx/2^bits, dy/2^bits (px), exact
    int min_dx = 0, max_dx = 0, min_dy = 0, max_dy = 0;  // offsets' bounds (1/2^bits px)
    std::int64_t one() const { return std::int64_t{1} << bits; }  // sub-pixel units per pixel
};

// What sample s adds to an edge value at the pixel centre (steps a, b per pixel), exact.
inline std::int64_t sample_edge_offset(std::int64_t a, std::int64_t b, const sample_pattern &pat, int s) {
    return a / pat.one() * pat.dx[s] + b / pat.one() * pat.dy[s];
}

// The pattern of 1, 4, 8 or 16 samples; other counts give the pixel centre.
const sample_pattern &pattern_of(int samples);

// Which kernel fills and resolves the samples (the kernel table, src/kernels.h): all give
// bit-identical samples; a SIMD one runs where its precondition holds (msaa_triangle::
// chunkable, narrow) and the portable 64-bit reference elsewhere.
using msaa_kernel = raster_simd;  // raster.h

// The samples of a tile of rows [origin, origin + rows): per pixel S depths and S colours,
// and a touched mark (untouched pixels hold the clear values, so clearing a tile writes one
// byte per pixel). Grows only, never per frame: a tile that stays in cache while
// every triangle reaching it is drawn is what keeps multisampling cheap (antialias.md).
//
// The tile is kept AT REST between bands: every sample of every pixel holds depth 1 and the
// clear colour in memory (resize establishes it, the resolve restores it), so the kernels use
// samples as loaded without asking whether a pixel was touched; the marks are then only the
// resolve's hint of where to read (the AVX-512 and AVX2 4× kernels mark one pixel of a block
// per step, the block resolve reads every 8 × 2 group with a mark; the 8× and 16× lane kernels mark
// every pixel they visit, covered or not).
//
// Two layouts. Rows: pixel after pixel, each its S depths then its S colours. Blocks (4
// samples, for AVX-512 and AVX2): 2 × 2 pixels in 128 aligned bytes, 16 depths then 16
// colours, pixel q = 2·row + column at float 4q + s: the AVX-512 block kernel's two registers
// and, a block row's 8 depths and 8 colours each contiguous, the AVX2 one's, with no
// permutes. Every kernel takes either layout (pixel, colour_offset, pixel_step).
class sample_store {
public:
    // Grows the tile to rows × width pixels of `samples` (blocks: 4 samples only), at rest
    // for `clear_colour`, which every later fill and resolve uses.
    void resize(int width, int rows, int samples, float clear_colour, bool blocks = false);
    static bool blocks_for(msaa_kernel kernel, int samples) { return samples == 4 && kernels_for(kernel).msaa_blocks4; }
    int width() const { return width_; }
    bool blocks() const { return blocks_; }
    // Makes the tile rows [y0, y1), every pixel untouched.
    void start(int y0, int y1);
    // Rows are padded to a multiple of STRIDE_PIXELS; the samples start 64-byte aligned.
    static constexpr int STRIDE_PIXELS = 2;
    int stride() const { return stride_; }
    // Floats from pixel (x, y) to pixel (x, y + rows), in either layout (with blocks: rows
    // even and y at an even row from the origin).
    std::ptrdiff_t rows_step(int rows) const { return static_cast<std::ptrdiff_t>(rows) * 2 * samples_ * stride_; }
    // Pixel (x, y)'s S sample depths (consecutive floats); its S colours lie colour_offset()
    // floats further on, and pixel (x + 1, y)'s depths pixel_step(x) floats on.
    float *pixel(int x, int y) { return base_ + offset(x, y); }
    const float *pixel(int x, int y) const { return base_ + offset(x, y); }
    int colour_offset() const { return colour_offset(samples_, blocks_); }
    static constexpr int colour_offset(int samples, bool blocks) { return blocks ? 16 : samples; }
    static constexpr int pixel_step(int samples, bool blocks, int x) {
        return blocks ? ((x & 1) ? 28 : 4) : 2 * samples;
    }
    int origin() const { return origin_; }
    std::uint8_t *touched_row(int y) { return touched_.data() + static_cast<std::size_t>(y - origin_) * stride_; }
    // Pixel (x, y)'s samples (at rest since resize: used as they are), marked touched.
    float *touch(int x, int y) {
        touched_row(y)[x] = 1;
        return pixel(x, y);
    }
    // canvas := each pixel's mean sample colour, depth := its nearest sample depth, summed
    // in one fixed order for every kernel (bit-identical). The tile is left at rest (for the
    // clear colour resize was given, which is also an unmarked pixel's colour).
    void resolve(canvas_t &canvas, zbuffer &depth, msaa_kernel kernel);

private:
    void put_at_rest(float *pixel) const;  // one pixel's samples: depth 1, rest_colour_
    std::size_t offset(int x, int y) const {
        const std::size_t row = static_cast<std::size_t>(y - origin_);
        if (!blocks_) return (row * stride_ + x) * 2 * samples_;
        return ((row >> 1) * stride_ + (x & ~1)) * 16 + (row & 1) * 8 + (x & 1) * 4;
    }
    int width_ = 0, stride_ = 0, rows_ = 0, samples_ = 1, origin_ = 0, end_ = 0;
    bool blocks_ = false;
    float rest_colour_ = 0.0f;  // every sample holds (1, rest_colour_) outside a band's drawing
    std::vector<float> data_;
    float *base_ = nullptr;  // data_ from its first 64-byte boundary
    std::vector<std::uint8_t> touched_;
};

// One triangle ready for the multisample fill. e: the three oriented, top-left-biased edge
// functions at the CENTRE of pixel (min_x, min_y), a/b their steps per pixel; depth and
// intensity planes likewise. narrow: every edge value inside the bounds fits 32 bits and
// the float offsets a·fdx + b·fdy are exact. chunkable: |a| + |b| < 2^28, so a row can be
// walked in chunks whose values fit 32 bits (msaa_kernels.h); narrow implies chunkable.
// clipped_x: the clip cut the bounds' columns; otherwise no pixel beside them has a sample
// inside, so the 4× pair and block kernels may reach past the bounds unmasked.
struct msaa_triangle {
    int min_x, max_x, min_y, max_y;
    std::int64_t e[3], a[3], b[3];
    float z, zdx, zdy, i, idx, idy;
    bool narrow, chunkable, clipped_x;
    std::uint32_t state;  // the render context's draw state (set by the caller)
};

// From snapped vertices (1/2^pat.bits px), their snapped_area2 (≠ 0), window depths and
// intensities per vertex. False when no pixel of the pattern's bounds is inside `clip`.
bool make_msaa_triangle(const std::int32_t X[3], const std::int32_t Y[3], std::int64_t area2, const sample_pattern &pat,
                        pixel_rect clip, const float depth[3], const float intensity[3], msaa_triangle &out);

// kernel_table::setup_msaa_batch: make_msaa_triangle for in.count lanes at once, bit for
// bit (state left alone), for 4 and 8 samples (the 1/16 px grid) and 16 (1/256). Verdict
// per lane: ready, empty, or scalar (a wide box): make_msaa_triangle sets those up; a lane
// the batch sets up is narrow.
#ifdef TINY3D_AVX512
void setup_msaa_batch_avx512(const setup_batch &in, const sample_pattern &pat, pixel_rect clip,
                             fast_setup verdict[SETUP_BATCH], msaa_triangle out[SETUP_BATCH]);
#endif
#ifdef TINY3D_AVX2
void setup_msaa_batch_avx2(const setup_batch &in, const sample_pattern &pat, pixel_rect clip,
                           fast_setup verdict[SETUP_BATCH], msaa_triangle out[SETUP_BATCH]);
#endif

// The pixels [x0, x1] × [y0, y1] with a sample of the pattern inside the box of the snapped
// vertices X, Y (1/2^pat.bits px), clamped to `clip`; empty when x0 > x1 or y0 > y1.
void msaa_bounds(const std::int32_t X[3], const std::int32_t Y[3], const sample_pattern &pat, pixel_rect clip, int &x0,
                 int &x1, int &y0, int &y1);

// The row fill of `kernel` for `samples` and `test`, chosen once before a band's triangles:
// it draws rows [y0, y1) ∩ [min_y, max_y], per sample coverage and depth test, the pixel's
// centre intensity (clamped to 0..1) into the passing samples.
msaa_row_fill msaa_fill_for(msaa_kernel kernel, int samples, depth_func test);

// The per-pixel path's walk: fragment(x, y, mask) for each pixel of `t` (set up from the
// snapped X, Y on the pattern's grid) inside `clip` with a covered sample, bit s of mask for
// sample s (the fill's rule).
template <class Fragment>
void for_each_covered_pixel(const triangle_edges &t, const std::int32_t X[3], const std::int32_t Y[3],
                            const sample_pattern &pat, pixel_rect clip, Fragment &&fragment) {
    int x0, x1, y0, y1;
    msaa_bounds(X, Y, pat, clip, x0, x1, y0, y1);
    std::int64_t d[3][MSAA_MAX_SAMPLES];
    for (int k = 0; k < 3; ++k)
        for (int s = 0; s < pat.count; ++s) d[k][s] = sample_edge_offset(t.a[k], t.b[k], pat, s);
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            unsigned mask = 0;
            for (int s = 0; s < pat.count; ++s) {
                bool in = true;
                for (int k = 0; k < 3; ++k) in = in && t.c[k] + t.a[k] * x + t.b[k] * y + d[k][s] >= 0;
                mask |= static_cast<unsigned>(in) << s;
            }
            if (mask) fragment(x, y, mask);
        }
}

}  // namespace tiny3d::detail

#endif
