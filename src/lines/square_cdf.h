// square_cdf.h — internal: the area of a unit pixel square on one side of a line, and of
// a band between two parallel lines, and the writer that lays such band coverage along
// canvas rows (used by the coverage and the tabulated lines).
#ifndef TINY3D_SQUARE_CDF_H
#define TINY3D_SQUARE_CDF_H

#include <algorithm>
#include <cmath>

#include "../simd_config.h"

#ifdef TINY3D_SSE2
#include <emmintrin.h>
#endif

#include "line_clip.h"
#include "../canvas/splat.h"  // floor_to_int

namespace tiny3d::detail {

// Corner regions of the square-in-band area narrower than this (px) are treated as empty.
constexpr double kNarrowCorner = 1e-12;

// D = double for stroke_math.inc (the set-up arithmetic the AVX-512 tabulated kernel
// repeats on eight lanes: see there).
namespace scalar_lanes {
inline double sqrt_of(double v) { return std::sqrt(v); }
inline double abs_of(double v) { return std::fabs(v); }
inline double min_of(double a, double b) { return std::min(a, b); }
inline double max_of(double a, double b) { return std::max(a, b); }
inline double select(bool m, double if_true, double if_false) { return m ? if_true : if_false; }
inline float to_float(double v) { return float(v); }
inline int floor_to_lanes(double v) { return floor_to_int(v); }
inline int ceil_to_lanes(double v) { return -floor_to_int(-v); }
#include "stroke_math.inc"
}  // namespace scalar_lanes

// Area of a unit square (centre at offset 0) on the side {s' ≤ s} of a line with unit
// normal (a, b), as the CDF of U = a·X + b·Y, X, Y ~ U(−½, ½): a trapezoidal density.
// With amax ≥ amin the abs components, w_lo = (amax − amin)/2, w_hi = (amax + amin)/2:
//   F(s) = ½ + sign(s)·H(|s|),  H(t) = τ/amax − m²/(2·amax·amin),  τ = min(t, w_hi),
//   m = max(τ − w_lo, 0)   (linear middle part, quadratic corners, H(w_hi) = ½). Beyond
//   w_hi, H is the same float constant for every t, so the two terms of band() cancel
//   exactly for a square outside the band.
struct square_cdf {
    float w_lo = 0, w_hi = 0, inv_amax = 0, inv_2ab = 0;

    square_cdf() = default;  // all zero: no line (set before use)
    // amin ≈ 0 (axis-aligned line): the quadratic corners are narrower than kNarrowCorner
    // px and contribute nothing visible; m ≡ 0 then, and a zero factor avoids 0·inf.
    square_cdf(double a, double b) {
        const scalar_lanes::cdf_factors<float> f = scalar_lanes::square_cdf_factors(a, b);
        w_lo = f.w_lo;
        w_hi = f.w_hi;
        inv_amax = f.inv_amax;
        inv_2ab = f.inv_2ab;
    }
    // sign(s)·H(|s|) = F(s) − ½
    float centred(float s) const {
        const float t = std::min(std::fabs(s), w_hi);
        const float m = std::max(t - w_lo, 0.0f);
        const float h = t * inv_amax - m * m * inv_2ab;
        return std::copysign(h, s);
    }
    // Area of the square inside the band |s'| ≤ half_width when its centre is at u:
    // F(h − u) − F(−h − u) = (F(h − u) − ½) + (F(h + u) − ½).
    float band(float u, float half_width) const { return centred(half_width - u) + centred(half_width + u); }
};

// Combines band coverage × intensity "over" into contiguous runs of pixels (along a canvas
// row) whose signed distance u changes by du from one pixel to the next: the per-line
// constants of square_cdf, held ready (as SSE2 vectors when available).
class band_writer {
public:
    band_writer(const square_cdf &cdf, float half_width, float intensity, double du)
        : cdf_(cdf), half_(half_width), ink_(intensity), du_(du) {}

    // Pixels lo..hi (0 ≤ lo ≤ hi < row_size) of `row`, pixel lo at signed distance u_lo.
    // Pixels of the row beyond lo..hi are never touched.
    void run(float *row, [[maybe_unused]] int row_size, int lo, int hi, double u_lo) const {
#ifdef TINY3D_SSE2
        // Groups of four, the last one moved back inside the row if needed; lanes outside
        // the pixels not yet drawn get coverage 0, and v + 0·(1 − v) leaves them unchanged.
        if (row_size >= 4) {
            const __m128 last = _mm_set1_ps(float(hi));
            for (int i = lo; i <= hi; i += 4) {
                const int start = std::min(i, row_size - 4);
                const __m128 index = _mm_add_ps(_mm_set1_ps(float(start)), lanes_);
                const __m128 keep = _mm_and_ps(_mm_cmpge_ps(index, _mm_set1_ps(float(i))), _mm_cmple_ps(index, last));
                const __m128 u = _mm_add_ps(_mm_set1_ps(float(u_lo + double(start - lo) * du_)), lane_du_);
                blend4(row + start, _mm_and_ps(keep, band4(u)));
            }
            return;
        }
#endif
        for (int i = lo; i <= hi; ++i)
            combine_over(row[i], ink_ * cdf_.band(float(u_lo + double(i - lo) * du_), half_));
    }

    // 4·groups pixels from p, the first at signed distance u, all of them inside the row
    // and free to draw: pixels beyond the band get coverage exactly 0 (both CDF terms
    // saturate at the same value), so a fixed window needs no masks.
    void window(float *p, float u, int groups) const {
#ifdef TINY3D_SSE2
        __m128 uv = _mm_add_ps(_mm_set1_ps(u), lane_du_);
        for (int g = 0; g < groups; ++g, p += 4, uv = _mm_add_ps(uv, du4_)) blend4(p, band4(uv));
#else
        for (int k = 0; k < 4 * groups; ++k)
            combine_over(p[k], ink_ * cdf_.band(float(u + float(k) * float(du_)), half_));
#endif
    }

#ifdef TINY3D_SSE2
    // Band coverage of four pixels with signed distances u (square_cdf::band).
    // Four pixels at p with coverages cov: "over" with c = intensity · coverage clamped to
    // 0..1 (the two band terms can sum to 1 + 1 ulp, or −1 ulp where they nearly cancel;
    // unclamped, overlapping strokes reach 1.0000001 and an empty canvas −3e-8).
    // band(u) = c(h − u) + c(h + u), c odd, so band depends on |u| only; when h ≥ w_hi
    // (T ≥ √2 at any angle) c(h + |u|) is the saturated constant H(w_hi).
    __m128 band4(__m128 u) const {
        const __m128 a = _mm_andnot_ps(sign_bit_, u);
        if (wide_) return _mm_add_ps(centred4(_mm_sub_ps(hw_, a)), saturated_);
        return _mm_add_ps(centred4(_mm_sub_ps(hw_, a)), centred4(_mm_add_ps(hw_, a)));
    }
    void blend4(float *p, __m128 cov) const {
        const __m128 c = _mm_max_ps(_mm_min_ps(_mm_mul_ps(ink4_, cov), one_), _mm_setzero_ps());
        const __m128 old = _mm_loadu_ps(p);
        _mm_storeu_ps(p, _mm_add_ps(old, _mm_mul_ps(c, _mm_sub_ps(one_, old))));
    }
    // square_cdf::centred for four values at once.
    __m128 centred4(__m128 s) const {
        const __m128 t = _mm_min_ps(_mm_andnot_ps(sign_bit_, s), w_hi_);
        const __m128 m = _mm_max_ps(_mm_sub_ps(t, w_lo_), _mm_setzero_ps());
        const __m128 h = _mm_sub_ps(_mm_mul_ps(t, inv_amax_), _mm_mul_ps(_mm_mul_ps(m, m), inv_2ab_));
        return _mm_or_ps(h, _mm_and_ps(sign_bit_, s));  // H ≥ 0: s's sign
    }
#endif

private:
    const square_cdf &cdf_;
    float half_, ink_;
    double du_;
#ifdef TINY3D_SSE2
    const __m128 sign_bit_ = _mm_set1_ps(-0.0f), w_lo_ = _mm_set1_ps(cdf_.w_lo), w_hi_ = _mm_set1_ps(cdf_.w_hi);
    const __m128 inv_amax_ = _mm_set1_ps(cdf_.inv_amax);
    const __m128 inv_2ab_ = _mm_set1_ps(cdf_.inv_2ab), hw_ = _mm_set1_ps(half_), ink4_ = _mm_set1_ps(ink_);
    const bool wide_ = half_ >= cdf_.w_hi;
    const __m128 saturated_ = centred4(_mm_set1_ps(cdf_.w_hi));
    const __m128 one_ = _mm_set1_ps(1.0f), lanes_ = _mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f);
    const __m128 lane_du_ = _mm_mul_ps(_mm_set1_ps(float(du_)), lanes_), du4_ = _mm_set1_ps(4.0f * float(du_));
#endif
};

}  // namespace tiny3d::detail

#endif
