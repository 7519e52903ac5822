// raster_context.cpp — the render context: a draw's steps (cull the mesh, transform its
// vertices, set up, clip and bin its triangles, draw the bands in parallel), the frame's
// begin and end (clear, translucent queue). Every buffer is owned by render_context::impl
// (render_context_impl.h) and reused from frame to frame; the worker pool is in
// src/parallel/, the vertex kernels in vertex_transform.*, the band sharing in
// render_bands.h, the per-pixel path in raster_pixel_path.cpp.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "render_context_impl.h"
#include "../simd_config.h"

#ifdef TINY3D_SSE2
#include <emmintrin.h>
#endif

namespace tiny3d {

using namespace detail;

namespace {

// A clipped vertex on the screen (clip_to_screen, with 1/w for perspective-correct
// attributes); false when it has no finite screen point.
bool to_screen(const vec4_t &clip, int width, int height, screen_vertex &out) {
    const screen_point p = clip_to_screen(clip, width, height);
    out = {p.x, p.y, p.depth, 1.0f / p.w};
    return !p.behind;
}

// The world position of a model-space point (the xyz part of model·(p, 1)).
vec3_t world_of(const mat4_t &model, vec3_t p) {
    const vec4_t h = mul_point_scalar(model, p);
    return {h.x, h.y, h.z};
}

// Whether every vertex index of `triangles` is < count. Runs on the caller's thread before the
// workers start, so it is branch-free: no early exit, four indices per SSE2 compare.
bool indices_below(const std::vector<std::array<std::uint32_t, 3>> &triangles, std::size_t count) {
    if (count > std::numeric_limits<std::uint32_t>::max()) return true;
    const std::uint32_t *index = triangles.empty() ? nullptr : triangles.front().data();
    const std::size_t n = triangles.size() * 3;
    const std::uint32_t limit = static_cast<std::uint32_t>(count);
    std::size_t k = 0;
    std::uint32_t out_of_range = 0;
#ifdef TINY3D_SSE2
    // Unsigned index ≥ limit  ⇔  (index ^ 2³¹) > (limit − 1) ^ 2³¹ as signed (limit ≥ 1).
    if (limit > 0) {
        const __m128i flip = _mm_set1_epi32(static_cast<int>(0x80000000u));
        const __m128i last = _mm_xor_si128(_mm_set1_epi32(static_cast<int>(limit - 1)), flip);
        __m128i any = _mm_setzero_si128();
        for (; k + 4 <= n; k += 4) {
            const __m128i v = _mm_xor_si128(_mm_loadu_si128(reinterpret_cast<const __m128i *>(index + k)), flip);
            any = _mm_or_si128(any, _mm_cmpgt_epi32(v, last));
        }
        out_of_range = static_cast<std::uint32_t>(_mm_movemask_epi8(any));
    }
#endif
    for (; k < n; ++k) out_of_range |= index[k] >= limit;
    return out_of_range == 0;
}

}  // namespace

// ---- phase 1b: triangles -------------------------------------------------------------------

// One convex polygon (already inside the near/far planes and the guard band) as a fan;
// `count`: add its triangles to the stats.
void render_context::impl::emit(const clip_vertex *poly, int n, const draw_params &p, std::uint32_t state,
                                bool generic, bool count, segment &out) {
    const int width = target->width, height = target->height;
    const pixel_rect full{0, 0, width, height};
    for (int k = 1; k + 1 < n; ++k) {
        const clip_vertex *c[3] = {&poly[0], &poly[k], &poly[k + 1]};
        screen_vertex v[3];
        // A vertex without a finite screen point: skipped, as triangle_setup would.
        if (!to_screen(c[0]->position, width, height, v[0]) || !to_screen(c[1]->position, width, height, v[1]) ||
            !to_screen(c[2]->position, width, height, v[2]))
            continue;
        const float shade[3] = {c[0]->attr[ATTR_SHADE], c[1]->attr[ATTR_SHADE], c[2]->attr[ATTR_SHADE]};
        const float depth[3] = {v[0].z, v[1].z, v[2].z};
        if (!multisampled()) {
            const triangle_edges t = triangle_setup(v[0], v[1], v[2], full, p.cull);
            if (!t.valid) {
                out.stats.culled_backface += count && t.culled;
                continue;
            }
            out.stats.rasterized += count;
            if (generic) out.generic.push_back(make_generic_triangle(v, c, state));
            else add_fast(t, depth, shade, out);
            continue;
        }
        // Multisampled: on the pattern's grid, as the unclipped triangles (setup_range); a
        // triangle without a covered pixel centre still counts (its samples may be covered).
        std::int32_t X[3], Y[3];
        bool usable = true;
        for (int j = 0; j < 3; ++j) usable = usable && detail::snap_vertex(v[j], X[j], Y[j], pattern->bits);
        const std::int64_t area2 = usable ? detail::snapped_area2(X, Y) : 0;
        if (area2 == 0) continue;
        if (detail::facing_culled(area2, p.cull)) {
            out.stats.culled_backface += count;
            continue;
        }
        out.stats.rasterized += count;
        if (generic) {
            out.generic.push_back(make_generic_triangle(v, c, state));
            if (p.alpha >= 1.0f) bin_generic(X, Y, out);
            continue;
        }
        detail::msaa_triangle f;
        if (make_msaa_triangle(X, Y, area2, *pattern, full, depth, shade, f)) add_msaa(f, state, out);
    }
}

// Thread `thread` walks every triangle but sets up only the fast ones that reach its bands
// (and every clipped or per-pixel-path one: rare, and cheap to repeat); each triangle is
// counted in the stats by one thread only (thread 0, or for fast triangles the owner of the
// first row's band). With clusters (`view` not null), whole chunks are decided first: a
// chunk proven back-facing is skipped by every thread and counted by one; a chunk inside the
// guard band is walked only by the threads drawing a band among its rows, and its culled
// triangles are counted by the owner of its first row's band (thread 0 when it has no row
// on the target) — the same counts as walking every triangle.
void render_context::impl::setup(const raster_mesh &m, const draw_params &p, const vertex_job &job, std::uint32_t state,
                                 int thread, const detail::cluster_view *view, segment &out) {
    if (!view) {
        transform(m, p, job, {nullptr, m.positions.size()}, out);
        setup_range(m, p, state, job.generic, thread, thread == 0, 0, m.triangles.size(), out);
        return;
    }
    // First decide every chunk, then transform: the vertices of the walked chunks one chunk
    // at a time when they are fewer than the mesh's (a vertex shared by two walked chunks is
    // transformed twice), else every vertex at once (meshes whose chunks are rarely skipped).
    const std::vector<raster_cluster> &chunks = p.clusters->clusters();
    out.chunks.resize(chunks.size());
    std::size_t walked_vertices = 0;
    for (std::size_t k = 0; k < chunks.size(); ++k) {
        const raster_cluster &c = chunks[k];
        const detail::cluster_verdict v = detail::classify_cluster(*view, c);
        const bool on_target = v.inside && v.row0 <= v.row1;
        const int counter = on_target ? bands.owner[bands.of(v.row0)] : 0;
        detail::chunk_walk &decision = out.chunks[k];
        decision = {false, thread == counter};
        if (v.back) {
            if (decision.counts) {
                out.stats.culled_backface += c.count;
                out.stats.backface_by_cluster += c.count;
            }
            continue;
        }
        decision.walk = !v.inside || decision.counts || (on_target && bands.draws_rows(thread, v.row0, v.row1));
        if (decision.walk) walked_vertices += c.vertex_count;
    }
    const bool per_chunk = walked_vertices < m.positions.size();
    if (!per_chunk) transform(m, p, job, {nullptr, m.positions.size()}, out);
    const std::uint32_t *chunk_vertices = p.clusters->vertices().data();
    for (std::size_t k = 0; k < chunks.size(); ++k) {
        if (!out.chunks[k].walk) continue;
        const raster_cluster &c = chunks[k];
        if (per_chunk) transform(m, p, job, {chunk_vertices + c.vertex_first, c.vertex_count}, out);
        setup_range(m, p, state, job.generic, thread, out.chunks[k].counts, c.first, c.first + c.count, out);
    }
}

// setup() for triangles [first, last); `counts_all`: this thread counts culled and clipped ones.
void render_context::impl::setup_range(const raster_mesh &m, const draw_params &p, std::uint32_t state, bool generic,
                                       int thread, bool counts_all, std::size_t first, std::size_t last,
                                       segment &out) {
    const bool flat = p.shade == shading::flat;
    const bool msaa = multisampled();
    const std::vector<detail::xvertex> &vertices = out.vertices;
    const std::vector<float> &vertex_attr = out.vertex_attr;
    const pixel_rect full{0, 0, target->width, target->height};
    const std::int64_t last_row = target->height - 1;
    for (std::size_t i = first; i < last; ++i) {
        const std::array<std::uint32_t, 3> &tri = m.triangles[i];
        const detail::xvertex &a = vertices[tri[0]], &b = vertices[tri[1]], &c = vertices[tri[2]];
        if (a.outcode & b.outcode & c.outcode) continue;  // all outside one plane
        float flat_shade = 0.0f;
        if (flat) flat_shade = shade_flat(p.lights, world_of(p.model, m.positions[tri[0]]),
                                          world_of(p.model, m.positions[tri[1]]), world_of(p.model, m.positions[tri[2]]));
        if ((a.outcode | b.outcode | c.outcode) == 0 && !generic) {
            // The common case: no clipping, straight to the fast setup.
            // Snapped once per vertex in transform(); an unusable vertex skips the triangle
            // exactly as triangle_setup would.
            if (!(a.snapped && b.snapped && c.snapped)) continue;
            const std::int32_t X[3] = {a.snapped_x, b.snapped_x, c.snapped_x};
            const std::int32_t Y[3] = {a.snapped_y, b.snapped_y, c.snapped_y};
            // Cheap early rejection on the snapped 2-D cross product (the same sign test
            // triangle_setup makes), before the full edge setup.
            const std::int64_t area2 = detail::snapped_area2(X, Y);
            if (area2 == 0) continue;
            if (detail::facing_culled(area2, p.cull)) {
                out.stats.culled_backface += counts_all;
                continue;
            }
            // Candidate rows (pixel centres 16·row + 8 within the snapped y range): skip the
            // triangle when this thread draws none of their bands.
            std::int64_t row0 = std::max<std::int64_t>(
                -((RASTER_SUBPIXEL_ONE / 2 - std::min({Y[0], Y[1], Y[2]})) >> RASTER_SUBPIXEL_BITS), 0);
            std::int64_t row1 = std::min<std::int64_t>(
                (std::max({Y[0], Y[1], Y[2]}) - RASTER_SUBPIXEL_ONE / 2) >> RASTER_SUBPIXEL_BITS, last_row);
            if (msaa) {  // rows with a sample row in the y range
                int r0, r1;
                msaa_candidate_rows(std::min({Y[0], Y[1], Y[2]}), std::max({Y[0], Y[1], Y[2]}), *pattern,
                                    static_cast<int>(last_row), r0, r1);
                row0 = r0, row1 = r1;
            }
            if (row0 > row1 || !bands.draws_rows(thread, static_cast<int>(row0), static_cast<int>(row1))) continue;
            const bool counts = bands.owner[bands.of(static_cast<int>(row0))] == thread;
            const float depth[3] = {a.depth, b.depth, c.depth};
            const float shade[3] = {flat ? flat_shade : a.shade, flat ? flat_shade : b.shade, flat ? flat_shade : c.shade};
            if (msaa) {  // (no pixel centre inside is fine: samples may be)
                out.stats.rasterized += counts;
                detail::msaa_triangle f;
                if (make_msaa_triangle(X, Y, area2, *pattern, full, depth, shade, f)) add_msaa(f, state, out);
                continue;
            }
            // Set up in a local and appended when ready (set up in place at the list's end,
            // emplace_back() zeroed each entry first, out of line).
            detail::fast_triangle f;
            const detail::fast_setup verdict = detail::setup_fast_triangle(X, Y, area2, full, depth, shade, f);
            if (verdict == detail::fast_setup::ready) {
                out.stats.rasterized += counts;
                bin_fast(f, out);
                continue;
            }
            if (verdict == detail::fast_setup::wide) {
                const triangle_edges t = detail::triangle_setup_snapped(X, Y, full, p.cull);
                if (!t.valid) continue;
                out.stats.rasterized += counts;
                add_fast(t, depth, shade, out);
            }
            continue;
        }
        clip_vertex in[3];
        for (int j = 0; j < 3; ++j) {
            const detail::xvertex &x = vertices[tri[j]];
            in[j].position = out.clip[tri[j]];
            in[j].attr.fill(0.0f);
            if (generic)
                for (int s = 0; s < ATTR_COUNT; ++s) in[j].attr[s] = vertex_attr[tri[j] * ATTR_COUNT + s];
            in[j].attr[ATTR_SHADE] = flat ? flat_shade : x.shade;
        }
        const unsigned planes = a.outcode | b.outcode | c.outcode;
        if (planes) out.stats.clipped += counts_all;
        clip_vertex poly[CLIP_MAX_VERTICES];
        const int n = planes ? clip_polygon(in, 3, planes, guard, ATTR_COUNT, poly) : 3;
        emit(planes ? poly : in, n, p, state, generic, counts_all, out);
    }
}

// ---- the steps of a draw -------------------------------------------------------------------

// Every thread's buffers hold a transformed copy of every vertex (and the per-pixel path's
// attributes when wanted).
void render_context::impl::grow_segments(std::size_t vertex_count, bool generic) {
    for (int t = 0; t < pool.size(); ++t) {
        segment &seg = segments[t];
        if (seg.vertices.size() < vertex_count) seg.vertices.resize(vertex_count), seg.clip.resize(vertex_count);
        if (generic && seg.vertex_attr.size() < vertex_count * ATTR_COUNT) seg.vertex_attr.resize(vertex_count * ATTR_COUNT);
    }
}

// One band: cleared if the frame has not been yet, then its fast triangles and (opaque)
// per-pixel-path triangles from `from`, in submission order.
void render_context::impl::draw_band(int band, const segment &from, const draw_params &p) {
    const int y0 = bands.y0(band), y1 = bands.y0(band + 1);
    if (pending_clear) clear_band(band);
    for (std::uint32_t index : from.bins[band]) {
        const fast_triangle &f = from.fast[index];
        fill_fast_rows(*target, &depth, f, f.wide >= 0 ? &from.wide[f.wide] : nullptr, p.depth, true, y0, y1);
    }
    if (p.alpha >= 1.0f)
        for (const generic_triangle &g : from.generic) draw_generic_rows(*target, depth, p, g, y0, y1);
}

// What thread `thread` does in a draw's one parallel phase: transform every vertex (with
// clusters: those of the chunks it walks) into its own segment (repeating that cheap pass
// costs less than sharing vertex lines between cores), set up the triangles that reach its
// bands, say so, and draw its bands, then help with the others' (draw_bands).
void render_context::impl::set_up_and_draw(int thread, const raster_mesh &m, const draw_params &p,
                                           const vertex_job &job, std::uint32_t state, const cluster_view *view) {
    segment &seg = segments[thread];
    if (!segments_hold_frame) {
        seg.fast.clear();
        seg.msaa.clear();
        seg.wide.clear();
        seg.generic.clear();
        for (int b = 0; b < bands.count; ++b) seg.bins[b].clear();
    }
    seg.stats = {};
    setup(m, p, job, state, thread, view, seg);
    if (multisampled()) return;  // drawn at end_frame
    claims.mark_ready(thread);
    draw_bands(bands, claims, thread, pool.size(), [&](int band, int owner) { draw_band(band, segments[owner], p); });
}

// Translucent triangles wait for end_frame: every segment holds all per-pixel-path
// triangles, so segment 0's are taken (from `first`: multisampled frames keep earlier draws').
void render_context::impl::queue_translucent(std::size_t first) {
    for (std::size_t k = first; k < segments[0].generic.size(); ++k) {
        generic_triangle g = segments[0].generic[k];
        g.sequence = static_cast<std::uint32_t>(translucent.size());
        translucent.push_back(g);
    }
}

void render_context::impl::gather_stats() {
    for (int t = 0; t < pool.size(); ++t) {
        const frame_stats &st = segments[t].stats;
        stats.culled_backface += st.culled_backface;
        stats.clipped += st.clipped;
        stats.rasterized += st.rasterized;
        stats.backface_by_cluster += st.backface_by_cluster;
    }
}

void render_context::draw(const raster_mesh &mesh, const draw_params &params) {
    impl &s = *impl_;
    if (!s.target || mesh.positions.size() != mesh.normals.size() || mesh.positions.size() != mesh.uvs.size()) return;
    s.stats.triangles_in += mesh.triangles.size();
    const mat4_t mvp = mat4_multiply(params.view_projection, params.model);
    if (cull_sphere(frustum_from_matrix(mvp), {mesh.bound_center, mesh.bound_radius}) == cull_result::outside) {
        s.stats.culled_frustum += mesh.triangles.size();
        return;
    }
    if (!indices_below(mesh.triangles, mesh.positions.size())) return;
    const bool generic = params.shade == shading::phong || params.tex != nullptr || params.alpha < 1.0f;
    const std::uint32_t state = static_cast<std::uint32_t>(s.states.size());
    s.states.push_back(params);
    // Cluster culling for the fast path, when the clusters were built from this mesh.
    const raster_clusters *clusters = params.clusters;
    const bool use_clusters = clusters && !generic && clusters->vertex_count() == mesh.positions.size() &&
                              clusters->triangle_count() == mesh.triangles.size();
    cluster_view view{};
    if (use_clusters) view = make_cluster_view(mvp, s.target->width, s.target->height, s.guard, params.cull);
    const vertex_job job = make_vertex_job(params, mvp, generic, s.target->width, s.target->height, s.pattern->bits);
    s.grow_segments(mesh.positions.size(), generic);
    s.claims.next_draw();
    auto phase = [&](int t) { s.set_up_and_draw(t, mesh, params, job, state, use_clusters ? &view : nullptr); };
    const std::size_t generic_first = s.segments_hold_frame ? s.segments[0].generic.size() : 0;
    s.pool.run(phase);
    s.segments_hold_frame = s.multisampled();
    if (params.alpha < 1.0f) s.queue_translucent(generic_first);
    s.pending_clear = false;
    s.gather_stats();
}

// ---- the public class -------------------------------------------------------------------------

render_context::render_context(int threads) : impl_(std::make_unique<impl>(std::clamp(threads, 1, detail::MAX_THREADS))) {}
render_context::~render_context() = default;
int render_context::threads() const { return impl_->pool.size(); }
const zbuffer &render_context::depth() const { return impl_->depth; }
const frame_stats &render_context::stats() const { return impl_->stats; }
multisample_simd render_context::multisample_simd_in_use() const { return impl_->kernel; }

bool render_context::use_multisample_simd(multisample_simd simd) {
    if (impl_->target || !detail::msaa_kernel_runs(simd)) return false;
    impl_->kernel = simd;
    return true;
}

status render_context::begin_frame(canvas_t &target, float clear_intensity, sample_count samples) {
    impl &s = *impl_;
    if (!target.pixels || !target.data) return error{"", 0, -1, "render_context: canvas has no pixels"};
    const int count = static_cast<int>(samples);
    if (count != 1 && count != 4 && count != 8 && count != 16)
        return error{"", 0, -1, "render_context: " + std::to_string(count) + " samples per pixel (1, 4, 8 or 16)"};
    const status size_ok = s.depth.resize(target.width, target.height);
    if (!size_ok) return size_ok;
    s.pattern = &detail::pattern_of(count);
    s.segments_hold_frame = false;
    s.target = &target;
    s.clear_intensity = detail::clamp01(clear_intensity);
    s.pending_clear = true;
    s.stats = {};
    s.states.clear();
    s.translucent.clear();
    s.bands.plan(target.height, s.pool.size(), count > 1 ? MSAA_BAND_ROWS : BAND_ROWS);
    if (count > 1) {
        const int tile_rows = (target.height + s.bands.count - 1) / s.bands.count;
        for (int t = 0; t < s.pool.size(); ++t) s.tiles[t].resize(target.width, tile_rows, count);
    }
    s.guard = std::clamp(GUARD_SPAN_PIXELS / static_cast<float>(std::max(target.width, target.height)), 1.0f, MAX_GUARD);
    return {};
}

void render_context::end_frame() {
    impl &s = *impl_;
    if (!s.target) return;
    // Back to front; equal depths keep submission order (std::sort: no temporary buffer).
    std::sort(s.translucent.begin(), s.translucent.end(), [](const generic_triangle &a, const generic_triangle &b) {
        return a.mean_depth != b.mean_depth ? a.mean_depth > b.mean_depth : a.sequence < b.sequence;
    });
    if (s.multisampled()) return s.end_multisampled_frame();
    if (s.translucent.empty() && !s.pending_clear) {
        s.target = nullptr;
        return;
    }
    auto phase = [&](int thread) {
        for (int band = 0; band < s.bands.count; ++band) {
            if (s.bands.owner[band] != thread) continue;
            const int y0 = s.bands.y0(band), y1 = s.bands.y0(band + 1);
            if (s.pending_clear) s.clear_band(band);
            for (const generic_triangle &g : s.translucent)
                draw_generic_rows(*s.target, s.depth, s.states[g.state], g, y0, y1);
        }
    };
    s.pool.run(phase);
    s.pending_clear = false;
    s.translucent.clear();
    s.target = nullptr;
}

}  // namespace tiny3d
