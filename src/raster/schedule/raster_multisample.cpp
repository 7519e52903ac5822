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
    constexpr std::size_t TRIANGLES_AHEAD = 6;
    // (Locals, not members: the fills are calls through pointers, after which members would be
    // loaded again.)
    const sample_pattern &pat = *pattern;
    const draw_params *const state_of = states.data();
    for (const piece &from : pieces_of({0, piece_count})) {
        const std::uint32_t *const bin = from.bins[band].data();
        const msaa_triangle *const triangles = from.msaa.data();
        const std::size_t entries = from.bins[band].size();
        for (std::size_t i = 0; i < entries; ++i) {
            // The set-up triangle TRIANGLES_AHEAD entries on in the bin, fetched meanwhile.
            if (i + TRIANGLES_AHEAD < entries && !(bin[i + TRIANGLES_AHEAD] & GENERIC_BIN)) {
                const char *line = reinterpret_cast<const char *>(triangles + bin[i + TRIANGLES_AHEAD]);
                __builtin_prefetch(line);
                __builtin_prefetch(line + sizeof(msaa_triangle) - 1);
            }
            const std::uint32_t index = bin[i];
            if (index & GENERIC_BIN) {
                const generic_triangle &g = from.generic[index & ~GENERIC_BIN];
                draw_generic_samples(tile, pat, state_of[g.state], g, y0, y1);
                continue;
            }
            const msaa_triangle &f = triangles[index];
            const depth_func test = state_of[f.state].depth;
            fill_for[static_cast<int>(test)](tile, f, pat, test, y0, y1);
        }
    }
    for (const generic_triangle &g : translucent)
        draw_generic_samples(tile, *pattern, states[g.state], g, y0, y1);
    tile.resolve(*target, depth, kernels->simd);
}

}  // namespace tiny3d
