// wireframe.cpp — edges → clip space → clipped screen segments → lines, with the report's
// far-to-near Z-sort, depth cueing, back-edge hiding and the circular viewport.
// See include/pipeline.h.
#include <algorithm>
#include <cmath>
#include <string>

#include "pipeline.h"

namespace tiny3d {

namespace {

// A clipped segment on the screen.
struct screen_segment {
    float x0, y0, x1, y1, depth;
};

vec4_t lerp4_d(const vec4_t &a, const vec4_t &b, double t) {
    auto mix = [t](float p, float q) { return float(double(p) + t * (double(q) - double(p))); };
    return {mix(a.x, b.x), mix(a.y, b.y), mix(a.z, b.z), mix(a.w, b.w)};
}

// Clips the clip-space segment a–b (near plane first, then the frustum) and maps the
// visible part to the screen. False when nothing is left.
bool clip_and_project(const vec4_t &a, const vec4_t &b, int width, int height, screen_segment &out) {
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
    const screen_point p = clip_to_screen(c.t0 > 0.0 ? end_at(c.t0, from_b.t1) : a, width, height);
    const screen_point q = clip_to_screen(c.t1 < 1.0 ? end_at(c.t1, from_b.t0) : b, width, height);
    if (p.behind || q.behind) return false;  // only for matrices whose near plane allows w ≤ 0
    out = {p.x, p.y, q.x, q.y, 0.5f * (p.depth + q.depth)};
    return true;
}

// Cuts the screen segment to the circle; false when nothing is inside.
bool clip_to_circle(const circle &c, screen_segment &s) {
    const segment_clip k = clip_segment_circle(c, s.x0, s.y0, s.x1, s.y1);
    if (!k.visible) return false;
    const double dx = double(s.x1) - s.x0, dy = double(s.y1) - s.y0;
    const screen_segment cut{float(s.x0 + k.t0 * dx), float(s.y0 + k.t0 * dy), float(s.x0 + k.t1 * dx),
                             float(s.y0 + k.t1 * dy), s.depth};
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
        // The report's line has no intensity: it always lays down full splats.
        draw_line_f(&canvas, s.x0, s.y0, s.x1, s.y1, thickness);
    }
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
    for (std::size_t e = 0; e < m.edges.size(); ++e)
        if (m.edges[e].a >= n || m.edges[e].b >= n)
            return fail("edge " + std::to_string(e) + " refers to a position out of range");
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

    // Per position: clip coordinates, outcode, and the screen point when inside.
    const std::size_t n = m.positions.size();
    ws.clip.resize(n);
    ws.outcode.resize(n);
    ws.screen_x.resize(n);
    ws.screen_y.resize(n);
    ws.screen_depth.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const vec4_t c = mat4_mul_vec4(model_view_proj, vec4_from_vec3(m.positions[i], 1.0f));
        ws.clip[i] = c;
        ws.outcode[i] = cull == cull_result::inside ? 0u : clip_outcode(c);
        if (ws.outcode[i] != 0) continue;
        const screen_point p = clip_to_screen(c, canvas.width, canvas.height);
        if (p.behind) {  // non-finite (a NaN position passes the sphere test): never drawn at (0, 0)
            ws.outcode[i] = clip_all;
            continue;
        }
        ws.screen_x[i] = p.x;
        ws.screen_y[i] = p.y;
        ws.screen_depth[i] = p.depth;
    }
    if (o.hide_back_edges) {
        ws.face_front.resize(m.face_count());
        for (std::size_t f = 0; f < m.face_count(); ++f) ws.face_front[f] = clip_orientation(m, f, ws.clip) > 0.0;
    }

    const circle circ = circular_viewport(canvas);
    ws.edges.clear();
    for (std::size_t e = 0; e < m.edges.size(); ++e) {
        const std::uint32_t a = m.edges[e].a, b = m.edges[e].b;
        if (o.hide_back_edges && o.adjacency->count(e) > 0 &&
            std::none_of(o.adjacency->begin(e), o.adjacency->end(e), [&](std::uint32_t f) { return ws.face_front[f]; })) {
            ++st.edges_hidden;
            continue;
        }
        screen_segment s;
        if ((ws.outcode[a] | ws.outcode[b]) == 0) {
            s = {ws.screen_x[a], ws.screen_y[a], ws.screen_x[b], ws.screen_y[b],
                 0.5f * (ws.screen_depth[a] + ws.screen_depth[b])};
        } else if ((ws.outcode[a] & ws.outcode[b]) != 0 ||
                   !clip_and_project(ws.clip[a], ws.clip[b], canvas.width, canvas.height, s)) {
            ++st.edges_clipped_away;
            continue;
        }
        if (o.circular_viewport && !clip_to_circle(circ, s)) {
            ++st.edges_clipped_away;
            continue;
        }
        ws.edges.push_back({s.x0, s.y0, s.x1, s.y1, s.depth, std::uint32_t(e)});
    }

    using drawn = wireframe_workspace::drawn_edge;
    if (o.depth_sort)  // far (larger depth) first; equal depths by edge index
        std::sort(ws.edges.begin(), ws.edges.end(), [](const drawn &p, const drawn &q) {
            return p.depth != q.depth ? p.depth > q.depth : p.edge < q.edge;
        });
    float nearest = 0.0f, farthest = 0.0f;
    if (o.depth_cue && !ws.edges.empty()) {
        const auto [lo, hi] = std::minmax_element(ws.edges.begin(), ws.edges.end(),
                                                  [](const drawn &p, const drawn &q) { return p.depth < q.depth; });
        nearest = lo->depth;
        farthest = hi->depth;
    }
    const float depth_range = farthest - nearest;
    // Tabulated lines go to draw_lines_tabulated a batch at a time (same image, faster).
    constexpr std::size_t kBatch = 64;
    line_segment batch[kBatch];
    std::size_t batched = 0;
    for (const drawn &d : ws.edges) {
        float ink = o.intensity;
        if (o.edge_intensity_fn) ink *= o.edge_intensity_fn(d.edge);
        else if (!o.edge_intensity.empty()) ink *= o.edge_intensity[d.edge];
        if (o.depth_cue && depth_range > 0.0f) ink *= 1.0f - (1.0f - o.depth_cue_far) * ((d.depth - nearest) / depth_range);
        if (!(ink > 0.0f)) continue;
        ++st.edges_drawn;
        if (table) {
            batch[batched++] = {d.x0, d.y0, d.x1, d.y1, std::min(ink, 1.0f)};
            if (batched == kBatch) {
                draw_lines_tabulated(&canvas, batch, batched, *table);
                batched = 0;
            }
            continue;
        }
        draw_segment(canvas, {d.x0, d.y0, d.x1, d.y1, d.depth}, o.method, o.thickness, std::min(ink, 1.0f));
    }
    if (batched) draw_lines_tabulated(&canvas, batch, batched, *table);
    return {};
}

}  // namespace tiny3d

void render_wireframe(canvas_t *canvas, vec3_t *vertices, int vertex_count, int edges[][2], int edge_count,
                      mat4_t model, mat4_t proj) {
    if (!canvas || !canvas->data || !vertices || !edges || vertex_count <= 0 || edge_count <= 0) return;
    constexpr float report_thickness = 1.0f;
    const mat4_t mvp = mat4_multiply(proj, model);
    for (int i = 0; i < edge_count; ++i) {
        const int a = edges[i][0], b = edges[i][1];
        if (a < 0 || a >= vertex_count || b < 0 || b >= vertex_count) continue;
        tiny3d::screen_segment s;
        if (!tiny3d::clip_and_project(mat4_mul_vec4(mvp, vec4_from_vec3(vertices[a], 1.0f)),
                                      mat4_mul_vec4(mvp, vec4_from_vec3(vertices[b], 1.0f)), canvas->width,
                                      canvas->height, s))
            continue;
        draw_line_f(canvas, s.x0, s.y0, s.x1, s.y1, report_thickness);
    }
}
