// line_tabulated_internal.h — internal: what the tabulated line's kernels share (the
// stroke set-up, the row walk, where an end's correction comes from, the end block) and
// the kernels' entry points. The geometry and the table are described in
// line_tabulated.cpp, which also sets strokes up and chooses the kernel (the one place:
// draw_prepared and draw_lines_tabulated, by line_table::simd()); the kernels are
// line_tabulated_portable.cpp (the reference), line_tabulated_sse2.cpp and
// line_tabulated_avx512.cpp.
// Everything here is baseline code: the AVX-512 kernel includes this before its target
// region opens, so these inline functions are never emitted as AVX-512 copies.
#ifndef TINY3D_LINE_TABULATED_INTERNAL_H
#define TINY3D_LINE_TABULATED_INTERNAL_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "canvas.h"
#include "lines.h"
#include "line_clip.h"
#include "../canvas/splat.h"  // floor_to_int
#include "square_cdf.h"
#include "../simd_config.h"

namespace tiny3d::tabulated {

// Segments longer than this (px) are drawn by draw_line_coverage (exact): u and v are
// stepped in float along a row, and the error of longer segments has not been tested.
constexpr double kExactFromLength = 64.0;
// Length of the straight part used to sample a half-infinite stroke (its far end is out
// of reach of the sampled pixels).
constexpr double kFarEnd = 64.0;
// Largest block side the drawers handle (T up to ~5.35 at kStampCells = 24).
constexpr int kMaxBlock = 8;
// Strokes prepared together by draw_lines_tabulated.
constexpr int kBatch = 8;

// ceil(v) as an int, v clamped to [lo, hi] first (so ±inf and huge values convert safely).
inline int clamped_ceil(double v, double lo, double hi) { return -detail::floor_to_int(-std::clamp(v, lo, hi)); }
inline int clamped_floor(double v, double lo, double hi) { return detail::floor_to_int(std::clamp(v, lo, hi)); }

// The pixel runs of a stroke, row by row from the top: per row, the pixels whose centres
// lie in the band |v| ≤ R and the slab −R ≤ u ≤ L + R. Each of the four chord ends (in
// canvas x, less ½: pixel i has its centre at i + ½) is linear in the row, so it is
// stepped by one addition per row; the chords are widened by kChordSlack (≫ the stepping's
// rounding) so that no pixel within reach is lost (a pixel at |v| = R or u = −R has
// coverage 0, so a few more are harmless). Direction (dx, dy) with dx ≥ 0, unit.
class row_runs {
public:
    row_runs(double ax, double ry, double dx, double dy, double length, double reach, int width)
        : width_(width) {
        constexpr double kAxisAligned = 1e-12, kUnbounded = 1e30, kChordSlack = 1e-6;
        // x − ax of the band's sides: (ry·dx ∓ R)/dy; of the slab's: (−R − ry·dy)/dx … (L + R − ry·dy)/dx.
        double band_slope = 0, band_half = kUnbounded, slab_slope = 0, slab_lo = -kUnbounded, slab_hi = kUnbounded;
        if (std::fabs(dy) > kAxisAligned) {
            const double inv_dy = 1.0 / dy;
            band_slope = dx * inv_dy;
            band_half = reach * std::fabs(inv_dy);
        }
        if (dx > kAxisAligned) {
            const double inv_dx = 1.0 / dx;
            slab_slope = -dy * inv_dx;
            slab_lo = -reach * inv_dx;
            slab_hi = (length + reach) * inv_dx;
        }
        const double x = ax - 0.5, centre = x + ry * band_slope, shift = x + ry * slab_slope;
        // Held as (low end, −high end) pairs, so one max gives both ends of the run.
        band_ = {centre - band_half - kChordSlack, -(centre + band_half + kChordSlack)};
        slab_ = {shift + slab_lo - kChordSlack, -(shift + slab_hi + kChordSlack)};
        band_step_ = {band_slope, -band_slope};
        slab_step_ = {slab_slope, -slab_slope};
    }
    // Pixels [first, last] of the current row (first > last: none), then steps to the next.
    // The ends are clamped to the row (also keeps the unbounded sides of an axis-aligned
    // stroke in int range), then ceil(lo) = W − ⌊W − lo⌋ and floor(hi) = ⌊1 + hi⌋ − 1 by
    // truncation of numbers ≥ 0.
    void next(int &first, int &last) {
#ifdef TINY3D_SSE2
        const __m128d lo_neg_hi = _mm_max_pd(load(band_), load(slab_));
        const __m128d clamped = _mm_min_pd(_mm_max_pd(lo_neg_hi, _mm_set_pd(1.0 - width_, 0.0)), _mm_set_pd(1.0, width_));
        const __m128i whole = _mm_cvttpd_epi32(_mm_sub_pd(_mm_set_pd(1.0, width_), clamped));
        first = width_ - _mm_cvtsi128_si32(whole);
        last = _mm_cvtsi128_si32(_mm_shuffle_epi32(whole, 1)) - 1;
        _mm_storeu_pd(band_.data(), _mm_add_pd(load(band_), load(band_step_)));
        _mm_storeu_pd(slab_.data(), _mm_add_pd(load(slab_), load(slab_step_)));
#else
        const double lo = std::min(std::max(std::max(band_[0], slab_[0]), 0.0), double(width_));
        const double neg_hi = std::min(std::max(std::max(band_[1], slab_[1]), 1.0 - width_), 1.0);
        first = width_ - int(width_ - lo);
        last = int(1.0 - neg_hi) - 1;
        for (int k = 0; k < 2; ++k) {
            band_[k] += band_step_[k];
            slab_[k] += slab_step_[k];
        }
#endif
    }

private:
#ifdef TINY3D_SSE2
    static __m128d load(const std::array<double, 2> &pair) { return _mm_loadu_pd(pair.data()); }
#endif
    int width_;
    std::array<double, 2> band_, slab_, band_step_, slab_step_;
};

// (u, v) of pixel centres row by row: (u0, v0) at the row's pixel 0, stepped by (dy, dx)
// per row; pixel i adds i·(dx, −dy). In double, rounded to float per run.
class row_frame {
public:
    row_frame(double u0, double v0, double dx, double dy)
#ifdef TINY3D_SSE2
        : uv_(_mm_set_pd(v0, u0)), down_(_mm_set_pd(dx, dy)), right_(_mm_set_pd(-dy, dx)) {}
    void step() { uv_ = _mm_add_pd(uv_, down_); }
    void at(int i, float &u, float &v) const {
        const __m128 uv = _mm_cvtpd_ps(_mm_add_pd(uv_, _mm_mul_pd(_mm_set1_pd(i), right_)));
        u = _mm_cvtss_f32(uv);
        v = _mm_cvtss_f32(_mm_shuffle_ps(uv, uv, _MM_SHUFFLE(1, 1, 1, 1)));
    }

private:
    __m128d uv_, down_, right_;
#else
        : u_(u0), v_(v0), dx_(dx), dy_(dy) {}
    void step() {
        u_ += dy_;
        v_ += dx_;
    }
    void at(int i, float &u, float &v) const {
        u = float(u_ + i * dx_);
        v = float(v_ + i * -dy_);
    }

private:
    double u_, v_, dx_, dy_;
#endif
};


// A stroke ready for the per-pixel loops (see draw_line_tabulated).
struct stroke_setup {
    double ax = 0, ay = 0, dx = 0, dy = 0, length = 0, reach = 0;
    bool end_a = true, end_b = true;  // false: that end was clipped off (no cap)
    detail::square_cdf cdf;
    float half = 0, length_f = 0, du = 0, dv = 0, ink = 0;
    int row_first = 0, row_last = -1;
    std::array<float, 4> exact{};  // x0, y0, x1, y1 of a segment handed to the exact line
};

// The stroke's rows from the top: row y, its pixels, its run first..last (next()) and its
// frame (uv.at(i) = (u, v) of pixel i's centre). Plain inline code, so the AVX-512 drawer
// can use it too (a template taking its lambda would be compiled for the baseline).
struct row_walk {
    row_walk(canvas_t *canvas, const stroke_setup &s)
        : runs(s.ax, s.row_first + 0.5 - s.ay, s.dx, s.dy, s.length, s.reach, canvas->width),
          uv((0.5 - s.ax) * s.dx + (s.row_first + 0.5 - s.ay) * s.dy, (s.row_first + 0.5 - s.ay) * s.dx - (0.5 - s.ax) * s.dy,
             s.dx, s.dy),
          row(canvas->data + std::size_t(s.row_first) * std::size_t(canvas->width)),
          y(s.row_first),
          width(canvas->width) {}
    void advance() {
        uv.step();
        row += width;
        ++y;
    }
    row_runs runs;
    row_frame uv;
    float *row;
    int y, width;
};

// Calls draw(row, y, first, last, uv) for each canvas row y the stroke reaches that has
// pixels in its run.
template <class Draw>
void for_each_run(canvas_t *canvas, const stroke_setup &s, Draw &&draw) {
    for (row_walk walk(canvas, s); walk.y <= s.row_last; walk.advance()) {
        int first, last;
        walk.runs.next(first, last);
        if (first <= last) draw(walk.row, walk.y, first, last, walk.uv);
    }
}

// Where one end's correction comes from: the 8 table blocks (s000 + i·next_x + j·next_y +
// k·next_q, i, j, k ∈ {0, 1}) and their weights, the fold (applied from the canvas to the
// table: flip x, flip y, then swap) and the canvas pixel of the block's first element
// after unfolding.
struct end_source {
    const float *s000;
    std::size_t next_x, next_y, next_q;
    float wx, wy, wq;
    bool flip_x, flip_y, swap;
    int x0, y0;
};

// The end at (px, py) whose stroke leaves it in direction (ex, ey) (unit). Static: each
// kernel file keeps its own copy, which GCC then compiles with its callers in view (the
// flips and the swap fold into the caller's arithmetic instead of a call's stores).
static inline end_source locate_end(const line_table &t, double px, double py, double ex, double ey) {
    end_source e;
    e.flip_x = ex < 0.0;
    e.flip_y = ey < 0.0;
    double cx = e.flip_x ? -px : px, cy = e.flip_y ? -py : py;
    double ax = std::fabs(ex), ay = std::fabs(ey);
    e.swap = ay > ax;
    if (e.swap) {
        std::swap(cx, cy);
        std::swap(ax, ay);
    }
    constexpr int intervals = line_table::kStampIntervals, cells = line_table::kStampCells;
    const double fq = ay / (ax + ay) * (2 * intervals);  // q = b/(a + b) scaled so slice k sits at k
    const int k = std::min(int(fq), intervals - 1);
    e.wq = float(fq - k);
    const int fx = detail::floor_to_int(cx), fy = detail::floor_to_int(cy);
    const double phx = (cx - fx) * cells, phy = (cy - fy) * cells;
    const int kx = std::min(int(phx), cells - 1), ky = std::min(int(phy), cells - 1);
    e.wx = float(phx - kx);
    e.wy = float(phy - ky);
    const int *axes = &t.stamp_axes[std::size_t(k) * 4];
    const bool past_x = kx >= axes[1], past_y = ky >= axes[3];
    const int sx = kx + past_x, sy = ky + past_y;
    const int size = t.stamp_size;
    const std::size_t area = std::size_t(size) * std::size_t(size), phases = line_table::kStampPhases;
    e.s000 = t.stamps.data() + (((std::size_t(k) * 2) * phases + std::size_t(sy)) * phases + std::size_t(sx)) * area;
    e.next_x = area;
    e.next_y = phases * area;
    e.next_q = phases * phases * area;
    // The block's canonical pixels (fx + ox + a, fy + oy + b) → canvas pixels.
    const int cx0 = fx + axes[0] + past_x, cy0 = fy + axes[2] + past_y;
    const int ux0 = e.swap ? cy0 : cx0, uy0 = e.swap ? cx0 : cy0;  // first pixel after unswapping
    e.x0 = e.flip_x ? -(ux0 + size - 1) - 1 : ux0;
    e.y0 = e.flip_y ? -(uy0 + size - 1) - 1 : uy0;
    return e;
}

// One end's correction D laid out on the canvas: block pixel (x0 + c, y0 + r) at
// rows[r·stride + kPad + c], each row padded with kPad zeros on both sides so a group of 4
// pixels overlapping the block anywhere reads its part with one unaligned load.
struct end_block {
    static constexpr int kPad = 4, kStride = kMaxBlock + 2 * kPad;
    int x0 = 0, y0 = 0, size = 0;
    alignas(16) float rows[kMaxBlock * kStride];
};

// Canonical element (a, b) of a size × size block → its place in the canvas block
// (undoing the fold: unswap, then unflip).
constexpr int unfolded_index(bool swap, bool flip_x, bool flip_y, int size, int a, int b) {
    int ux = swap ? b : a, uy = swap ? a : b;
    if (flip_x) ux = size - 1 - ux;
    if (flip_y) uy = size - 1 - uy;
    return uy * size + ux;
}

// ---- the kernels (each draws the image of draw_portable to within float rounding) ----
// One pixel at a time: the reference every other kernel is tested against.
void draw_portable(canvas_t *canvas, const stroke_setup &s, const line_table &table);
#ifdef TINY3D_SSE2
// Four pixels at a time; canvases at least 4 pixels wide.
void draw_sse2(canvas_t *canvas, const stroke_setup &s, const line_table &table);
#endif
#ifdef TINY3D_AVX512
// AVX-512 (line_simd::avx512: only on CPUs line_kernels_run() reports it for; tables with
// 4 × 4 blocks). draw_batch_avx512 draws `count` (≤ kBatch) prepared strokes in order;
// prepare8_avx512 sets up prepare_stroke's common case for n ≤ kBatch segments at once,
// with the arithmetic prepare_stroke uses (stroke_math.inc, on eight lanes), so bit for
// bit as prepare_stroke, and returns the mask of the lanes it set up.
void draw_batch_avx512(canvas_t *canvas, const stroke_setup *strokes, int count, const line_table &table);
unsigned prepare8_avx512(const canvas_t &canvas, const line_segment *segments, int n, const line_table &table,
                         stroke_setup *out);
#endif

}  // namespace tiny3d::tabulated

#endif
