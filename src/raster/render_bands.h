// render_bands.h — how the render context shares a frame between threads: the frame is cut
// into horizontal bands, each owned by one thread, and a thread done with its own bands
// draws (steals) other threads' bands not yet claimed. Not installed.
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
// Blocks of neighbouring bands per thread: 2 (256-row blocks at 1024 px on two threads) lets
// a thread skip whole cluster chunks (~100 rows high at Scene S level 6) far more often than
// 4 did, and fewer triangles straddle two owners; per-thread work stayed as even on Scene S
// and on the sphere moved off-centre (documentation/raster.md).
inline constexpr int BLOCKS_PER_THREAD = 2;
static_assert(MAX_BANDS <= 256, "band_layout stores band numbers in 8 bits");

// Which rows form each band and which thread owns it (set once per frame).
struct band_layout {
    int count = 1;
    int height = 0;
    std::vector<std::uint8_t> row_band;  // the band holding each row (inverse of y0)
    std::uint8_t owner[MAX_BANDS];       // the thread that sets up each band's triangles

    // Bands of band_rows rows (at least one per thread, at most MAX_BANDS and `height`);
    // threads own blocks of neighbouring bands, dealt in turn (BLOCKS_PER_THREAD each when
    // there are enough bands): few triangles straddle two owners, and the load stays even
    // when the scene is not.
    void plan(int rows, int threads, int band_rows = BAND_ROWS) {
        height = rows;
        count = std::clamp(rows / band_rows, threads, MAX_BANDS);
        count = std::min(count, std::max(rows, 1));
        if (row_band.size() < static_cast<std::size_t>(rows)) row_band.resize(rows);
        for (int b = 0; b < count; ++b)
            for (int y = y0(b); y < y0(b + 1); ++y) row_band[static_cast<std::size_t>(y)] = static_cast<std::uint8_t>(b);
        const int block = std::max(1, count / (BLOCKS_PER_THREAD * threads));
        for (int b = 0; b < count; ++b) owner[b] = static_cast<std::uint8_t>(b / block % threads);
    }
    int of(int y) const { return row_band[static_cast<std::size_t>(y)]; }
    // First row of band b (b = count: the target's height).
    int y0(int b) const { return static_cast<int>(static_cast<long long>(height) * b / count); }
    // Whether thread t owns a band among rows [first, last] (inclusive, inside the target).
    bool draws_rows(int t, int first, int last) const {
        for (int b = of(first); b <= of(last); ++b)
            if (owner[b] == t) return true;
        return false;
    }
};

// Per draw (numbered by serial): which bands have been claimed for drawing, and which
// threads' set-ups are complete. A band is drawn by its owner or, once the owner's set-up is
// complete, by a thread that has finished its own bands (always from the owner's set-up, in
// submission order, so the pixels do not depend on who draws it).
struct band_claims {
    std::uint32_t serial = 0;
    std::atomic<std::uint32_t> claim[MAX_BANDS] = {};
    struct alignas(CACHE_LINE) ready_flag {
        std::atomic<std::uint32_t> serial{0};
    };
    ready_flag ready[MAX_THREADS];

    // Starts a draw (before the workers run: published to them by worker_pool::run).
    void next_draw() {
        if (++serial == 0) {  // wrapped: 0 is what the flags start from
            for (auto &c : claim) c.store(0, std::memory_order_relaxed);
            for (auto &r : ready) r.serial.store(0, std::memory_order_relaxed);
            serial = 1;
        }
    }
    // True for the one thread that claims band b in this draw.
    bool take(int b) { return claim[b].exchange(serial, std::memory_order_relaxed) != serial; }
    bool taken(int b) const { return claim[b].load(std::memory_order_relaxed) == serial; }
    void mark_ready(int thread) { ready[thread].serial.store(serial, std::memory_order_release); }
    void wait_ready(int thread) const {
        parallel::spin_until_yielding([&] { return ready[thread].serial.load(std::memory_order_acquire) == serial; });
    }
};

// Thread t of n draws its own bands in order, then helps: the other threads' bands not yet
// claimed, from their last band backwards (their owners go forwards), each once its owner's
// set-up is complete. draw_band(band, owner) draws one band from the owner's set-up.
template <class DrawBand>
void draw_bands(const band_layout &layout, band_claims &claims, int t, int n, DrawBand &&draw_band) {
    for (int band = 0; band < layout.count; ++band)
        if (layout.owner[band] == t && claims.take(band)) draw_band(band, t);
    for (int k = 1; k < n; ++k) {
        const int owner = (t + k) % n;
        bool ready = false;
        for (int band = layout.count - 1; band >= 0; --band) {
            if (layout.owner[band] != owner || claims.taken(band)) continue;
            if (!ready) {
                claims.wait_ready(owner);
                ready = true;
            }
            if (claims.take(band)) draw_band(band, owner);
        }
    }
}

}  // namespace tiny3d::detail

#endif
