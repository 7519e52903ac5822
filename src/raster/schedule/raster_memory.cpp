// raster_memory.cpp — the render context's memory: growing the per-thread vertex buffers,
// and render_context::draw's guard: memory that runs out in a draw (a std::bad_alloc from
// growing the frame's lists, on any thread: the workers catch their own, see
// set_up_and_draw) leaves that draw out and is the frame's status (raster.h).
#include <new>
#include <string>

#include "render_context_impl.h"

namespace tiny3d {

// The first `threads` threads' buffers can hold a transformed copy of every vertex (and the
// per-pixel path's attributes when wanted): only thread 0's when all transform into it.
void render_context::impl::grow_segments(std::size_t vertex_count, bool generic, int threads) {
    for (int t = 0; t < threads; ++t) {
        segment &seg = segments[t];
        if (seg.vertices.size() < vertex_count)
            seg.vertices.resize(vertex_count), seg.clip.resize(vertex_count), seg.stamp.resize(vertex_count, 0u);
        if (generic && seg.vertex_attr.size() < vertex_count * detail::ATTR_COUNT)
            seg.vertex_attr.resize(vertex_count * detail::ATTR_COUNT);
    }
}

void render_context::draw(const raster_mesh &mesh, const draw_params &params) {
    impl &s = *impl_;
    if (!s.target || mesh.positions.size() != mesh.normals.size() || mesh.positions.size() != mesh.uvs.size()) return;
    if (!check_material(params.surface)) return;  // a bad material draws nothing
    const int pieces_before = s.multisampled() ? s.piece_count : 0;
    s.out_of_memory.store(false, std::memory_order_relaxed);
    try {
        s.draw(mesh, params);
    } catch (const std::bad_alloc &) {
        s.out_of_memory.store(true, std::memory_order_relaxed);
    }
    if (!s.out_of_memory.load(std::memory_order_relaxed)) return;
    s.piece_count = pieces_before;  // nothing of this draw is drawn
    if (s.failure.ok())
        s.failure = error{"", 0, -1,
                          "out of memory drawing a mesh of " + std::to_string(mesh.triangles.size()) + " triangles and " +
                              std::to_string(mesh.positions.size()) + " vertices"};
}

status render_context::frame_status() const { return impl_->failure; }

void render_context::report_progress(void (*report)(const progress &, void *), void *user) {
    impl_->progress_report = report;
    impl_->progress_user = user;
}

}  // namespace tiny3d
