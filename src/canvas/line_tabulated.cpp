// line_tabulated.cpp — the tabulated thick line (include/canvas.h): the stroke of
// draw_line_coverage with the pixels near its ends interpolated from a table of the exact
// end coverage instead of integrated.
//
// Frame of an end: origin at the end point, u along the stroke (into it), v across.
// E(u, v) = area of the pixel (centre at (u, v)) inside the half-infinite stroke that
// starts at that end. For a stroke A→B of length L:
//   stroke = K_A ∩ K_B, K_A ∪ K_B = the infinite band |v| ≤ h (when L ≥ h, each cap's disc
//   lies inside the other half-infinite stroke), so by inclusion–exclusion
//   coverage = E(u, v) + E(L − u, −v) − band(v)                                        (1)
// with band(v) the closed-form band area (square_cdf.h). E(u, v) = band(v) once the
// pixel lies wholly on the stroke's side of the end line (u ≥ √2/2 covers every angle)
// and 0 beyond the cap's reach (u ≤ −R or |v| ≥ R, R = h + √2/2).
// Symmetries used by the table: turning the picture by 90° about a pixel centre maps
// pixels to pixels and keeps (u, v), so only the direction modulo 90° matters; mirroring
// v → −v turns the direction θ into 90° − θ relative to the grid.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <string>

#include "canvas.h"
#include "line_clip.h"
#include "square_cdf.h"

namespace tiny3d {
namespace {

constexpr double kHalfDiagonal = 0.70710678118654752;
// Table range along u: beyond kUMax (≥ √2/2) the pixel is on the stroke's side of the end line.
constexpr double kUMax = 0.7072;
constexpr double kUStep = 1.0 / 32.0, kVStep = 1.0 / 16.0;
constexpr int kDirectionSlices = 32;
// Segments longer than this (px) are drawn by draw_line_coverage (exact). Set when the
// exact line was the faster one there; per segment at T = 1.5 the tabulated line now takes
// ≈ 140 ns + 7.6 ns/px against ≈ 530 ns + 7.5 ns/px, and is still 1.2× faster at 256 px
// with this limit lifted — but u and v are stepped in float along a row, and the error of
// longer segments has not been tested, so the limit stays.
constexpr double kExactFromLength = 64.0;
// Length of the straight part used to sample a half-infinite stroke (its far end is out
// of reach of the sampled pixel).
constexpr double kFarEnd = 64.0;

// The direction (dx, dy) folded into the first quadrant by 90° turns, as the diamond
// angle q = b / (a + b) ∈ [0, 1] of the folded (a, b).
double diamond_angle(double dx, double dy) {
    const double ax = std::fabs(dx), ay = std::fabs(dy);
    const double b = dx * dy >= 0.0 ? ay : ax;  // quadrants 1, 3: (|dx|, |dy|); 2, 4: (|dy|, |dx|)
    return b / (ax + ay);
}

// The direction slice nearest to the diamond angle q; its mirror image (v → −v) is slice
// t.slices − that.
int nearest_slice(const line_table &t, double q) { return int(std::clamp(q, 0.0, 1.0) * t.slices + 0.5); }

// Offset in table.values of direction slice s.
std::size_t slice_start(const line_table &t, int s) {
    return std::size_t(s) * (std::size_t(t.nu) + 1) * (std::size_t(t.nv) + 1);
}

// E(u, v) of one end from the direction slice nearest to the stroke's (bilinear in u, v).
class end_lookup {
public:
    end_lookup(const line_table &table, int slice)
        : values_(table.values.data() + slice_start(table, slice)),
          row_(std::size_t(table.nu) + 1),
          u_min_(table.u_min),
          inv_u_(1.0f / table.u_step),
          inv_v_(1.0f / table.v_step),
          nu_(table.nu),
          nv_(float(table.nv)) {}

    // v ≥ 0, u below the table's upper end (√2/2); 0 beyond the cap's reach.
    float operator()(float u, float v) const {
        const float fu = (u - u_min_) * inv_u_, fv = v * inv_v_;
        if (!(fu > 0.0f) || !(fv < nv_)) return 0.0f;
        const int iu = std::min(int(fu), nu_ - 1), iv = int(fv);
        const float au = fu - float(iu), av = fv - float(iv);
        const float *c = values_ + std::size_t(iv) * row_ + std::size_t(iu);
        const float bottom = c[0] + au * (c[1] - c[0]), top = c[row_] + au * (c[row_ + 1] - c[row_]);
        return bottom + av * (top - bottom);
    }

private:
    const float *values_;
    std::size_t row_;
    float u_min_, inv_u_, inv_v_;
    int nu_;
    float nv_;
};

#ifdef __SSE2__
// end_lookup for four pixels at once: lanes with v ≥ 0 read the `pos` slice, lanes with
// v < 0 its mirror image at |v|; lanes beyond the cap's reach get 0 (clamped onto the
// table's border, which is 0: line_table::make). Indices are formed
// in float (exact: a table holds < 2^24 values); SSE2 has no gather, so each lane's
// four corners are loaded as two adjacent pairs and transposed.
class end_lookup4 {
public:
    end_lookup4(const line_table &table, int pos)
        : values_(table.values.data()),
          u_min_(_mm_set1_ps(table.u_min)),
          inv_u_(_mm_set1_ps(1.0f / table.u_step)),
          inv_v_(_mm_set1_ps(1.0f / table.v_step)),
          v_cells_(_mm_set1_ps(float(table.nv))),
          u_top_(_mm_set1_ps(float(table.nu) - kBelowOne)),
          v_last_cell_(_mm_set1_ps(float(table.nv - 1))),
          row_(_mm_set1_ps(float(table.nu + 1))),
          pos_(_mm_set1_ps(float(slice_start(table, pos)))),
          neg_(_mm_set1_ps(float(slice_start(table, table.slices - pos)))),
          row_size_(table.nu + 1) {}

    [[gnu::always_inline]] __m128 operator()(__m128 u, __m128 v) const {
        const __m128 zero = _mm_setzero_ps();
        const __m128 negative = _mm_cmplt_ps(v, zero);
        const __m128 abs_v = _mm_andnot_ps(_mm_set1_ps(-0.0f), v);
        // Clamped into the table so every lane's corners are valid addresses: u below the
        // table reads its first column (u = −R), |v| beyond it its last row (v = R), both 0.
        const __m128 fu = _mm_min_ps(_mm_max_ps(_mm_mul_ps(_mm_sub_ps(u, u_min_), inv_u_), zero), u_top_);
        const __m128 fv = _mm_min_ps(_mm_mul_ps(abs_v, inv_v_), v_cells_);
        const __m128 cell_u = _mm_cvtepi32_ps(_mm_cvttps_epi32(fu));
        const __m128 cell_v = _mm_min_ps(_mm_cvtepi32_ps(_mm_cvttps_epi32(fv)), v_last_cell_);
        const __m128 au = _mm_sub_ps(fu, cell_u), av = _mm_sub_ps(fv, cell_v);
        const __m128 slice = _mm_or_ps(_mm_and_ps(negative, neg_), _mm_andnot_ps(negative, pos_));
        alignas(16) int at[4];
        _mm_store_si128(reinterpret_cast<__m128i *>(at),
                        _mm_cvttps_epi32(_mm_add_ps(slice, _mm_add_ps(_mm_mul_ps(cell_v, row_), cell_u))));
        // A cell's corners are two adjacent pairs (iu, iu + 1) on rows iv and iv + 1: two
        // 64-bit loads per lane give (c00, c10, c01, c11), transposed into one vector per corner.
        auto cell = [&](int lane) {
            const float *c = values_ + std::uint32_t(at[lane]);  // ≥ 0: no sign extension
            return _mm_loadh_pi(_mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64 *>(c)),
                                reinterpret_cast<const __m64 *>(c + row_size_));
        };
        __m128 c00 = cell(0), c10 = cell(1), c01 = cell(2), c11 = cell(3);
        _MM_TRANSPOSE4_PS(c00, c10, c01, c11);
        const __m128 bottom = _mm_add_ps(c00, _mm_mul_ps(au, _mm_sub_ps(c10, c00)));
        const __m128 top = _mm_add_ps(c01, _mm_mul_ps(au, _mm_sub_ps(c11, c01)));
        return _mm_add_ps(bottom, _mm_mul_ps(av, _mm_sub_ps(top, bottom)));
    }

private:
    const float *values_;
    // A clamped cell coordinate stays below the last cell's upper edge.
    static constexpr float kBelowOne = 0.999f;
    __m128 u_min_, inv_u_, inv_v_, v_cells_, u_top_, v_last_cell_, row_, pos_, neg_;
    std::size_t row_size_;
};
#endif

// ceil(v) as an int, v clamped to [lo, hi] first (so ±inf and huge values convert safely).
int clamped_ceil(double v, double lo, double hi) { return -detail::floor_to_int(-std::clamp(v, lo, hi)); }
int clamped_floor(double v, double lo, double hi) { return detail::floor_to_int(std::clamp(v, lo, hi)); }

}  // namespace

result<line_table> line_table::make(float thickness, line_cap cap) {
    if (!std::isfinite(thickness) || !(thickness > 0.0f) || thickness > kMaxThickness)
        return error{"", 0, -1,
                     "line_table: thickness must be finite and in (0, " + std::to_string(kMaxThickness) + "] px, got " +
                         std::to_string(thickness)};
    line_table t;
    t.thickness_ = thickness;
    t.cap_ = cap;
    const double h = 0.5 * double(thickness), reach = h + kHalfDiagonal;
    t.reach = float(reach);
    t.u_min = float(-reach);
    t.nu = int(std::ceil((kUMax + reach) / kUStep));
    t.u_step = float((kUMax + reach) / t.nu);
    t.nv = int(std::ceil(reach / kVStep));
    t.v_step = float(reach / t.nv);
    t.slices = kDirectionSlices;
    t.values.resize(std::size_t(t.slices + 1) * std::size_t(t.nv + 1) * std::size_t(t.nu + 1));
    // Sample pixel (px, px); the end is placed so that the pixel's centre sits at (u, v).
    // The first column (u = −R) and the last row of each slice (v = R) are 0 exactly: the
    // pixel is h + √2/2 from the cap or the stroke's side, so they touch at most at a point
    // (the reference gives ≤ 1e-14 there). Lookups beyond the reach clamp onto them.
    constexpr int px = 8;
    constexpr double centre = px + 0.5;
    float *out = t.values.data();
    for (int s = 0; s <= t.slices; ++s) {
        const double q = double(s) / t.slices, norm = std::hypot(1.0 - q, q);
        const double dx = (1.0 - q) / norm, dy = q / norm;  // folded direction (a, b), normal (−b, a)
        for (int iv = 0; iv <= t.nv; ++iv)
            for (int iu = 0; iu <= t.nu; ++iu) {
                if (iu == 0 || iv == t.nv) {
                    *out++ = 0.0f;
                    continue;
                }
                const double u = double(t.u_min) + iu * double(t.u_step), v = iv * double(t.v_step);
                const double ax = centre - u * dx + v * dy, ay = centre - u * dy - v * dx;
                *out++ = float(line_coverage_reference_at(px, px, ax, ay, ax + kFarEnd * dx, ay + kFarEnd * dy,
                                                          thickness, cap));
            }
    }
    return t;
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

}  // namespace

void draw_line_tabulated(canvas_t *canvas, float x0, float y0, float x1, float y1, const line_table &table,
                         float intensity) {
    if (!canvas || !canvas->data || canvas->width <= 0 || canvas->height <= 0 || table.values.empty()) return;
    if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1) ||
        !std::isfinite(intensity) || !(intensity > 0.0f))
        return;
    const float ink = std::min(intensity, 1.0f);
    const double h = 0.5 * double(table.thickness());
    // Left to right (dx ≥ 0), so u grows along a canvas row.
    if (x1 < x0 || (x1 == x0 && y1 < y0)) {
        std::swap(x0, x1);
        std::swap(y0, y1);
    }
    // Float ends: their differences and squares are finite in double.
    const double full_dx = double(x1) - x0, full_dy = double(y1) - y0;
    const double full_length = std::sqrt(full_dx * full_dx + full_dy * full_dy);
    // (1) needs L ≥ h; beyond kExactFromLength the exact line draws (see the constant).
    if (!(full_length >= h) || full_length > kExactFromLength) {
        draw_line_coverage(canvas, x0, y0, x1, y1, table.thickness(), {table.cap(), ink});
        return;
    }
    const double dx = full_dx / full_length, dy = full_dy / full_length;
    // Clip to the canvas grown by 2R + 2: a clipped end is then so far off the canvas that
    // no canvas pixel within reach of the stroke lies near it; it gets no cap.
    const double reach = table.reach, margin = 2.0 * reach + 2.0;
    const int width = canvas->width, height = canvas->height;
    detail::clipped_segment clip{x0, y0, x1, y1, false, false};
    // (x0 ≤ x1 here.) The common case, both ends in the grown canvas, needs no call.
    const double y_min = std::min(y0, y1), y_max = std::max(y0, y1);
    if (!(x0 >= -margin && x1 <= width + margin && y_min >= -margin && y_max <= height + margin) &&
        !detail::clip_segment(x0, y0, x1, y1, -margin, -margin, width + margin, height + margin, clip))
        return;
    const double ax = clip.x0, ay = clip.y0;
    const double length = std::max(0.0, (clip.x1 - ax) * dx + (clip.y1 - ay) * dy);
    const bool end_a = !clip.start_clipped, end_b = !clip.end_clipped;

    const int slice = nearest_slice(table, diamond_angle(dx, dy));
    const detail::square_cdf cdf(-dy, dx);
    const float hf = float(h), lf = float(length);
    // A pixel whose centre has u ≥ w_hi lies wholly on the stroke's side of an end line
    // (w_hi = half the pixel's extent along the stroke): E = band there, exactly.
    const float umax = cdf.w_hi;
    const float du = float(dx), dv = float(-dy);
    // Rows whose centre lies within R of the segment's y range (the stroke's full extent).
    const int row_first = clamped_ceil(std::min(ay, clip.y1) - reach - 0.5, 0.0, height);
    const int row_last = clamped_floor(std::max(ay, clip.y1) + reach - 0.5, -1.0, height - 1.0);
    // Calls draw(row, first, last, u, v) for each row's run, (u, v) the centre of pixel first.
    auto for_each_run = [&](auto &&draw) {
        const double ry = row_first + 0.5 - ay, rx = 0.5 - ax;
        row_runs runs(ax, ry, dx, dy, length, reach, width);
        row_frame uv(rx * dx + ry * dy, ry * dx - rx * dy, dx, dy);
        float *row = canvas->data + std::size_t(row_first) * std::size_t(width);
        for (int j = row_first; j <= row_last; ++j, uv.step(), row += width) {
            int first, last;
            runs.next(first, last);
            if (first > last) continue;
            float u, v;
            uv.at(first, u, v);
            draw(row, first, last, u, v);
        }
    };

#ifdef __SSE2__
    if (width >= 4) {
        const detail::band_writer body(cdf, hf, ink, dv);
        const end_lookup4 lookup4(table, slice);
        const __m128 lanes = _mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f), du4 = _mm_set1_ps(4.0f * du),
                     dv4 = _mm_set1_ps(4.0f * dv);
        const __m128 du1 = _mm_set1_ps(du), dv1 = _mm_set1_ps(dv);
        const __m128 lane_du = _mm_mul_ps(lanes, du1), lane_dv = _mm_mul_ps(lanes, dv1);
        const __m128 umax_a = _mm_set1_ps(end_a ? umax : -INFINITY), umax_b = _mm_set1_ps(end_b ? umax : -INFINITY);
        const __m128 length4 = _mm_set1_ps(lf);
        // Coverage (1) of four pixels with centres (u, v). Every pixel gets its true
        // coverage, so groups may run past a row's run (those pixels are beyond the
        // stroke's reach: 0).
        auto group = [&](__m128 u, __m128 v) __attribute__((always_inline)) {
            const __m128 band = body.band4(v);
            const __m128 near_a = _mm_cmplt_ps(u, umax_a);
            const __m128 u_b = _mm_sub_ps(length4, u);
            const __m128 near_b = _mm_cmplt_ps(u_b, umax_b);
            __m128 coverage = band;
            if (_mm_movemask_ps(_mm_or_ps(near_a, near_b))) {
                __m128 e_a = band, e_b = band;
                if (_mm_movemask_ps(near_a))
                    e_a = _mm_or_ps(_mm_and_ps(near_a, lookup4(u, v)), _mm_andnot_ps(near_a, band));
                if (_mm_movemask_ps(near_b))
                    e_b = _mm_or_ps(_mm_and_ps(near_b, lookup4(u_b, _mm_sub_ps(_mm_setzero_ps(), v))),
                                    _mm_andnot_ps(near_b, band));
                coverage = _mm_sub_ps(_mm_add_ps(e_a, e_b), band);
            }
            return coverage;
        };
        for_each_run([&](float *row, int first, int last, float u0, float v0) {
            __m128 u = _mm_add_ps(_mm_set1_ps(u0), lane_du), v = _mm_add_ps(_mm_set1_ps(v0), lane_dv);
            for (int i = first; i <= last; i += 4, u = _mm_add_ps(u, du4), v = _mm_add_ps(v, dv4)) {
                if (i + 4 <= width) {
                    body.blend4(row + i, group(u, v));
                } else {  // the row's end: the group moved back inside, its first lanes (done) untouched
                    const __m128 back = _mm_set1_ps(float(i + 4 - width));
                    const __m128 cover = group(_mm_sub_ps(u, _mm_mul_ps(back, du1)), _mm_sub_ps(v, _mm_mul_ps(back, dv1)));
                    body.blend4(row + width - 4, _mm_and_ps(_mm_cmpge_ps(lanes, back), cover));
                }
            }
        });
        return;
    }
#endif
    // Portable path (and canvases narrower than 4): one pixel at a time.
    const end_lookup lookup_pos(table, slice), lookup_neg(table, table.slices - slice);  // v ≥ 0; v < 0 (mirrored)
    for_each_run([&](float *row, int first, int last, float u, float v) {
        for (int i = first; i <= last; ++i, u += du, v += dv) {
            const float band = cdf.band(v, hf), u_b = lf - u;
            const float e_a = end_a && u < umax ? (v >= 0.0f ? lookup_pos(u, v) : lookup_neg(u, -v)) : band;
            const float e_b = end_b && u_b < umax ? (v <= 0.0f ? lookup_pos(u_b, -v) : lookup_neg(u_b, v)) : band;
            detail::combine_over(row[i], ink * (e_a + e_b - band));
        }
    });
}

}  // namespace tiny3d
