// line_coverage.cpp — the exact-coverage thick line (fast), its double-precision reference
// and a supersampled variant for the benchmark.
//
// The stroke of segment A→B with half-width h is  rectangle ∪ (round caps: two half-discs).
// In the line's frame (u across, v along, origin A) the rectangle is |u| ≤ h, 0 ≤ v ≤ L.
// A pixel whose square lies inside 0 ≤ v ≤ L sees only the band |u| ≤ h, and the area of
// a unit square inside a band depends only on the angle and the centre's u (closed form
// below). The few pixels whose square crosses v = 0 or v = L are clipped exactly.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>
#include <vector>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "canvas.h"
#include "coverage_geometry.h"
#include "line_clip.h"
#include "stroke_outline.h"

namespace tiny3d {
namespace {

using detail::clip_half_plane;
using detail::point2;
using detail::polygon_disc_area;
using detail::signed_area;
using detail::small_polygon;

// Below this length (px) a segment is a point: its direction is taken as +x.
constexpr double kPointLength = 1e-9;
// Half the diagonal of a unit pixel: no point of a pixel is farther than this from its centre.
constexpr double kHalfDiagonal = 0.70710678118654752;
// Corner regions of the square-in-band area narrower than this (px) are treated as empty.
constexpr double kNarrowCorner = 1e-12;
// Margin (px) beyond the stroke's reach when clipping, so clipped ends stay off the canvas.
constexpr double kClipSlack = 2.0;

// Area of a unit square (centre at offset 0) on the side {s' ≤ s} of a line with unit
// normal (a, b), as the CDF of U = a·X + b·Y, X, Y ~ U(−½, ½): a trapezoidal density.
// With amax ≥ amin the abs components, w_lo = (amax − amin)/2, w_hi = (amax + amin)/2:
//   F(s) = ½ + sign(s)·H(|s|),  H(t) = min(t, w_lo)/amax + m(2·amin − m)/(2·amax·amin),
//   m = clamp(t − w_lo, 0, amin)   (linear middle part, quadratic corners, H(w_hi) = ½).
struct square_cdf {
    float w_lo, w_hi, inv_amax, amin, inv_2ab;

    square_cdf(double a, double b) {
        const double amax = std::max(std::fabs(a), std::fabs(b));
        const double amin_d = std::min(std::fabs(a), std::fabs(b));
        w_lo = float((amax - amin_d) / 2);
        w_hi = float((amax + amin_d) / 2);
        inv_amax = float(1.0 / amax);
        amin = float(amin_d);
        // amin ≈ 0 (axis-aligned line): the quadratic corners are narrower than kNarrowCorner
        // px and contribute nothing visible; m ≡ 0 then, and a zero factor avoids 0·inf.
        inv_2ab = amin_d > kNarrowCorner ? float(1.0 / (2.0 * amax * amin_d)) : 0.0f;
        if (!(amin_d > kNarrowCorner)) amin = 0.0f;
    }
    // sign(s)·H(|s|) = F(s) − ½
    float centred(float s) const {
        const float t = std::fabs(s);
        const float m = std::clamp(t - w_lo, 0.0f, amin);
        const float h = std::min(t, w_lo) * inv_amax + m * (2.0f * amin - m) * inv_2ab;
        return std::copysign(h, s);
    }
    // Area of the square inside the band |s'| ≤ half_width when its centre is at u:
    // F(h − u) − F(−h − u) = (F(h − u) − ½) + (F(h + u) − ½).
    float band(float u, float half_width) const { return centred(half_width - u) + centred(half_width + u); }
};

// Combines band coverage × intensity "over" into runs of pixels down a column: the
// per-line constants of square_cdf, held ready (as SSE2 vectors when available).
class band_writer {
public:
    band_writer(const square_cdf &cdf, float half_width, float intensity, float du, std::ptrdiff_t stride,
                int column_size)
        : cdf_(cdf), half_(half_width), ink_(intensity), du_(du), stride_(stride), column_size_(column_size) {}

    // `count` pixels from `first` (a row index within the column starting at `column`),
    // the first at signed distance u, each next one du further.
    void run(float *column, int first, int count, float u) const {
#ifdef __SSE2__
        // Whole groups of four: pad the run at its end (or, at the column's end, at its
        // start). Padded pixels lie outside the band, where the coverage is exactly 0 and
        // v + 0·(1 − v) leaves them bit-for-bit unchanged.
        const int padded = (count + 3) & ~3;
        if (padded <= column_size_) {
            const int shift = std::max(0, first + padded - column_size_);
            first -= shift;
            u -= float(shift) * du_;
            float *p = column + first * stride_;
            __m128 uv = _mm_add_ps(_mm_set1_ps(u), steps_);
            for (int j = 0; j < padded; j += 4, p += 4 * stride_, uv = _mm_add_ps(uv, du4_)) {
                const __m128 cov = _mm_add_ps(centred4(_mm_sub_ps(hw_, uv)), centred4(_mm_add_ps(hw_, uv)));
                const __m128 old = stride_ == 1 ? _mm_loadu_ps(p) : _mm_set_ps(p[3 * stride_], p[2 * stride_], p[stride_], p[0]);
                // "over": v + c·(1 − v), c = min(intensity · coverage, 1) (the two band
                // terms can sum to 1 + 1 ulp; unclamped, overlapping strokes reach 1.0000001)
                alignas(16) float v[4];
                const __m128 c = _mm_min_ps(_mm_mul_ps(ink4_, cov), one_);
                _mm_store_ps(v, _mm_add_ps(old, _mm_mul_ps(c, _mm_sub_ps(one_, old))));
                if (stride_ == 1) {
                    _mm_storeu_ps(p, _mm_load_ps(v));
                } else {
                    p[0] = v[0];
                    p[stride_] = v[1];
                    p[2 * stride_] = v[2];
                    p[3 * stride_] = v[3];
                }
            }
            return;
        }
#endif
        float *p = column + first * stride_;
        for (int j = 0; j < count; ++j, u += du_, p += stride_) detail::combine_over(*p, ink_ * cdf_.band(u, half_));
    }

private:
#ifdef __SSE2__
    // square_cdf::centred for four values at once.
    __m128 centred4(__m128 s) const {
        const __m128 t = _mm_andnot_ps(sign_bit_, s);
        const __m128 m = _mm_min_ps(_mm_max_ps(_mm_sub_ps(t, w_lo_), _mm_setzero_ps()), amin_);
        const __m128 lin = _mm_mul_ps(_mm_min_ps(t, w_lo_), inv_amax_);
        const __m128 quad = _mm_mul_ps(_mm_mul_ps(m, _mm_sub_ps(two_amin_, m)), inv_2ab_);
        return _mm_or_ps(_mm_add_ps(lin, quad), _mm_and_ps(sign_bit_, s));  // H ≥ 0: s's sign
    }
#endif
    const square_cdf &cdf_;
    float half_, ink_, du_;
    std::ptrdiff_t stride_;
    int column_size_;
#ifdef __SSE2__
    const __m128 sign_bit_ = _mm_set1_ps(-0.0f), w_lo_ = _mm_set1_ps(cdf_.w_lo), amin_ = _mm_set1_ps(cdf_.amin);
    const __m128 two_amin_ = _mm_set1_ps(2.0f * cdf_.amin), inv_amax_ = _mm_set1_ps(cdf_.inv_amax);
    const __m128 inv_2ab_ = _mm_set1_ps(cdf_.inv_2ab), hw_ = _mm_set1_ps(half_), ink4_ = _mm_set1_ps(ink_);
    const __m128 one_ = _mm_set1_ps(1.0f), du4_ = _mm_set1_ps(4.0f * du_);
    const __m128 steps_ = _mm_mul_ps(_mm_set1_ps(du_), _mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f));
#endif
};

// The stroke in a local frame: origin A, unit direction (dx, dy), normal (−dy, dx),
// length L, half-width h; round caps at A and/or B.
template <class T>
struct stroke_frame {
    T dx, dy, length, half;
    bool cap_a, cap_b;

    // Exact area of the convex polygon `sq` (coordinates relative to A) inside the stroke:
    // the rectangle's four half-planes, then each cap's disc beyond its end. The plain
    // form, used by the reference.
    T area(const small_polygon<T> &sq) const {
        const T nx = -dy, ny = dx;
        small_polygon<T> body = clip_half_plane(sq, nx, ny, half);
        body = clip_half_plane(body, -nx, -ny, half);
        body = clip_half_plane(body, -dx, -dy, T(0));
        body = clip_half_plane(body, dx, dy, length);
        T total = std::fabs(signed_area(body));
        if (cap_a) total += polygon_disc_area(clip_half_plane(sq, dx, dy, T(0)), T(0), T(0), half);
        if (cap_b)
            total += polygon_disc_area(clip_half_plane(sq, -dx, -dy, -length), dx * length, dy * length, half);
        return total;
    }

    static small_polygon<T> square(T x, T y) {
        small_polygon<T> sq;
        sq.n = 4;
        sq.v[0] = {x, y};
        sq.v[1] = {x + 1, y};
        sq.v[2] = {x + 1, y + 1};
        sq.v[3] = {x, y + 1};
        return sq;
    }

};

// Direction, length and normal of a segment, with a point treated as direction +x.
struct segment_axes {
    double dx = 1.0, dy = 0.0, length = 0.0;
    segment_axes(double x0, double y0, double x1, double y1) {
        const double len = std::hypot(x1 - x0, y1 - y0);
        if (len > kPointLength && std::isfinite(len)) {
            dx = (x1 - x0) / len;
            dy = (y1 - y0) / len;
            length = len;
        }
    }
};

bool finite_all(std::initializer_list<double> values) {
    for (double v : values)
        if (!std::isfinite(v)) return false;
    return true;
}

// Pixel cells [first, last] of a row of `size` that the open span (lo, hi) (px) touches,
// clamped to the row; first > last when none. (Clamping first keeps the int conversions
// in range and lets truncation stand in for floor.)
std::pair<int, int> touched_cells(double lo, double hi, int size) {
    lo = std::max(lo, 0.0);
    hi = std::min(hi, double(size));
    if (!(lo < hi)) return {0, -1};
    const int first = int(lo);
    int end = int(hi);
    if (double(end) < hi) ++end;  // ceil(hi)
    return {first, end - 1};
}

// A cell index (a floor or ceil already taken) clamped to [−1, size]: safe to convert.
int clamp_cell(double cell, int size) { return int(std::clamp(cell, -1.0, double(size))); }

}  // namespace

void draw_line_coverage(canvas_t *canvas, float x0, float y0, float x1, float y1, float thickness,
                        const line_style &style) {
    if (!canvas || !finite_all({x0, y0, x1, y1, thickness, style.intensity}) || !(thickness > 0.0f) ||
        !(style.intensity > 0.0f))
        return;
    const float intensity = std::min(style.intensity, 1.0f);
    const bool round = style.cap == line_cap::round;
    const double h = 0.5 * double(thickness);

    // Work in (major, minor) coordinates: the major axis is the one the line advances
    // along faster, so every major column holds a short run of pixels. One code path.
    const bool steep = std::fabs(double(y1) - y0) > std::fabs(double(x1) - x0);
    double ax = steep ? y0 : x0, ay = steep ? x0 : y0, bx = steep ? y1 : x1, by = steep ? x1 : y1;
    // Canonical endpoint order, so drawing B→A is bit-identical to A→B.
    if (bx < ax || (bx == ax && by < ay)) {
        std::swap(ax, bx);
        std::swap(ay, by);
    }
    const int major_size = steep ? canvas->height : canvas->width;
    const int minor_size = steep ? canvas->width : canvas->height;
    const std::ptrdiff_t major_stride = steep ? canvas->width : 1;
    const std::ptrdiff_t minor_stride = steep ? 1 : canvas->width;

    // Clip to the canvas grown by the stroke's reach: a clipped end lies ≥ kClipSlack px
    // off the canvas, so its (dropped) cap cannot touch a canvas pixel.
    const segment_axes axes(ax, ay, bx, by);
    const double margin = h + kClipSlack;
    detail::clipped_segment clip;
    if (!detail::clip_segment(ax, ay, bx, by, -margin, -margin, major_size + margin, minor_size + margin, clip))
        return;
    const double cax = clip.x0, cay = clip.y0;
    const double length = (clip.start_clipped || clip.end_clipped)
                              ? std::max(0.0, (clip.x1 - cax) * axes.dx + (clip.y1 - cay) * axes.dy)
                              : axes.length;
    const bool round_a = round && !clip.start_clipped, round_b = round && !clip.end_clipped;
    const detail::stroke_outline outline(axes.dx, axes.dy, length, h, round_a, round_b);

    // Columns of the major axis: near each end (where the stroke's X extent begins, up to
    // where the end line v = 0 or v = L stops: ±h·|dy| around the end's X) every pixel is
    // computed from the outline; between them each column crosses only the band |u| ≤ h,
    // whose closed form is exact there.
    const double end_halo = h * std::fabs(axes.dy);
    const double bx_local = length * axes.dx;
    const int first_col = clamp_cell(std::floor(cax + outline.x_min), major_size);
    const int last_col = clamp_cell(std::ceil(cax + outline.x_max) - 1.0, major_size);
    int end_a_last = clamp_cell(std::ceil(cax + end_halo) - 1.0, major_size);
    int end_b_first = clamp_cell(std::floor(cax + bx_local - end_halo), major_size);
    if (end_b_first <= end_a_last + 1) {  // short: the ends' columns meet
        end_a_last = last_col;
        end_b_first = last_col + 1;
    }
    float *const data = canvas->data;
    auto end_columns = [&](int from, int to) {
        for (int i = std::max(from, 0); i <= std::min(to, major_size - 1); ++i)
            detail::draw_outline_column(outline, i - cax, cay, data + i * major_stride, minor_stride, minor_size,
                                        intensity);
    };
    end_columns(first_col, end_a_last);
    end_columns(end_b_first, last_col);

    const double nx = -axes.dy, ny = axes.dx;  // unit normal; axes.dx ≥ |axes.dy|
    const square_cdf cdf(nx, ny);
    const float hf = float(h);
    const float du = float(ny);  // change of u per minor step
    // Per column, the minor span of the band: |minor − centreline| ≤ h / axes.dx over the column.
    const double slope = axes.dy / axes.dx, band_half = h / axes.dx;
    const double span_lo = std::min(0.0, slope) - band_half, span_hi = std::max(0.0, slope) + band_half;
    const band_writer writer(cdf, hf, intensity, du, minor_stride, minor_size);
    for (int i = std::max(end_a_last + 1, 0); i < std::min(end_b_first, major_size); ++i) {
        const double y_left = cay + (i - cax) * slope;
        const auto [row_first, row_last] = touched_cells(y_left + span_lo, y_left + span_hi, minor_size);
        if (row_first > row_last) continue;
        const double rx = i + 0.5 - cax, ry = row_first + 0.5 - cay;
        writer.run(data + i * major_stride, row_first, row_last - row_first + 1, float(rx * nx + ry * ny));
    }
}

namespace {

// Distance from (px, py) to the stroke's centre segment, in the frame of `axes` from (x0, y0).
double distance_to_segment(double px, double py, double x0, double y0, const segment_axes &axes) {
    const double rx = px - x0, ry = py - y0;
    const double v = std::clamp(rx * axes.dx + ry * axes.dy, 0.0, axes.length);
    return std::hypot(rx - v * axes.dx, ry - v * axes.dy);
}

// Is the offset (rx, ry) from the first endpoint inside the stroke?
bool inside_stroke(double rx, double ry, const segment_axes &axes, double h, line_cap cap) {
    const double v = rx * axes.dx + ry * axes.dy;
    const double u = ry * axes.dx - rx * axes.dy;
    if (cap == line_cap::butt) return std::fabs(u) <= h && v >= 0.0 && v <= axes.length;
    const double vc = std::clamp(v, 0.0, axes.length);
    const double ex = rx - vc * axes.dx, ey = ry - vc * axes.dy;
    return ex * ex + ey * ey <= h * h;
}

// Calls visit(x, y) for the canvas pixels whose centre is within h + half a diagonal of
// the segment: a superset of the pixels the stroke touches (round or butt caps).
template <class Visit>
void for_pixels_near_stroke(int width, int height, double x0, double y0, double x1, double y1, double h,
                            Visit &&visit) {
    const segment_axes axes(x0, y0, x1, y1);
    const double reach = h + kHalfDiagonal;
    detail::clipped_segment clip;
    if (!detail::clip_segment(x0, y0, x1, y1, -reach, -reach, width + reach, height + reach, clip)) return;
    const double ax = clip.x0, ay = clip.y0, bx = clip.x1, by = clip.y1;
    // Distances to the clipped part, measured from its start (small numbers even for far
    // ends); a canvas pixel's nearest point never lies on the part clipped away.
    segment_axes near = axes;
    if (clip.start_clipped || clip.end_clipped) near.length = std::max(0.0, (bx - ax) * axes.dx + (by - ay) * axes.dy);
    const auto [xa, xb] = touched_cells(std::min(ax, bx) - reach, std::max(ax, bx) + reach, width);
    const auto [ya, yb] = touched_cells(std::min(ay, by) - reach, std::max(ay, by) + reach, height);
    for (int y = ya; y <= yb; ++y)
        for (int x = xa; x <= xb; ++x)
            if (distance_to_segment(x + 0.5, y + 0.5, ax, ay, near) <= reach) visit(x, y);
}

bool reference_inputs_ok(double x0, double y0, double x1, double y1, double thickness) {
    return finite_all({x0, y0, x1, y1, thickness}) && thickness > 0.0;
}

}  // namespace

double line_coverage_reference_at(int px, int py, double x0, double y0, double x1, double y1, double thickness,
                                  line_cap cap) {
    if (!reference_inputs_ok(x0, y0, x1, y1, thickness)) return 0.0;
    const segment_axes axes(x0, y0, x1, y1);
    const double h = 0.5 * thickness;
    // Only the part of the segment near this pixel matters: clip it to the pixel grown by
    // the stroke's reach, and measure from the clipped start, so coordinates stay small
    // (exact even for ends at ±1e300). A clipped end is ≥ kClipSlack px away: its cap
    // cannot reach the pixel.
    const double margin = h + kClipSlack;
    detail::clipped_segment clip;
    if (!detail::clip_segment(x0, y0, x1, y1, px - margin, py - margin, px + 1 + margin, py + 1 + margin, clip))
        return 0.0;
    const double length = (clip.start_clipped || clip.end_clipped)
                              ? std::max(0.0, (clip.x1 - clip.x0) * axes.dx + (clip.y1 - clip.y0) * axes.dy)
                              : axes.length;
    const bool round = cap == line_cap::round;
    const stroke_frame<double> frame{axes.dx, axes.dy, length, h, round && !clip.start_clipped,
                                     round && !clip.end_clipped};
    return std::min(frame.area(stroke_frame<double>::square(px - clip.x0, py - clip.y0)), 1.0);
}

void line_coverage_reference(std::vector<double> &coverage, int width, int height, double x0, double y0,
                             double x1, double y1, double thickness, line_cap cap) {
    coverage.assign(std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0)), 0.0);
    if (width <= 0 || height <= 0 || !reference_inputs_ok(x0, y0, x1, y1, thickness)) return;
    for_pixels_near_stroke(width, height, x0, y0, x1, y1, 0.5 * thickness, [&](int x, int y) {
        coverage[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
            line_coverage_reference_at(x, y, x0, y0, x1, y1, thickness, cap);
    });
}

void draw_line_supersampled(canvas_t *canvas, float x0, float y0, float x1, float y1, float thickness,
                            int samples_per_axis, const line_style &style) {
    if (!canvas || !reference_inputs_ok(x0, y0, x1, y1, thickness) || samples_per_axis < 1 ||
        !std::isfinite(style.intensity) || !(style.intensity > 0.0f))
        return;
    const float intensity = std::min(style.intensity, 1.0f);
    const segment_axes axes(x0, y0, x1, y1);
    const double h = 0.5 * double(thickness);
    const double step = 1.0 / samples_per_axis;
    const double weight = step * step;
    for_pixels_near_stroke(canvas->width, canvas->height, x0, y0, x1, y1, h, [&](int x, int y) {
        int hits = 0;
        for (int sy = 0; sy < samples_per_axis; ++sy)
            for (int sx = 0; sx < samples_per_axis; ++sx)
                hits += inside_stroke(x + (sx + 0.5) * step - x0, y + (sy + 0.5) * step - y0, axes, h, style.cap);
        if (hits) detail::combine_over(canvas->pixels[y][x], float(intensity * hits * weight));
    });
}

}  // namespace tiny3d
