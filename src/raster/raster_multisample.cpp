// raster_multisample.cpp — the render context's multisampled frames (sample_count x4, x8,
// x16): draw() sets up and bins every draw's triangles (raster_context.cpp, with the
// pattern's sample rows), and end_frame() draws the frame band by band, each band into a
// per-thread tile of samples that stays in cache, then resolves the tile into the canvas
// and the depth buffer. The kernels are in msaa.cpp.
#include "render_context_impl.h"

namespace tiny3d {

using namespace detail;

void render_context::impl::add_msaa(msaa_triangle &f, std::uint32_t state, segment &out) {
    f.state = state;
    const std::uint32_t index = static_cast<std::uint32_t>(out.msaa.size());
    out.msaa.push_back(f);
    for (int b = bands.of(f.min_y); b <= bands.of(f.max_y); ++b) out.bins[b].push_back(index);
}

void render_context::impl::bin_generic(const std::int32_t X[3], const std::int32_t Y[3], segment &out) {
    int x0, x1, y0, y1;
    msaa_bounds(X, Y, *pattern, {0, 0, target->width, target->height}, x0, x1, y0, y1);
    if (x0 > x1 || y0 > y1) return;
    const std::uint32_t index = static_cast<std::uint32_t>(out.generic.size() - 1) | GENERIC_BIN;
    for (int b = bands.of(y0); b <= bands.of(y1); ++b) out.bins[b].push_back(index);
}

// Every triangle of the frame that reaches the band, in submission order (its owner set up
// all of them: the opaque fast and per-pixel-path ones in its bins), then the translucent
// queue (sorted), into the tile; then the resolve.
void render_context::impl::draw_multisampled_band(int band, sample_store &tile) {
    const int y0 = bands.y0(band), y1 = bands.y0(band + 1);
    if (y0 >= y1) return;
    tile.start(y0, y1);
    const segment &from = segments[bands.owner[band]];
    for (std::uint32_t index : from.bins[band]) {
        if (index & GENERIC_BIN) {
            const generic_triangle &g = from.generic[index & ~GENERIC_BIN];
            draw_generic_samples(tile, *pattern, clear_intensity, states[g.state], g, y0, y1);
            continue;
        }
        const msaa_triangle &f = from.msaa[index];
        fill_msaa_rows(tile, f, *pattern, states[f.state].depth, true, clear_intensity, y0, y1, kernel);
    }
    for (const generic_triangle &g : translucent)
        draw_generic_samples(tile, *pattern, clear_intensity, states[g.state], g, y0, y1);
    tile.resolve(*target, depth, clear_intensity, kernel);
}

// Bands from a shared queue: a band's pixels depend only on its own bins, so not on which
// thread draws it; the queue keeps the threads' loads even.
void render_context::impl::end_multisampled_frame() {
    next_band.store(0, std::memory_order_relaxed);
    auto phase = [&](int thread) {
        for (int band; (band = next_band.fetch_add(1, std::memory_order_relaxed)) < bands.count;)
            draw_multisampled_band(band, tiles[thread]);
    };
    pool.run(phase);
    pending_clear = false;
    segments_hold_frame = false;
    translucent.clear();
    target = nullptr;
}

}  // namespace tiny3d
