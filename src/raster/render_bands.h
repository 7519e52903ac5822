// render_bands.h — how the render context shares a draw between threads ("sort-middle"):
// the draw's triangles are cut into pieces (runs of consecutive cluster chunks, or of
// triangles), handed out to the threads one at a time; a thread sets up the triangles of a
// piece into that piece's own lists and bins them by the horizontal bands of the frame they
// reach. Once every piece is set up, the bands are handed out; a band is drawn by one
// thread, piece after piece in piece order — the draw's submission order — so the pixels
// depend neither on the number of threads nor on which thread set up or drew what, and a
// piece's lists grow to the same sizes every frame whoever sets it up (no allocation in a
// steady scene). Not installed.
#ifndef TINY3D_RENDER_BANDS_H
#define TINY3D_RENDER_BANDS_H

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "../parallel/worker_pool.h"

namespace tiny3d::detail {

inline constexpr int MAX_THREADS = 16;
inline constexpr std::size_t CACHE_LINE = 64;  // bytes
// The frame is cut into horizontal bands of BAND_ROWS rows (at most MAX_BANDS), so that one
// band's colour and depth rows stay in cache while all its triangles are drawn.
inline constexpr int BAND_ROWS = 32;
inline constexpr int MAX_BANDS = 128;
static_assert(MAX_BANDS <= 256, "band_layout stores band numbers in 8 bits");
// Pieces per thread in a draw on more than one thread: enough that a thread whose pieces
// were cheap (back-facing chunks) takes more of them, few enough that the per-piece
// bookkeeping (a bin per band, visited by every band's draw) stays small. One thread sets
// up a draw as one piece.
inline constexpr int PIECES_PER_THREAD = 8;
// Without clusters, a piece is at least this many triangles.
inline constexpr std::size_t MIN_PIECE_TRIANGLES = 512;

// Which rows form each band (set once per frame).
struct band_layout {
    int count = 1;
    int height = 0;
    std::vector<std::uint8_t> row_band;  // the band holding each row (inverse of y0)

    // Bands of band_rows rows, at least min_count (one per thread: a small target still
    // keeps every thread busy), at most MAX_BANDS and `rows`.
    void plan(int rows, int min_count, int band_rows = BAND_ROWS) {
        height = rows;
        count = std::clamp(rows / band_rows, min_count, MAX_BANDS);
        count = std::min(count, std::max(rows, 1));
        if (row_band.size() < static_cast<std::size_t>(rows)) row_band.resize(rows);
        for (int b = 0, end = y0(0); b < count; ++b) {  // (one division per band, not per row)
            const int start = end;
            end = y0(b + 1);
            std::fill(row_band.begin() + start, row_band.begin() + end, static_cast<std::uint8_t>(b));
        }
    }
    int of(int y) const { return row_band[static_cast<std::size_t>(y)]; }
    // First row of band b (b = count: the target's height).
    int y0(int b) const { return static_cast<int>(static_cast<long long>(height) * b / count); }
};

// The shared counters of one draw's phase, each on a cache line of its own: the next piece
// and band to hand out, and how many pieces (and vertex ranges) are done. Reset by the
// caller before the workers start (published to them by worker_pool::run).
struct phase_counters {
    alignas(CACHE_LINE) std::atomic<int> next_piece{0};
    alignas(CACHE_LINE) std::atomic<int> pieces_done{0};
    alignas(CACHE_LINE) std::atomic<int> next_band{0};
    alignas(CACHE_LINE) std::atomic<int> vertex_ranges_done{0};
    std::atomic<bool> bad_indices{false};  // a piece found a vertex index out of range

    void reset() {
        bad_indices.store(false, std::memory_order_relaxed);
        next_piece.store(0, std::memory_order_relaxed);
        pieces_done.store(0, std::memory_order_relaxed);
        next_band.store(0, std::memory_order_relaxed);
        vertex_ranges_done.store(0, std::memory_order_relaxed);
    }
    // Calls take(k) for k = 0, 1, … up to n − 1, each k once over all threads.
    template <class Take>
    void hand_out(std::atomic<int> &next, int n, Take &&take) {
        for (int k; (k = next.fetch_add(1, std::memory_order_relaxed)) < n;) take(k);
    }
    // Waits (spinning, then yielding) until `counter` reaches n; the acquire pairs with the
    // release of the increments, so everything written before them is visible.
    static void wait_for(const std::atomic<int> &counter, int n) {
        parallel::spin_until_yielding([&] { return counter.load(std::memory_order_acquire) >= n; });
    }
};

}  // namespace tiny3d::detail

#endif
