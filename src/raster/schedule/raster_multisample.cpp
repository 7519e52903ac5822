// raster_multisample.cpp — the render context's multisampled frames (sample_count x4, x8,
// x16): draw() sets up and bins every draw's triangles (raster_context.cpp, with the
// pattern's sample rows), and end_frame()'s band pass (raster_context.cpp) draws the frame
// band by band here, each band into a per-thread tile of samples that stays in cache, then
// resolves the tile into the canvas and the depth buffer. The kernels are in msaa/.
#include "render_context_impl.h"

namespace tiny3d {

using namespace detail;

void render_context::impl::add_msaa(const msaa_triangle &f, std::uint32_t state, piece &out) {
    const std::uint32_t index = static_cast<std::uint32_t>(out.msaa.size());
    out.msaa.push_back(f);
    out.msaa.back().state = state;
    bin_bands(bands.of(f.min_y), bands.of(f.max_y), index, out);
}

// Every triangle of the frame that reaches the band, in submission order (piece after piece
// of every draw: the opaque fast and per-pixel-path ones in its bins), then the translucent
// queue (sorted), into the tile; then the resolve. The set-up triangle TRIANGLES_AHEAD bin
// entries on is fetched meanwhile (the frame's list outgrows the caches, and a bin skips
// through it where the hardware prefetcher does not follow).
void render_context::impl::draw_multisampled_band(int band, sample_store &tile) {
    const int y0 = bands.y0(band), y1 = bands.y0(band + 1);
    if (y0 >= y1) return;
    tile.start(y0, y1);
    constexpr int DEPTH_TESTS = static_cast<int>(depth_func::always) + 1;  // (raster.h: never … always)
    msaa_row_fill fill_for[DEPTH_TESTS];
    for (int test = 0; test < DEPTH_TESTS; ++test)
        fill_for[test] = msaa_fill_for(kernels->simd, pattern->count, static_cast<depth_func>(test));
    constexpr int TRIANGLES_AHEAD = 6;
    struct cursor {  // an entry of the band's bins, in drawing order
        int number = 0;
        std::size_t k = 0;
    } later;
    auto bin_of = [&](int number) -> const std::vector<std::uint32_t> & {
        return pieces[static_cast<std::size_t>(number)].bins[band];
    };
    auto advance = [&](cursor &c) {
        for (++c.k; c.number < piece_count && c.k >= bin_of(c.number).size(); c.k = 0) ++c.number;
    };
    later.k = static_cast<std::size_t>(-1);  // (the first entry, then TRIANGLES_AHEAD on)
    for (int n = 0; n <= TRIANGLES_AHEAD; ++n) advance(later);
    for (const piece &from : pieces_of({0, piece_count})) {
        for (std::uint32_t index : from.bins[band]) {
            if (later.number < piece_count) {
                const std::uint32_t on = bin_of(later.number)[later.k];
                if (!(on & GENERIC_BIN)) {
                    const char *line = reinterpret_cast<const char *>(&pieces[static_cast<std::size_t>(later.number)].msaa[on]);
                    __builtin_prefetch(line);
                    __builtin_prefetch(line + sizeof(msaa_triangle) - 1);
                }
                advance(later);
            }
            if (index & GENERIC_BIN) {
                const generic_triangle &g = from.generic[index & ~GENERIC_BIN];
                draw_generic_samples(tile, *pattern, states[g.state], g, y0, y1);
                continue;
            }
            const msaa_triangle &f = from.msaa[index];
            const depth_func test = states[f.state].depth;
            fill_for[static_cast<int>(test)](tile, f, *pattern, test, true, y0, y1);
        }
    }
    for (const generic_triangle &g : translucent)
        draw_generic_samples(tile, *pattern, states[g.state], g, y0, y1);
    tile.resolve(*target, depth, kernels->simd);
}

}  // namespace tiny3d
