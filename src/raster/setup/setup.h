// setup.h — the set-up stage (internal). In: a triangle's screen vertices (or their snapped
// sub-pixel coordinates from the vertex stage). Out: the snapped, culled triangle as edge
// equations and attribute planes — fast_triangle for the 1-sample fill, triangle_edges for
// the 64-bit one (msaa/msaa.h has the multisampled form) — one at a time
// (setup/triangle_setup.cpp) or eight at a time (setup_fast_batch: setup_batch.inc over
// the lane traits of the table's setup_batch_avx2/avx512.cpp). Called by the render
// context's set-up loop (schedule/raster_context.cpp) and the public fill_triangle
// (fill/raster_fill.cpp).
// Also the depth tests every stage shares. Not installed.
#ifndef TINY3D_RASTER_SETUP_H
#define TINY3D_RASTER_SETUP_H

#include <algorithm>
#include <cstdint>
#include <type_traits>

#include "raster.h"
#include "../../kernels.h"
#include "../../pipeline/screen_snap.h"
#include "../../simd_config.h"

#ifdef TINY3D_SSE2
#include <emmintrin.h>
#endif

namespace tiny3d::detail {

// Snapping is the vertex stage's (pipeline/screen_snap.h: snap_screen_point): the set-up
// snaps through it, to 1/16 px (RASTER_SUBPIXEL_BITS) everywhere but the 16-sample frames,
// whose vertices are snapped finer (MSAA_16_SUBPIXEL_BITS, msaa.h).
static_assert(RASTER_MAX_COORD == SNAP_MAX_COORD);

// floor(n / d) for d > 0 (C++ division truncates towards zero); −n + d − 1 must not overflow.
template <class Int>
inline Int floor_div(Int n, Int d) {
    return n >= 0 ? n / d : -((-n + d - 1) / d);
}

// Pixels p (one axis) whose centre 2^bits·p + 2^bits/2 plus an offset in [lo_off, hi_off]
// (sample offsets; 0 for pixel centres) meets [lo, hi] (sub-pixel units; >> is floor
// division, defined in C++20), clamped to [clip0, clip1). True when the clamp cut that range.
inline bool axis_bounds(std::int64_t lo, std::int64_t hi, int lo_off, int hi_off, int bits, int clip0, int clip1,
                        int &first, int &last) {
    const std::int64_t half = std::int64_t{1} << (bits - 1);
    const std::int64_t from = -((half + hi_off - lo) >> bits), to = (hi - half - lo_off) >> bits;
    first = static_cast<int>(std::max<std::int64_t>(from, clip0));
    last = static_cast<int>(std::min<std::int64_t>(to, clip1 - 1));
    return from < clip0 || to >= clip1;
}

// The snapped vertex box (sub-pixel units).
struct snapped_box {
    std::int64_t min_X, max_X, min_Y, max_Y;
    static snapped_box of(const std::int32_t X[3], const std::int32_t Y[3]) {
        return {std::min({X[0], X[1], X[2]}), std::max({X[0], X[1], X[2]}), std::min({Y[0], Y[1], Y[2]}),
                std::max({Y[0], Y[1], Y[2]})};
    }
};

// Twice the signed area of a snapped triangle, in sub-pixel units²: negative = front facing
// (counter-clockwise in NDC, clockwise on the y-down screen), 0 = degenerate.
inline std::int64_t snapped_area2(const std::int32_t X[3], const std::int32_t Y[3]) {
    return (static_cast<std::int64_t>(X[1]) - X[0]) * (static_cast<std::int64_t>(Y[2]) - Y[0]) -
           (static_cast<std::int64_t>(Y[1]) - Y[0]) * (static_cast<std::int64_t>(X[2]) - X[0]);
}

// Whether `cull` removes a triangle of nonzero signed area area2 (snapped_area2, or the
// reference renderer's in double).
template <class Area>
inline bool facing_culled(Area area2, cull_mode cull) {
    const bool front_facing = area2 < 0;
    return (cull == cull_mode::back && !front_facing) || (cull == cull_mode::front && front_facing);
}

// Edge k of a snapped triangle is the edge opposite vertex k, from vertex a = k + 1 to
// b = k − 1 (mod 3), oriented by s = sign(snapped_area2) so that the inside is positive:
//   E(P) = dx·(Py − ya) − dy·(Px − xa) − (top_left_edge(dx, dy) ? 0 : 1)   (sub-pixel units),
// dx = s·(xb − xa), dy = s·(yb − ya). Every triangle setup uses this ONE top-left fill rule
// (raster.h): bias 0 on a top edge (dy = 0, dx > 0) or a left edge (dy < 0), else 1, so
// that a pixel centre exactly on a right or bottom edge falls outside and "inside" is
// E ≥ 0 for every edge.
inline bool top_left_edge(std::int64_t dx, std::int64_t dy) { return dy < 0 || (dy == 0 && dx > 0); }

// Edge k of the snapped triangle (X, Y) by the rule above, oriented by s: its dx, dy and
// its value E at the sub-pixel point (px, py). Every triangle setup computes its edges here.
struct snapped_edge {
    std::int64_t dx, dy, e;
};
inline snapped_edge snapped_edge_at(const std::int32_t X[3], const std::int32_t Y[3], std::int64_t s, int k,
                                    std::int64_t px, std::int64_t py) {
    const int ia = k == 2 ? 0 : k + 1, ib = k == 0 ? 2 : k - 1;  // edge opposite vertex k
    const std::int64_t dx = s * (static_cast<std::int64_t>(X[ib]) - X[ia]);
    const std::int64_t dy = s * (static_cast<std::int64_t>(Y[ib]) - Y[ia]);
    return {dx, dy, dx * (py - Y[ia]) - dy * (px - X[ia]) - (top_left_edge(dx, dy) ? 0 : 1)};
}

// The snapped vertices in pixels (exact: multiples of 1/2^bits).
inline void snapped_to_px(const std::int32_t X[3], const std::int32_t Y[3], double x[3], double y[3],
                          int bits = RASTER_SUBPIXEL_BITS) {
    const double step = 1.0 / static_cast<double>(1 << bits);  // exact: a power of two
    for (int k = 0; k < 3; ++k) {
        x[k] = static_cast<double>(X[k]) * step;
        y[k] = static_cast<double>(Y[k]) * step;
    }
}

// triangle_setup on already snapped, usable vertices (sub-pixel units): same result. With
// bits other than RASTER_SUBPIXEL_BITS (the 16-sample frames' finer grid) every sub-pixel
// quantity of the result (a, b, c, area2, span) is in 1/2^bits px instead of 1/16;
// |X|, |Y| < 2^29 so that no edge value overflows.
triangle_edges triangle_setup_snapped(const std::int32_t X[3], const std::int32_t Y[3], pixel_rect clip,
                                      cull_mode cull, int bits = RASTER_SUBPIXEL_BITS);

// The span fill's precision argument (fast_triangle) holds when the snapped vertex
// bounding box spans less than this many sub-pixel units per axis: then every edge value
// inside the box has |E| ≤ |dX|·|Py − Ya| + |dY|·|Px − Xa| < 2 · (2^15)^2 = 2^31 and
// |a| = 16·|dY| < 2^19.
// On a grid of 1/2^bits px the same bound holds below span_limit(bits).
inline constexpr std::int64_t span_limit(int bits) { return (1 << 15) - 8 * (1 << bits); }
inline constexpr std::int64_t FAST_SPAN_LIMIT = span_limit(RASTER_SUBPIXEL_BITS);

// One triangle ready for the span fill. Row min_y + dy covers exactly the columns
// min_x + [ceil(max(L0, L1)), floor(min(R0, R1))], where Lj = cross + step·dy is where a
// left edge (E growing with x) crosses zero, relative to min_x, and Rj the same for a right
// edge; they are stored as the pairs (L0, −R0) and (L1, −R1), so that one max gives both
// ends (an absent edge is −∞). Rows cut by a horizontal edge are already removed from
// [min_y, max_y]. Why this equals the integer test E ≥ 0 exactly: the true crossing −E/a is
// a fraction with |a| < 2^19, so a non-integer one is at least 2^-19 from any integer,
// while the double evaluation errs by < 2^-24 (|values| < 2^28); rounding with a bias
// CROSS_EPS between the two decides every pixel as the integers do.
// Attribute values at the centre of pixel (min_x, min_y) with per-pixel steps.
// Band-independent: a band only chooses which rows to draw, so any thread count gives the
// same pixels. Aligned to 16 bytes (its size is seven 16-byte blocks), so that
// streamed_triangles can store it in 16-byte streaming stores.
struct alignas(16) fast_triangle {
    int min_x, max_x, min_y, max_y;  // inclusive pixel bounds, clamped to the target
    double cross[4], cross_step[4];  // (L0, −R0, L1, −R1) at dy = 0 and per row
    float z, zdx, zdy;               // window depth plane
    float i, idx, idy;               // intensity plane
    std::int32_t wide;               // ≥ 0: index of the 64-bit edges in the wide list
};

inline constexpr double CROSS_EPS = 1.0 / (1 << 21);

// The covered columns [lo, hi] of each row of a fast-path triangle (wide < 0), relative to
// min_x (empty when lo > hi): u = max((L0, −R0), (L1, −R1)) − CROSS_EPS gives
// lo = ceil(u0) and hi = −ceil(u1); u is first clamped to lo ∈ [0, w + 1], hi ∈ [−1, w]
// (ceil commutes with the clamp), then ceil(v) = K − trunc(K − v) on a positive K − v.
class row_spans {
public:
#ifdef TINY3D_SSE2
    explicit row_spans(const fast_triangle &f)
        : a_(_mm_loadu_pd(f.cross)), a_step_(_mm_loadu_pd(f.cross_step)), b_(_mm_loadu_pd(f.cross + 2)),
          b_step_(_mm_loadu_pd(f.cross_step + 2)),
          low_(_mm_setr_pd(-0.5, -(f.max_x - f.min_x) - 0.5)), high_(_mm_setr_pd(f.max_x - f.min_x + 0.5, 0.5)) {}
    void at(int dy, int &lo, int &hi) const {
        const __m128d d = _mm_set1_pd(dy);
        const __m128d a = _mm_add_pd(a_, _mm_mul_pd(a_step_, d)), b = _mm_add_pd(b_, _mm_mul_pd(b_step_, d));
        const __m128d u = _mm_min_pd(_mm_max_pd(_mm_sub_pd(_mm_max_pd(a, b), _mm_set1_pd(CROSS_EPS)), low_), high_);
        const __m128i t = _mm_cvttpd_epi32(_mm_sub_pd(_mm_set1_pd(K), u));
        lo = static_cast<int>(K) - _mm_cvtsi128_si32(t);
        hi = _mm_cvtsi128_si32(_mm_srli_si128(t, 4)) - static_cast<int>(K);
    }

private:
    __m128d a_, a_step_, b_, b_step_, low_, high_;
#else
    explicit row_spans(const fast_triangle &f) : f_(f), w_(f.max_x - f.min_x) {}
    void at(int dy, int &lo, int &hi) const {
        const double d = dy;
        const double u0 = std::max(f_.cross[0] + f_.cross_step[0] * d, f_.cross[2] + f_.cross_step[2] * d) - CROSS_EPS;
        const double u1 = std::max(f_.cross[1] + f_.cross_step[1] * d, f_.cross[3] + f_.cross_step[3] * d) - CROSS_EPS;
        lo = static_cast<int>(K) - static_cast<int>(K - std::min(std::max(u0, -0.5), w_ + 0.5));
        hi = static_cast<int>(K - std::min(std::max(u1, -w_ - 0.5), 0.5)) - static_cast<int>(K);
    }

private:
    const fast_triangle &f_;
    double w_;
#endif
    static constexpr double K = 1 << 20;
};

#ifdef TINY3D_SSE2
// A narrow triangle's depth and intensity in groups of four columns from min_x, as the SSE2
// narrow kernel forms them and every kernel that draws the same pixels repeats: row dy's
// first group is the row's plane value plus the lane offsets (first_group), each further
// group the previous one plus the group step (zstep, istep).
struct group_planes {
    __m128 zoff, ioff, zstep, istep;
    float z0, zdy, i0, idy;  // copies: the kernels' stores could alias the triangle
    explicit group_planes(const fast_triangle &f)
        : zoff(_mm_mul_ps(_mm_set1_ps(f.zdx), _mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f))),
          ioff(_mm_mul_ps(_mm_set1_ps(f.idx), _mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f))), zstep(_mm_set1_ps(4.0f * f.zdx)),
          istep(_mm_set1_ps(4.0f * f.idx)), z0(f.z), zdy(f.zdy), i0(f.i), idy(f.idy) {}
    void first_group(int dy, __m128 &z, __m128 &in) const {
        const float dy_f = static_cast<float>(dy);
        z = _mm_add_ps(_mm_set1_ps(z0 + zdy * dy_f), zoff);
        in = _mm_add_ps(_mm_set1_ps(i0 + idy * dy_f), ioff);
    }
};
#endif

// Builds a fast_triangle from already computed edges (t.valid) and per-vertex window depth and
// intensity. Returns false when the bounds are empty. When the triangle is too large for
// 32-bit edges, sets `wide` to wide_index (the caller keeps `t` at that index).
bool make_fast_triangle(const triangle_edges &t, const float depth[3], const float intensity[3],
                        std::int32_t wide_index, fast_triangle &out);

// setup_fast_triangle's verdict on one snapped triangle.
enum class fast_setup {
    ready,   // `out` is set
    empty,   // no pixel centre inside (within the clip rectangle)
    wide,    // too big for the fast path: use triangle_setup_snapped + make_fast_triangle
    scalar,  // (setup_fast_batch only) a horizontal edge: use setup_fast_triangle
};

// The fast path's setup straight from snapped, usable vertices (sub-pixel units) of
// nonzero signed area area2 (snapped_area2), without building the 64-bit triangle_edges:
// the same fast_triangle as make_fast_triangle(triangle_setup_snapped(X, Y, clip, ·), …).
fast_setup setup_fast_triangle(const std::int32_t X[3], const std::int32_t Y[3], std::int64_t area2, pixel_rect clip,
                               const float depth[3], const float intensity[3], fast_triangle &out);

// Up to SETUP_BATCH triangles for setup_fast_batch, one lane each: the arguments of
// setup_fast_triangle (snapped vertices, area2, depths, shades), lane by lane.
inline constexpr int SETUP_BATCH = BATCH_LANES;
struct setup_batch {
    alignas(64) std::int64_t area2[SETUP_BATCH] = {};
    alignas(32) std::int32_t X[3][SETUP_BATCH] = {}, Y[3][SETUP_BATCH] = {};
    alignas(32) float depth[3][SETUP_BATCH] = {}, shade[3][SETUP_BATCH] = {};
    int count = 0;
    void add(const std::int32_t x[3], const std::int32_t y[3], std::int64_t a2, const float z[3], const float i[3]) {
        area2[count] = a2;
        for (int k = 0; k < 3; ++k) X[k][count] = x[k], Y[k][count] = y[k], depth[k][count] = z[k], shade[k][count] = i[k];
        ++count;
    }
    // Lane l's arguments back, as add took them (its area2 is area2[l]).
    void lane(int l, std::int32_t x[3], std::int32_t y[3], float z[3], float i[3]) const {
        for (int k = 0; k < 3; ++k) x[k] = X[k][l], y[k] = Y[k][l], z[k] = depth[k][l], i[k] = shade[k][l];
    }
};

// kernel_table::setup_fast_batch: setup_fast_triangle for the first in.count lanes of `in`
// at once (AVX-512, eight lanes of doubles; AVX2, two halves of four): the same operations
// in the same order, so the same fast_triangle bit for bit and the same verdict — except
// that a triangle with a horizontal edge gets fast_setup::scalar (rare: its rows are cut in
// integers; setup_fast_triangle does it). Lanes at and after in.count are left alone.
#ifdef TINY3D_AVX512
void setup_fast_batch_avx512(const setup_batch &in, pixel_rect clip, fast_setup verdict[SETUP_BATCH],
                             fast_triangle out[SETUP_BATCH]);
#endif
#ifdef TINY3D_AVX2
void setup_fast_batch_avx2(const setup_batch &in, pixel_rect clip, fast_setup verdict[SETUP_BATCH],
                           fast_triangle out[SETUP_BATCH]);
#endif

// The depth and intensity planes (z, zdx, zdy, i, idx, idy of a fast_triangle or an
// msaa_triangle) at the centre of pixel (out.min_x, out.min_y), steps per pixel, through the
// snapped vertices (x, y in px), by Cramer's rule in double: the geometry once, then each
// attribute's value at the reference pixel centre and its steps. Every set-up's planes.
template <class Triangle>
inline void set_planes(const double x[3], const double y[3], const float depth[3], const float intensity[3],
                       Triangle &out) {
    const double d1x = x[1] - x[0], d1y = y[1] - y[0], d2x = x[2] - x[0], d2y = y[2] - y[0];
    // det = twice the signed area in px² (the snapped area2 carries the orientation sign).
    const double inv_det = 1.0 / (d1x * d2y - d2x * d1y);
    const double ref_dx = out.min_x + 0.5 - x[0], ref_dy = out.min_y + 0.5 - y[0];
    auto plane = [&](const float f[3], float &at_ref, float &fdx, float &fdy) {
        const double f1 = static_cast<double>(f[1]) - f[0], f2 = static_cast<double>(f[2]) - f[0];
        const double gx = (f1 * d2y - f2 * d1y) * inv_det, gy = (f2 * d1x - f1 * d2x) * inv_det;
        at_ref = static_cast<float>(f[0] + gx * ref_dx + gy * ref_dy);
        fdx = static_cast<float>(gx), fdy = static_cast<float>(gy);
    };
    plane(depth, out.z, out.zdx, out.zdy);
    plane(intensity, out.i, out.idx, out.idy);
}

// Depth comparison as a function, shared by the scalar paths.
// (A template so the double-precision reference renderer uses the same comparisons.)
template <class Depth>
inline bool depth_passes(depth_func test, Depth fragment, Depth stored) {
    switch (test) {
        case depth_func::never: return false;
        case depth_func::less: return fragment < stored;
        case depth_func::less_equal: return fragment <= stored;
        case depth_func::equal: return fragment == stored;
        case depth_func::greater: return fragment > stored;
        case depth_func::greater_equal: return fragment >= stored;
        case depth_func::not_equal: return fragment != stored;
        case depth_func::always: return true;
    }
    return false;
}

// The kernels' templates on the depth test, one switch for all: calls
// kernel(std::integral_constant<depth_func, T>{}) for test T, nothing for never.
template <class Kernel>
inline void with_depth_test(depth_func test, Kernel &&kernel) {
    using D = depth_func;
    switch (test) {
        case D::never: return;
        case D::less: return kernel(std::integral_constant<D, D::less>{});
        case D::less_equal: return kernel(std::integral_constant<D, D::less_equal>{});
        case D::equal: return kernel(std::integral_constant<D, D::equal>{});
        case D::greater: return kernel(std::integral_constant<D, D::greater>{});
        case D::greater_equal: return kernel(std::integral_constant<D, D::greater_equal>{});
        case D::not_equal: return kernel(std::integral_constant<D, D::not_equal>{});
        case D::always: return kernel(std::integral_constant<D, D::always>{});
    }
}

using tiny3d::clamp01;  // math3d.h: NaN → 0, as the SIMD fills (maxps) do

}  // namespace tiny3d::detail

#endif
