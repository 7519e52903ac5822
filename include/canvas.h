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
// thickness ≤ ~0.7 draws nothing, thickness 1 puts about twice the true ink down, and the
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

}  // namespace tiny3d

namespace tiny3d {

// Writes `size` bytes to `path` atomically (temporary file in the same folder, fsync,
// rename). On failure nothing is left behind and an existing file is untouched; the
// error names the path and the reason. Existing non-regular files (devices, FIFOs) are
// written in place. Used by every image writer in the library.
status write_file_atomic(const std::string &path, const void *data, std::size_t size);

}  // namespace tiny3d

#endif
