// render_bands.h — how the render context shares a draw between threads ("sort-middle"):
// the draw's triangles are cut into pieces (runs of consecutive cluster chunks, or of
// triangles), dealt to the threads in runs of neighbouring pieces (phase_counters); a thread
// sets up the triangles of a piece into that piece's own lists and bins them by the
// horizontal bands of the frame they reach. Once every piece is set up, each thread claims
// bands, those it drew in the frame before and those holding most of its own triangles first
// (band_affinity); a band is drawn by one thread, piece after piece in piece order — the
// draw's submission order — so the pixels depend neither on the number of threads nor on
// which thread set up or drew what, and a piece's lists grow to the same sizes every frame
// whoever sets it up (no allocation in a steady scene). Not installed.
#ifndef TINY3D_RENDER_BANDS_H
#define TINY3D_RENDER_BANDS_H

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "../../parallel/worker_pool.h"

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

// What one thread knows of the bands when it starts drawing: how many bin entries of each
// band it set up itself (its own pieces' triangles, still in its cache), and from that the
// order in which it claims bands — the bands it drew last time, then most of its own
// entries first (rank) — so that a band is mostly drawn by the thread that set up its
// triangles instead of fetching them from another core's cache (reading lines another core
// has just written takes ~3× as long as reading one's own), and by the same thread as in
// the frame before. Only speed depends on it: a band's pixels do not depend on who draws it.
// On a cache line of its own per thread.
struct alignas(CACHE_LINE) band_affinity {
    std::uint32_t own[MAX_BANDS] = {};  // bin entries per band in the pieces this thread set up
    std::uint8_t order[MAX_BANDS] = {};
    int cursor = 0;  // order[cursor..] are still to be tried
    // The bands this thread drew in its last band phase: where its next set-up expects to
    // draw (none before the first; detail::streamed_triangles).
    std::uint8_t drew[MAX_BANDS] = {};

    void forget(int count) { std::fill(own, own + count, 0u); }
    template <class Bins>
    void count(const Bins &bins, int count) {
        for (int b = 0; b < count; ++b) own[b] += static_cast<std::uint32_t>(bins[b].size());
    }
    // The claiming order, for `count` bands:
    //  - kept_then_own: the bands this thread drew in its last band phase (drew) first, then
    //    the others, each group by own entries (most first; ties: top band first). A band
    //    stays with one thread from frame to frame, and with it its colour and depth rows,
    //    which the next clear and fill then find in that core's caches instead of the
    //    other core's: Scene S level 6 on two threads drew 3–5 of its 32 bands on the other
    //    thread than the frame before when ranked by own entries alone;
    //  - own_entries: by own entries alone (multisampled frames, whose band phase comes
    //    after all their draws' set-ups: drew may describe another band layout);
    //  - top_down: top to bottom (one thread; translucent triangles, which are not binned).
    enum class claim_order { top_down, own_entries, kept_then_own };
    void rank(int count, claim_order how) {
        for (int b = 0; b < count; ++b) order[b] = static_cast<std::uint8_t>(b);
        const bool kept_first = how == claim_order::kept_then_own;
        if (how != claim_order::top_down)
            std::sort(order, order + count, [&](int a, int b) {
                if (kept_first && drew[a] != drew[b]) return drew[a] > drew[b];
                return own[a] != own[b] ? own[a] > own[b] : a < b;
            });
        cursor = 0;
    }
};

// The shared state of one draw's phase, each on a cache line of its own: the pieces dealt
// to the threads, which bands are taken, and how many pieces (and vertex ranges) are done.
// Reset by the caller before the workers start (published to them by worker_pool::run).
//
// Pieces: thread t's home run is pieces [t·P/n, (t+1)·P/n) — consecutive pieces are
// neighbouring triangles of the mesh, so a thread's pieces reach few bands and the same
// thread sets up about the same pieces every frame. It takes its run from the front; a
// thread whose run is done takes the last pieces of the runs before its own (t − 1, t − 2,
// …, the run that ends where its own begins first), so nobody waits while pieces are left.
// Each run is one 64-bit atomic [next, end): the owner and the takers never get one piece twice.
struct phase_counters {
    struct alignas(CACHE_LINE) piece_run {
        std::atomic<std::uint64_t> range{0};  // next | end << 32
    };
    piece_run runs[MAX_THREADS];
    alignas(CACHE_LINE) std::atomic<int> pieces_done{0};
    alignas(CACHE_LINE) std::atomic<int> vertex_ranges_done{0};
    std::atomic<bool> bad_indices{false};  // a piece found a vertex index out of range
    alignas(CACHE_LINE) std::atomic<std::uint8_t> band_taken[MAX_BANDS] = {};

    // A new phase of `pieces` pieces shared by `threads` threads, over `bands` bands.
    void reset(int pieces, int threads, int bands) {
        bad_indices.store(false, std::memory_order_relaxed);
        for (int t = 0; t < threads; ++t) {
            const std::uint64_t first = static_cast<std::uint64_t>(pieces) * t / threads;
            const std::uint64_t end = static_cast<std::uint64_t>(pieces) * (t + 1) / threads;
            runs[t].range.store(first | end << 32, std::memory_order_relaxed);
        }
        pieces_done.store(0, std::memory_order_relaxed);
        vertex_ranges_done.store(0, std::memory_order_relaxed);
        for (int b = 0; b < bands; ++b) band_taken[b].store(0, std::memory_order_relaxed);
    }
    // The next piece for `thread` of `threads`, or −1 when every piece is taken.
    int take_piece(int thread, int threads) {
        if (const int k = take(runs[thread].range, true); k >= 0) return k;
        for (int i = 1; i < threads; ++i)
            if (const int k = take(runs[(thread - i + threads) % threads].range, false); k >= 0) return k;
        return -1;
    }
    // The next band in `mine`'s order that no thread has taken, or `count` when none is left.
    int take_band(band_affinity &mine, int count) {
        while (mine.cursor < count) {
            const int b = mine.order[mine.cursor++];
            if (band_taken[b].load(std::memory_order_relaxed) == 0 &&
                band_taken[b].exchange(1, std::memory_order_relaxed) == 0)
                return b;
        }
        return count;
    }
    // While waiting() holds: the next band in `mine`'s order that no thread has taken, given
    // to work(band) and recorded in claimed[] — at most `share` bands, this thread's part of
    // `count` among `threads`, so that a thread which waits long (the others' set-up
    // unfinished: one descheduled, or started late) cannot take every band and leave the
    // others nothing to draw. Returns how many it claimed.
    template <class Waiting, class Work>
    int claim_while(band_affinity &mine, int count, int threads, Waiting &&waiting, Work &&work, int claimed[]) {
        const int share = (count + threads - 1) / threads;
        int n = 0;
        while (n < share && waiting()) {
            const int band = take_band(mine, count);
            if (band >= count) break;
            work(band);
            claimed[n++] = band;
        }
        return n;
    }
    // Waits (spinning, then yielding) until `counter` reaches n; the acquire pairs with the
    // release of the increments, so everything written before them is visible.
    static void wait_for(const std::atomic<int> &counter, int n) {
        parallel::spin_until_yielding([&] { return counter.load(std::memory_order_acquire) >= n; });
    }

private:
    // One piece of a run, from its front (its owner) or its back (another thread).
    static int take(std::atomic<std::uint64_t> &range, bool front) {
        std::uint64_t v = range.load(std::memory_order_relaxed);
        for (;;) {
            const std::uint32_t next = static_cast<std::uint32_t>(v), end = static_cast<std::uint32_t>(v >> 32);
            if (next >= end) return -1;
            const std::uint64_t taken = front ? v + 1 : v - (std::uint64_t{1} << 32);
            if (range.compare_exchange_weak(v, taken, std::memory_order_relaxed))
                return static_cast<int>(front ? next : end - 1);
        }
    }
};

}  // namespace tiny3d::detail

#endif
