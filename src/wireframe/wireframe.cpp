// wireframe.cpp — edges → clip space → clipped screen segments → lines, with the report's
// far-to-near Z-sort, depth cueing, back-edge hiding and the circular viewport.
// See include/wireframe.h.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <string>

#include "canvas.h"
#include "lines.h"
#include "mesh.h"
#include "pipeline.h"
#include "raster.h"  // zbuffer: the hidden-line test reads the filled pipeline's depth
#include "wireframe.h"
#include "../pipeline/project4.h"
#include "../simd_config.h"


namespace tiny3d {

namespace {

// A clipped segment on the screen: ends, mean depth, end depths.
struct screen_segment {
    float x0, y0, x1, y1, depth;
    float depth0 = 0, depth1 = 0;
};

vec4_t lerp4_d(const vec4_t &a, const vec4_t &b, double t) {
    auto mix = [t](float p, float q) { return float(double(p) + t * (double(q) - double(p))); };
    return {mix(a.x, b.x), mix(a.y, b.y), mix(a.z, b.z), mix(a.w, b.w)};
}

// Clips the clip-space segment a–b (near plane first, then the frustum) and maps the
// visible part to the screen (the library's viewport, or the report's). False when
// nothing is left.
bool clip_and_project(const vec4_t &a, const vec4_t &b, int width, int height, screen_segment &out,
                      bool report_viewport = false) {
    const segment_clip c = clip_segment(a, b, clip_all);
    if (!c.visible) return false;
    // A clipped end is interpolated from the original end it is nearer to: from a far-off
    // end (1e30) its parameter is 1 − 1e-28, which rounds to 1, and a + (b − a)·t cancels
    // to garbage (the edge vanished when listed far end first). Clipping b→a gives the
    // same interval as small parameters from b.
    const segment_clip from_b = clip_segment(b, a, clip_all);
    auto end_at = [&](double t, double t_from_b) {
        return t <= 0.5 || !from_b.visible ? lerp4_d(a, b, t) : lerp4_d(b, a, t_from_b);
    };
    const auto to_screen = report_viewport ? clip_to_report_screen : clip_to_screen;
    const screen_point p = to_screen(c.t0 > 0.0 ? end_at(c.t0, from_b.t1) : a, width, height);
    const screen_point q = to_screen(c.t1 < 1.0 ? end_at(c.t1, from_b.t0) : b, width, height);
    if (p.behind || q.behind) return false;  // only for matrices whose near plane allows w ≤ 0
    out = {p.x, p.y, q.x, q.y, 0.5f * (p.depth + q.depth), p.depth, q.depth};
    return true;
}

// Cuts the screen segment to the circle; false when nothing is inside.
bool clip_to_circle(const circle &c, screen_segment &s) {
    const segment_clip k = clip_segment_circle(c, s.x0, s.y0, s.x1, s.y1);
    if (!k.visible) return false;
    const double dx = double(s.x1) - s.x0, dy = double(s.y1) - s.y0;
    const double dz = double(s.depth1) - s.depth0;
    const screen_segment cut{float(s.x0 + k.t0 * dx), float(s.y0 + k.t0 * dy), float(s.x0 + k.t1 * dx),
                             float(s.y0 + k.t1 * dy), s.depth,  float(s.depth0 + k.t0 * dz),
                             float(s.depth0 + k.t1 * dz)};
    s = cut;
    return true;
}

// Orientation of the face in clip space: Σ over its fan triangles of det[x y w] (in
// double). For a perspective matrix this is a positive multiple of the view-space triple
// product, whose sign says on which side of the face's plane the eye is, whatever the
// signs of w (Olano & Greer 1997); > 0 = counter-clockwise on screen = front facing.
double clip_orientation(const mesh &m, std::size_t f, const std::vector<vec4_t> &clip) {
    const std::uint32_t s = m.face_start[f], e = m.face_start[f + 1];
    const vec4_t &a = clip[m.indices[s]];
    double sum = 0.0;
    for (std::uint32_t k = s + 1; k + 1 < e; ++k) {
        const vec4_t &b = clip[m.indices[k]], &c = clip[m.indices[k + 1]];
        sum += double(a.x) * (double(b.y) * c.w - double(b.w) * c.y) -
               double(a.y) * (double(b.x) * c.w - double(b.w) * c.x) +
               double(a.w) * (double(b.x) * c.y - double(b.y) * c.x);
    }
    return sum;
}

// Moves the workspace's table for `thickness` to the front, building it if missing (the
// least recently used table makes room).
status use_line_table(wireframe_workspace &ws, float thickness) {
    auto &tables = ws.line_tables;
    const auto found = std::find_if(tables.begin(), tables.end(),
                                    [&](const line_table &t) { return t.thickness() == thickness; });
    if (found != tables.end()) {
        std::rotate(tables.begin(), found, found + 1);
        return {};
    }
    result<line_table> made = line_table::make(thickness);
    if (!made) return error{"", 0, -1, "render_wireframe: " + made.err().reason};
    if (tables.size() >= wireframe_workspace::kLineTables) tables.pop_back();
    tables.insert(tables.begin(), std::move(made).value());
    return {};
}

// A segment by the coverage or the faithful line (tabulated ones are drawn in batches).
void draw_segment(canvas_t &canvas, const screen_segment &s, line_method method, float thickness, float ink) {
    if (method == line_method::coverage) {
        line_style style;
        style.intensity = ink;
        draw_line_coverage(&canvas, s.x0, s.y0, s.x1, s.y1, thickness, style);
    } else {
        // The report's line has no intensity: it always lays down full splats. It takes the
        // report's coordinates (pixel centres on integers): the library's minus 0.5.
        draw_line_f(&canvas, s.x0 - 0.5f, s.y0 - 0.5f, s.x1 - 0.5f, s.y1 - 0.5f, thickness);
    }
}

using projected_vertex = wireframe_workspace::projected_vertex;
using drawn_edge = wireframe_workspace::drawn_edge;

// One position's screen point and outcode (the definition the SSE2 path below matches):
// clip_outcode (0 for every point when the mesh's sphere is wholly inside), then
// clip_to_screen for the inside points.
projected_vertex project_one(const vec4_t &c, bool all_inside, int width, int height) {
    const unsigned code = all_inside ? 0u : clip_outcode(c);
    if (code != 0) return {0.0f, 0.0f, 0.0f, code};
    const screen_point p = clip_to_screen(c, width, height);
    // Non-finite (a NaN position passes the sphere test): never drawn at (0, 0).
    if (p.behind) return {0.0f, 0.0f, 0.0f, clip_all};
    return {p.x, p.y, p.depth, 0u};
}

#ifdef TINY3D_SSE2
// project_one for clip[0..3], one lane per point: the vertex stage's project4 (the same
// float operations as clip_outcode and clip_to_screen), then project_one's choices.
void project_four(const vec4_t *clip, bool all_inside, float width, float height, projected_vertex *out) {
    __m128 x = _mm_loadu_ps(&clip[0].x), y = _mm_loadu_ps(&clip[1].x), z = _mm_loadu_ps(&clip[2].x),
           w = _mm_loadu_ps(&clip[3].x);
    _MM_TRANSPOSE4_PS(x, y, z, w);
    const detail::projected4 p = detail::project4(x, y, z, w, 1.0f, width, height, !all_inside);
    const __m128i all_planes = _mm_set1_epi32(int(clip_all));
    const __m128i inside = _mm_cmpeq_epi32(p.outcode, _mm_setzero_si128());
    const __m128i code = _mm_or_si128(p.outcode, _mm_and_si128(_mm_andnot_si128(_mm_castps_si128(p.in_front), inside), all_planes));
    const __m128 shown = _mm_castsi128_ps(_mm_cmpeq_epi32(code, _mm_setzero_si128()));
    __m128 sx = _mm_and_ps(p.x, shown), sy = _mm_and_ps(p.y, shown), depth = _mm_and_ps(p.depth, shown);
    __m128 packed_code = _mm_castsi128_ps(code);
    _MM_TRANSPOSE4_PS(sx, sy, depth, packed_code);
    _mm_storeu_ps(&out[0].x, sx);
    _mm_storeu_ps(&out[1].x, sy);
    _mm_storeu_ps(&out[2].x, depth);
    _mm_storeu_ps(&out[3].x, packed_code);
}
#endif

// ws.vertices from ws.clip.
void project_vertices(wireframe_workspace &ws, bool all_inside, int width, int height) {
    const std::size_t n = ws.clip.size();
    ws.vertices.resize(n);
    std::size_t i = 0;
#ifdef TINY3D_SSE2
    static_assert(sizeof(projected_vertex) == 4 * sizeof(float) && sizeof(vec4_t) == 4 * sizeof(float));
    for (; i + 4 <= n; i += 4) project_four(&ws.clip[i], all_inside, float(width), float(height), &ws.vertices[i]);
#endif
    for (; i < n; ++i) ws.vertices[i] = project_one(ws.clip[i], all_inside, width, height);
}

// Inks and draws listed edges in the order given: ink = intensity × per-edge value ×
// depth cue; tabulated lines go to draw_lines_tabulated a batch at a time (same image,
// faster). finish() draws what is left.
class edge_painter {
public:
    edge_painter(canvas_t &canvas, const wireframe_options &o, const line_table *table, wireframe_stats &st)
        : canvas_(canvas), o_(o), table_(table), st_(st) {}
    // Every edge gets o.intensity (no per-edge value, no depth cue): callers may use draw.
    bool uniform_ink() const { return !o_.edge_intensity_fn && o_.edge_intensity.empty() && !o_.depth_cue; }
    // Depth cueing from the nearest and farthest listed depths.
    void set_depth_range(float nearest, float farthest) {
        nearest_ = nearest;
        depth_range_ = farthest - nearest;
    }
    void paint(const drawn_edge &d) {
        float ink = o_.intensity;
        if (o_.edge_intensity_fn) ink *= o_.edge_intensity_fn(d.edge);
        else if (!o_.edge_intensity.empty()) ink *= o_.edge_intensity[d.edge];
        if (o_.depth_cue && depth_range_ > 0.0f)
            ink *= 1.0f - (1.0f - o_.depth_cue_far) * ((d.depth - nearest_) / depth_range_);
        if (ink > 0.0f) draw(d, std::min(ink, 1.0f));
    }
    // Draws d with ink in (0, 1] (tabulated lines: queues it in the batch).
    void draw(const drawn_edge &d, float ink) {
        ++st_.edges_drawn;
        if (!table_) return draw_one(d, ink);
        batch_[batched_++] = {d.x0, d.y0, d.x1, d.y1, ink};
        if (batched_ == kBatch) finish();
    }
    [[gnu::noinline]] void finish() {
        if (batched_) draw_lines_tabulated(&canvas_, batch_, batched_, *table_);
        batched_ = 0;
    }

private:
    [[gnu::noinline]] void draw_one(const drawn_edge &d, float ink) {
        draw_segment(canvas_, {d.x0, d.y0, d.x1, d.y1, d.depth}, o_.method, o_.thickness, ink);
    }
    static constexpr std::size_t kBatch = 64;
    canvas_t &canvas_;
    const wireframe_options &o_;
    const line_table *table_;
    wireframe_stats &st_;
    float nearest_ = 0.0f, depth_range_ = 0.0f;
    line_segment batch_[kBatch];
    std::size_t batched_ = 0;
};

// Writes the drawn edge between two inside points: their screen points and the mean depth
// 0.5·(p.depth + q.depth). Plain C++: GCC -O2 compiles it to two 8-byte copies and the
// depth's add and multiply (9 instructions, as many as the SSE2 version it replaces).
inline void list_inside_edge(const projected_vertex &p, const projected_vertex &q, std::uint32_t e, drawn_edge &out) {
    std::memcpy(&out.x0, &p.x, 2 * sizeof(float));  // x0, y0 (x, y adjacent in both)
    std::memcpy(&out.x1, &q.x, 2 * sizeof(float));
    out.depth = 0.5f * (p.depth + q.depth);
    out.edge = e;
}

// True when every face of edge e faces away (edges with no face are kept).
bool back_edge(const edge_adjacency &adjacency, const std::vector<std::uint8_t> &face_front, std::size_t e) {
    return adjacency.count(e) > 0 &&
           std::none_of(adjacency.begin(e), adjacency.end(e), [&](std::uint32_t f) { return face_front[f]; });
}

// What listing an edge needs besides the edge itself.
struct listing {
    const canvas_t &canvas;
    const wireframe_workspace &ws;
    const edge_adjacency *hide;  // non-null: hide back edges
    const circle *round;         // non-null: clip to this circle
    std::vector<float> *end_depths;  // non-null (depth_test): record each listed edge's end depths
    wireframe_stats &st;
};

// Lists edge e = a–b in the general case (out of line, so the loop over the edges stays
// tight for the plain one, both ends inside with no back-edge test or circle): hidden if
// it faces away, else clipped in clip space if an end is outside the frustum, then to the
// circle. False (and counted) when it is not listed.
[[gnu::noinline]] bool list_general_edge(const listing &l, std::uint32_t a, std::uint32_t b, std::size_t e,
                                         drawn_edge &out) {
    if (l.hide && back_edge(*l.hide, l.ws.face_front, e)) {
        ++l.st.edges_hidden;
        return false;
    }
    const projected_vertex &p = l.ws.vertices[a], &q = l.ws.vertices[b];
    screen_segment s;
    if ((p.outcode | q.outcode) == 0) {
        s = {p.x, p.y, q.x, q.y, 0.5f * (p.depth + q.depth), p.depth, q.depth};
    } else if ((p.outcode & q.outcode) != 0 ||
               !clip_and_project(l.ws.clip[a], l.ws.clip[b], l.canvas.width, l.canvas.height, s)) {
        ++l.st.edges_clipped_away;
        return false;
    }
    if (l.round && !clip_to_circle(*l.round, s)) {
        ++l.st.edges_clipped_away;
        return false;
    }
    out = {s.x0, s.y0, s.x1, s.y1, s.depth, std::uint32_t(e)};
    if (l.end_depths) (*l.end_depths)[2 * e] = s.depth0, (*l.end_depths)[2 * e + 1] = s.depth1;
    return true;
}

// Lists the visible part of every edge in ws.edges (mesh order), counting the hidden and
// clipped ones, and hands each listed edge to on_listed.
template <class OnListed>
void list_edges(const canvas_t &canvas, const mesh &m, const wireframe_options &o, wireframe_workspace &ws,
                wireframe_stats &st, OnListed on_listed) {
    const circle circ = circular_viewport(canvas);
    if (o.depth_test) ws.end_depths.resize(2 * m.edges.size());
    const listing general{canvas, ws, o.hide_back_edges ? o.adjacency : nullptr, o.circular_viewport ? &circ : nullptr,
                          o.depth_test ? &ws.end_depths : nullptr, st};
    // Nonzero when every edge needs the general path (OR-ed into the ends' outcodes).
    const std::uint32_t all_general = general.hide || general.round || general.end_depths ? 1u : 0u;
    const projected_vertex *vertex = ws.vertices.data();
    const edge *const edges = m.edges.data();
    const std::size_t edge_count = m.edges.size();
    ws.edges.resize(edge_count);  // at most every edge; trimmed to the listed ones below
    drawn_edge *const first = ws.edges.data();
    drawn_edge *out = first;
    for (std::size_t e = 0; e < edge_count; ++e) {
        const std::uint32_t a = edges[e].a, b = edges[e].b;
        if ((vertex[a].outcode | vertex[b].outcode | all_general) == 0)
            list_inside_edge(vertex[a], vertex[b], std::uint32_t(e), *out);
        else if (!list_general_edge(general, a, b, e, *out)) continue;
        on_listed(*out);
        ++out;
    }
    ws.edges.resize(std::size_t(out - first));
}

// The largest position index among the edges' ends (0 for none), in one branch-free pass
// (the first bad edge is looked for only when there is one). Four indices (two edges) per
// step in four running maxima, compared as signed after flipping their top bit (x ↦ x − 2³¹
// keeps the order): plain C++ that GCC -O2 vectorises into the SSE2 loop (pxor, pcmpgtd,
// pand/pandn/por; 11 instructions per two edges).
std::uint32_t highest_edge_end(const std::vector<edge> &edges) {
    constexpr std::uint32_t kTopBit = 0x80000000u;
    static_assert(sizeof(edge) == 2 * sizeof(std::uint32_t), "edges are two packed indices");
    std::int32_t top[4];
    std::fill(std::begin(top), std::end(top), std::numeric_limits<std::int32_t>::min());  // 0, flipped
    std::size_t i = 0;
    for (; i + 2 <= edges.size(); i += 2) {
        std::uint32_t ends[4];
        std::memcpy(ends, &edges[i], sizeof ends);
        for (int k = 0; k < 4; ++k) {
            const std::int32_t flipped = std::int32_t(ends[k] ^ kTopBit);
            top[k] = flipped > top[k] ? flipped : top[k];
        }
    }
    std::uint32_t highest = 0;
    for (const std::int32_t t : top) highest = std::max(highest, std::uint32_t(t) ^ kTopBit);
    for (; i < edges.size(); ++i) highest = std::max(highest, std::max(edges[i].a, edges[i].b));
    return highest;
}

// The listed edges far to near (depth_sort) and the depth cue's range (depth_cue).
void order_edges(const wireframe_options &o, wireframe_workspace &ws, edge_painter &painter) {
    if (o.depth_sort)  // far (larger depth) first; equal depths by edge index
        std::sort(ws.edges.begin(), ws.edges.end(), [](const drawn_edge &p, const drawn_edge &q) {
            return p.depth != q.depth ? p.depth > q.depth : p.edge < q.edge;
        });
    if (o.depth_cue && !ws.edges.empty()) {
        const auto [lo, hi] = std::minmax_element(
            ws.edges.begin(), ws.edges.end(), [](const drawn_edge &p, const drawn_edge &q) { return p.depth < q.depth; });
        painter.set_depth_range(lo->depth, hi->depth);
    }
}

// Paints the visible parts of d (end depths z0, z1): test points every ≤ ½ px along it,
// each run of visible points drawn as one segment ending halfway to its hidden neighbours
// (the whole edge, exactly as listed, when every point is visible).
void paint_visible_parts(const drawn_edge &d, float z0, float z1, const zbuffer &depth, float bias, edge_painter &painter) {
    const double dx = double(d.x1) - d.x0, dy = double(d.y1) - d.y0;
    constexpr double STEP = 0.5;  // px between test points
    const int steps = std::max(1, int(std::ceil(std::sqrt(dx * dx + dy * dy) / STEP)));
    auto visible_at = [&](int k) {
        const double t = double(k) / steps;
        return depth_point_visible(depth, float(d.x0 + t * dx), float(d.y0 + t * dy), float(z0 + t * (double(z1) - z0)), bias);
    };
    int run_start = -1;  // first visible point of the current run
    bool all = true;
    auto paint_run = [&](int first, int last) {  // points first..last visible
        const double t0 = first == 0 ? 0.0 : (first - 0.5) / steps, t1 = last == steps ? 1.0 : (last + 0.5) / steps;
        drawn_edge part = d;
        part.x0 = float(d.x0 + t0 * dx), part.y0 = float(d.y0 + t0 * dy);
        part.x1 = float(d.x0 + t1 * dx), part.y1 = float(d.y0 + t1 * dy);
        painter.paint(part);
    };
    for (int k = 0; k <= steps; ++k) {
        const bool v = visible_at(k);
        all = all && v;
        if (v && run_start < 0) run_start = k;
        if (!v && run_start >= 0) paint_run(run_start, k - 1), run_start = -1;
    }
    if (all) return painter.paint(d);
    if (run_start >= 0) paint_run(run_start, steps);
}

status check_inputs(const canvas_t &canvas, const mesh &m, const wireframe_options &o) {
    auto fail = [](std::string why) { return status(error{"", 0, -1, "render_wireframe: " + std::move(why)}); };
    if (!canvas.data || canvas.width <= 0 || canvas.height <= 0) return fail("canvas has no pixels");
    if (!std::isfinite(o.thickness) || !(o.thickness > 0.0f)) return fail("thickness must be finite and > 0");
    if (!o.edge_intensity.empty() && o.edge_intensity.size() != m.edges.size())
        return fail("edge_intensity has " + std::to_string(o.edge_intensity.size()) + " values for " +
                    std::to_string(m.edges.size()) + " edges");
    if (o.hide_back_edges && (!o.adjacency || o.adjacency->start.size() != m.edges.size() + 1))
        return fail("hide_back_edges needs adjacency = mesh_edge_faces(mesh) for this mesh");
    const std::size_t n = m.positions.size();
    if (!m.edges.empty() && highest_edge_end(m.edges) >= n)
        for (std::size_t e = 0; e < m.edges.size(); ++e)
            if (m.edges[e].a >= n || m.edges[e].b >= n)
                return fail("edge " + std::to_string(e) + " refers to a position out of range");
    if (o.depth_test && (o.depth_test->width() != canvas.width || o.depth_test->height() != canvas.height))
        return fail("depth_test buffer is " + std::to_string(o.depth_test->width()) + " x " +
                    std::to_string(o.depth_test->height()) + ", the canvas " + std::to_string(canvas.width) + " x " +
                    std::to_string(canvas.height));
    if (o.depth_test && !(std::isfinite(o.depth_bias) && o.depth_bias >= 0.0f))
        return fail("depth_bias must be finite and >= 0");
    if (o.hide_back_edges) {
        for (std::uint32_t idx : m.indices)
            if (idx >= n) return fail("a face refers to a position out of range");
        for (std::uint32_t f : o.adjacency->faces)
            if (f >= m.face_count()) return fail("adjacency refers to a face out of range");
    }
    return {};
}

}  // namespace

status render_wireframe(canvas_t &canvas, const mesh &m, const mat4_t &model_view_proj,
                        const wireframe_options &o, wireframe_workspace &ws, wireframe_stats *stats) {
    wireframe_stats local;
    wireframe_stats &st = stats ? *stats : local;
    st = {};
    if (status s = check_inputs(canvas, m, o); !s) return s;
    const line_table *table = nullptr;
    if (o.method == line_method::tabulated) {
        if (status s = use_line_table(ws, o.thickness); !s) return s;
        table = &ws.line_tables.front();
    }

    cull_result cull = cull_result::intersecting;
    if (o.frustum_cull) {
        cull = cull_sphere(frustum_from_matrix(model_view_proj), o.bounds ? *o.bounds : mesh_bounding_sphere(m));
        if (cull == cull_result::outside) {
            st.mesh_culled = true;
            return {};
        }
    }

    // Per position: clip coordinates, then the packed screen point and outcode.
    ws.clip.resize(m.positions.size());
    (void)transform_points_homogeneous(model_view_proj, m.positions, ws.clip);  // sizes match: cannot fail
    project_vertices(ws, cull == cull_result::inside, canvas.width, canvas.height);
    if (o.hide_back_edges) {
        ws.face_front.resize(m.face_count());
        for (std::size_t f = 0; f < m.face_count(); ++f) ws.face_front[f] = clip_orientation(m, f, ws.clip) > 0.0;
    }

    edge_painter painter(canvas, o, table, st);
    const auto list_only = [](const drawn_edge &) {};
    if (o.depth_test) {  // hidden lines: list, order, then paint each edge's visible parts
        list_edges(canvas, m, o, ws, st, list_only);
        order_edges(o, ws, painter);
        for (const drawn_edge &d : ws.edges)
            paint_visible_parts(d, ws.end_depths[2 * d.edge], ws.end_depths[2 * d.edge + 1], *o.depth_test, o.depth_bias,
                                painter);
    } else if (!o.depth_sort && !o.depth_cue) {  // mesh order, nothing to know first: paint as listed
        if (!painter.uniform_ink()) {
            list_edges(canvas, m, o, ws, st, [&](const drawn_edge &d) { painter.paint(d); });
        } else if (o.intensity > 0.0f) {
            const float ink = std::min(o.intensity, 1.0f);
            list_edges(canvas, m, o, ws, st, [&](const drawn_edge &d) { painter.draw(d, ink); });
        } else {
            list_edges(canvas, m, o, ws, st, list_only);  // no ink anywhere: nothing to draw
        }
    } else {
        list_edges(canvas, m, o, ws, st, list_only);
        order_edges(o, ws, painter);
        for (const drawn_edge &d : ws.edges) painter.paint(d);
    }
    painter.finish();
    return {};
}

bool depth_point_visible(const zbuffer &depth, float x, float y, float z, float bias) {
    const int w = depth.width(), h = depth.height();
    if (w <= 0 || h <= 0) return true;
    if (std::isnan(x) || std::isnan(y) || std::isnan(z)) return false;
    const float fx = std::clamp(x - 0.5f, 0.0f, float(w - 1)), fy = std::clamp(y - 0.5f, 0.0f, float(h - 1));
    const int x0 = int(fx), y0 = int(fy), x1 = std::min(x0 + 1, w - 1), y1 = std::min(y0 + 1, h - 1);
    const float stored = std::max(std::max(depth.at(x0, y0), depth.at(x1, y0)), std::max(depth.at(x0, y1), depth.at(x1, y1)));
    return z <= stored + bias;
}

}  // namespace tiny3d

void render_wireframe(canvas_t *canvas, vec3_t *vertices, int vertex_count, int edges[][2], int edge_count,
                      mat4_t model, mat4_t proj) {
    if (!canvas || !canvas->data || !vertices || !edges || vertex_count <= 0 || edge_count <= 0) return;
    constexpr float report_thickness = 1.0f;
    // Model, then projection, per vertex as the report's project_vertex does, so an edge
    // that needs no clipping gets the report's end points bit for bit.
    const auto to_clip = [&](const vec3_t &v) { return mat4_mul_vec4(proj, mat4_mul_vec4(model, vec4_from_vec3(v, 1.0f))); };
    for (int i = 0; i < edge_count; ++i) {
        const int a = edges[i][0], b = edges[i][1];
        if (a < 0 || a >= vertex_count || b < 0 || b >= vertex_count) continue;
        tiny3d::screen_segment s;
        if (!tiny3d::clip_and_project(to_clip(vertices[a]), to_clip(vertices[b]), canvas->width, canvas->height, s,
                                      true))
            continue;
        draw_line_f(canvas, s.x0, s.y0, s.x1, s.y1, report_thickness);
    }
}
