// kernels.h — internal: the one place that says which instruction set's kernels run.
//
// In: the CPU's features (checked once) and the environment variable
//   TINY3D_KERNELS=portable|sse2|avx2|avx512 (read once, for tests and benchmarks).
// Out: a kernel_table per instruction set — the set-up batches, the 1-sample fills, the
//   multisample fills and resolve, and the tabulated line kernels — and the table every
//   render context and line_table starts with (default_kernels).
// Who calls it: the render context holds a table pointer chosen at construction or by
//   use_simd and calls through it; the lines module asks for its line kernels
//   (line_kernels_for). No other file compares instruction sets: adding a kernel is
//   a function in its family's folder and one entry in kernels.cpp.
//
// The types are only declared here (the lines module includes this header and stays below
// the raster module).
#ifndef TINY3D_KERNELS_H
#define TINY3D_KERNELS_H

#include <cstdint>
#include <string>

struct canvas_t;

namespace tiny3d {
enum class raster_simd;
enum class line_simd;
enum class depth_func;
struct pixel_rect;
class zbuffer;
class line_table;
struct line_segment;
namespace tabulated {
struct stroke_setup;
}
}  // namespace tiny3d

namespace tiny3d::detail {

enum class fast_setup;
struct setup_batch;
struct fast_triangle;
struct band_bin;
struct band_prefetch;
struct sample_pattern;
class sample_store;
struct msaa_triangle;
struct tap_walk;

inline constexpr int BATCH_LANES = 8;  // = SETUP_BATCH (the set-up batches' lanes)

// One multisample row fill, its sample count and depth test chosen (msaa_fill_for).
// Depths are written where the test passes (the render context has no draw without depth
// writes; translucent triangles take the per-pixel path).
using msaa_row_fill = void (*)(sample_store &store, const msaa_triangle &f, const sample_pattern &pat, depth_func test,
                               int y0, int y1);

// The kernels of one instruction set. A null entry: the set has no kernel of its own there,
// and the caller runs the family's portable reference (named beside each entry).
struct kernel_table {
    raster_simd simd;
    const char *name;  // "portable", "sse2", "avx2", "avx512"
    line_simd lines;   // the line kernels this set draws with (line_kernels_for)

    // Set-up, eight triangles at once (null: setup_fast_triangle / make_msaa_triangle one at
    // a time).
    void (*setup_fast_batch)(const setup_batch &in, pixel_rect clip, fast_setup verdict[BATCH_LANES],
                             fast_triangle out[BATCH_LANES]);
    void (*setup_msaa_batch)(const setup_batch &in, const sample_pattern &pat, pixel_rect clip,
                             fast_setup verdict[BATCH_LANES], msaa_triangle out[BATCH_LANES]);
    // 1 sample: a band's bins (never null), and one narrow triangle's rows (null: the
    // rows kernel of the build, fill_fast_rows).
    void (*fill_fast_bins)(canvas_t &canvas, zbuffer &depth, const band_bin *bins, int bin_count, depth_func test,
                           int y0, int y1, band_prefetch &ahead);
    void (*fill_rows_narrow)(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, depth_func test,
                             bool depth_write, int y0, int y1);
    // Multisampled: the row fill for 4, 8 or 16 samples and a test other than never (null:
    // the portable fill), whether 4-sample tiles are stored in 2 × 2 blocks, and the
    // resolves (null / false: the portable per-pixel resolve).
    msaa_row_fill (*msaa_fill)(int samples, depth_func test);
    bool msaa_blocks4;
    bool resolve_rows_simd;  // rows resolved four samples at a time (SSE2)
    void (*resolve_blocks4)(float *p, const std::uint8_t *touched0, const std::uint8_t *touched1, int pixels,
                            float clear_colour, float *colour0, float *z0, float *colour1, float *z1);
    // (rows layout, 8 and 16 samples) a row's first `pixels` columns (a multiple of 8), null:
    // SSE2's. (No table has one for a rows tile of 4: those with an eight-pixel 4× resolve
    // store blocks.)
    void (*resolve_rows8)(float *p, const std::uint8_t *touched, int pixels, float clear_colour, float *colour,
                          float *z);
    void (*resolve_rows16)(float *p, const std::uint8_t *touched, int pixels, float clear_colour, float *colour,
                           float *z);
    // Textures: the anisotropic filter's taps over one mip level (null: walk_taps_portable).
    float (*walk_taps)(const tap_walk &w);
};

// The table of `simd` (every one exists; kernels_run says whether this CPU and build run it).
const kernel_table &kernels_for(raster_simd simd);
bool kernels_run(raster_simd simd);
// The best table this CPU runs, or the one TINY3D_KERNELS names if it runs here.
const kernel_table &default_kernels();
// What TINY3D_KERNELS held (empty when unset) and whether default_kernels() is that table.
struct kernel_request {
    std::string requested;
    bool honoured = false;
};
const kernel_request &default_kernels_request();

// The tabulated line kernels of one line_simd (src/lines/line_tabulated_*.cpp).
struct line_kernels {
    // One prepared stroke on a canvas at least 4 pixels wide (narrower: draw_portable).
    void (*draw_one)(canvas_t *canvas, const tabulated::stroke_setup &s, const line_table &table);
    // Strokes of 4 × 4 end blocks, `count` ≤ kBatch of them, and the eight-lane set-up
    // (null: draw_one each, prepare_stroke each).
    void (*draw_batch)(canvas_t *canvas, const tabulated::stroke_setup *strokes, int count, const line_table &table);
    unsigned (*prepare8)(const canvas_t &canvas, const line_segment *segments, int n, const line_table &table,
                         tabulated::stroke_setup *out);
};
const line_kernels &line_kernels_for(line_simd simd);
bool line_kernels_run(line_simd simd);

}  // namespace tiny3d::detail

#endif
