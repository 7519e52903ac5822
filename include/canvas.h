// canvas.h — the float canvas, sub-pixel splats, lines and PGM files.
//
// Conventions (pinned by tests/canvas_test.cpp):
//  * A canvas is width × height intensities in 0..1, stored in ONE contiguous,
//    row-major float block (canvas->data, 64-byte aligned). canvas->pixels[y][x] works
//    as in the libtiny3d report: pixels[y] points at row y inside that block.
//  * Origin top-left, x right, y down. Pixel (x, y) covers [x, x+1) × [y, y+1);
//    its centre is (x + 0.5, y + 0.5).
//  * Writes clamp to 0..1.
//  * PGM output: 8-bit, value = round(clamp(v, 0, 1) · 255), no gamma. Binary P5 by
//    default, ASCII P2 on request. Saving is atomic: a temporary file in the same
//    folder is renamed over the target, so a failed save leaves neither a partial file
//    nor a temporary one, and the previous file (if any) stays as it was.
#ifndef TINY3D_CANVAS_H
#define TINY3D_CANVAS_H

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "tiny3d_result.h"

typedef struct canvas_t {
    int width;
    int height;
    float **pixels;  // pixels[y][x]: row pointers into data
    float *data;     // width*height floats, row-major, 64-byte aligned
} canvas_t;

// Largest canvas: each side at most 32768 and width*height at most 2^28 pixels (1 GiB).
inline constexpr int CANVAS_MAX_SIDE = 32768;
inline constexpr long long CANVAS_MAX_PIXELS = 1LL << 28;

// ---- the libtiny3d report's API ------------------------------------------------------

// A width × height canvas, all pixels 0. Returns nullptr when a side is ≤ 0, the size
// exceeds the limits above, or memory runs out; tiny3d::check_canvas_size(width, height)
// says which. Free it with destroy_canvas (or remove_canvas).
canvas_t *create_canvas(int width, int height);
void destroy_canvas(canvas_t *canvas);  // nullptr is ignored
void remove_canvas(canvas_t *canvas);   // the report's name for destroy_canvas

// The report's bilinear splat: intensity is shared over the 2×2 pixels whose centres
// surround (x, y), weights (1−fx)(1−fy), fx(1−fy), (1−fx)fy, fx·fy where
// fx = x − 0.5 − floor(x − 0.5) (so a splat exactly at a pixel centre lands on that one
// pixel only). Additive, each pixel clamped to 1; parts off the canvas are dropped.
// Non-finite coordinates or intensity draw nothing.
void set_pixel_f(canvas_t *canvas, float x, float y, float intensity);

// The report's anti-aliased line, kept as its faithful variant: DDA samples every 0.5 px
// from (x0, y0) to (x1, y1) (both ends included); at each sample a disc of diameter
// `thickness` made of set_pixel_f(…, 1) splats on a 0.5 px grid. Coordinates in pixels
// (pixel centres at +0.5). Known flaws, kept on purpose and measured by the benchmark:
// thickness < 2 − √2 ≈ 0.586 draws nothing (no disc sample passes kx² + ky² ≤ T²/4),
// thickness 1 puts about twice the true ink down, and the
// cost grows with thickness². The line is clipped to the canvas first (margins of
// thickness), so huge coordinates cost no more than a line across the canvas.
void draw_line_f(canvas_t *canvas, float x0, float y0, float x1, float y1, float thickness);

// Writes the canvas as binary PGM (P5). Returns true on success; false (with nothing
// written) on failure — tiny3d::save_pgm gives the reason.
bool save_canvas(const canvas_t *canvas, const char *path);

// ---- libtiny3d additions --------------------------------------------------------------

void canvas_clear(canvas_t *canvas, float value);            // every pixel := clamp(value)
float get_pixel(const canvas_t *canvas, int x, int y);       // 0 outside the canvas

namespace tiny3d {

// Why create_canvas(width, height) would fail; ok() when it would not (memory aside).
status check_canvas_size(int width, int height);

struct canvas_deleter {
    void operator()(canvas_t *c) const { destroy_canvas(c); }
};
using canvas_ptr = std::unique_ptr<canvas_t, canvas_deleter>;

// RAII form of create_canvas, with the reason on failure.
result<canvas_ptr> make_canvas(int width, int height);

enum class pgm_encoding { binary_p5, ascii_p2 };

// Atomic PGM save (see top of file). Errors name the path and the reason (missing
// folder, permission, disk full, path is a folder, …). Existing non-regular files
// (e.g. /dev/full, a FIFO) are written in place, not replaced.
status save_pgm(const canvas_t &canvas, const std::string &path,
                pgm_encoding encoding = pgm_encoding::binary_p5);

// ---- lines beyond the report (src/canvas/line_coverage.cpp, line_thin.cpp) -------------
//
// Coordinates are in pixels with the convention above (pixel (x, y) is the unit square
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
// primitive ½(w·√(h² − w²) + h²·asin(w/h))) — see src/canvas/stroke_outline.h. A stroke
// that contains the whole canvas fills it. Measured against line_coverage_reference over
// thousands of random segments (lengths 0–300 px, T 0.5–8): max |error| < 1e-4 (about
// 1e-6 seen), total ink = length·T (+ πT²/4 for round caps) to 1e-3 relative
// (tests/lines_test.cpp). Half-widths beyond ~1e9 px whose edge crosses the canvas lose
// double precision in the end columns (area error ≈ T·1e-16).
// Drawing (x1, y1)→(x0, y0) gives the bit-identical image (the ends are put in a
// canonical order first). thickness ≤ 0, NaN or ±inf anywhere draws nothing; a
// zero-length segment with round caps is a disc (butt: nothing). Cost grows with the
// length plus a fixed part per end: ~9.7 ns per px of length at T = 1.5 on 5–300 px lines,
// ~0.3 µs per end (tests/bench/lines.cpp, documentation/benchmarks.md).
void draw_line_coverage(canvas_t *canvas, float x0, float y0, float x1, float y1, float thickness,
                        const line_style &style = {});

// Exact reference for draw_line_coverage, in double: the area (0..1) of pixel (px, py)'s
// square inside the stroke, by clipping the square against the rectangle's four
// half-planes (Sutherland–Hodgman, shoelace area) plus, for round caps, the area of the
// square beyond each end inside the end's disc (exact circle-segment areas). 0 for
// non-finite input or thickness ≤ 0. Slow (~0.2 µs per pixel); for tests and benchmarks.
double line_coverage_reference_at(int px, int py, double x0, double y0, double x1, double y1, double thickness,
                                  line_cap cap = line_cap::round);

// The reference coverage of a whole width × height image into `coverage` (resized,
// row-major, zero where the stroke does not reach). Visits only pixels within
// thickness/2 + √2/2 of the segment. Allocates (it is a reference, not a drawer).
void line_coverage_reference(std::vector<double> &coverage, int width, int height, double x0, double y0,
                             double x1, double y1, double thickness, line_cap cap = line_cap::round);

// Coverage table for draw_line_tabulated: the exact coverage (line_coverage_reference_at,
// double) of a pixel near the END of a long stroke of one thickness and cap, sampled in
// the stroke's frame — u along the stroke from the end (−R … √2/2, step ≤ 1/32 px), v
// across (0 … R, step ≤ 1/16 px), R = thickness/2 + √2/2 — for 33 directions of the stroke
// against the pixel grid (the "diamond angle" q = b/(a + b) of the direction folded into
// the first quadrant, 0 … 1 in steps of 1/32; 90° turns and the mirror v → −v reduce
// every direction to these). Float, ~230 KB at thickness 1.5 (grows like R²). Building it
// evaluates the reference ~58,000 times (~18 ms at thickness 1.5; 5.5 MB, 0.22 s at 16): make it
// once per thickness and keep it (render_wireframe keeps one in its workspace).
class line_table {
public:
    static constexpr float kMaxThickness = 16.0f;
    // Fails (nothing built) when thickness is not finite or not in (0, kMaxThickness].
    static result<line_table> make(float thickness, line_cap cap = line_cap::round);

    float thickness() const { return thickness_; }
    line_cap cap() const { return cap_; }

    // Internal layout (for the drawer): values[(slice·(nv + 1) + iv)·(nu + 1) + iu] at
    // u = u_min + iu·u_step, v = iv·v_step, q = slice / slices.
    float u_min = 0, u_step = 0, v_step = 0, reach = 0;
    int nu = 0, nv = 0, slices = 0;
    std::vector<float> values;

private:
    line_table() = default;
    float thickness_ = 0;
    line_cap cap_ = line_cap::round;
};

// The tabulated anti-aliased thick line: the stroke of draw_line_coverage (same
// thickness and cap as `table`, same "over" combine; intensity clamped to ≤ 1, ≤ 0 or NaN
// draws nothing), but each pixel near an end is interpolated from `table` (bilinear in
// u, v on the direction slice nearest the stroke's) instead of integrated exactly; the
// other pixels get the exact closed-form band area, 4 at a time with SSE2. A pixel's
// coverage is E(u, v) + E(L − u, −v) − band(v), E the coverage of a half-infinite stroke
// (an exact set identity for L ≥ thickness/2; shorter segments, and segments longer than
// 64 px — whose error along float-stepped rows is not tested — are drawn by
// draw_line_coverage). Error against line_coverage_reference over random segments (1–40
// px, every angle, thickness 0.5–8, round and butt): mean ~1e-4, max 0.008–0.012
// (tests/line_tabulated_test.cpp bounds: mean ≤ 4e-4, max ≤ 0.015). For many short lines
// of one width (wireframes), where the exact ends dominate draw_line_coverage's cost: per
// segment at T = 1.5, ≈ 140 ns + 7.6 ns/px against ≈ 530 ns + 7.5 ns/px (3.3× faster at
// 4 px, 2.5× at 16, 1.6× at 64). Drawing B→A gives the bit-identical image. Non-finite
// coordinates draw nothing; ends far off the canvas are clipped first (the stroke
// continues, no cap there).
void draw_line_tabulated(canvas_t *canvas, float x0, float y0, float x1, float y1, const line_table &table,
                         float intensity = 1.0f);

// Supersampled stroke: coverage = fraction of samples_per_axis² stratified samples per
// pixel inside the stroke (samples_per_axis = 16 in the benchmark), combined "over".
void draw_line_supersampled(canvas_t *canvas, float x0, float y0, float x1, float y1, float thickness,
                            int samples_per_axis, const line_style &style = {});

// Xiaolin Wu's thin (≈1 px) anti-aliased line: along the major axis, each column's
// intensity is split between the two pixels whose centres straddle the line, in
// proportion to their distance; the end columns are weighted by how much of the pixel
// the segment spans. Pixel centres at +0.5 as above. Combined "over".
void draw_line_wu(canvas_t *canvas, float x0, float y0, float x1, float y1, float intensity = 1.0f);

// Integer Bresenham (seed 003, all eight octants by swapping axes and ends; one code path):
// sets pixels (x, y) from (x0, y0) to (x1, y1), both included, to `intensity` (clamped
// 0..1). The chosen minor coordinate at major step k is round(k·dy/dx) with exact halves
// rounded towards the start after ordering the ends by the major axis, so swapping the
// endpoints gives the same pixel set. Any int coordinates (64/128-bit intermediates).
void draw_line_bresenham(canvas_t *canvas, int x0, int y0, int x1, int y1, float intensity = 1.0f);

// Seed 004's mixColors for intensities: a·(1 − t) + b·t with t clamped to 0..1.
float mix_intensity(float a, float b, float t);

// Seed 004's gradient line: the Bresenham pixels of (x0, y0)–(x1, y1), each set to
// mix_intensity(intensity0, intensity1, k / n) for the k-th of the n + 1 pixels from
// (x0, y0) (n = max(|dx|, |dy|); a single pixel takes intensity0).
void draw_line_gradient(canvas_t *canvas, int x0, int y0, int x1, int y1, float intensity0, float intensity1);

// ---- reading and writing PNM images (src/canvas/pnm_io.cpp) -----------------------------

// Reads a PGM (P2 ASCII, P5 binary) or PPM (P3, P6; converted to grey by Rec. 709
// luminance Y = 0.2126 R + 0.7152 G + 0.0722 B on the linear values, no gamma) into a new
// canvas, values = sample / maxval. Accepts '#' comments anywhere in the header, any
// maxval 1..65535 (binary samples with maxval > 255 are 2 bytes, big-endian). Errors name
// the file and the 1-based line (header, ASCII data) or byte offset (binary data) for: a
// missing or unreadable file, a bad magic number, malformed or missing numbers, a size
// beyond the canvas limits, more pixels than the file could hold (checked against the
// file size before any allocation), samples above maxval, truncated data.
result<canvas_ptr> load_pgm(const std::string &path);

enum class ppm_encoding { binary_p6, ascii_p3 };

// Writes the grey canvas as a colour PPM (R = G = B = round(clamp(v)·255)), atomically
// like save_pgm, with the same errors.
status save_ppm(const canvas_t &canvas, const std::string &path, ppm_encoding encoding = ppm_encoding::binary_p6);

}  // namespace tiny3d

namespace tiny3d {

// Writes `size` bytes to `path` atomically (temporary file in the same folder, fsync,
// rename). On failure nothing is left behind and an existing file is untouched; the
// error names the path and the reason. Existing non-regular files (devices, FIFOs) are
// written in place. Used by every image writer in the library.
status write_file_atomic(const std::string &path, const void *data, std::size_t size);

}  // namespace tiny3d

#include "compat/canvas_alias.h"  // other libtiny3d programs' names (canvas_create, …)

#endif
