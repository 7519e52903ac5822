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

// The sub-pixel grid of the 16-sample frames' vertices and sample offsets: 1/256 px. Their
// error target (silhouette error ≤ 3 grey levels against the converged image) is below
// what vertices on the 1/16 px grid allow (3.13 on Scene S: the snap moves a silhouette
// by up to 1/32 px); the other modes keep 1/16, where the snap is a small part of their
// error and the 32-bit kernels take triangles up to ~2000 px (span_limit: ~120 px here).
inline constexpr int MSAA_16_SUBPIXEL_BITS = 8;

// Sample offsets from the pixel centre in 1/2^bits px (y down), on the pattern's snapping
// grid, so the edge functions at every sample are exact integers: the standard 4-sample
// rotated grid and 8-sample pattern (those of Direct3D 10.1 / Vulkan's standard sample
// locations) on the 1/16 px grid, and for 16 a 4 × 4 grid rotated by atan(1/4), every row
// and column distinct, centred on the pixel (sixteen distinct columns of a 1/16 grid cannot
// be: the standard 16-sample pattern's mean is (−1/32, −1/32) px), its offsets odd
// multiples of 1/32 px on the 1/256 px grid of MSAA_16_SUBPIXEL_BITS. A frame's vertices are
// snapped to the grid of its pattern.
struct sample_pattern {
    int count = 1;
    int bits = RASTER_SUBPIXEL_BITS;  // the grid: 1/2^bits px
    std::int16_t dx[MSAA_MAX_SAMPLES] = {}, dy[MSAA_MAX_SAMPLES] = {};
    alignas(16) float fdx[MSAA_MAX_SAMPLES] = {}, fdy[MSAA_MAX_SAMPLES] = {};  // dx/2^bits, dy/2^bits (px), exact
    int min_dx = 0, max_dx = 0, min_dy = 0, max_dy = 0;  // offsets' bounds (1/2^bits px)
    std::int64_t one() const { return std::int64_t{1} << bits; }  // sub-pixel units per pixel
};

// What sample s adds to an edge value at the pixel centre, for an edge of steps a, b per
// pixel on the pattern's grid: a/2^bits·dx[s] + b/2^bits·dy[s], exact (every kernel's
// offsets, and the per-pixel path's).
inline std::int64_t sample_edge_offset(std::int64_t a, std::int64_t b, const sample_pattern &pat, int s) {
    return a / pat.one() * pat.dx[s] + b / pat.one() * pat.dy[s];
}

// The pattern of 1, 4, 8 or 16 samples (1: the pixel centre); other counts give the centre.
const sample_pattern &pattern_of(int samples);

// Which kernel fills and resolves the samples: the portable reference (64-bit edge values,
// one sample at a time), SSE2 (32-bit edge values, four samples per register), AVX2 (for
// narrow triangles two pixels' 8 samples per register at 4×, a pixel's 8 or 16 samples in
// one or two registers at 8× and 16×; SSE2 for the others) or AVX-512 (a pixel's
// 8 or 16 samples in one register; at 4× a 2 × 2 block of pixels' 16 samples, or for
// triangles that are not narrow the SSE2 kernel's code compiled for AVX-512). The resolve
// is SSE2's for all but the portable one. All give bit-identical samples and images; a
// faster one runs where its precondition holds (msaa_triangle::chunkable, narrow) and the
// portable one elsewhere.
// Which of them runs: the render context's kernel table (src/kernels.h), as for the
// 1-sample fill.
using msaa_kernel = raster_simd;  // raster.h

// The samples of a tile of rows [origin, origin + rows) of the canvas: per pixel S sample
// depths and S sample colours (floats, laid out as below), and whether the pixel has been
// touched (untouched pixels hold the clear values implicitly, so clearing a tile writes one
// byte per pixel; a touched pixel's samples are in memory — the AVX2 4× kernel, which stores
// whole lines, also marks the pixels it covered no sample of: their samples hold the clear
// values, whose mean is the clear intensity exactly, as begin_frame clamps it to [0, 1]; in
// a tile at rest, below, every pixel's samples are in memory and a mark is a hint). Grows
// only (resize), never per frame. A tile small enough to stay in the core's cache while
// every triangle of the frame that reaches it is drawn is what keeps multisampling cheap
// (documentation/antialias.md).
//
// A 4-sample tile is also kept AT REST between bands: every sample of every pixel, touched
// or not, holds depth 1 and the clear colour in memory. resize establishes it (when the
// layout or the clear colour changed since) and the resolve restores it (it writes the
// clear values back into the touched pixels it has just read), so the 4× kernels (AVX-512
// blocks, AVX2 pairs, SSE2 pixels) use the samples as loaded without first asking whether
// their pixels were touched, and the portable kernel and the per-pixel path initialise
// nothing (touch). In a tile at rest the marks are only the resolve's hint of where to
// read: the AVX-512 block kernel marks the first pixel of each block it stores (one byte
// store per block instead of two), and the block
// resolve reads every 8 × 2 group of pixels with a mark, its per-pixel tail every pixel.
//
// Two layouts. Rows: pixel after pixel along a row, each its S depths then its S colours
// (every count; at 4 samples the two pixels from an even column are one aligned 64-byte
// line, the AVX2 4× kernel's unit). Blocks (4 samples, for the AVX-512 kernels): 2 × 2
// pixels — columns paired from column 0, rows from the tile's origin, an odd last row
// paired with padding — each block 128 bytes, aligned: its 16 depths, then its 16 colours,
// sample s of the block's pixel q = 2·(row in block) + (column in block) at float 4q + s
// of each: the block kernel's two registers, loaded and stored as they are, with no
// permutes (the row kernels walk a row through twice the lines in it, so SSE2 and AVX2
// keep rows). Every kernel takes either layout (pixel, colour_offset,
// pixel_step), so a tile's layout and the kernel need not match.
class sample_store {
public:
    // Grows the tile (never shrinks it) to `rows` rows of `width` pixels at `samples` per
    // pixel, in blocks when `blocks` (4 samples only) and rows otherwise; with 4 samples,
    // also at rest for `clear_colour` (above), which must be the clear colour every fill and
    // resolve of the tile is then given.
    void resize(int width, int rows, int samples, float clear_colour, bool blocks = false);
    // The layout the render context gives `kernel`'s tiles: blocks for the AVX-512 kernels
    // at 4 samples.
    static bool blocks_for(msaa_kernel kernel, int samples) { return samples == 4 && kernels_for(kernel).msaa_blocks4; }
    int samples() const { return samples_; }
    int width() const { return width_; }
    bool blocks() const { return blocks_; }
    // Makes the tile rows [y0, y1) (y1 − y0 ≤ rows of resize), every pixel untouched.
    void start(int y0, int y1);
    // Rows are padded to a multiple of STRIDE_PIXELS (stride() ≥ width(); the pixels past
    // the width are padding no resolve reads) and the samples start 64-byte aligned.
    static constexpr int STRIDE_PIXELS = 2;
    int stride() const { return stride_; }
    // Pixel (x, y)'s S sample depths (consecutive floats); its S colours lie colour_offset()
    // floats further on, and pixel (x + 1, y)'s depths pixel_step(x) floats on.
    float *pixel(int x, int y) { return base_ + offset(x, y); }
    const float *pixel(int x, int y) const { return base_ + offset(x, y); }
    int colour_offset() const { return colour_offset(samples_, blocks_); }
    static constexpr int colour_offset(int samples, bool blocks) { return blocks ? 16 : samples; }
    static constexpr int pixel_step(int samples, bool blocks, int x) {
        return blocks ? ((x & 1) ? 28 : 4) : 2 * samples;
    }
    // The tile's first row (blocks pair the rows from here).
    int origin() const { return origin_; }
    std::uint8_t *touched_row(int y) { return touched_.data() + static_cast<std::size_t>(y - origin_) * stride_; }
    // Every sample of every pixel in memory (above): 4-sample tiles.
    bool at_rest() const { return at_rest_; }
    // Pixel (x, y)'s samples, about to be drawn: marked touched, and on the first touch of a
    // tile not at rest initialised (depth 1, clear_colour).
    float *touch(int x, int y, float clear_colour) {
        std::uint8_t &mark = touched_row(y)[x];
        float *p = pixel(x, y);
        if (!mark && !at_rest_) initialise(p, clear_colour);
        mark = 1;
        return p;
    }
    // Rows [y0, y1) := untouched.
    void clear_rows(int y0, int y1);
    // A pixel's first touch: every sample := (depth 1, clear_colour).
    void initialise(float *pixel, float clear_colour) const;
    // The tile's rows: canvas := the mean of each pixel's sample colours (clear_colour when
    // untouched), depth := the nearest sample depth (1 when untouched). The sums run in one
    // fixed order (every kernel alike: bit-identical). A 4-sample tile is left at rest.
    void resolve(canvas_t &canvas, zbuffer &depth, float clear_colour, msaa_kernel kernel);

private:
    std::size_t offset(int x, int y) const {
        const std::size_t row = static_cast<std::size_t>(y - origin_);
        if (!blocks_) return (row * stride_ + x) * 2 * samples_;
        return ((row >> 1) * stride_ + (x & ~1)) * 16 + (row & 1) * 8 + (x & 1) * 4;  // (the layout above)
    }
    int width_ = 0, stride_ = 0, rows_ = 0, samples_ = 1, origin_ = 0, end_ = 0;
    bool blocks_ = false;
    bool at_rest_ = false;     // every sample holds (1, rest_colour_): 4-sample tiles only
    float rest_colour_ = 0.0f;
    std::vector<float> data_;
    float *base_ = nullptr;  // data_ from its first 64-byte boundary
    std::vector<std::uint8_t> touched_;
};

// One triangle ready for the multisample fill. Bounds: the pixels with a sample inside the
// snapped vertex box. e: the three oriented, top-left-biased edge functions (as
// triangle_edges) at the CENTRE of pixel (min_x, min_y), a/b their steps per pixel; the
// value at sample s of a pixel adds a/2^bits·dx[s] + b/2^bits·dy[s] (exact). Depth and
// intensity planes at that centre, steps per pixel.
// narrow: every edge value inside the bounds fits 32 bits and the SIMD kernels' float
// offsets a·fdx + b·fdy are exact. chunkable: |a| + |b| < 2^28 for every edge, so that the
// SIMD kernels can walk a row in chunks of columns whose values fit 32 bits (a value beyond
// ±2^30 at a chunk's start keeps its sign over the chunk and is clamped: msaa_kernels.h);
// narrow implies chunkable. The portable kernel takes any triangle.
// clipped_x: the clip rectangle cut the bounds' columns, so a pixel left or right of them may
// have a sample inside the triangle; otherwise none has (the AVX-512 and AVX2 4× kernels
// then walk blocks or pairs reaching a column past the bounds without masking it off).
struct msaa_triangle {
    int min_x, max_x, min_y, max_y;
    std::int64_t e[3], a[3], b[3];
    float z, zdx, zdy, i, idx, idy;
    bool narrow, chunkable, clipped_x;
    std::uint32_t state;  // the render context's draw state (set by the caller)
};

// From valid triangle_edges (bounds recomputed for the pattern, clamped to `clip`), window
// depths and intensities per vertex. False when no pixel of the pattern's bounds is on the
// clip rectangle.
// t is set up on the pattern's grid (triangle_setup_snapped with pat.bits).
bool make_msaa_triangle(const triangle_edges &t, const sample_pattern &pat, pixel_rect clip, const float depth[3],
                        const float intensity[3], msaa_triangle &out);
// The same from the snapped vertices (in 1/2^pat.bits px, usable: snap_vertex) and their
// snapped_area2 (≠ 0), without setting up triangle_edges first (the render context's
// triangles). The first form converts t's vertices and calls this one.
bool make_msaa_triangle(const std::int32_t X[3], const std::int32_t Y[3], std::int64_t area2, const sample_pattern &pat,
                        pixel_rect clip, const float depth[3], const float intensity[3], msaa_triangle &out);

// make_msaa_triangle for the first in.count lanes of `in` at once with `kernel`'s
// instructions where it has a batch (batched_setup: AVX-512, AVX2; the same integer edges
// and the same plane doubles in the same order, so the same msaa_triangle bit for bit;
// state is left alone), for a pattern on the 1/16 px grid (pat.bits = RASTER_SUBPIXEL_BITS:
// 4 and 8 samples). Verdict per lane: ready (out[l] set), empty (make_msaa_triangle returns
// false), or scalar: a box spanning FAST_SPAN_LIMIT or more on an axis, or every lane with
// another kernel, which make_msaa_triangle sets up. Lanes at and after in.count are left
// alone.
void setup_msaa_batch(fill_kernel kernel, const setup_batch &in, const sample_pattern &pat, pixel_rect clip,
                      fast_setup verdict[SETUP_BATCH], msaa_triangle out[SETUP_BATCH]);
// The batch kernels' verdicts for lanes [0, count): scalar (wide), empty, or ready, out[l]
// then set with its edges (e[k][l], a[k][l], b[k][l]); a lane they set up is narrow (its box
// spans less than span_limit), so chunkable too.
inline void finish_msaa_batch(const batch_lanes &lanes, int count, const std::int64_t e[3][SETUP_BATCH],
                              const std::int64_t a[3][SETUP_BATCH], const std::int64_t b[3][SETUP_BATCH],
                              fast_setup verdict[SETUP_BATCH], msaa_triangle out[SETUP_BATCH]) {
    for (int l = 0; l < count; ++l) {
        const unsigned bit = 1u << l;
        if (lanes.wide & bit) verdict[l] = fast_setup::scalar;
        else if (lanes.empty & bit) verdict[l] = fast_setup::empty;
        else {
            verdict[l] = fast_setup::ready;
            msaa_triangle &f = out[l];
            lanes.unpack(l, f);
            for (int k = 0; k < 3; ++k) f.e[k] = e[k][l], f.a[k] = a[k][l], f.b[k] = b[k][l];
            f.narrow = true, f.chunkable = true, f.clipped_x = (lanes.clipped_x & bit) != 0;
        }
    }
}
#ifdef TINY3D_AVX512
void setup_msaa_batch_avx512(const setup_batch &in, const sample_pattern &pat, pixel_rect clip,
                             fast_setup verdict[SETUP_BATCH], msaa_triangle out[SETUP_BATCH]);
#endif
#ifdef TINY3D_AVX2
void setup_msaa_batch_avx2(const setup_batch &in, const sample_pattern &pat, pixel_rect clip,
                           fast_setup verdict[SETUP_BATCH], msaa_triangle out[SETUP_BATCH]);
#endif

// t's snapped vertices in 1/2^pat.bits px, exactly (t on the pattern's grid: t.x, t.y are
// multiples of 1/2^pat.bits px).
inline void snapped_of(const triangle_edges &t, const sample_pattern &pat, std::int32_t X[3], std::int32_t Y[3]) {
    const double one = static_cast<double>(pat.one());
    for (int k = 0; k < 3; ++k) {
        X[k] = static_cast<std::int32_t>(t.x[k] * one);
        Y[k] = static_cast<std::int32_t>(t.y[k] * one);
    }
}

// The pixels [x0, x1] × [y0, y1] with a sample of the pattern inside the box of the snapped
// vertices X, Y (1/2^pat.bits px), clamped to `clip`; empty when x0 > x1 or y0 > y1.
void msaa_bounds(const std::int32_t X[3], const std::int32_t Y[3], const sample_pattern &pat, pixel_rect clip, int &x0,
                 int &x1, int &y0, int &y1);

// The candidate rows of snapped vertices with y range [min_Y, max_Y] (1/2^pat.bits px): rows with a
// sample row inside it, clamped to [0, last_row].
void msaa_candidate_rows(std::int64_t min_Y, std::int64_t max_Y, const sample_pattern &pat, int last_row, int &row0,
                         int &row1);

// Draws rows [y0, y1) ∩ [min_y, max_y]: per sample coverage and depth test, the pixel's
// intensity (at its centre, clamped to 0..1) into the passing samples, by `kernel` (the
// portable one where the triangle is not chunkable; tests compare them).
void fill_msaa_rows(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, depth_func test,
                    bool depth_write, float clear_colour, int y0, int y1, msaa_kernel kernel);
// fill_msaa_rows with its kernel, sample count and depth test chosen once: the function
// msaa_fill_for(kernel, pat.count, test) draws what fill_msaa_rows(…, test, …, kernel) draws
// (which calls it), given the same pattern and test. A band's loop picks its functions
// before its triangles: the choice per triangle went through three calls.
// (msaa_row_fill: src/kernels.h)
msaa_row_fill msaa_fill_for(msaa_kernel kernel, int samples, depth_func test);

// The per-pixel path's multisampled walk: for each pixel of `t` (valid triangle_edges on the
// pattern's grid: triangle_setup_snapped with pat.bits) inside
// `clip` with at least one covered sample, calls fragment(x, y, mask) with bit s set for
// each covered sample s (64-bit exact edge functions, the same rule as the fill).
template <class Fragment>
void for_each_covered_pixel(const triangle_edges &t, const sample_pattern &pat, pixel_rect clip, Fragment &&fragment);

// The gradient (per pixel) of the plane through (x_k, y_k, f_k) of a screen triangle.
void screen_gradient(const screen_vertex v[3], const float f[3], float &fdx, float &fdy);

// ---- template definition ----

template <class Fragment>
void for_each_covered_pixel(const triangle_edges &t, const sample_pattern &pat, pixel_rect clip, Fragment &&fragment) {
    int x0, x1, y0, y1;
    std::int32_t X[3], Y[3];
    snapped_of(t, pat, X, Y);
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
