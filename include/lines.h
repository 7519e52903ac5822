// lines.h — lines on the canvas: the report's DDA splat line (draw_line_f), the exact
// coverage line, the tabulated coverage line (portable / SSE2 / AVX-512), the supersampled
// line, Wu, Bresenham and the gradient line. Implementations: src/lines/.
//
// Coordinates follow canvas.h's conventions: pixel (x, y) is the unit square
// [x, x+1) × [y, y+1), except the report's draw_line_f, which keeps the report's
// convention (integer coordinates are pixel centres; canvas.h).
//
// The report's canvas.h declared draw_line_f, so canvas.h still makes this header
// available to report programs (its compat include, compat/canvas_alias.h); the library's
// own files include lines.h where they draw lines.
#ifndef TINY3D_LINES_H
#define TINY3D_LINES_H

#include "canvas.h"
#include "tiny3d_result.h"

#ifdef __cplusplus
#include <cstddef>
#include <new>
#include <vector>
#endif

// ---- the libtiny3d report's line (src/lines/line_faithful.cpp) ------------------------

// The report's anti-aliased line, kept as its faithful variant: DDA samples every 0.5 px
// from (x0, y0) to (x1, y1) (both ends included); at each sample a disc of diameter
// `thickness` made of set_pixel_f(…, 1) splats on a 0.5 px grid. Coordinates in the
// report's convention (canvas.h: integer coordinates are pixel centres); the report's
// pixels bit for bit while the line stays on the canvas, to float rounding when it is
// clipped. Known flaws, kept on purpose (bench `lines`, rows 'faithful DDA splat …'): thickness
// < 2 − √2 ≈ 0.586 draws nothing (no disc sample passes kx² + ky² ≤ T²/4); from there up
// to T = 1 each sample is a single splat, offset (½ − T/2)·(1, 1) from the line, about
// 2–2.5 times the true ink at 0.59–0.70; thickness 1 puts about twice the true ink down;
// the cost grows with thickness². The line is clipped to the canvas first (margins of
// thickness), so huge coordinates cost no more than a line across the canvas.
// C linkage (and C11): the one declaration a C program sees from this header.
TINY3D_C_BEGIN
void draw_line_f(canvas_t *canvas, float x0, float y0, float x1, float y1, float thickness);
TINY3D_C_END

#ifdef __cplusplus
namespace tiny3d {

// ---- lines beyond the report (src/lines/line_coverage.cpp, line_tabulated*.cpp, line_thin.cpp)
//
// Coordinates are in pixels with canvas.h's convention (pixel (x, y) is the unit square
// [x, x+1) × [y, y+1)). Every line is clipped to the canvas first (Liang–Barsky, in double),
// so endpoints like (−1e9, 5) cost no more than a line across the canvas and never
// overflow. Non-finite coordinates draw nothing. No function here allocates.
//
// "Over" combine (anti-aliased lines): a pixel v receiving coverage c becomes
//   v + c·(1 − v)
// so two half-covering strokes give 0.75, ink never exceeds 1, and a fully covered pixel
// becomes exactly 1.

enum class line_cap {
    round,  // half-discs of radius thickness/2 at both ends (the stroke is a capsule)
    butt    // the stroke ends flat at the endpoints (a rectangle)
};

struct line_style {
    line_cap cap = line_cap::round;
    float intensity = 1.0f;  // c = intensity · coverage; clamped to ≤ 1, ≤ 0 or NaN draws nothing
};

// The fast anti-aliased thick line: each pixel receives the exact area of its square
// covered by the stroke of (x0, y0)–(x1, y1) of width `thickness` (px), times
// style.intensity, combined "over". Only pixels near the line are visited. Columns of the
// major axis that lie between the two ends see only the band |u| ≤ thickness/2 (u = signed
// distance across the line), whose area in a unit square is a closed form of the angle
// and the centre's u (a piecewise quadratic, evaluated 4 pixels at a time with SSE2,
// float, along contiguous canvas rows). The two or three columns at each end are
// integrated exactly in double from the stroke's outline: over a column the stroke's
// cross-section is one interval [lower(X), upper(X)], so a pixel's area is a difference
// of ∫ max(y − t, 0) dX over the boundary pieces (straight sides, butt ends, cap arcs with
// primitive ½(w·√(h² − w²) + h²·asin(w/h))) — see src/lines/stroke_outline.h. A stroke
// that contains the whole canvas fills it. Against line_coverage_reference over thousands
// of random segments (lengths 0–300 px, T 0.5–8): max |error| < 1e-4, total ink =
// length·T (+ πT²/4 for round caps) to 1e-3 relative (tests/lines_test.cpp). Half-widths
// beyond ~1e9 px whose edge crosses the canvas lose double precision in the end columns
// (area error ≈ T·1e-16).
// Drawing (x1, y1)→(x0, y0) gives the bit-identical image (the ends are put in a
// canonical order first). thickness ≤ 0, NaN or ±inf anywhere draws nothing; a
// zero-length segment with round caps is a disc (butt: nothing). Cost grows with the
// length plus a fixed part per end (bench `lines`, rows 'fast coverage').
void draw_line_coverage(canvas_t *canvas, float x0, float y0, float x1, float y1, float thickness,
                        const line_style &style = {});

// Exact reference for draw_line_coverage, in double: the area (0..1) of pixel (px, py)'s
// square inside the stroke, by clipping the square against the rectangle's four
// half-planes (Sutherland–Hodgman, shoelace area) plus, for round caps, the area of the
// square beyond each end inside the end's disc (exact circle-segment areas). 0 for
// non-finite input or thickness ≤ 0. Slow (a polygon clipped per pixel); for tests and
// benchmarks (bench `lines`, rows 'exact reference').
double line_coverage_reference_at(int px, int py, double x0, double y0, double x1, double y1, double thickness,
                                  line_cap cap = line_cap::round);

// The reference coverage of a whole width × height image into `coverage` (resized,
// row-major, zero where the stroke does not reach). Visits only pixels within
// thickness/2 + √2/2 of the segment. Allocates (it is a reference, not a drawer).
void line_coverage_reference(std::vector<double> &coverage, int width, int height, double x0, double y0,
                             double x1, double y1, double thickness, line_cap cap = line_cap::round);

// std::allocator with 64-byte (cache line) alignment, for tables read in whole lines.
template <class T>
struct cache_line_allocator {
    using value_type = T;
    static constexpr std::align_val_t kAlignment{64};
    cache_line_allocator() = default;
    template <class U>
    cache_line_allocator(const cache_line_allocator<U> &) {}
    T *allocate(std::size_t n) { return static_cast<T *>(::operator new(n * sizeof(T), kAlignment)); }
    void deallocate(T *p, std::size_t) { ::operator delete(p, kAlignment); }
    template <class U>
    bool operator==(const cache_line_allocator<U> &) const { return true; }
};

// The instruction sets draw_line_tabulated can use. SSE2 gives the portable path's image to
// 1e-6 per pixel, AVX-512 to 0.004 (it locates the ends in float; the bounds
// tests/line_tabulated_test.cpp checks for every path this CPU runs, each also against the
// reference).
enum class line_simd {
    portable,  // plain C++, one pixel at a time
    sse2,      // 4 pixels at a time (every x86-64 CPU)
    avx512     // 16 pixels at a time (AVX-512 F/VL/DQ/BW; blocks of 4 × 4, i.e. thickness < 1.8)
};
// The best of them this CPU runs (CPUID, read by the compiler's runtime), or the line
// kernels of the table TINY3D_KERNELS names (raster.h, best_raster_simd: sse2 and avx2 draw
// lines with sse2).
line_simd best_line_simd();

// End-correction table for draw_line_tabulated. A pixel near an end of a stroke gets
// band + D, D = (area inside the stroke that starts at that end and never stops) − (area
// inside the infinite band): 0 except in a small block of pixels around the end (4 × 4
// up to thickness 1.75, 8 × 8 up to 5.3). The table holds D, computed exactly
// (line_coverage_reference_at, double), for such blocks: directions folded into the
// first octant by the pixel grid's symmetries (16 intervals, both ends of each) and end
// positions within their pixel in steps of 1/24 px per axis; a drawn end blends 8 of them
// (bilinear in position, linear in direction). Float: 1.35 MB up to thickness 1.75,
// 5.4 MB beyond; building it evaluates the reference ~690,000 times up to 1.75, ~2.1 M at
// 4: make it once per thickness and keep it (render_wireframe keeps them in its
// workspace). From about 5.35 px (up to kMaxThickness) the table is empty and
// draw_line_tabulated draws with the exact line.
class line_table {
public:
    static constexpr float kMaxThickness = 16.0f;
    // Fails (nothing built) when thickness is not finite or not in (0, kMaxThickness].
    static result<line_table> make(float thickness, line_cap cap = line_cap::round);

    float thickness() const { return thickness_; }
    line_cap cap() const { return cap_; }
    // Instruction set used to draw (best_line_simd() unless changed). use_simd returns
    // false, changing nothing, for one this CPU does not run.
    line_simd simd() const { return simd_; }
    bool use_simd(line_simd simd);

    // Internal layout (for the drawer). Block side S = stamp_size (0: no table);
    // stamps[(((interval·2 + end)·kStampPhases + sy)·kStampPhases + sx)·S² + b·S + a];
    // stamp_axes per interval: first pixel (origin) and the cell from which it is one
    // further (jump), for x then y — see src/lines/line_tabulated.cpp.
    static constexpr int kStampIntervals = 16, kStampCells = 24, kStampPhases = kStampCells + 2;
    float reach = 0;  // thickness/2 + √2/2: how far a stroke reaches pixel centres
    int stamp_size = 0;
    std::vector<int> stamp_axes;
    std::vector<float, cache_line_allocator<float>> stamps;  // each 4 × 4 block in one cache line

private:
    line_table() = default;
    float thickness_ = 0;
    line_cap cap_ = line_cap::round;
    line_simd simd_ = line_simd::portable;
};

// The tabulated anti-aliased thick line: the stroke of draw_line_coverage (same
// thickness and cap as `table`, same "over" combine; intensity clamped to ≤ 1, ≤ 0 or NaN
// draws nothing). A pixel's coverage is band + D_A + D_B: the exact closed-form area of
// the infinite band, plus each end's correction D (see line_table) interpolated from the
// table's blocks — an exact set identity for L ≥ thickness/2; shorter segments, segments
// longer than 64 px (whose error along float-stepped rows is not tested) and thicknesses
// from ~5.35 px on (no table) are drawn by draw_line_coverage. Pixels are done 16 at a time with AVX-512
// (tiles of 4 × 4, 8 × 2 or 16 × 1 pixels, the narrowest the stroke fits), 4 at a time
// with SSE2, or one at a time: table.simd(). Error against line_coverage_reference over
// random segments (1–40 px, every angle, thickness 0.5–3, round and butt): mean ≤ 2e-4,
// max ≤ 0.015 (tests/line_tabulated_test.cpp); cost: bench `lines`, rows 'tabulated
// coverage'. Drawing B→A gives the bit-identical image. Non-finite coordinates draw
// nothing; ends far off the canvas are clipped first (the stroke continues, no cap
// there).
void draw_line_tabulated(canvas_t *canvas, float x0, float y0, float x1, float y1, const line_table &table,
                         float intensity = 1.0f);

// Many tabulated lines of one table at once (the wireframe's way): the image of calling
// draw_line_tabulated on each segment in order, bit for bit, but faster, as the table
// reads of several segments overlap. No allocation. Null `segments` draws nothing.
struct line_segment {
    float x0, y0, x1, y1;
    float intensity = 1.0f;
};
void draw_lines_tabulated(canvas_t *canvas, const line_segment *segments, std::size_t count, const line_table &table);

// Supersampled stroke: coverage = fraction of samples_per_axis² stratified samples per
// pixel inside the stroke (samples_per_axis = 16 in the benchmark), combined "over".
void draw_line_supersampled(canvas_t *canvas, float x0, float y0, float x1, float y1, float thickness,
                            int samples_per_axis, const line_style &style = {});

// Xiaolin Wu's thin (≈1 px) anti-aliased line: along the major axis, each column's
// intensity is split between the two pixels whose centres straddle the line, in
// proportion to their distance; the end columns are weighted by how much of the pixel
// the segment spans. Pixel centres at +0.5 as above. Combined "over".
void draw_line_wu(canvas_t *canvas, float x0, float y0, float x1, float y1, float intensity = 1.0f);

// Integer Bresenham (all eight octants by swapping axes and ends; one code path):
// sets pixels (x, y) from (x0, y0) to (x1, y1), both included, to `intensity` (clamped
// 0..1). The chosen minor coordinate at major step k is round(k·dy/dx) with exact halves
// rounded towards the start after ordering the ends by the major axis, so swapping the
// endpoints gives the same pixel set. Any int coordinates (64/128-bit intermediates).
void draw_line_bresenham(canvas_t *canvas, int x0, int y0, int x1, int y1, float intensity = 1.0f);

// The linear mix of two intensities (the gradient line's colour mix): a·(1 − t) + b·t
// with t clamped to 0..1.
float mix_intensity(float a, float b, float t);

// The gradient line: the Bresenham pixels of (x0, y0)–(x1, y1), each set to
// mix_intensity(intensity0, intensity1, k / n) for the k-th of the n + 1 pixels from
// (x0, y0) (n = max(|dx|, |dy|); a single pixel takes intensity0).
void draw_line_gradient(canvas_t *canvas, int x0, int y0, int x1, int y1, float intensity0, float intensity1);

}  // namespace tiny3d

#include "compat/lines_alias.h"  // the 7-argument draw_line_f other libtiny3d programs call
#endif  // __cplusplus

#endif
