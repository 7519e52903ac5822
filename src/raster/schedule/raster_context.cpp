// raster_context.cpp — the render context: a draw's steps (cull, transform, set up, clip
// and bin, draw the bands in parallel) and the frame's begin and end. Its buffers live in
// render_context::impl (render_context_impl.h), reused from frame to frame; the vertex stage
// is src/pipeline/, the band sharing in render_bands.h, the per-pixel path in
// raster_pixel_path.cpp, the draw's memory guard in raster_memory.cpp.
#include <algorithm>
#include <new>
#include <limits>
#include <string>

#include "render_context_impl.h"
#include "../../simd_config.h"

#ifdef TINY3D_SSE2
#include <emmintrin.h>
#endif

namespace tiny3d {

using namespace detail;

namespace {

// Whether a draw takes the per-pixel path (Phong, a texture, translucency), not the fast one.
bool per_pixel_path(const draw_params &p) { return p.shade == shading::phong || p.tex != nullptr || p.alpha < 1.0f; }

// Whether every vertex index of triangles [first, last) is < count (branch-free, SSE2).
bool indices_below(const std::vector<std::array<std::uint32_t, 3>> &triangles, std::size_t first, std::size_t last,
                   std::size_t count) {
    if (count > std::numeric_limits<std::uint32_t>::max() || first >= last) return true;
    const std::uint32_t *index = triangles[first].data();
    const std::size_t n = (last - first) * 3;
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

// ---- a piece's triangles ---------------------------------------------------------------------
// One convex polygon (already inside the near/far planes and the guard band) as a fan.
void render_context::impl::emit(const clip_vertex *poly, int n, const draw_params &p, std::uint32_t state,
                                bool generic, piece &out) {
    const int width = target->width, height = target->height;
    const pixel_rect full{0, 0, width, height};
    for (int k = 1; k + 1 < n; ++k) {
        const clip_vertex *c[3] = {&poly[0], &poly[k], &poly[k + 1]};
        screen_vertex v[3];  // (with 1/w for perspective-correct attributes)
        bool in_front = true;
        for (int j = 0; j < 3 && in_front; ++j) {
            const screen_point s = clip_to_screen(c[j]->position, width, height);
            v[j] = {s.x, s.y, s.depth, 1.0f / s.w};
            in_front = !s.behind;
        }
        if (!in_front) continue;
        const float shade[3] = {c[0]->attr[ATTR_SHADE], c[1]->attr[ATTR_SHADE], c[2]->attr[ATTR_SHADE]};
        const float depth[3] = {v[0].z, v[1].z, v[2].z};
        // Snapped on the pattern's grid, as the unclipped triangles (setup_range).
        std::int32_t X[3], Y[3];
        bool usable = true;
        for (int j = 0; j < 3; ++j) usable = usable && snap_screen_point(v[j].x, v[j].y, pattern->bits, X[j], Y[j]);
        const std::int64_t area2 = usable ? detail::snapped_area2(X, Y) : 0;
        if (area2 == 0) continue;
        if (detail::facing_culled(area2, p.cull)) {
            out.stats.culled_backface += 1;
            continue;
        }
        int y0, y1;  // a per-pixel-path triangle's rows, for its bins
        if (!multisampled()) {
            const triangle_edges t = triangle_setup_snapped(X, Y, full, cull_mode::none);
            if (!t.valid) continue;
            out.stats.rasterized += 1;
            if (!generic) {
                add_fast(t, depth, shade, out);
                continue;
            }
            y0 = t.min_y, y1 = t.max_y;
        } else {
            out.stats.rasterized += 1;
            if (!generic) {
                detail::msaa_triangle f;
                if (make_msaa_triangle(X, Y, area2, *pattern, full, depth, shade, f)) add_msaa(f, state, out);
                continue;
            }
            int x0, x1;
            msaa_bounds(X, Y, *pattern, full, x0, x1, y0, y1);
            if (x0 > x1) y1 = y0 - 1;  // no pixel: no bin
        }
        out.generic.push_back(make_generic_triangle(v, c, state));
        if (p.alpha >= 1.0f && y0 <= y1)  // opaque: binned (translucent: queued by draw)
            bin_bands(bands.of(y0), bands.of(y1), static_cast<std::uint32_t>(out.generic.size() - 1) | GENERIC_BIN, out);
    }
}

// Piece `number` of the frame set up by `thread` into the piece's lists and bins. With
// clusters the piece is a run of chunks: back-facing ones are skipped first, then the walked
// chunks' vertices are transformed chunk by chunk when they are fewer than the mesh's (else
// all at once), and their triangles set up.
void render_context::impl::set_up_piece(int thread, int number, const raster_mesh &m, const draw_params &p,
                                        const vertex_job &job, std::uint32_t state, const cluster_view *view,
                                        const draw_plan &plan) {
    segment &seg = segments[thread];
    piece &out = pieces[static_cast<std::size_t>(number)];
    out.fast.clear();
    out.far.clear();
    out.near_bands = pool.size() > 1 && streaming ? affinity[thread].drew : nullptr;
    out.msaa.clear();
    out.wide.clear();
    out.generic.clear();
    if (out.bins.size() < static_cast<std::size_t>(bands.count)) out.bins.resize(bands.count);
    for (int b = 0; b < bands.count; ++b) out.bins[b].clear();
    out.stats = {};
    // Its triangles' vertex indices first: one out of range, and the whole draw is dropped.
    const std::vector<raster_cluster> *chunks = view ? &p.clusters->clusters() : nullptr;
    const std::size_t units = chunks ? chunks->size() : m.triangles.size();
    const std::size_t first = std::min(units, plan.size * static_cast<std::size_t>(number - plan.first));
    const std::size_t last = std::min(units, first + plan.size);
    if (first == last) return;
    const std::size_t first_triangle = chunks ? (*chunks)[first].first : first;
    const std::size_t last_triangle = chunks ? (*chunks)[last - 1].first + (*chunks)[last - 1].count : last;
    if (!indices_below(m.triangles, first_triangle, last_triangle, m.positions.size())) {
        counters.bad_indices.store(true, std::memory_order_relaxed);
        return;
    }
    if (!view) {
        if (!plan.shared_vertices) transform(job, {nullptr, m.positions.size()}, seg);
        setup_range(m, p, state, job.generic, plan.shared_vertices ? segments[0] : seg, first, last, out);
        return;
    }
    if (seg.walk.size() < plan.size) seg.walk.resize(plan.size);
    std::size_t walked_vertices = 0;
    for (std::size_t k = first; k < last; ++k) {
        const raster_cluster &c = (*chunks)[k];
        const bool back = detail::cluster_back_facing(*view, c);
        seg.walk[k - first] = !back;
        if (back) {
            out.stats.culled_backface += c.count;
            out.stats.backface_by_cluster += c.count;
        } else {
            walked_vertices += c.vertex_count;
        }
    }
    const bool per_chunk = walked_vertices < m.positions.size();
    if (!per_chunk) transform(job, {nullptr, m.positions.size()}, seg);
    const std::uint32_t *chunk_vertices = p.clusters->vertices().data();
    for (std::size_t k = first; k < last; ++k) {
        if (!seg.walk[k - first]) continue;
        const raster_cluster &c = (*chunks)[k];
        if (per_chunk) transform(job, seg.not_yet_transformed(chunk_vertices + c.vertex_first, c.vertex_count), seg);
        setup_range(m, p, state, job.generic, seg, c.first, c.first + c.count, out);
    }
}

// Triangles [first, last) of m, their vertices transformed in `from`, set up into `out`.
void render_context::impl::setup_range(const raster_mesh &m, const draw_params &p, std::uint32_t state, bool generic,
                                       const segment &from, std::size_t first, std::size_t last, piece &out) {
    const bool flat = p.shade == shading::flat;
    const bool flat_material = flat && !material_is_lambert(p.surface);  // Blinn-Phong at the centroid
    const viewer eye = flat_material ? viewer_of(p.view_projection) : viewer{};
    const bool msaa = multisampled();
    const detail::xvertex *vertices = from.vertices.data();
    const float *vertex_attr = from.vertex_attr.data();
    const pixel_rect full{0, 0, target->width, target->height};
    const int height = target->height;
    auto bin_ready = [&](const fast_triangle &f) {
        out.stats.rasterized += 1;
        bin_fast(f, out);
    };
    // A fast triangle's set-up verdict, acted on: binned, or too wide for the fast path.
    auto finish = [&](fast_setup verdict, const fast_triangle &f, const std::int32_t X[3], const std::int32_t Y[3],
                      const float depth[3], const float shade[3]) {
        if (verdict == fast_setup::ready) {
            bin_ready(f);
        } else if (verdict == fast_setup::wide) {
            const triangle_edges t = detail::triangle_setup_snapped(X, Y, full, p.cull);
            if (!t.valid) return;
            out.stats.rasterized += 1;
            add_fast(t, depth, shade, out);
        }
    };
    // With set-up batches in the table, triangles are set up eight at a time (the batch is
    // finished before a clipped triangle, to keep submission order).
    setup_batch batch;
    const bool batched = msaa ? kernels->setup_msaa_batch != nullptr : kernels->setup_fast_batch != nullptr;
    auto finish_batch = [&] {
        if (batch.count == 0) return;
        fast_setup verdict[SETUP_BATCH];
        if (msaa) {
            msaa_triangle set_up[SETUP_BATCH];
            kernels->setup_msaa_batch(batch, *pattern, full, verdict, set_up);
            for (int l = 0; l < batch.count; ++l) {
                if (verdict[l] == fast_setup::ready) add_msaa(set_up[l], state, out);
                if (verdict[l] != fast_setup::scalar) continue;
                std::int32_t X[3], Y[3];  // a lane the batch left to the scalar set-up
                float depth[3], shade[3];
                batch.lane(l, X, Y, depth, shade);
                if (make_msaa_triangle(X, Y, batch.area2[l], *pattern, full, depth, shade, set_up[l]))
                    add_msaa(set_up[l], state, out);
            }
            batch.count = 0;
            return;
        }
        fast_triangle set_up[SETUP_BATCH];
        kernels->setup_fast_batch(batch, full, verdict, set_up);
        for (int l = 0; l < batch.count; ++l) {
            if (verdict[l] == fast_setup::ready) {  // (the common case: no lane gathered)
                bin_ready(set_up[l]);
                continue;
            }
            std::int32_t X[3], Y[3];
            float depth[3], shade[3];
            batch.lane(l, X, Y, depth, shade);
            if (verdict[l] == fast_setup::scalar)
                verdict[l] = detail::setup_fast_triangle(X, Y, batch.area2[l], full, depth, shade, set_up[l]);
            finish(verdict[l], set_up[l], X, Y, depth, shade);
        }
        batch.count = 0;
    };
    for (std::size_t i = first; i < last; ++i) {
        const std::array<std::uint32_t, 3> &tri = m.triangles[i];
        const detail::xvertex &a = vertices[tri[0]], &b = vertices[tri[1]], &c = vertices[tri[2]];
        if (a.outcode & b.outcode & c.outcode) continue;  // all outside one plane
        float flat_shade = 0.0f;
        if (flat) {
            const vec3_t w[3] = {world_of(p.model, m.positions[tri[0]]), world_of(p.model, m.positions[tri[1]]),
                                 world_of(p.model, m.positions[tri[2]])};
            flat_shade = flat_material ? shade_flat_material(p.lights, p.surface, eye, w[0], w[1], w[2])
                                       : shade_flat(p.lights, w[0], w[1], w[2]);
        }
        if ((a.outcode | b.outcode | c.outcode) == 0 && !generic) {
            // No clipping: straight to the fast set-up (vertices snapped in transform()).
            if (!(a.snapped && b.snapped && c.snapped)) continue;
            const std::int32_t X[3] = {a.snapped_x, b.snapped_x, c.snapped_x};
            const std::int32_t Y[3] = {a.snapped_y, b.snapped_y, c.snapped_y};
            const std::int64_t area2 = detail::snapped_area2(X, Y);
            if (area2 == 0) continue;
            if (detail::facing_culled(area2, p.cull)) {
                out.stats.culled_backface += 1;
                continue;
            }
            const float depth[3] = {a.depth, b.depth, c.depth};
            const float shade[3] = {flat ? flat_shade : a.shade, flat ? flat_shade : b.shade, flat ? flat_shade : c.shade};
            // No sample row (pixel centre row at 1×) of the target in the y range: nothing to count.
            // (At 1× the 1-sample pattern's offsets and grid as constants: a shift by a constant
            // per triangle, not by pattern->bits.)
            const std::int32_t min_Y = std::min({Y[0], Y[1], Y[2]}), max_Y = std::max({Y[0], Y[1], Y[2]});
            int row0, row1;
            if (msaa) axis_bounds(min_Y, max_Y, pattern->min_dy, pattern->max_dy, pattern->bits, 0, height, row0, row1);
            else axis_bounds(min_Y, max_Y, 0, 0, RASTER_SUBPIXEL_BITS, 0, height, row0, row1);
            if (row0 > row1) continue;
            if (msaa) out.stats.rasterized += 1;
            if (batched) {
                batch.add(X, Y, area2, depth, shade);
                if (batch.count == SETUP_BATCH) finish_batch();
                continue;
            }
            if (msaa) {
                detail::msaa_triangle f;
                if (make_msaa_triangle(X, Y, area2, *pattern, full, depth, shade, f)) add_msaa(f, state, out);
                continue;
            }
            // Set up in a local (emplace_back() would zero each entry first, out of line).
            detail::fast_triangle f;
            finish(detail::setup_fast_triangle(X, Y, area2, full, depth, shade, f), f, X, Y, depth, shade);
            continue;
        }
        finish_batch();
        clip_vertex in[3];
        for (int j = 0; j < 3; ++j) {
            const detail::xvertex &x = vertices[tri[j]];
            in[j].position = from.clip[tri[j]];
            in[j].attr.fill(0.0f);
            if (generic)
                for (int s = 0; s < ATTR_COUNT; ++s) in[j].attr[s] = vertex_attr[tri[j] * ATTR_COUNT + s];
            in[j].attr[ATTR_SHADE] = flat ? flat_shade : x.shade;
        }
        const unsigned planes = a.outcode | b.outcode | c.outcode;
        if (planes) out.stats.clipped += 1;
        clip_vertex poly[CLIP_MAX_VERTICES];
        const int n = planes ? clip_polygon(in, 3, planes, guard, ATTR_COUNT, poly) : 3;
        emit(planes ? poly : in, n, p, state, generic, out);
    }
    finish_batch();
}

// ---- the steps of a draw -------------------------------------------------------------------

// The draw's pieces over `units` chunks or triangles: one on one thread, else up to
// PIECES_PER_THREAD · n, after the frame's earlier draws' (multisampled frames keep them).
draw_plan render_context::impl::plan_draw(std::size_t units, bool clustered) {
    const int n = pool.size();
    draw_plan plan;
    std::size_t count = 1;
    if (n > 1) {
        const std::size_t by_size = clustered ? units : (units + MIN_PIECE_TRIANGLES - 1) / MIN_PIECE_TRIANGLES;
        count = std::clamp<std::size_t>(by_size, 1, static_cast<std::size_t>(PIECES_PER_THREAD * n));
    }
    plan.size = std::max<std::size_t>((units + count - 1) / count, 1);
    plan.count = static_cast<int>(units == 0 ? 0 : (units + plan.size - 1) / plan.size);
    plan.shared_vertices = !clustered && n > 1;
    plan.first = piece_count;
    piece_count += plan.count;
    if (pieces.size() < static_cast<std::size_t>(piece_count)) pieces.resize(static_cast<std::size_t>(piece_count));
    return plan;
}

// One band: cleared if still pending (and `clear`), then the draw's triangles reaching it in
// piece order, while the lines of band `next` (or −1) are fetched for its clear.
void render_context::impl::draw_band(int band, const draw_params &p, const draw_plan &plan, bool clear, int next) {
    const int y0 = bands.y0(band), y1 = bands.y0(band + 1);
    if (clear && pending_clear) clear_band(band);
    band_prefetch ahead;  // the next band, when it is still to be cleared
    if (pending_clear && next >= 0 && next < bands.count) {
        const int n0 = bands.y0(next), n1 = bands.y0(next + 1);
        ahead = band_prefetch(target->pixels[n0], depth.row(n0), static_cast<std::size_t>(n1 - n0) * target->width);
    }
    if (!per_pixel_path(p)) {  // one call for the band's bins of every piece (translucent triangles are not binned)
        band_bin bins[PIECES_PER_THREAD * MAX_THREADS];  // (plan_draw: at most that many pieces)
        int count = 0;
        for (const piece &from : pieces_of(plan)) {
            const std::vector<std::uint32_t> &bin = from.bins[band];
            if (!bin.empty()) bins[count++] = {from.fast.data(), from.far.data(), from.wide.data(), bin.data(), bin.size()};
        }
        kernels->fill_fast_bins(*target, depth, bins, count, p.depth, y0, y1, ahead);
        return;
    }
    for (const piece &from : pieces_of(plan))
        for (std::uint32_t index : from.bins[band]) draw_generic_rows(*target, depth, p, from.generic[index & ~GENERIC_BIN], y0, y1);
}

// One thread's part of a draw's parallel phase (render_bands.h): [shared vertices: transform
// its range, wait for the others'] set up pieces; then, in a 1-sample frame, wait for every
// piece and draw the bands it claims (multisampled frames draw at end_frame).
void render_context::impl::set_up_and_draw(int thread, const raster_mesh &m, const draw_params &p,
                                           const vertex_job &job, std::uint32_t state, const cluster_view *view,
                                           const draw_plan &plan) {
    segments[thread].begin_draw();
    if (plan.shared_vertices) {
        // Ranges of whole 64-vertex blocks: no two threads write one cache line of the arrays.
        const int n = pool.size();
        const std::size_t blocks = (m.positions.size() + 63) / 64;
        const std::size_t first = std::min(m.positions.size(), blocks * thread / n * 64);
        const std::size_t last = std::min(m.positions.size(), blocks * (thread + 1) / n * 64);
        transform(job, {nullptr, last - first, static_cast<std::uint32_t>(first)}, segments[0]);
        counters.vertex_ranges_done.fetch_add(1, std::memory_order_release);
        phase_counters::wait_for(counters.vertex_ranges_done, n);
    }
    band_affinity &mine = affinity[thread];
    if (!multisampled()) mine.forget(bands.count);  // (a multisampled frame counts every draw's)
    for (int k; (k = counters.take_piece(thread, pool.size())) >= 0;) {
        // Running out of memory drops the draw (as a bad index does); the piece still counts
        // as done, so no thread waits for it and no exception leaves the worker.
        try {
            set_up_piece(thread, plan.first + k, m, p, job, state, view, plan);
            piece &done = pieces[static_cast<std::size_t>(plan.first + k)];
            mine.count(done.bins, bands.count);
            if (done.near_bands) {
                // Either list may hold all of a piece's triangles in another frame: both grow
                // to the largest total, so that a steady scene allocates nothing per frame.
                const std::size_t total = done.fast.size() + done.far.size();
                done.fast.reserve(total);
                done.far.reserve(total);
                if (!done.far.empty()) detail::stream_fence();  // (streamed triangles before the release)
            }
        } catch (const std::bad_alloc &) {
            out_of_memory.store(true, std::memory_order_relaxed);
            counters.bad_indices.store(true, std::memory_order_relaxed);
        }
        counters.pieces_done.fetch_add(1, std::memory_order_release);
    }
    if (multisampled()) return;  // drawn at end_frame
    mine.rank(bands.count, pool.size() > 1 ? band_affinity::claim_order::kept_then_own : band_affinity::claim_order::top_down);
    std::fill(mine.drew, mine.drew + bands.count, std::uint8_t{0});
    // While the others still set up: claim and clear this thread's next bands (first draw).
    int claimed[MAX_BANDS], claimed_count = 0;
    if (pending_clear)
        claimed_count = counters.claim_while(
            mine, bands.count, pool.size(),
            [&] { return counters.pieces_done.load(std::memory_order_acquire) < plan.count; },
            [&](int band) { clear_band(band); }, claimed);
    phase_counters::wait_for(counters.pieces_done, plan.count);
    const bool drop = counters.bad_indices.load(std::memory_order_relaxed);
    // Bands one ahead, so the next one's lines are fetched while drawing the current one.
    int next = counters.take_band(mine, bands.count);
    auto draw = [&](int band, bool cleared, int ahead) {
        mine.drew[band] = 1;
        if (drop) {
            if (pending_clear && !cleared) clear_band(band);
            return;
        }
        draw_band(band, p, plan, !cleared, ahead);
        band_drawn(thread);
    };
    for (int k = 0; k < claimed_count; ++k) draw(claimed[k], true, k + 1 < claimed_count ? -1 : next);
    while (next < bands.count) {
        const int band = next;
        next = counters.take_band(mine, bands.count);
        draw(band, false, next);
    }
}

void render_context::impl::draw(const raster_mesh &mesh, const draw_params &params) {
    impl &s = *this;
    s.stats.triangles_in += mesh.triangles.size();
    const mat4_t mvp = mat4_multiply(params.view_projection, params.model);
    if (cull_sphere(frustum_from_matrix(mvp), {mesh.bound_center, mesh.bound_radius}) == cull_result::outside) {
        s.stats.culled_frustum += mesh.triangles.size();
        return;
    }
    const bool generic = per_pixel_path(params);
    const std::uint32_t state = static_cast<std::uint32_t>(s.states.size());
    s.states.push_back(params);
    // Cluster culling for the fast path, when built from this mesh.
    const raster_clusters *clusters = params.clusters;
    const bool use_clusters = clusters && !generic && clusters->vertex_count() == mesh.positions.size() &&
                              clusters->triangle_count() == mesh.triangles.size();
    cluster_view view{};
    if (use_clusters) view = make_cluster_view(mvp, s.target->width, s.target->height, s.guard, params.cull);
    const vertex_job job = make_vertex_job(mesh, params, mvp, generic, s.target->width, s.target->height, s.pattern->bits);
    if (!s.multisampled()) s.piece_count = 0;  // (a multisampled frame keeps every draw's pieces)
    const draw_plan plan = s.plan_draw(use_clusters ? clusters->clusters().size() : mesh.triangles.size(), use_clusters);
    s.grow_segments(mesh.positions.size(), generic, plan.shared_vertices ? 1 : s.pool.size());
    s.counters.reset(plan.count, s.pool.size(), s.bands.count);
    auto phase = [&](int t) { s.set_up_and_draw(t, mesh, params, job, state, use_clusters ? &view : nullptr, plan); };
    s.start_pass(mesh.triangles.size());
    s.pool.run(phase);
    s.end_pass();
    s.pending_clear = false;
    if (s.counters.bad_indices.load(std::memory_order_relaxed)) {  // an index out of range: nothing drawn
        s.piece_count = plan.first;  // (a multisampled frame's earlier draws stay)
        return;
    }
    for (piece &from : s.pieces_of(plan)) {
        if (params.alpha < 1.0f)  // translucent triangles wait for end_frame
            for (generic_triangle g : from.generic) {
                g.sequence = static_cast<std::uint32_t>(s.translucent.size());
                s.translucent.push_back(g);
            }
        s.stats.culled_backface += from.stats.culled_backface;
        s.stats.clipped += from.stats.clipped;
        s.stats.rasterized += from.stats.rasterized;
        s.stats.backface_by_cluster += from.stats.backface_by_cluster;
    }
}

// ---- the public class -------------------------------------------------------------------------

render_context::render_context(int threads) : impl_(std::make_unique<impl>(std::clamp(threads, 1, detail::MAX_THREADS))) {}
render_context::~render_context() = default;
int render_context::threads() const { return impl_->pool.size(); }
const zbuffer &render_context::depth() const { return impl_->depth; }
const frame_stats &render_context::stats() const { return impl_->stats; }
raster_simd render_context::simd_in_use() const { return impl_->kernels->simd; }

bool render_context::use_simd(raster_simd simd) {
    if (impl_->target || !detail::kernels_run(simd)) return false;
    impl_->kernels = &detail::kernels_for(simd);
    return true;
}

bool render_context::use_streaming_stores(bool on) {
    if (impl_->target) return false;
    impl_->streaming = on;
    return true;
}
bool render_context::streaming_stores() const { return impl_->streaming; }

status render_context::begin_frame(canvas_t &target, float clear_intensity, sample_count samples) {
    impl &s = *impl_;
    if (!target.pixels || !target.data) return error{"", 0, -1, "render_context: canvas has no pixels"};
    const int count = static_cast<int>(samples);
    if (count != 1 && count != 4 && count != 8 && count != 16)
        return error{"", 0, -1, "render_context: " + std::to_string(count) + " samples per pixel (1, 4, 8 or 16)"};
    s.target = nullptr;
    s.failure = {};
    try {
        const status size_ok = s.depth.resize(target.width, target.height);
        if (!size_ok) return size_ok;
        s.pattern = &detail::pattern_of(count);
        s.piece_count = 0;
        s.clear_intensity = detail::clamp01(clear_intensity);
        s.pending_clear = true;
        s.stats = {};
        s.states.clear();
        s.translucent.clear();
        s.bands.plan(target.height, s.pool.size(), band_rows(count));
        if (count > 1) {
            const int tile_rows = (target.height + s.bands.count - 1) / s.bands.count;
            const bool blocks = detail::sample_store::blocks_for(s.kernels->simd, count);
            for (int t = 0; t < s.pool.size(); ++t)
                s.tiles[t].resize(target.width, tile_rows, count, s.clear_intensity, blocks);
        }
    } catch (const std::bad_alloc &) {
        return error{"", 0, -1, "render_context: out of memory for a " + std::to_string(target.width) + " x " +
                                    std::to_string(target.height) + " frame at " + std::to_string(count) + "x"};
    }
    s.target = &target;
    s.guard = std::clamp(GUARD_SPAN_PIXELS / static_cast<float>(std::max(target.width, target.height)), 1.0f, MAX_GUARD);
    return {};
}

// The frame's last band pass (bands claimed as in draw): a multisampled frame's every band,
// a 1-sample frame's translucent queue (not binned) and any clear still pending.
void render_context::end_frame() {
    impl &s = *impl_;
    if (!s.target) return;
    // Back to front; equal depths keep submission order (std::sort: no temporary buffer).
    std::sort(s.translucent.begin(), s.translucent.end(), [](const generic_triangle &a, const generic_triangle &b) {
        return a.mean_depth != b.mean_depth ? a.mean_depth > b.mean_depth : a.sequence < b.sequence;
    });
    const bool msaa = s.multisampled();
    if (msaa || !s.translucent.empty() || s.pending_clear) {
        s.counters.reset(0, s.pool.size(), s.bands.count);
        if (msaa) s.start_pass(s.stats.triangles_in);
        auto phase = [&](int thread) {
            band_affinity &mine = s.affinity[thread];
            mine.rank(s.bands.count, msaa && s.pool.size() > 1 ? band_affinity::claim_order::own_entries
                                                               : band_affinity::claim_order::top_down);
            for (int band; (band = s.counters.take_band(mine, s.bands.count)) < s.bands.count;) {
                if (msaa) {
                    s.draw_multisampled_band(band, s.tiles[thread]);
                    s.band_drawn(thread);
                    continue;
                }
                if (s.pending_clear) s.clear_band(band);
                for (const generic_triangle &g : s.translucent)
                    draw_generic_rows(*s.target, s.depth, s.states[g.state], g, s.bands.y0(band), s.bands.y0(band + 1));
            }
            mine.forget(s.bands.count);  // (counted again by the next frame's draws)
        };
        s.pool.run(phase);
        if (msaa) s.end_pass();
    }
    s.pending_clear = false;
    s.piece_count = 0;
    s.translucent.clear();
    s.target = nullptr;
}

}  // namespace tiny3d
