// canvas.h — the float canvas, the report's sub-pixel splat and image files (PGM, PPM, PNG;
// the library's one file reader and atomic writer). Implementations: src/canvas/. Lines
// are lines.h (which canvas.h includes for report programs: see its end).
//
// Conventions (pinned by tests/canvas_test.cpp):
//  * A canvas is width × height intensities in 0..1, stored in ONE contiguous,
//    row-major float block (canvas->data, 64-byte aligned). canvas->pixels[y][x] works
//    as in the libtiny3d report: pixels[y] points at row y inside that block.
//  * Origin top-left, x right, y down. Pixel (x, y) covers [x, x+1) × [y, y+1);
//    its centre is (x + 0.5, y + 0.5).
//  * EXCEPT the libtiny3d report's own functions — set_pixel_f here, draw_line_f in
//    lines.h, project_vertex in pipeline.h and the 7-argument render_wireframe in
//    wireframe.h — which keep the
//    report's convention so that its programs get its pixels: integer coordinates are
//    pixel CENTRES (pixel (x, y) is centred on (x, y)), and project_vertex maps NDC ±1 to
//    0 and width − 1 (height − 1). A point at library coordinates (x, y) is at report
//    coordinates (x − 0.5, y − 0.5).
//  * Writes clamp to 0..1.
//  * PGM output: 8-bit, value = round(clamp(v, 0, 1) · 255), no gamma. Binary P5 by
//    default, ASCII P2 on request. Saving is atomic: a temporary file in the same
//    folder is renamed over the target, so a failed save leaves neither a partial file
//    nor a temporary one, and the previous file (if any) stays as it was.
#ifndef TINY3D_CANVAS_H
#define TINY3D_CANVAS_H

#include "tiny3d_result.h"

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <span>
#include <string>
#include <string_view>
#include <vector>
#endif

// From C (C11) this header declares the C part only: canvas_t and the functions with C
// linkage below (extern "C" under C++); everything in namespace tiny3d is C++ only.
typedef struct canvas_t {
    int width;
    int height;
    float **pixels;  // pixels[y][x]: row pointers into data
    float *data;     // width*height floats, row-major, 64-byte aligned
} canvas_t;

// Largest canvas: each side at most 32768 and width*height at most 2^28 pixels (1 GiB).
#ifdef __cplusplus
inline constexpr int CANVAS_MAX_SIDE = 32768;
inline constexpr long long CANVAS_MAX_PIXELS = 1LL << 28;
#else
enum { CANVAS_MAX_SIDE = 32768 };
#define CANVAS_MAX_PIXELS (1LL << 28)
#endif

TINY3D_C_BEGIN

// ---- the libtiny3d report's API ------------------------------------------------------

// A width × height canvas, all pixels 0. Returns NULL when a side is ≤ 0, the size
// exceeds the limits above, or memory runs out; tiny3d::check_canvas_size(width, height)
// says which. Free it with destroy_canvas (or remove_canvas).
canvas_t *create_canvas(int width, int height);
void destroy_canvas(canvas_t *canvas);  // NULL is ignored
void remove_canvas(canvas_t *canvas);   // the report's name for destroy_canvas

// The report's bilinear splat (report convention, above): with x0 = floor(x),
// dx = x − x0 (likewise y0, dy), pixel (x0 + i, y0 + j) for i, j ∈ {0, 1} gains
// intensity · (1 − |i − dx|) · (1 − |j − dy|) — so set_pixel_f(c, 3, 3, v) adds v to
// pixel (3, 3) only, and (3.5, 3) splits it evenly between pixels (3, 3) and (4, 3).
// Additive, each pixel clamped to 0..1 (the report clamps at 1 only; the two differ
// only for a negative intensity); parts off the canvas are dropped. Non-finite
// coordinates or intensity draw nothing.
void set_pixel_f(canvas_t *canvas, float x, float y, float intensity);

// Writes the canvas as binary PGM (P5). Returns true on success; false (with nothing
// written) on failure — tiny3d::save_pgm gives the reason.
bool save_canvas(const canvas_t *canvas, const char *path);

// ---- libtiny3d additions --------------------------------------------------------------

// Every pixel := clamp(value) (NaN → 0); NULL is ignored. In its own object file of the
// archive, so a program that defines its own canvas_clear(canvas_t *, float) links its own.
// (C++ also has canvas_clear(c), every pixel := 0: compat/canvas_alias.h.)
void canvas_clear(canvas_t *canvas, float value);
float get_pixel(const canvas_t *canvas, int x, int y);       // 0 outside the canvas
// How many pixels differ from `value` (0 for a null canvas). A frame that should show
// geometry and counts 0 against its clear value came out blank: programs report that as
// an error instead of writing it (a mesh that could not be framed, a NaN matrix, …).
size_t canvas_count_differing(const canvas_t *canvas, float value);

TINY3D_C_END

#ifdef __cplusplus
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

// Atomic PGM save (see top of file and atomic_file below). Errors name the path and the
// reason (missing folder, permission, disk full, path is a folder or a FIFO, …). An
// existing character device (e.g. /dev/full) is written in place, not replaced.
status save_pgm(const canvas_t &canvas, const std::string &path,
                pgm_encoding encoding = pgm_encoding::binary_p5);

// ---- reading and writing PNM images (src/canvas/file_io.cpp, src/canvas/pnm_read.cpp) -----------------------------

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

// ---- writing PNG (src/canvas/png.cpp) ---------------------------------------------------
// CRC-32 as used by PNG and gzip (polynomial 0xEDB88320 reflected, initial and final
// xor 0xFFFFFFFF): crc32 of "123456789" is 0xCBF43926.
std::uint32_t crc32(std::span<const std::uint8_t> bytes);
// Adler-32 as used by zlib (sums modulo 65521): adler32 of "Wikipedia" is 0x11E60398.
std::uint32_t adler32(std::span<const std::uint8_t> bytes);

// The canvas as a PNG file image: 8-bit greyscale (colour type 0), no interlace, each row
// with filter type 0, value = round(clamp(v, 0, 1) · 255) as in PGM; the zlib stream uses
// stored (uncompressed) deflate blocks, so the file is about width × height bytes.
std::vector<std::uint8_t> encode_png(const canvas_t &canvas);
// Writes encode_png(canvas) atomically (see write_file_atomic); errors name the path.
status save_png(const canvas_t &canvas, const std::string &path);

}  // namespace tiny3d

namespace tiny3d {

// A file written atomically: open() creates a temporary file in the target's folder,
// write() appends to it, commit() makes it the target (fchmod 0644, fsync, rename) and
// abandon() (or the destructor, or any failed step) removes it, so the target is either
// the old file untouched or the complete new one, and no temporary stays.
//  * The temporary is created fresh, exclusively (O_CREAT | O_EXCL) under a name no entry
//    has: "<path>.tmp", "<path>.tmp-1" … "<path>.tmp-7", then "<path>.tmp-XXXXXX" (random).
//    Nothing found at those names is opened or written: a hard link or symlink to a file
//    elsewhere, a folder or a FIFO there stays as it was. The one exception is what a
//    killed save left: a plain file with a single link, owned by this user and not locked
//    by a live save (a save holds an flock on its temporary, which the kernel drops when
//    the process dies) is removed, so killed runs leave no growing heap of temporaries.
//  * The rename is the only step that touches the destination.
//  * An existing character device at `path` (/dev/null, /dev/full) is written in place,
//    never replaced; a FIFO, socket or block device there is refused at open() ("the path
//    is a FIFO (named pipe), not a regular file"): nothing ever blocks on it.
// Errors name the path and the reason (missing folder, permission, disk full, …). Used by
// every image writer in the library; one writer at a time per object (move-only).
class atomic_file {
public:
    static result<atomic_file> open(const std::string &path);
    atomic_file(atomic_file &&other) noexcept;
    atomic_file &operator=(atomic_file &&other) noexcept;
    ~atomic_file();  // abandon()s an uncommitted file
    // Appends bytes; on failure the file is abandoned (later calls fail).
    status write(const void *data, std::size_t size);
    status commit();   // once, after the last write; the object is closed after it either way
    void abandon();    // removes the temporary (nothing happens to the target); idempotent
    const std::string &path() const { return path_; }

private:
    atomic_file() = default;
    std::string path_, temporary_;  // temporary_ empty: writing in place (a device) or closed
    int fd_ = -1;
};

// Writes `size` bytes to `path` through an atomic_file (above): open, write, commit.
status write_file_atomic(const std::string &path, const void *data, std::size_t size);

// Saves the bytes encode() makes of `image` (a std::string or byte vector) with
// write_file_atomic; memory that runs out while encoding is an error naming the path and
// the image's size. The image writers' common end (PGM, PPM, PNG, …).
template <class Encode>
status save_encoded(const std::string &path, const canvas_t &image, Encode &&encode) {
    try {
        const auto bytes = encode();
        return write_file_atomic(path, bytes.data(), bytes.size());
    } catch (const std::bad_alloc &) {
        return error{path, 0, -1, "cannot save: out of memory encoding a " + std::to_string(image.width) + " x " +
                                      std::to_string(image.height) + " image"};
    }
}

// The largest file read_file_bytes reads unless told otherwise: 2 GiB.
inline constexpr std::uint64_t max_read_file_bytes = std::uint64_t(1) << 31;

// Checks the first bytes of a file (up to read_file_probe_bytes, or the whole file if
// shorter) before the rest is read; an error stops the read (e.g. a text loader refusing
// NUL bytes, so a 500 MB file of zeros fails after 64 KiB, not after 500 MB).
using file_probe = status (*)(std::string_view first_bytes, const std::string &path);
inline constexpr std::size_t read_file_probe_bytes = std::size_t(1) << 16;

// Reads a whole file into memory, the one file reader of the library (meshes, PNM images,
// textures). The file is opened non-blocking and its type checked with fstat BEFORE
// anything is read or allocated: a device (e.g. /dev/zero or a symlink to it), a socket or
// a directory is refused ("… is a character device: expected a regular file or a pipe").
// A regular file above `max_bytes` fails at once with its size in the message (a 3 GB
// sparse file costs no memory). Every file is read to the end of its stream, whatever size
// it announced: a pipe or FIFO (e.g. /dev/stdin fed by `cat mesh.obj |`, read blocking once
// opened), a /proc pseudo-file (size 0), a file that grows while read; past `max_bytes`
// it fails ("more than the N-byte limit came through the pipe"). A FIFO that no writer has
// open gives no bytes and fails at once instead of waiting. `probe`, if given, judges the
// first bytes first. Errors name the path and the reason (memory that runs out included);
// reading retries interrupted calls; a file that shrinks while being read gives what was there.
result<std::string> read_file_bytes(const std::string &path, std::uint64_t max_bytes = max_read_file_bytes,
                                    file_probe probe = nullptr);

}  // namespace tiny3d

namespace tiny3d {

// ---- animated GIF (src/canvas/gif.cpp) ------------------------------------------------
//
// A sequence of grey canvases as one animated GIF89a file, lossless: the global colour
// table holds the 256 greys (index i = grey i, i.e. R = G = B = i), and a pixel's index is
// the byte save_pgm writes for it, round(clamp(v, 0, 1) · 255), so every frame decodes to
// exactly its PGM's samples. The first frame is stored whole; each later frame stores only
// the smallest rectangle holding every pixel that differs from the frame before (disposal
// method 1, "do not dispose": the rest of the picture stays); an unchanged frame is a 1 × 1
// rectangle repeating the top-left pixel, so it still holds its delay. Pixel data is LZW
// as GIF89a appendix F defines it: minimum code size 8, codes of 9 up to 12 bits, a clear
// code first and whenever the 4,096-entry table fills, the code width grown as the decoder
// expects it (when the next code to be assigned no longer fits), an end code last.
//
// Frame k (0-based) shows from t_k = k / fps seconds on; its delay (in hundredths of a
// second, the unit GIF has) is floor(100 · (k + 1) / fps) − floor(100 · k / fps), so the
// delays' running sum stays within 1/100 s of the true time: 30 fps gives 3, 3, 4, 3, 3, 4, …
struct gif_options {
    // Frames per second, 0.01 … 50. Above 50 some delays would be 0 or 1 hundredth, which
    // viewers replace by a tenth of a second.
    double fps = 30.0;
    // The NETSCAPE2.0 application block's loop count: 0 (default) = loop forever;
    // 1 … 65535 = play once and then repeat that many times; −1 = no block (viewers play
    // the animation once).
    int loop_count = 0;
};

// The delay of frame k (≥ 0) at `fps`, in hundredths of a second (formula above). The
// caller keeps fps within gif_options' range (gif_writer::create checks it).
int gif_frame_delay(double fps, long frame);

// Streams frames into an animated GIF. Memory stays the same whatever the number of frames
// (two frames of bytes, the LZW table and one frame's encoded bytes). The file is an
// atomic_file: it appears at `path` only when finish() succeeds. Any error (a write
// failing, a frame of another size) removes the temporary, makes every later call return
// the same error and leaves no file; destroying a writer that was not finished leaves no
// file either. Errors name the path and the problem. Move-only; a moved-from writer
// returns an error from every call.
class gif_writer {
public:
    // Opens `path` (atomic_file::open's errors) and writes the header, the grey table and
    // the loop block. Errors also for a size outside 1 … 65535 per side (GIF's limit) or
    // beyond the canvas limits, an fps outside 0.01 … 50, a loop count outside −1 … 65535.
    static result<gif_writer> create(const std::string &path, int width, int height, const gif_options &options = {});
    gif_writer(gif_writer &&) noexcept;
    gif_writer &operator=(gif_writer &&) noexcept;
    gif_writer(const gif_writer &) = delete;
    gif_writer &operator=(const gif_writer &) = delete;
    ~gif_writer();  // an unfinished writer removes its temporary: no file is left

    // Appends one frame, shown for gif_frame_delay(fps, k) hundredths (k = frames before
    // it). Error when the canvas is invalid or not width × height ("frame 3 is 64x48, the
    // animation is 64x64"), or the write fails; the writer then has failed (see above).
    status add_frame(const canvas_t &frame);
    // Writes the trailer and renames the file into place. Error when no frame was added, or
    // after any earlier error, or when the write, fsync or rename fails (nothing left).
    status finish();

    long frame_count() const;    // frames added so far
    std::string path() const;  // empty for a moved-from writer

private:
    struct state;
    explicit gif_writer(std::unique_ptr<state> s);
    std::unique_ptr<state> s_;
};

}  // namespace tiny3d
#endif  // __cplusplus

// Compat layer: other libtiny3d programs' names (canvas_create, …) and, because the
// report's canvas.h declared draw_line_f, lines.h (a report program that includes canvas.h
// alone still draws lines). Library files do not rely on it: they include lines.h.
#include "compat/canvas_alias.h"

#endif
