// wireframe.h — a mesh's edges drawn as lines: through the vertex stage (pipeline.h) to
// screen segments, then Z-sort, depth cueing, back-edge hiding, the circular viewport,
// hidden lines against a depth buffer, and the line method (lines.h). Implementation:
// src/wireframe/wireframe.cpp.
//
// Conventions: pipeline.h's (clip space, the library's viewport, screen depth in [0, 1]);
// the report's 7-argument render_wireframe uses the report's viewport (pipeline.h) and
// canvas.h's report convention.
#ifndef TINY3D_WIREFRAME_H
#define TINY3D_WIREFRAME_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>
#endif

#include "canvas.h"
#include "lines.h"
#include "math3d.h"
#include "mesh.h"
#include "pipeline.h"
#include "tiny3d_result.h"

// ---- the libtiny3d report's API (C linkage; all a C program sees from this header) -----
TINY3D_C_BEGIN

// The report's wireframe: every edge (pairs of indices into vertices) transformed by
// proj·model, clipped in clip space (cut at the near plane, never mirrored through w ≤ 0,
// then at the frustum), mapped by the report's viewport (pipeline.h) and drawn with
// draw_line_f at thickness 1, intensity 1 (additive
// splats, so the drawing order does not change the image). Edges with an index outside
// 0..vertex_count−1, null arrays, negative counts or a null canvas are skipped silently
// (nothing is printed). Allocates nothing.
void render_wireframe(canvas_t *canvas, vec3_t *vertices, int vertex_count, int edges[][2],
                      int edge_count, mat4_t model, mat4_t proj);
TINY3D_C_END

#ifdef __cplusplus
namespace tiny3d {

// The depth buffer wireframe_options::depth_test reads (raster.h: the hidden-line test
// reads the filled pipeline's output; only a pointer is held here).
class zbuffer;

// ---- wireframes of tiny3d::mesh ---------------------------------------------------------

enum class line_method {
    faithful,  // the report's draw_line_f (additive splats), handed this viewport's ends
               // moved to the report's convention (x − 0.5, y − 0.5), so the line lies
               // where the other methods draw it. It has no intensity: every
               // edge with ink > 0 is drawn at full ink (per-edge intensity and depth cueing
               // only decide which edges are skipped, ink ≤ 0)
    coverage,  // tiny3d::draw_line_coverage: exact area coverage, round caps, combined
               // "over" (v += c·(1 − v)) with c = ink · coverage
    tabulated, // tiny3d::draw_lines_tabulated: the same stroke and combine, the pixels near
               // each end corrected from a line_table of exact end corrections (max error
               // ≤ 0.015, mean ~5e-5 per line); the workspace builds the
               // table once per thickness (an expensive step) and keeps the last few
};

struct wireframe_options {
    line_method method = line_method::faithful;
    float thickness = 1.0f;         // line width in pixels
    float intensity = 1.0f;         // ink of every edge (times the per-edge value below)
    // Per-edge intensity, one value per mesh edge (e.g. Lambert per edge from the lighting
    // module); empty = 1. If `edge_intensity_fn` is set it is called instead, with the edge
    // index into mesh::edges.
    std::span<const float> edge_intensity{};
    std::function<float(std::uint32_t edge_index)> edge_intensity_fn{};
    // Edges drawn from the farthest to the nearest (the report's Z-sort), by the mean
    // screen depth of the visible part; ties by edge index. Off: mesh::edges order.
    bool depth_sort = true;
    // Depth cueing: ink × (1 − (1 − depth_cue_far)·s), s = 0 for the nearest drawn edge and 1
    // for the farthest (by the same mean depth), linear in between.
    bool depth_cue = false;
    float depth_cue_far = 0.3f;
    // Hide edges whose adjacent faces all face away from the camera (edges with no face
    // are kept). Needs `adjacency` = mesh_edge_faces(mesh).
    bool hide_back_edges = false;
    const edge_adjacency *adjacency = nullptr;
    // Clip the drawing to the circle inscribed in the canvas (the report's viewport).
    bool circular_viewport = false;
    // Skip the whole mesh when its bounding sphere lies outside the frustum. `bounds`
    // may give a precomputed sphere (model space); null = computed on each call (O(V)).
    bool frustum_cull = true;
    const bounding_sphere *bounds = nullptr;
    // Hidden lines: with a depth buffer of the canvas' size (e.g. render_context::depth()
    // after drawing the filled objects), each edge's window depth, interpolated linearly
    // along it on the screen (exact for a straight 3-D edge: z/w is affine in screen space),
    // is tested every half pixel against the buffer, and only the visible parts are drawn:
    // a point is visible when its depth ≤ the largest stored depth of the 2 × 2 pixels
    // around it + depth_bias (so an edge ON a filled surface stays visible, one behind it is
    // hidden). Visible parts end halfway between a visible and a hidden test point. Null:
    // edges are always on top (no test). The buffer must outlive the call.
    const zbuffer *depth_test = nullptr;
    float depth_bias = 1e-4f;  // window-depth units (0..1), ≥ 0
};

struct wireframe_stats {
    std::size_t edges_drawn = 0;
    std::size_t edges_hidden = 0;    // back-facing (hide_back_edges)
    std::size_t edges_clipped_away = 0;  // nothing left after near/frustum/circle clipping
    bool mesh_culled = false;        // frustum culling skipped the whole mesh
};

// Buffers the wireframe renderer reuses from frame to frame: after the first frame of a
// given mesh size (and, for line_method::tabulated, of each thickness among the last
// kLineTables used), rendering allocates nothing (tests/soak_test.cpp). One workspace per
// thread.
class wireframe_workspace {
public:
    struct drawn_edge {
        float x0, y0, x1, y1;  // screen endpoints of the visible part
        float depth;           // mean screen depth of the visible part
        std::uint32_t edge;    // index into mesh::edges
    };
    // A position's screen point and outcode side by side, so an edge reads each end with
    // one 16-byte load.
    struct projected_vertex {
        float x, y;             // pixels (pipeline.h's viewport); 0 unless outcode is 0
        float depth;            // screen depth in [0, 1]; 0 unless outcode is 0
        std::uint32_t outcode;  // clip_outcode of the clip point (0 = inside the frustum; 0 for
                                // every point when the mesh's sphere lies wholly inside), or
                                // clip_all when an inside point has no finite screen point
    };
    std::vector<vec4_t> clip;                  // per position: clip-space coordinates
    std::vector<projected_vertex> vertices;    // per position
    std::vector<std::uint8_t> face_front;  // per face (hide_back_edges)
    std::vector<drawn_edge> edges;         // the frame's visible edges
    std::vector<float> end_depths;         // depth_test only: per mesh edge, the window depths
                                           // at the two ends of its visible part
    // line_method::tabulated: the tables of the last few thicknesses drawn, most recent
    // first (at most kLineTables), so alternating widths do not rebuild them every frame.
    static constexpr std::size_t kLineTables = 4;
    std::vector<line_table> line_tables;
};

// Draws the mesh's edges (mesh::edges; derive them first) transformed by model_view_proj
// (= proj · view · model), clipped as clip_segment does and then to the circle if asked.
// Errors (nothing drawn): an edge index ≥ positions.size(), edge_intensity of the wrong
// size, hide_back_edges without a matching adjacency, thickness not finite or ≤ 0 (or
// above line_table::kMaxThickness with line_method::tabulated), a depth_test buffer of
// another size than the canvas or a depth_bias not finite or < 0.
// Skipped silently (not errors): edges with a NaN or infinite end, whether from a position
// or from the matrix (tests/hostile_test.cpp).
status render_wireframe(canvas_t &canvas, const mesh &m, const mat4_t &model_view_proj,
                        const wireframe_options &options, wireframe_workspace &workspace,
                        wireframe_stats *stats = nullptr);

// The hidden-line test of wireframe_options::depth_test for one screen point (x, y) in
// pixels (centres at +0.5) at window depth z (0..1): true when z ≤ the largest stored depth
// of the 2 × 2 pixels whose centres surround the point (clamped to the buffer) + bias. For
// drawing other marks (dots, labels) over filled objects as the wireframes are. An empty
// buffer hides nothing (true); a NaN z or position is hidden (false).
bool depth_point_visible(const zbuffer &depth, float x, float y, float z, float bias = 1e-4f);

}  // namespace tiny3d
#endif  // __cplusplus

#endif
