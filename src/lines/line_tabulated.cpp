// line_tabulated.cpp — the tabulated thick line (include/canvas.h): the stroke of
// draw_line_coverage with the pixels near its ends interpolated from a table of exact
// end corrections instead of integrated.
//
// Frame of a stroke: u along it (from end A), v across. E_A = area of a pixel inside the
// half-infinite stroke that starts at end A (and runs on through B), E_B likewise. For a
// stroke A→B of length L:
//   stroke = K_A ∩ K_B, K_A ∪ K_B = the infinite band |v| ≤ h (when L ≥ h, each cap's disc
//   lies inside the other half-infinite stroke), so by inclusion–exclusion
//   coverage = E_A + E_B − band = band + D_A + D_B,   D = E − band                      (1)
// with band(v) the closed-form band area (square_cdf.h). D_A = 0 for a pixel wholly on the
// stroke's side of A's end line (u ≥ w_hi, half the pixel's extent along the stroke) or
// out of the band's reach (|v| ≥ R, R = h + √2/2); beyond the cap's reach (u ≤ −R) the
// pixel is simply not drawn. So D_A is non-zero only in a small rectangle around A — at
// most 4 × 4 pixels up to T = 1.75, 8 × 8 up to T ≈ 5.3 — and the table stores those blocks.
//
// The table ("stamps"): pixel-grid symmetries (flip x, flip y, swap x and y) fold any end
// into one with its stroke leaving in direction (a, b), a ≥ b ≥ 0, i.e. q = b/(a + b) in
// [0, ½]; q is cut into kStampIntervals intervals. For each interval, both of its end
// directions, and each end position phase (the end point's offset within its pixel, in
// steps of 1/kStampCells per axis), the table holds D of an S × S block of pixels. An end
// is drawn from 8 blocks: bilinear in its phase, linear in q. The block's placement is
// the same for the 2 × 2 phases of one cell and both directions of one interval (see
// stamp_axis_layout), so the 8 blocks combine lane for lane. Interpolating in direction
// matters: the nearest direction alone rotates the whole block about the end point, and
// 1.8° at 1.4 px from it moves the pixels by 0.04 px (errors up to 0.045 were measured).
#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <string>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

#include "canvas.h"
#include "line_clip.h"
#include "square_cdf.h"

namespace tiny3d {
namespace {

constexpr double kHalfDiagonal = 0.70710678118654752;
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

// One axis of a stamp layout: the end region's pixel-centre offsets from the end point
// lie in the open interval lo..hi; a phase cell c (end point at Px + φ, φ ∈ [c, c+1]/cells)
// then needs pixels Px + first(c) … Px + last(c). first(c) steps up at most once over the
// cells (at `jump`), so the blocks of cell c start at origin + (c ≥ jump).
struct stamp_axis_layout {
    int origin = 0, jump = 0, size = 0;
    stamp_axis_layout(double lo, double hi) {
        constexpr int cells = line_table::kStampCells;
        auto first = [&](int c) { return int(std::floor(double(c) / cells + lo - 0.5)) + 1; };
        auto last = [&](int c) { return int(std::ceil(double(c + 1) / cells + hi - 0.5)) - 1; };
        origin = first(0);
        jump = cells;
        for (int c = 0; c < cells; ++c) {
            if (first(c) > origin && jump == cells) jump = c;
            size = std::max(size, last(c) - first(c) + 1);
        }
    }
    // Stored sample s (0 … cells + 1) → its phase sample and its block's first pixel.
    int phase(int s) const { return s <= jump ? s : s - 1; }
    int origin_of(int s) const { return s <= jump ? origin : origin + 1; }
};

// Unit direction of stamp slice k (q = b / (a + b) = k / (2·intervals)).
void stamp_direction(double k, double &a, double &b) {
    const double q = k / (2.0 * line_table::kStampIntervals), norm = std::hypot(1.0 - q, q);
    a = (1.0 - q) / norm;
    b = q / norm;
}

// Layout of direction interval k (slices k … k + 1): bounds of the end region over
// directions sampled across the interval.
struct stamp_interval_layout {
    stamp_axis_layout x, y;
};
stamp_interval_layout interval_layout(int k, double reach) {
    constexpr int kSamples = 16;
    double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
    for (int i = 0; i <= kSamples; ++i) {
        double a, b;
        stamp_direction(k + double(i) / kSamples, a, b);
        const double w_hi = 0.5 * (a + b);
        for (double s : {-reach, w_hi})
            for (double t : {-reach, reach}) {
                const double ox = s * a - t * b, oy = s * b + t * a;
                xmin = std::min(xmin, ox);
                xmax = std::max(xmax, ox);
                ymin = std::min(ymin, oy);
                ymax = std::max(ymax, oy);
            }
    }
    return {stamp_axis_layout(xmin, xmax), stamp_axis_layout(ymin, ymax)};
}

void build_stamps(line_table &t, double reach, float thickness, line_cap cap) {
    constexpr int intervals = line_table::kStampIntervals, phases = line_table::kStampPhases;
    int size = 0;
    for (int k = 0; k < intervals; ++k) {
        const stamp_interval_layout g = interval_layout(k, reach);
        size = std::max({size, g.x.size, g.y.size});
    }
    const int side = (size + 3) / 4 * 4;  // whole SIMD groups (the extra pixels hold 0)
    if (side > kMaxBlock) return;         // too wide for the drawers: the exact line draws
    t.stamp_size = side;
    const std::size_t area = std::size_t(side) * std::size_t(side);
    t.stamps.assign(std::size_t(intervals) * 2 * phases * phases * area, 0.0f);
    t.stamp_axes.assign(std::size_t(intervals) * 4, 0);
    constexpr int base = 32;  // the sampled end sits in pixel (base, base)
    for (int k = 0; k < intervals; ++k) {
        const stamp_interval_layout g = interval_layout(k, reach);
        int *axes = &t.stamp_axes[std::size_t(k) * 4];
        axes[0] = g.x.origin;
        axes[1] = g.x.jump;
        axes[2] = g.y.origin;
        axes[3] = g.y.jump;
        for (int end = 0; end < 2; ++end) {
            double dx, dy;
            stamp_direction(k + end, dx, dy);
            for (int sy = 0; sy < phases; ++sy)
                for (int sx = 0; sx < phases; ++sx) {
                    const double px = base + double(g.x.phase(sx)) / line_table::kStampCells;
                    const double py = base + double(g.y.phase(sy)) / line_table::kStampCells;
                    const double fx = px + kFarEnd * dx, fy = py + kFarEnd * dy;  // far along the stroke
                    const double bx = px - kFarEnd * dx, by = py - kFarEnd * dy;  // far back: the band
                    float *out = &t.stamps[(((std::size_t(k) * 2 + end) * phases + sy) * phases + sx) * area];
                    for (int b = 0; b < size; ++b)
                        for (int a = 0; a < size; ++a) {
                            const int ix = base + g.x.origin_of(sx) + a, iy = base + g.y.origin_of(sy) + b;
                            const double e = line_coverage_reference_at(ix, iy, px, py, fx, fy, thickness, cap);
                            const double band = line_coverage_reference_at(ix, iy, bx, by, fx, fy, thickness, cap);
                            out[b * side + a] = float(e - band);
                        }
                }
        }
    }
}

// ceil(v) as an int, v clamped to [lo, hi] first (so ±inf and huge values convert safely).
int clamped_ceil(double v, double lo, double hi) { return -detail::floor_to_int(-std::clamp(v, lo, hi)); }
int clamped_floor(double v, double lo, double hi) { return detail::floor_to_int(std::clamp(v, lo, hi)); }

}  // namespace

line_simd best_line_simd() {
#if defined(__x86_64__) && defined(__GNUC__)
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
        __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw"))
        return line_simd::avx512;
#endif
#ifdef __SSE2__
    return line_simd::sse2;
#else
    return line_simd::portable;
#endif
}

result<line_table> line_table::make(float thickness, line_cap cap) {
    if (!std::isfinite(thickness) || !(thickness > 0.0f) || thickness > kMaxThickness)
        return error{"", 0, -1,
                     "line_table: thickness must be finite and in (0, " + std::to_string(kMaxThickness) + "] px, got " +
                         std::to_string(thickness)};
    line_table t;
    t.thickness_ = thickness;
    t.cap_ = cap;
    t.simd_ = best_line_simd();
    const double reach = 0.5 * double(thickness) + kHalfDiagonal;
    t.reach = float(reach);
    build_stamps(t, reach, thickness, cap);
    return t;
}

bool line_table::use_simd(line_simd simd) {
    if (int(simd) > int(best_line_simd())) return false;
    simd_ = simd;
    return true;
}

namespace {

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
#ifdef __SSE2__
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
#ifdef __SSE2__
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
#ifdef __SSE2__
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

// The end at (px, py) whose stroke leaves it in direction (ex, ey) (unit).
end_source locate_end(const line_table &t, double px, double py, double ex, double ey) {
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

// Canonical element (a, b) of a size × size block → its place in the canvas block
// (undoing the fold: unswap, then unflip).
constexpr int unfolded_index(bool swap, bool flip_x, bool flip_y, int size, int a, int b) {
    int ux = swap ? b : a, uy = swap ? a : b;
    if (flip_x) ux = size - 1 - ux;
    if (flip_y) uy = size - 1 - uy;
    return uy * size + ux;
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

#ifdef __SSE2__
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
#endif

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

#if defined(__x86_64__) && defined(__GNUC__)
// ---- AVX-512 ----
// Compiled for AVX-512 here (the rest of the library stays baseline x86-64) and run only
// on CPUs that have it (best_line_simd). What it calls from outside this region is
// baseline inline code, which may be inlined into it; nothing defined here is called
// from outside except draw_avx512. No FMA contraction: the same arithmetic as the SSE2
// path, rounding step by step.
#define TINY3D_LINE_AVX512 1
#pragma GCC push_options
#pragma GCC target("avx512f,avx512vl,avx512dq,avx512bw")
#pragma GCC optimize("fp-contract=off")
// GCC 12's AVX-512 intrinsics pass _mm512_undefined_ps() (self-initialised) as the unused
// merge source, which -W(maybe-)uninitialized reports once inlined (GCC bug 105593).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
// Vector arguments and results between functions of this file only: no ABI to keep.
#pragma GCC diagnostic ignored "-Wpsabi"

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

// prepare_stroke's common case (both ends finite and in the grown canvas, h ≤ L ≤ 64 px,
// intensity > 0) for up to 8 segments at once: the same double operations lane by lane,
// so the set-ups are bit for bit prepare_stroke's. Returns the lanes it set up; the
// caller hands the others to prepare_stroke. The table has blocks (stamp_size > 0).
unsigned prepare8_avx512(const canvas_t &canvas, const line_segment *g, int n, const line_table &table,
                         stroke_setup *out) {
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
    const __m512d X0 = _mm512_cvtps_pd(x0), Y0 = _mm512_cvtps_pd(y0), X1 = _mm512_cvtps_pd(x1), Y1 = _mm512_cvtps_pd(y1);
    const __m512d full_dx = _mm512_sub_pd(X1, X0), full_dy = _mm512_sub_pd(Y1, Y0);
    const __m512d length_full = _mm512_sqrt_pd(_mm512_add_pd(_mm512_mul_pd(full_dx, full_dx), _mm512_mul_pd(full_dy, full_dy)));
    const double h = 0.5 * double(table.thickness());
    ok &= _mm512_cmp_pd_mask(length_full, _mm512_set1_pd(h), _CMP_GE_OQ) &
          _mm512_cmp_pd_mask(length_full, _mm512_set1_pd(kExactFromLength), _CMP_LE_OQ);
    const __m512d inv_length = _mm512_div_pd(_mm512_set1_pd(1.0), length_full);
    const __m512d dx = _mm512_mul_pd(full_dx, inv_length), dy = _mm512_mul_pd(full_dy, inv_length);
    const double reach = table.reach, margin = 2.0 * reach + 2.0;
    const double width = canvas.width, height = canvas.height;
    const __m512d y_min = _mm512_min_pd(Y1, Y0), y_max = _mm512_max_pd(Y1, Y0);  // equal: either
    ok &= _mm512_cmp_pd_mask(X0, _mm512_set1_pd(-margin), _CMP_GE_OQ) &
          _mm512_cmp_pd_mask(X1, _mm512_set1_pd(width + margin), _CMP_LE_OQ) &
          _mm512_cmp_pd_mask(y_min, _mm512_set1_pd(-margin), _CMP_GE_OQ) &
          _mm512_cmp_pd_mask(y_max, _mm512_set1_pd(height + margin), _CMP_LE_OQ);
    if (!ok) return 0;
    const __m512d zero = _mm512_setzero_pd();
    const __m512d length = _mm512_max_pd(_mm512_add_pd(_mm512_mul_pd(full_dx, dx), _mm512_mul_pd(full_dy, dy)), zero);
    // square_cdf(−dy, dx)
    const __m512d sign = _mm512_set1_pd(-0.0);
    const __m512d abs_a = _mm512_andnot_pd(sign, dy), abs_b = _mm512_andnot_pd(sign, dx);
    const __m512d amax = _mm512_max_pd(abs_a, abs_b), amin = _mm512_min_pd(abs_a, abs_b);
    const __m512d two = _mm512_set1_pd(2.0);
    const __m256 w_lo = _mm512_cvtpd_ps(_mm512_div_pd(_mm512_sub_pd(amax, amin), two));
    const __m256 w_hi = _mm512_cvtpd_ps(_mm512_div_pd(_mm512_add_pd(amax, amin), two));
    const __mmask8 cornered = _mm512_cmp_pd_mask(amin, _mm512_set1_pd(detail::kNarrowCorner), _CMP_GT_OQ);
    const __m512d r = _mm512_div_pd(_mm512_set1_pd(1.0), _mm512_mul_pd(amax, amin));
    const __m256 inv_amax = _mm512_cvtpd_ps(
        _mm512_mask_blend_pd(cornered, _mm512_div_pd(_mm512_set1_pd(1.0), amax), _mm512_mul_pd(amin, r)));
    const __m256 inv_2ab = _mm256_maskz_mov_ps(cornered, _mm512_cvtpd_ps(_mm512_mul_pd(_mm512_set1_pd(0.5), r)));
    // Rows within R of the y range: −⌊−clamp(·)⌋ and ⌊clamp(·)⌋ as in clamped_ceil / clamped_floor.
    auto clamp = [](__m512d v, double lo, double hi) {
        return _mm512_mask_blend_pd(_mm512_cmp_pd_mask(v, _mm512_set1_pd(lo), _CMP_LT_OQ),
                                    _mm512_mask_blend_pd(_mm512_cmp_pd_mask(_mm512_set1_pd(hi), v, _CMP_LT_OQ), v,
                                                         _mm512_set1_pd(hi)),
                                    _mm512_set1_pd(lo));
    };
    auto floor_int = [](__m512d v) {
        return _mm512_cvttpd_epi32(_mm512_roundscale_pd(v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC));
    };
    const __m256i row_first = _mm256_sub_epi32(
        _mm256_setzero_si256(),
        floor_int(_mm512_sub_pd(zero, clamp(_mm512_sub_pd(_mm512_sub_pd(y_min, _mm512_set1_pd(reach)), _mm512_set1_pd(0.5)), 0.0, height))));
    const __m256i row_last =
        floor_int(clamp(_mm512_sub_pd(_mm512_add_pd(y_max, _mm512_set1_pd(reach)), _mm512_set1_pd(0.5)), -1.0, height - 1.0));
    alignas(64) double ax[8], ay[8], adx[8], ady[8], alen[8];
    alignas(32) float lo[8], hi[8], ia[8], i2[8], ink_f[8];
    alignas(32) std::int32_t first[8], last[8];
    _mm512_store_pd(ax, X0);
    _mm512_store_pd(ay, Y0);
    _mm512_store_pd(adx, dx);
    _mm512_store_pd(ady, dy);
    _mm512_store_pd(alen, length);
    _mm256_store_ps(lo, w_lo);
    _mm256_store_ps(hi, w_hi);
    _mm256_store_ps(ia, inv_amax);
    _mm256_store_ps(i2, inv_2ab);
    _mm256_store_ps(ink_f, _mm256_min_ps(ink, _mm256_set1_ps(1.0f)));
    _mm256_store_si256(reinterpret_cast<__m256i *>(first), row_first);
    _mm256_store_si256(reinterpret_cast<__m256i *>(last), row_last);
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

#pragma GCC diagnostic pop
#pragma GCC pop_options
#endif

}  // namespace

namespace {

enum class stroke_kind { nothing, exact, tabulated };

// Checks and clips one segment and fills `s` for the tabulated drawers.
stroke_kind prepare_stroke(const canvas_t *canvas, float x0, float y0, float x1, float y1, const line_table &table,
                           float intensity, stroke_setup &s) {
    if (!canvas || !canvas->data || canvas->width <= 0 || canvas->height <= 0) return stroke_kind::nothing;
    if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1) ||
        !std::isfinite(intensity) || !(intensity > 0.0f) || !(table.thickness() > 0.0f))
        return stroke_kind::nothing;
    s.ink = std::min(intensity, 1.0f);
    const double h = 0.5 * double(table.thickness());
    // Left to right (dx ≥ 0), so u grows along a canvas row.
    if (x1 < x0 || (x1 == x0 && y1 < y0)) {
        std::swap(x0, x1);
        std::swap(y0, y1);
    }
    // Float ends: their differences and squares are finite in double.
    const double full_dx = double(x1) - x0, full_dy = double(y1) - y0;
    const double full_length = std::sqrt(full_dx * full_dx + full_dy * full_dy);
    // (1) needs L ≥ h; beyond kExactFromLength, or without stamps (thick lines), the exact line draws.
    if (!(full_length >= h) || full_length > kExactFromLength || table.stamp_size == 0) {
        s.exact = {x0, y0, x1, y1};
        return stroke_kind::exact;
    }
    const double inv_length = 1.0 / full_length;
    s.dx = full_dx * inv_length;
    s.dy = full_dy * inv_length;
    // Clip to the canvas grown by 2R + 2: a clipped end is then so far off the canvas that
    // no canvas pixel within reach of the stroke lies near it; it gets no cap.
    s.reach = table.reach;
    const double margin = 2.0 * s.reach + 2.0;
    const int width = canvas->width, height = canvas->height;
    detail::clipped_segment clip{x0, y0, x1, y1, false, false};
    // (x0 ≤ x1 here.) The common case, both ends in the grown canvas, needs no call.
    const double y_min = std::min(y0, y1), y_max = std::max(y0, y1);
    if (!(x0 >= -margin && x1 <= width + margin && y_min >= -margin && y_max <= height + margin) &&
        !detail::clip_segment(x0, y0, x1, y1, -margin, -margin, width + margin, height + margin, clip))
        return stroke_kind::nothing;
    s.ax = clip.x0;
    s.ay = clip.y0;
    s.length = std::max(0.0, (clip.x1 - s.ax) * s.dx + (clip.y1 - s.ay) * s.dy);
    s.end_a = !clip.start_clipped;
    s.end_b = !clip.end_clipped;
    s.cdf = detail::square_cdf(-s.dy, s.dx);
    s.half = float(h);
    s.length_f = float(s.length);
    s.du = float(s.dx);
    s.dv = float(-s.dy);
    // Rows whose centre lies within R of the segment's y range (the stroke's full extent).
    s.row_first = clamped_ceil(std::min(s.ay, clip.y1) - s.reach - 0.5, 0.0, height);
    s.row_last = clamped_floor(std::max(s.ay, clip.y1) + s.reach - 0.5, -1.0, height - 1.0);
    return stroke_kind::tabulated;
}

void draw_prepared(canvas_t *canvas, stroke_kind kind, const stroke_setup &s, const line_table &table) {
    if (kind == stroke_kind::exact) {
        draw_line_coverage(canvas, s.exact[0], s.exact[1], s.exact[2], s.exact[3], table.thickness(),
                           {table.cap(), s.ink});
        return;
    }
    if (kind != stroke_kind::tabulated) return;
#ifdef TINY3D_LINE_AVX512
    if (table.simd() == line_simd::avx512 && table.stamp_size == 4) return draw_batch_avx512(canvas, &s, 1, table);
#endif
#ifdef __SSE2__
    if (table.simd() != line_simd::portable && canvas->width >= 4) return draw_sse2(canvas, s, table);
#endif
    draw_portable(canvas, s, table);
}

}  // namespace

void draw_line_tabulated(canvas_t *canvas, float x0, float y0, float x1, float y1, const line_table &table,
                         float intensity) {
    stroke_setup s;
    draw_prepared(canvas, prepare_stroke(canvas, x0, y0, x1, y1, table, intensity, s), s, table);
}

void draw_lines_tabulated(canvas_t *canvas, const line_segment *segments, std::size_t count, const line_table &table) {
    if (!segments) return;
    stroke_setup strokes[kBatch];
    stroke_kind kinds[kBatch];
    for (std::size_t start = 0; start < count; start += kBatch) {
        const int n = int(std::min<std::size_t>(kBatch, count - start));
        bool all_wide = true;
        unsigned ready = 0;  // set up by the vector code
#ifdef TINY3D_LINE_AVX512
        if (table.simd() == line_simd::avx512 && table.stamp_size == 4 && canvas && canvas->data && canvas->width > 0 &&
            canvas->height > 0)
            ready = prepare8_avx512(*canvas, segments + start, n, table, strokes);
#endif
        for (int i = 0; i < n; ++i) {
            if (ready >> i & 1) {
                kinds[i] = stroke_kind::tabulated;
                continue;
            }
            const line_segment &g = segments[start + std::size_t(i)];
            kinds[i] = prepare_stroke(canvas, g.x0, g.y0, g.x1, g.y1, table, g.intensity, strokes[i]);
            all_wide = all_wide && kinds[i] == stroke_kind::tabulated;
        }
#ifdef TINY3D_LINE_AVX512
        if (all_wide && table.simd() == line_simd::avx512 && table.stamp_size == 4) {
            draw_batch_avx512(canvas, strokes, n, table);
            continue;
        }
#endif
        for (int i = 0; i < n; ++i) draw_prepared(canvas, kinds[i], strokes[i], table);
    }
}

}  // namespace tiny3d
