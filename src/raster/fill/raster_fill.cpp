// raster_fill.cpp — the 1-sample fill (fill.h): the half-space fill with depth and affine
// intensity (SSE2 4-wide, scalar 64-bit fallback; the portable and SSE2 band kernels), the
// public fill_triangle, and the faithful scan-line fill (the classic edge-walking method).
#include <algorithm>
#include <cmath>

#include "fill.h"
#include "../../simd_config.h"

#ifdef TINY3D_SSE2
#include <emmintrin.h>
#endif

namespace tiny3d {

namespace detail {

namespace {

// One pixel of the scalar paths (also the right-edge tail of the SIMD path).
inline void shade_pixel(float *color, float *zrow, int x, float z, float intensity, depth_func test,
                        bool depth_write) {
    if (zrow) {
        if (!depth_passes(test, z, zrow[x])) return;
        if (depth_write) zrow[x] = z;
    }
    color[x] = clamp01(intensity);
}

void fill_rows_scalar64(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, const triangle_edges &t,
                        depth_func test, bool depth_write, int y0, int y1) {
    for (int y = y0; y < y1; ++y) {
        std::int64_t e[3];
        for (int k = 0; k < 3; ++k) e[k] = t.c[k] + t.a[k] * f.min_x + t.b[k] * y;
        const float zr = f.z + f.zdy * static_cast<float>(y - f.min_y);
        const float ir = f.i + f.idy * static_cast<float>(y - f.min_y);
        float *color = canvas.pixels[y];
        float *zrow = depth ? depth->row(y) : nullptr;
        for (int x = f.min_x; x <= f.max_x; ++x) {
            if ((e[0] | e[1] | e[2]) >= 0) {
                const float dxp = static_cast<float>(x - f.min_x);
                shade_pixel(color, zrow, x, zr + f.zdx * dxp, ir + f.idx * dxp, test, depth_write);
            }
            for (int k = 0; k < 3; ++k) e[k] += t.a[k];
        }
    }
}

#ifdef TINY3D_SSE2
#include "narrow_rows.inc"

// The 4-wide span loop: each row runs from its exact first covered pixel (row_spans) in
// groups of four; only the last group of a row is partial (its lanes below the row's end
// are covered), and no edge function is evaluated per pixel. A last group that would pass
// the canvas' right edge is finished lane by lane. A whole group whose four pixels all pass
// the depth test is written with plain stores, without reading the colour (with spans,
// whole groups are fully covered, so this branch is well predicted even on small
// triangles).
template <depth_func Test, bool HasDepth>
void fill_rows_sse2(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, bool depth_write, int y0,
                    int y1) {
    const __m128i lane = _mm_set_epi32(3, 2, 1, 0);
    const __m128 all_lanes = _mm_castsi128_ps(_mm_set1_epi32(-1));
    const __m128 lane_f = _mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f);
    const __m128 zstep = _mm_set1_ps(4.0f * f.zdx), istep = _mm_set1_ps(4.0f * f.idx);
    const __m128 zoff = _mm_mul_ps(_mm_set1_ps(f.zdx), lane_f), ioff = _mm_mul_ps(_mm_set1_ps(f.idx), lane_f);
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
    const int width = canvas.width;
    const row_spans spans(f);
    // Local copies: the colour and depth stores are floats and could alias f's floats.
    const float z0 = f.z, zdx = f.zdx, zdy = f.zdy, i0 = f.i, idx = f.idx, idy = f.idy;
    const int min_x = f.min_x, min_y = f.min_y;
    for (int y = y0; y < y1; ++y) {
        const int dy = y - min_y;
        int lo, hi;
        spans.at(dy, lo, hi);
        if (lo > hi) continue;
        const float lo_f = static_cast<float>(lo), dy_f = static_cast<float>(dy);
        __m128 z = _mm_add_ps(_mm_set1_ps(z0 + zdy * dy_f + zdx * lo_f), zoff);
        __m128 in = _mm_add_ps(_mm_set1_ps(i0 + idy * dy_f + idx * lo_f), ioff);
        float *color = canvas.pixels[y];
        float *zrow = HasDepth ? depth->row(y) : nullptr;
        const int x_end = min_x + hi + 1;
        int x = min_x + lo;
        // One group of four pixels from x; `cover` marks the lanes inside the span (all of
        // them when `whole`, a std::bool_constant).
        auto group = [&](auto whole, __m128 cover) {
            __m128 mask = cover, stored = z;
            if constexpr (HasDepth) {
                stored = _mm_loadu_ps(zrow + x);
                mask = _mm_and_ps(mask, lanes4::depth_mask<Test>(z, stored));
            }
            const int pass = _mm_movemask_ps(mask);
            if (decltype(whole)::value && pass == 0xF) {  // all four pass: plain stores, no colour read
                if (HasDepth && depth_write) _mm_storeu_ps(zrow + x, z);
                _mm_storeu_ps(color + x, _mm_min_ps(_mm_max_ps(in, zero), one));
            } else {
                if (HasDepth && depth_write) _mm_storeu_ps(zrow + x, lanes4::select(mask, z, stored));
                if (pass) {
                    const __m128 shade = _mm_min_ps(_mm_max_ps(in, zero), one);
                    _mm_storeu_ps(color + x, lanes4::select(mask, shade, _mm_loadu_ps(color + x)));
                }
            }
        };
        for (; x + 4 <= x_end; x += 4) {  // whole groups (x_end ≤ width: never past the row)
            group(std::true_type{}, all_lanes);
            z = _mm_add_ps(z, zstep);
            in = _mm_add_ps(in, istep);
        }
        if (x == x_end) continue;
        if (x + 4 <= width) {
            group(std::false_type{}, _mm_castsi128_ps(_mm_cmpgt_epi32(_mm_set1_epi32(x_end - x), lane)));
        } else {  // the last group would pass the canvas' right edge: lane by lane
            alignas(16) float zl[4], il[4];
            _mm_store_ps(zl, z);
            _mm_store_ps(il, in);
            for (int l = 0; x + l < x_end; ++l) shade_pixel(color, zrow, x + l, zl[l], il[l], Test, depth_write);
        }
    }
}

// Flattened: both kernels inlined, no call per triangle (GCC's heuristics keep the larger
// narrow cases out of line otherwise).
template <depth_func Test, bool HasDepth>
[[gnu::flatten]] void fill_rows_sse2_any(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, bool depth_write, int y0, int y1) {
    if (narrow_fits(f, canvas.width))
        return narrow_rows_any<lanes4, Test, HasDepth>(canvas, depth, f, depth_write, y0, y1);
    fill_rows_sse2<Test, HasDepth>(canvas, depth, f, depth_write, y0, y1);
}

#endif

}  // namespace

void fill_floats(float *dst, std::size_t count, float value) {
    std::size_t i = 0;
#ifdef TINY3D_SSE2
    for (; i < count && (reinterpret_cast<std::uintptr_t>(dst + i) & 15u); ++i) dst[i] = value;
    const __m128 v = _mm_set1_ps(value);
    for (; i + 16 <= count; i += 16) {
        _mm_store_ps(dst + i, v);
        _mm_store_ps(dst + i + 4, v);
        _mm_store_ps(dst + i + 8, v);
        _mm_store_ps(dst + i + 12, v);
    }
#endif
    for (; i < count; ++i) dst[i] = value;
}

void fill_fast_rows(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, const triangle_edges *wide_edges,
                         depth_func test, bool depth_write, int y0, int y1) {
    y0 = std::max(y0, f.min_y);
    y1 = std::min(y1, f.max_y + 1);
    if (y0 >= y1) return;
    if (f.wide >= 0) {
        if (wide_edges) fill_rows_scalar64(canvas, depth, f, *wide_edges, test, depth_write, y0, y1);
        return;
    }
#ifdef TINY3D_SSE2
    if (!depth) return fill_rows_sse2_any<depth_func::always, false>(canvas, depth, f, false, y0, y1);
    with_depth_test(test, [&](auto t) { fill_rows_sse2_any<t.value, true>(canvas, depth, f, depth_write, y0, y1); });
#else
    const row_spans spans(f);
    for (int y = y0; y < y1; ++y) {
        const int dy = y - f.min_y;
        int lo, hi;
        spans.at(dy, lo, hi);
        const float zr = f.z + f.zdy * static_cast<float>(dy), ir = f.i + f.idy * static_cast<float>(dy);
        float *zrow = depth ? depth->row(y) : nullptr;
        for (int x = lo; x <= hi; ++x)
            shade_pixel(canvas.pixels[y], zrow, f.min_x + x, zr + f.zdx * static_cast<float>(x),
                        ir + f.idx * static_cast<float>(x), test, depth_write);
    }
#endif
}

#ifdef TINY3D_SSE2
void fill_fast_bins_sse2(canvas_t &canvas, zbuffer &depth, const band_bin *bins, int bin_count, depth_func test, int y0,
                         int y1, band_prefetch &ahead) {
    with_depth_test(test, [&](auto t) {
        for_each_bin_triangle(bins, bin_count, ahead, [&](const band_bin &bin, const fast_triangle &f) {
            const int first = std::max(y0, f.min_y), end = std::min(y1, f.max_y + 1);
            if (first >= end) return;
            if (f.wide >= 0) fill_rows_scalar64(canvas, &depth, f, bin.wide[f.wide], test, true, first, end);
            else fill_rows_sse2_any<t.value, true>(canvas, &depth, f, true, first, end);
        });
    });
}
#endif

void fill_fast_bins_portable(canvas_t &canvas, zbuffer &depth, const band_bin *bins, int bin_count, depth_func test,
                             int y0, int y1, band_prefetch &ahead) {
    for_each_bin_triangle(bins, bin_count, ahead, [&](const band_bin &bin, const fast_triangle &f) {
        fill_fast_rows(canvas, &depth, f, f.wide >= 0 ? &bin.wide[f.wide] : nullptr, test, true, y0, y1);
    });
}

}  // namespace detail

void fill_triangle(canvas_t &canvas, zbuffer *depth, const screen_vertex v[3], const float intensity[3],
                   depth_func test, bool depth_write, pixel_rect clip) {
    if (!canvas.pixels || (depth && (depth->width() != canvas.width || depth->height() != canvas.height))) return;
    clip.x0 = std::max(clip.x0, 0);
    clip.y0 = std::max(clip.y0, 0);
    clip.x1 = std::min(clip.x1, canvas.width);
    clip.y1 = std::min(clip.y1, canvas.height);
    const triangle_edges t = triangle_setup(v[0], v[1], v[2], clip);
    detail::fast_triangle f;
    const float depth_z[3] = {v[0].z, v[1].z, v[2].z};
    if (!detail::make_fast_triangle(t, depth_z, intensity, 0, f)) return;
    const auto narrow = detail::kernels_for(best_raster_simd()).fill_rows_narrow;
    if (narrow && f.wide < 0 && detail::narrow_fits(f, canvas.width))
        return narrow(canvas, depth, f, test, depth_write, f.min_y, f.max_y + 1);
    detail::fill_fast_rows(canvas, depth, f, &t, test, depth_write, f.min_y, f.max_y + 1);
}

// ---- the faithful scan-line fill (classic edge walking) ---------------------------------

void fill_triangle_scanline(canvas_t &canvas, zbuffer *depth, const screen_vertex v[3], const float intensity[3],
                            depth_func test) {
    if (!canvas.pixels || (depth && (depth->width() != canvas.width || depth->height() != canvas.height))) return;
    for (int k = 0; k < 3; ++k)
        if (!detail::snappable(v[k].x, v[k].y) || !std::isfinite(v[k].z) || !std::isfinite(intensity[k])) return;
    // Sort by y (a bubble sort of the three), keeping each vertex's intensity with it.
    int order[3] = {0, 1, 2};
    if (v[order[0]].y > v[order[1]].y) std::swap(order[0], order[1]);
    if (v[order[1]].y > v[order[2]].y) std::swap(order[1], order[2]);
    if (v[order[0]].y > v[order[1]].y) std::swap(order[0], order[1]);
    const screen_vertex &p0 = v[order[0]], &p1 = v[order[1]], &p2 = v[order[2]];
    const float area = (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x);
    if (area == 0.0f || p2.y == p0.y) return;
    const float i0 = intensity[order[0]], i1 = intensity[order[1]], i2 = intensity[order[2]];
    // Rows whose centre y + 0.5 lies in [p0.y, p2.y].
    const int row0 = std::max(0, static_cast<int>(std::ceil(p0.y - 0.5f)));
    const int row1 = std::min(canvas.height - 1, static_cast<int>(std::floor(p2.y - 0.5f)));
    for (int y = row0; y <= row1; ++y) {
        const float cy = static_cast<float>(y) + 0.5f;
        // Long edge p0→p2 and the short edge of this half.
        const float xl = p0.x + (p2.x - p0.x) * (cy - p0.y) / (p2.y - p0.y);
        const bool upper = cy < p1.y;
        const screen_vertex &s0 = upper ? p0 : p1, &s1 = upper ? p1 : p2;
        const float xs = s1.y != s0.y ? s0.x + (s1.x - s0.x) * (cy - s0.y) / (s1.y - s0.y) : s1.x;
        const float xa = std::min(xl, xs), xb = std::max(xl, xs);
        const int col0 = std::max(0, static_cast<int>(std::ceil(xa - 0.5f)));
        const int col1 = std::min(canvas.width - 1, static_cast<int>(std::floor(xb - 0.5f)));
        float *color = canvas.pixels[y];
        float *zrow = depth ? depth->row(y) : nullptr;
        for (int x = col0; x <= col1; ++x) {
            const float cx = static_cast<float>(x) + 0.5f;
            // Barycentrics of the centre (areas of the sub-triangles over the whole).
            const float l1 = ((cx - p0.x) * (p2.y - p0.y) - (cy - p0.y) * (p2.x - p0.x)) / area;
            const float l2 = ((p1.x - p0.x) * (cy - p0.y) - (p1.y - p0.y) * (cx - p0.x)) / area;
            const float l0 = 1.0f - l1 - l2;
            detail::shade_pixel(color, zrow, x, l0 * p0.z + l1 * p1.z + l2 * p2.z, l0 * i0 + l1 * i1 + l2 * i2,
                                test, true);
        }
    }
}

}  // namespace tiny3d
