// fill.h — the 1-sample fill stage (internal). In: set-up fast_triangles (setup/setup.h),
// binned by band (band_bin), and a band's rows. Out: shaded, depth-tested pixels in the
// canvas and the depth buffer. The kernels: fill/raster_fill.cpp (portable and SSE2),
// raster_fill_avx2.cpp, raster_fill_avx512.cpp (narrow_rows.inc: the narrow rows kernel
// SSE2 and AVX2 share, over the register width), chosen through the kernel table
// (src/kernels.h). Called by the render context's band loop (schedule/raster_context.cpp)
// and the public fill_triangle. Not installed.
#ifndef TINY3D_RASTER_FILL_H
#define TINY3D_RASTER_FILL_H

#include <cstddef>
#include <cstdint>
#include <memory>

#include "../setup/setup.h"
#include "../../simd_config.h"

#ifdef TINY3D_SSE2
#include <emmintrin.h>
#endif
#ifdef TINY3D_AVX2
#include <immintrin.h>
#endif

namespace tiny3d::detail {

// Draws rows [y0, y1) ∩ [min_y, max_y] of the triangle with the build's rows kernel (SSE2's,
// or the portable one), which every table uses for the triangles its narrow kernel does not
// take. `wide_edges` is the triangle's 64-bit edges when f.wide ≥ 0 (ignored otherwise).
void fill_fast_rows(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, const triangle_edges *wide_edges,
                         depth_func test, bool depth_write, int y0, int y1);

// The colour and depth lines of the band a thread draws next, brought into its cache a few
// at a time while it draws the current band, so that the next band's clear finds them
// there instead of waiting for each line (a band's clear touches every line of it at once,
// faster than the hardware prefetcher ramps up).
struct band_prefetch {
    static constexpr int LINES_PER_TRIANGLE = 4;  // of each buffer, per triangle drawn
    const char *colour = nullptr, *depth = nullptr;
    std::size_t lines = 0, next = 0;  // 64-byte lines in each; the next one to fetch

    band_prefetch() = default;
    band_prefetch(const float *colour_rows, const float *depth_rows, std::size_t floats)
        : colour(reinterpret_cast<const char *>(colour_rows)), depth(reinterpret_cast<const char *>(depth_rows)),
          lines(floats * sizeof(float) / 64) {}
    void step() {
        for (int k = 0; k < LINES_PER_TRIANGLE && next < lines; ++k, ++next) {
            __builtin_prefetch(colour + 64 * next, 1, 3);
            __builtin_prefetch(depth + 64 * next, 1, 3);
        }
    }
};

// A piece's set-up triangles that another thread is expected to draw (render_bands.h),
// appended with streaming stores: they go to memory without first taking the lines into the
// writing core's cache. Reading a line makes a copy in the reader's cache, and a core that
// later stores into that line waits until the copy is gone, one line at a time; when the two
// cores have separate last-level caches that round trip is several times a shared cache's
// and dominates the next frame's set-up. Storage is grown (normal stores) and never shrunk; the
// elements are not zeroed first (a zeroing store would bring the line back into the cache).
// Portable build: plain stores. A reader on another thread needs stream_fence() by the writer
// before the release that publishes the list.
class streamed_triangles {
public:
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    const fast_triangle *data() const { return data_.get(); }
    void clear() { size_ = 0; }
    // Appends f; returns its index.
    std::size_t append(const fast_triangle &f) {
        if (size_ == capacity_) grow();
        fast_triangle *to = data_.get() + size_;
#ifdef TINY3D_SSE2
        const __m128i *from = reinterpret_cast<const __m128i *>(&f);
        __m128i *out = reinterpret_cast<__m128i *>(to);
        for (std::size_t k = 0; k < sizeof(fast_triangle) / 16; ++k) _mm_stream_si128(out + k, _mm_load_si128(from + k));
#else
        *to = f;
#endif
        return size_++;
    }

    // Room for n triangles without growing.
    void reserve(std::size_t n) {
        if (n > capacity_) grow(n);
    }

private:
    void grow() { grow(std::max<std::size_t>(2 * capacity_, 64)); }
    void grow(std::size_t n) {
        std::unique_ptr<fast_triangle[]> bigger(new fast_triangle[n]);  // (not zeroed)
        std::copy(data_.get(), data_.get() + size_, bigger.get());
        data_ = std::move(bigger);
        capacity_ = n;
    }
    std::unique_ptr<fast_triangle[]> data_;
    std::size_t size_ = 0, capacity_ = 0;
};
static_assert(sizeof(fast_triangle) % 16 == 0, "streamed_triangles stores 16-byte blocks");

// Orders a thread's streaming stores before its later stores (the release that tells the
// other threads the data is ready).
inline void stream_fence() {
#ifdef TINY3D_SSE2
    _mm_sfence();
#endif
}

// A band bin entry with FAR_ENTRY set names a triangle of the piece's streamed list.
inline constexpr std::uint32_t FAR_ENTRY = 1u << 30;

// The triangles of one piece that reach a band: triangle(index[k]) for k < count (count ≥ 1),
// `wide` holding the 64-bit edges of the triangles with wide ≥ 0.
struct band_bin {
    const fast_triangle *tris = nullptr;  // the piece's triangles stored normally
    const fast_triangle *far = nullptr;   // and those streamed (FAR_ENTRY)
    const triangle_edges *wide = nullptr;
    const std::uint32_t *index = nullptr;
    std::size_t count = 0;
    const fast_triangle &triangle(std::uint32_t entry) const {
        return entry & FAR_ENTRY ? far[entry & ~FAR_ENTRY] : tris[entry];
    }
};

// draw(bin, triangle) for every triangle of bins[0..bin_count), bin after bin and each in its
// order, ahead.step() before each: the band loop of fill_fast_bins' portable and SSE2 kernels
// (the AVX-512 one walks the same order with a prefetch that looks into the next bin).
template <class Draw>
inline void for_each_bin_triangle(const band_bin *bins, int bin_count, band_prefetch &ahead, Draw &&draw) {
    for (int j = 0; j < bin_count; ++j)
        for (std::size_t k = 0; k < bins[j].count; ++k) {
            ahead.step();
            draw(bins[j], bins[j].triangle(bins[j].index[k]));
        }
}

// Draws rows [y0, y1) of every triangle of bins[0..bin_count) (none empty), bin after bin and
// each in its order, with depth (the render context's band loop, kernel_table::fill_fast_bins):
// fill_fast_rows for each, the depth test chosen once per band; ahead.step() after each
// triangle. The portable, SSE2, AVX2 and AVX-512 kernels.
void fill_fast_bins_portable(canvas_t &canvas, zbuffer &depth, const band_bin *bins, int bin_count, depth_func test,
                             int y0, int y1, band_prefetch &ahead);
#ifdef TINY3D_SSE2
void fill_fast_bins_sse2(canvas_t &canvas, zbuffer &depth, const band_bin *bins, int bin_count, depth_func test,
                         int y0, int y1, band_prefetch &ahead);
#endif

// Triangles at most NARROW_WIDTH px wide whose groups of four from min_x stay inside the
// canvas (`width`) are drawn by the narrow kernels: every row as the same groups, the lanes
// outside the row's span masked off.
inline constexpr int NARROW_WIDTH = 16;
inline bool narrow_fits(const fast_triangle &f, int width) {
    return f.max_x - f.min_x < NARROW_WIDTH && f.min_x + 4 * ((f.max_x - f.min_x + 4) / 4) <= width;
}

#ifdef TINY3D_AVX2
// The SSE2 kernel's depth compares (cmpltps … cmpneqps: ordered and signalling but for
// not_equal, which is true on NaN) as one predicate of vcmpps, for the AVX2 and AVX-512
// kernels.
template <depth_func Test>
constexpr int depth_predicate() {
    if constexpr (Test == depth_func::less) return _CMP_LT_OS;
    else if constexpr (Test == depth_func::less_equal) return _CMP_LE_OS;
    else if constexpr (Test == depth_func::equal) return _CMP_EQ_OQ;
    else if constexpr (Test == depth_func::greater) return _CMP_GT_OS;
    else if constexpr (Test == depth_func::greater_equal) return _CMP_GE_OS;
    else if constexpr (Test == depth_func::not_equal) return _CMP_NEQ_UQ;
    else if constexpr (Test == depth_func::always) return _CMP_TRUE_UQ;
    else return _CMP_FALSE_OQ;
}

// The AVX2 band kernel for the narrow triangles (raster_fill_avx2.cpp: narrow_rows.inc with
// two groups of four per register; SSE2's for the others).
void fill_fast_bins_avx2(canvas_t &canvas, zbuffer &depth, const band_bin *bins, int bin_count, depth_func test,
                         int y0, int y1, band_prefetch &ahead);
#endif

#ifdef TINY3D_AVX512
// The AVX-512 kernel (raster_fill_avx512.cpp) for a triangle that narrow_fits, rows
// [y0, y1) within f's.
void fill_rows_narrow_avx512(canvas_t &canvas, zbuffer *depth, const fast_triangle &f, depth_func test,
                             bool depth_write, int y0, int y1);
// The AVX-512 band kernel for the narrow triangles (SSE2's for the others).
void fill_fast_bins_avx512(canvas_t &canvas, zbuffer &depth, const band_bin *bins, int bin_count, depth_func test,
                           int y0, int y1, band_prefetch &ahead);
#endif

// dst[0..count) := value (SSE2 stores when available).
void fill_floats(float *dst, std::size_t count, float value);

}  // namespace tiny3d::detail

#endif
