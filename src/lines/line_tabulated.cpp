// line_tabulated.cpp — the tabulated thick line (include/lines.h): the stroke of
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
#include <cmath>
#include <string>

#include "line_tabulated_internal.h"
#include "../kernels.h"

namespace tiny3d {
using namespace tabulated;
namespace {

constexpr double kHalfDiagonal = 0.70710678118654752;
// Length of the straight part used to sample a half-infinite stroke (its far end is out
// of reach of the sampled pixels).
constexpr double kFarEnd = 64.0;

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

}  // namespace

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
    if (!detail::line_kernels_run(simd)) return false;
    simd_ = simd;
    return true;
}

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
    namespace lanes = detail::scalar_lanes;  // the arithmetic prepare8_avx512 repeats on eight lanes
    const lanes::segment_extent<double> full = lanes::extent_of<double>(x0, y0, x1, y1);
    // (1) needs L ≥ h; beyond kExactFromLength, or without stamps (thick lines), the exact line draws.
    if (!lanes::tabulates(full.length, h, kExactFromLength) || table.stamp_size == 0) {
        s.exact = {x0, y0, x1, y1};
        return stroke_kind::exact;
    }
    const lanes::unit_direction<double> d = lanes::direction_of(full);
    s.dx = d.x;
    s.dy = d.y;
    // Clip to the canvas grown by 2R + 2: a clipped end is then so far off the canvas that
    // no canvas pixel within reach of the stroke lies near it; it gets no cap.
    s.reach = table.reach;
    const double margin = 2.0 * s.reach + 2.0;
    const int width = canvas->width, height = canvas->height;
    detail::clipped_segment clip{x0, y0, x1, y1, false, false};
    // (x0 ≤ x1 here.) The common case, both ends in the grown canvas, needs no call.
    if (!lanes::inside_grown_canvas<double>(x0, y0, x1, y1, margin, width, height) &&
        !detail::clip_segment(x0, y0, x1, y1, -margin, -margin, width + margin, height + margin, clip))
        return stroke_kind::nothing;
    s.ax = clip.x0;
    s.ay = clip.y0;
    const lanes::stroke_span<double, int> span = lanes::span_of(s.ax, s.ay, clip.x1, clip.y1, d, s.reach, height);
    s.length = span.length;
    s.end_a = !clip.start_clipped;
    s.end_b = !clip.end_clipped;
    s.cdf = detail::square_cdf(-s.dy, s.dx);
    s.half = float(h);
    s.length_f = float(s.length);
    s.du = float(s.dx);
    s.dv = float(-s.dy);
    // Rows whose centre lies within R of the segment's y range (the stroke's full extent).
    s.row_first = span.row_first;
    s.row_last = span.row_last;
    return stroke_kind::tabulated;
}

void draw_prepared(canvas_t *canvas, stroke_kind kind, const stroke_setup &s, const line_table &table) {
    if (kind == stroke_kind::exact) {
        draw_line_coverage(canvas, s.exact[0], s.exact[1], s.exact[2], s.exact[3], table.thickness(),
                           {table.cap(), s.ink});
        return;
    }
    if (kind != stroke_kind::tabulated) return;
    const detail::line_kernels &k = detail::line_kernels_for(table.simd());
    if (k.draw_batch && table.stamp_size == 4) return k.draw_batch(canvas, &s, 1, table);
    if (canvas->width >= 4) return k.draw_one(canvas, s, table);
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
    const detail::line_kernels &k = detail::line_kernels_for(table.simd());
    const bool batched = k.draw_batch && table.stamp_size == 4;
    for (std::size_t start = 0; start < count; start += kBatch) {
        const int n = int(std::min<std::size_t>(kBatch, count - start));
        bool all_wide = true;
        unsigned ready = 0;  // set up by the vector code
        if (batched && canvas && canvas->data && canvas->width > 0 && canvas->height > 0)
            ready = k.prepare8(*canvas, segments + start, n, table, strokes);
        for (int i = 0; i < n; ++i) {
            if (ready >> i & 1) {
                kinds[i] = stroke_kind::tabulated;
                continue;
            }
            const line_segment &g = segments[start + std::size_t(i)];
            kinds[i] = prepare_stroke(canvas, g.x0, g.y0, g.x1, g.y1, table, g.intensity, strokes[i]);
            all_wide = all_wide && kinds[i] == stroke_kind::tabulated;
        }
        if (all_wide && batched) {
            k.draw_batch(canvas, strokes, n, table);
            continue;
        }
        for (int i = 0; i < n; ++i) draw_prepared(canvas, kinds[i], strokes[i], table);
    }
}

}  // namespace tiny3d
