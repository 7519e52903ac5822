// render_bands.h — how the render context shares a draw between threads ("sort-middle"):
// the draw's triangles are cut into pieces, dealt to the threads in runs of neighbouring
// pieces (phase_counters); a thread sets up a piece into its own lists, binned by band.
// Then each thread claims bands (band_affinity); a band is drawn by one thread, piece after
// piece in submission order, so the pixels do not depend on the number of threads or on who
// set up what, and a piece's lists grow to the same sizes every frame. Not installed.
#ifndef TINY3D_RENDER_BANDS_H
#define TINY3D_RENDER_BANDS_H

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
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
// Pieces per thread on several threads: enough that a thread whose pieces were cheap takes
// more, few enough that the per-piece bins (visited by every band's draw) stay few.
inline constexpr int PIECES_PER_THREAD = 8;
// Without clusters, a piece is at least this many triangles.
inline constexpr std::size_t MIN_PIECE_TRIANGLES = 512;

// Which rows form each band (set once per frame).
struct band_layout {
    int count = 1;
    int height = 0;
    std::vector<std::uint8_t> row_band;  // the band holding each row (inverse of y0)

    // Bands of band_rows rows, at least min_count (one per thread), at most MAX_BANDS and `rows`.
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

// One thread's claiming order of the bands: those it drew last time, then most of its own
// bin entries first, so a band is mostly drawn by the core that set up its triangles and
// holds its rows in cache. Only speed depends on it.
struct alignas(CACHE_LINE) band_affinity {
    std::uint32_t own[MAX_BANDS] = {};  // bin entries per band in the pieces this thread set up
    std::uint8_t order[MAX_BANDS] = {};
    int cursor = 0;  // order[cursor..] are still to be tried
    // The bands this thread drew in its last band phase (detail::streamed_triangles).
    std::uint8_t drew[MAX_BANDS] = {};

    void forget(int count) { std::fill(own, own + count, 0u); }
    template <class Bins>
    void count(const Bins &bins, int count) {
        for (int b = 0; b < count; ++b) own[b] += static_cast<std::uint32_t>(bins[b].size());
    }
    // kept_then_own: drew first, then by own entries (ties: top first), so a band and its
    // rows stay with one core from frame to frame; own_entries: multisampled frames (drew
    // may describe another band layout); top_down: one thread, or translucent triangles.
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

// The shared state of one draw's phase, each on a cache line of its own. Reset by the
// caller before the workers start (published by worker_pool::run).
// Thread t's home run is pieces [t·P/n, (t+1)·P/n): neighbouring triangles, so its pieces
// reach few bands and are the same every frame. It takes its run from the front, then the
// back of the runs before its own, so nobody waits while pieces are left. Each run is one
// 64-bit atomic [next, end), so no piece is taken twice.
struct phase_counters {
    struct alignas(CACHE_LINE) piece_run {
        std::atomic<std::uint64_t> range{0};  // next | end << 32
    };
    piece_run runs[MAX_THREADS];
    alignas(CACHE_LINE) std::atomic<int> pieces_done{0};
    alignas(CACHE_LINE) std::atomic<int> vertex_ranges_done{0};
    std::atomic<bool> bad_indices{false};  // a piece found a vertex index out of range
    alignas(CACHE_LINE) std::atomic<std::uint8_t> band_taken[MAX_BANDS] = {};

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
    // While waiting() holds, claims bands for work(band) into claimed[] (returns how many):
    // at most this thread's share, so a thread that waits long cannot leave the others none.
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
    // Waits until `counter` reaches n; the acquire pairs with the increments' release.
    static void wait_for(const std::atomic<int> &counter, int n) {
        parallel::spin_until_yielding([&] { return counter.load(std::memory_order_acquire) >= n; });
    }

private:
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
