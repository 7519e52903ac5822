// render_context_impl.h — the schedule stage (internal): the render context's state
// (render_context::impl) and the per-pixel path's triangle. In: the program's draws
// (raster.h). Out: the frame — each draw's vertices transformed (pipeline/vertex_transform.h),
// its triangles set up (setup/) in pieces shared by the threads and binned by band
// (render_bands.h), then each band drawn by one thread through the kernel table (fill/,
// msaa/) or the per-pixel path (raster_pixel_path.cpp). Called by the public render_context
// (raster_context.cpp, raster_multisample.cpp). Not installed.
#ifndef TINY3D_RENDER_CONTEXT_IMPL_H
#define TINY3D_RENDER_CONTEXT_IMPL_H

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <span>
#include <vector>

#include "../../parallel/worker_pool.h"
#include "../../pipeline/vertex_transform.h"
#include "../fill/fill.h"
#include "../msaa/msaa.h"
#include "cluster_view.h"
#include "render_bands.h"

namespace tiny3d {

namespace detail {

// Guard band: the x/y clip planes sit at |x|, |y| ≤ guard·w, chosen so that the whole band
// spans fewer pixels than the 32-bit fill allows; never tighter than the frustum itself.
inline constexpr float GUARD_SPAN_PIXELS = 2000.0f;
inline constexpr float MAX_GUARD = 4.0f;

// The vertex stage's job for drawing m with p through mvp; `generic`: the per-pixel path's
// attributes are wanted. m and p must outlive the job.
inline vertex_job make_vertex_job(const raster_mesh &m, const draw_params &p, const mat4_t &mvp, bool generic,
                                  int width, int height, int subpixel_bits) {
    vertex_job job;
    job.positions = m.positions.data();
    job.normals = m.normals.data();
    job.uvs = m.uvs.data();
    job.mvp = mvp;
    job.model = p.model;
    job.nt = make_normal_transform(p.model);
    job.lights = &p.lights;
    job.surface = &p.surface;
    job.width = width;
    job.height = height;
    job.subpixel_bits = subpixel_bits;
    job.gouraud = p.shade == shading::gouraud;
    job.generic = generic;
    job.material_lit = job.gouraud && !material_is_lambert(p.surface);
    job.eye = job.material_lit ? viewer_of(p.view_projection) : viewer{};
    job.directional_gouraud = job.gouraud && !generic && !job.material_lit &&
                              std::all_of(p.lights.lights, p.lights.lights + p.lights.count,
                                          [](const light_t &l) { return l.kind == light_kind::directional; });
    return job;
}

// A triangle for the per-pixel path (Phong, textures, translucency).
struct generic_triangle {
    screen_vertex v[3];
    float attr[3][ATTR_COUNT];
    float mean_depth;
    std::uint32_t state;     // index into the frame's draw states
    std::uint32_t sequence;  // submission order among the translucent ones (sort tie-break)
};

generic_triangle make_generic_triangle(const screen_vertex v[3], const clip_vertex *const c[3], std::uint32_t state);

// Draws rows [y0, y1) of g: per pixel depth test, perspective-correct attributes, shade,
// texture, then opaque write or "over" blend with p.alpha (colour only).
void draw_generic_rows(canvas_t &target, zbuffer &depth, const draw_params &p, const generic_triangle &g, int y0,
                       int y1);
// The same into a tile of samples: coverage and depth per sample, the shade once per pixel.
void draw_generic_samples(sample_store &tile, const sample_pattern &pat, const draw_params &p,
                          const generic_triangle &g, int y0, int y1);

// Multisampled bands of band_rows(samples) rows: one band's samples stay in the core's
// caches while its triangles are drawn (16 rows at 8× and 16×), yet at 4× 32 rows still fit
// and halve the triangles straddling a band edge. A bin entry with GENERIC_BIN set names a
// per-pixel-path triangle.
inline constexpr int MSAA_BAND_ROWS = 16;
inline constexpr int band_rows(int samples) { return samples == 1 || samples == 4 ? BAND_ROWS : MSAA_BAND_ROWS; }
inline constexpr std::uint32_t GENERIC_BIN = 1u << 31;

// A draw's pieces [first, first + count) of the frame's, each `size` cluster chunks or
// triangles; shared_vertices: the threads first transform a range of vertices each into
// segment 0's arrays, which every piece reads (no clusters, several threads).
struct draw_plan {
    int first = 0, count = 0;
    std::size_t size = 0;
    bool shared_vertices = false;
};

}  // namespace detail

struct render_context::impl {
    explicit impl(int threads) : pool(threads) {}

    parallel::worker_pool pool;
    canvas_t *target = nullptr;
    zbuffer depth;
    bool pending_clear = false;
    float clear_intensity = 0.0f;
    float guard = 1.0f;
    frame_stats stats;
    // Multisampled frames: draw() only sets up and bins; end_frame() draws band by band into
    // a per-thread tile of samples and resolves it (raster_multisample.cpp).
    const detail::sample_pattern *pattern = &detail::pattern_of(1);
    detail::sample_store tiles[detail::MAX_THREADS];
    const detail::kernel_table *kernels = &detail::default_kernels();  // every fill's (use_simd)
    bool multisampled() const { return pattern->count > 1; }

    // One thread's transformed vertices, on a cache line of its own: the vector headers are
    // read per triangle (no false sharing).
    struct alignas(detail::CACHE_LINE) segment {
        std::vector<detail::xvertex> vertices;
        std::vector<vec4_t> clip;
        std::vector<float> vertex_attr;         // ATTR_COUNT per vertex (generic path only)
        std::vector<std::uint8_t> walk;         // a piece's cluster chunks: walked or skipped
        // Vertex i is transformed in this draw when stamp[i] == generation, so a vertex shared
        // by several walked chunks is transformed once.
        std::vector<std::uint32_t> stamp;
        std::uint32_t generation = 0;
        std::vector<std::uint32_t> fresh;  // a chunk's vertices not yet transformed
        void begin_draw() {
            if (++generation == 0) std::fill(stamp.begin(), stamp.end(), 0u), generation = 1;
        }
        // The vertices of `list` not yet transformed, marked as transformed now.
        detail::vertex_set not_yet_transformed(const std::uint32_t *list, std::size_t count) {
            if (fresh.size() < count) fresh.resize(count);  // (grown once: the largest chunk)
            std::size_t n = 0;
            for (std::size_t k = 0; k < count; ++k) {  // (branch-free: the fresh ones are mixed)
                const std::uint32_t i = list[k];
                fresh[n] = i;
                n += stamp[i] != generation;
                stamp[i] = generation;
            }
            return {fresh.data(), n};
        }
    };
    // What the set-up of one piece produced, on cache lines of its own.
    struct alignas(detail::CACHE_LINE) piece {
        std::vector<detail::fast_triangle> fast;
        // Fast triangles reaching a band another thread drew last time: likely drawn there
        // again, so streamed when streaming is on; their bin entries carry FAR_ENTRY.
        detail::streamed_triangles far;
        // While set up: band_affinity::drew, or null (none far: one thread, or streaming off).
        const std::uint8_t *near_bands = nullptr;
        std::vector<detail::msaa_triangle> msaa;  // instead of `fast` in multisampled frames
        std::vector<triangle_edges> wide;
        std::vector<detail::generic_triangle> generic;
        std::vector<std::vector<std::uint32_t>> bins;  // per band: fast-triangle indices (multisampled:
                                                       // msaa ones), or generic with GENERIC_BIN
        frame_stats stats;
    };
    segment segments[detail::MAX_THREADS];
    std::vector<piece> pieces;  // the frame's first piece_count are in use (grown, never shrunk)
    int piece_count = 0;
    std::span<piece> pieces_of(const detail::draw_plan &plan) {  // a draw's, or the frame's: {0, piece_count}
        return {pieces.data() + plan.first, static_cast<std::size_t>(plan.count)};
    }
    std::vector<draw_params> states;                    // this frame's draw calls
    std::vector<detail::generic_triangle> translucent;  // queued for end_frame
    detail::band_layout bands;
    detail::phase_counters counters;
    detail::band_affinity affinity[detail::MAX_THREADS];  // per thread, for the bands it claims
    bool streaming = false;  // render_context::use_streaming_stores (several threads, one sample)
    // Memory ran out in the current draw (set by any thread), and the frame's first failure.
    std::atomic<bool> out_of_memory{false};
    status failure;
    void draw(const raster_mesh &mesh, const draw_params &params);  // render_context::draw's work
    // report_progress: the caller's callback and the current pass's progress.
    void (*progress_report)(const render_context::progress &, void *) = nullptr;
    void *progress_user = nullptr;
    std::atomic<int> bands_drawn{0};
    std::size_t pass_triangles = 0;
    void start_pass(std::size_t triangles) {
        bands_drawn.store(0, std::memory_order_relaxed);
        pass_triangles = triangles;
    }
    int progress_shown = 0;  // bands_done of the pass's last report
    void band_drawn(int thread) {  // after each band of a pass; reports on the caller's thread (0)
        const int done = bands_drawn.fetch_add(1, std::memory_order_relaxed) + 1;
        if (thread == 0 && progress_report) {
            progress_shown = done;
            progress_report({pass_triangles, done, bands.count}, progress_user);
        }
    }
    void end_pass() {  // on the caller's thread, after the pass: its end, if not reported yet
        const int done = bands_drawn.load(std::memory_order_relaxed);
        if (progress_report && done > progress_shown) progress_report({pass_triangles, done, bands.count}, progress_user);
        progress_shown = 0;
    }

    void clear_band(int b) {
        const int y0 = bands.y0(b), y1 = bands.y0(b + 1);
        if (y0 >= y1) return;
        detail::fill_floats(target->pixels[y0], static_cast<std::size_t>(y1 - y0) * target->width, clear_intensity);
        depth.clear_rows(y0, y1, 1.0f);
    }

    // The steps of draw (raster_context.cpp).
    void grow_segments(std::size_t vertex_count, bool generic, int threads);
    detail::draw_plan plan_draw(std::size_t units, bool clustered);
    void set_up_and_draw(int thread, const raster_mesh &m, const draw_params &p, const detail::vertex_job &job,
                         std::uint32_t state, const detail::cluster_view *view, const detail::draw_plan &plan);
    void draw_band(int band, const draw_params &p, const detail::draw_plan &plan, bool clear, int next);

    void transform(const detail::vertex_job &job, detail::vertex_set set, segment &out) {
        detail::transform_vertices(job, guard, set, out.vertices.data(), out.clip.data(), out.vertex_attr.data());
    }
    void set_up_piece(int thread, int number, const raster_mesh &m, const draw_params &p, const detail::vertex_job &job,
                      std::uint32_t state, const detail::cluster_view *view, const detail::draw_plan &plan);
    void setup_range(const raster_mesh &m, const draw_params &p, std::uint32_t state, bool generic,
                     const segment &vertices, std::size_t first, std::size_t last, piece &out);
    // Appends a fast triangle and its band bins (skips empty ones).
    void add_fast(const triangle_edges &t, const float depth_at[3], const float shade[3], piece &out) {
        detail::fast_triangle f;
        if (!detail::make_fast_triangle(t, depth_at, shade, static_cast<std::int32_t>(out.wide.size()), f)) return;
        if (f.wide >= 0) out.wide.push_back(t);
        bin_fast(f, out);
    }
    // Appends a fast triangle to out.fast (or out.far: piece::near_bands) and bins it. Out of
    // line, so that the vector appends inline here (in the set-up loop GCC calls them).
    [[gnu::noinline]] void bin_fast(const detail::fast_triangle &f, piece &out) {
        const int first = bands.of(f.min_y), last = bands.of(f.max_y);
        const bool near = !out.near_bands || std::all_of(out.near_bands + first, out.near_bands + last + 1,
                                                         [](std::uint8_t drew) { return drew != 0; });
        std::uint32_t index;
        if (near) {
            index = static_cast<std::uint32_t>(out.fast.size());
            out.fast.push_back(f);
        } else {
            index = static_cast<std::uint32_t>(out.far.append(f)) | detail::FAR_ENTRY;
        }
        bin_bands(first, last, index, out);
    }
    // Bin entry `index` into the bins of bands [first, last] (inclusive). Inlined: a call
    // would spill bin_fast's live values around it.
    [[gnu::always_inline]] void bin_bands(int first, int last, std::uint32_t index, piece &out) {
        for (int b = first; b <= last; ++b) out.bins[b].push_back(index);
    }
    void emit(const clip_vertex *poly, int n, const draw_params &p, std::uint32_t state, bool generic, piece &out);

    // Multisampled frames (raster_multisample.cpp): appends f with the draw state and bins it.
    void add_msaa(const detail::msaa_triangle &f, std::uint32_t state, piece &out);
    void draw_multisampled_band(int band, detail::sample_store &tile);
};

}  // namespace tiny3d

#endif
