// pipeline.h — projection, viewport, clipping, frustum culling and wireframes (part of the
// renderer module; renderer.h includes it). Implementations: src/pipeline/vertex_projection.cpp,
// src/pipeline/clipping.cpp, src/wireframe/wireframe.cpp.
//
// Stages, as data flows:
//   model space --model--> world --view--> camera --proj--> clip space (x, y, z, w)
//   --clip (near plane first, then the frustum; w > 0 afterwards)--> divide by w --> NDC
//   --viewport--> screen pixels --(optional circular viewport)--> lines on the canvas.
//
// Conventions:
//  * Clip space is OpenGL's: a point is inside when −w ≤ x, y, z ≤ w; w > 0 in front of
//    the camera. NDC z = −1 is the near plane, +1 the far plane.
//  * Viewport (the pixel-centre convention of canvas.h): NDC x = −1 maps to the LEFT EDGE of
//    the canvas (screen x = 0) and +1 to the right edge (x = width); NDC y = +1 maps to the
//    TOP edge (y = 0), −1 to the bottom edge (y = height):
//        sx = (ndc_x + 1) / 2 · width,   sy = (1 − ndc_y) / 2 · height.
//    The NDC origin therefore lands on (width/2, height/2), the boundary between the two
//    middle pixels: a symmetric frustum stays centred and covers exactly W×H pixels.
//  * The report's viewport (project_vertex, the 7-argument render_wireframe; canvas.h's
//    report convention, integer coordinates are pixel centres), as the report's code:
//        sx = (ndc_x·0.5 + 0.5)·(width − 1),   sy = (1 − (ndc_y·0.5 + 0.5))·(height − 1),
//    NDC ±1 → the centres of the first and last pixels: the same picture as the library's
//    viewport, shrunk by one pixel about the canvas centre.
//  * Screen depth: NDC z remapped to [0, 1] (0 at the near plane, 1 at the far plane).
#ifndef TINY3D_PIPELINE_H
#define TINY3D_PIPELINE_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "canvas.h"
#include "math3d.h"
#include "mesh.h"
#include "tiny3d_result.h"

// ---- the libtiny3d report's API ------------------------------------------------------

// Transforms v by model, then by proj (two products, as the report), divides by w and
// maps to the screen by the REPORT's viewport (above). Returns 1 and writes *x_out, *y_out in pixels when the point is in front of the
// camera (clip w > 0 and finite); returns 0 and leaves the outputs untouched when w ≤ 0
// (at or behind the camera) or the result is not finite. Null output pointers are allowed
// (nothing is written there). Points off the canvas (outside the frustum) still return 1.
int project_vertex(vec3_t v, mat4_t model, mat4_t proj, int width, int height, float *x_out,
                   float *y_out);

// True when (x, y) (pixels) lies inside or on the circle inscribed in the canvas: centre
// (width/2, height/2), radius min(width, height)/2 — the report's circular viewport. False
// for a null canvas or non-finite coordinates.
bool clip_to_circular_viewport(canvas_t *c, float x, float y);

// The report's wireframe: every edge (pairs of indices into vertices) transformed by
// proj·model, clipped in clip space (cut at the near plane, never mirrored through w ≤ 0,
// then at the frustum), mapped by the report's viewport (above) and drawn with
// draw_line_f at thickness 1, intensity 1 (additive
// splats, so the drawing order does not change the image). Edges with an index outside
// 0..vertex_count−1, null arrays, negative counts or a null canvas are skipped silently
// (nothing is printed). Allocates nothing.
void render_wireframe(canvas_t *canvas, vec3_t *vertices, int vertex_count, int edges[][2],
                      int edge_count, mat4_t model, mat4_t proj);

namespace tiny3d {

class zbuffer;  // raster.h: the depth buffer wireframe_options::depth_test reads

// ---- projection and viewport (src/pipeline/vertex_projection.cpp) ----------------------------

struct screen_point {
    float x, y;     // pixels (viewport convention above)
    float depth;    // NDC z mapped to [0, 1]: 0 near plane, 1 far plane
    float w;        // clip-space w (view-space distance along the view axis for glFrustum)
    bool behind;    // w ≤ 0 or not finite: x, y, depth are then meaningless (set to 0)
};

// NDC → pixels (the viewport convention above).
inline float ndc_to_screen_x(float ndc_x, float width) { return (ndc_x + 1.0f) * 0.5f * width; }
inline float ndc_to_screen_y(float ndc_y, float height) { return (1.0f - ndc_y) * 0.5f * height; }

// The report's viewport (above), in its float operations.
inline float report_ndc_to_screen_x(float ndc_x, int width) { return (ndc_x * 0.5f + 0.5f) * float(width - 1); }
inline float report_ndc_to_screen_y(float ndc_y, int height) {
    return (1.0f - (ndc_y * 0.5f + 0.5f)) * float(height - 1);
}

// Clip space → screen point (divides by w when w > 0).
screen_point clip_to_screen(vec4_t clip, int width, int height);
// The same by the report's viewport (x / w as the report divides, then report_ndc_to_screen).
screen_point clip_to_report_screen(vec4_t clip, int width, int height);

// v (model space) through model_view_proj to the screen.
screen_point project_point(vec3_t v, const mat4_t &model_view_proj, int width, int height);

// ---- clipping (src/pipeline/clipping.cpp) -------------------------------------------

// The visible part of a segment as parameters along it: points a + t·(b − a), t in
// [t0, t1]; visible = false when nothing remains.
struct segment_clip {
    bool visible;
    double t0, t1;  // double: a float t would cost up to ~1e-4 px on a 2000-px segment
};

// The clip-space planes of both pipelines, inside where the named signed distance is ≥ 0.
// g is the guard band (1 = the frustum itself; the render context widens the x/y planes so
// that triangles are clipped only where the 32-bit fill needs it).
enum clip_plane_bits : unsigned {
    clip_near = 1u << 0,    // z + w ≥ 0
    clip_far = 1u << 1,     // w − z ≥ 0
    clip_left = 1u << 2,    // x + g·w ≥ 0
    clip_right = 1u << 3,   // g·w − x ≥ 0
    clip_bottom = 1u << 4,  // y + g·w ≥ 0
    clip_top = 1u << 5,     // g·w − y ≥ 0
    clip_all = 63u,
};

// Bits of the planes p is outside of (0 = inside), the distances evaluated in float
// (g·w rounded once, then one sum each; the sign of such a sum is that of the exact sum of
// the two floats). A point with any NaN or infinite coordinate is outside every plane
// (clip_all). guard ≥ 1 and finite.
unsigned clip_outcode(vec4_t p, float guard = 1.0f);

// Liang–Barsky in homogeneous clip space against the planes in `planes` (default: all six;
// pass clip_near alone to cut only at the near plane). Intersections are computed in double
// precision from the signed distances d(a), d(b): t = d(a) / (d(a) − d(b)). Because the
// near plane is cut before the divide, a segment from in front of the camera to behind it
// keeps only its front part (no wrap-around through infinity). A segment with any NaN
// coordinate is invisible.
segment_clip clip_segment(vec4_t a, vec4_t b, unsigned planes = clip_all);

// a + t·(b − a), componentwise.
vec4_t lerp4(vec4_t a, vec4_t b, float t);

// ---- clipping triangles (src/pipeline/clip_triangle.cpp) -------------------------------

// A clip-space vertex with interpolated attributes (intensity, normal, uv, …).
inline constexpr int CLIP_MAX_ATTRIBUTES = 12;
struct clip_vertex {
    vec4_t position;  // clip space (OpenGL): visible when −w ≤ x, y, z ≤ w
    std::array<float, CLIP_MAX_ATTRIBUTES> attr;
};
inline constexpr int CLIP_MAX_VERTICES = 9;  // a triangle clipped by 6 planes

// Sutherland–Hodgman: clips the convex polygon in[0..n) against every plane (clip_plane_bits)
// in `planes`, the x/y planes at the guard band |x|, |y| ≤ guard·w (attributes interpolated
// linearly in clip space, which is perspective-correct), writing the result to out
// (capacity CLIP_MAX_VERTICES). Returns the vertex count (0 = all clipped away, else ≥ 3).
// n must be ≤ 3 (a triangle) — larger polygons return 0.
int clip_polygon(const clip_vertex *in, int n, unsigned planes, float guard, int attr_count,
                 clip_vertex *out);

// A circle in pixels.
struct circle {
    float cx, cy, radius;
};
// The circle inscribed in the canvas (see clip_to_circular_viewport).
circle circular_viewport(const canvas_t &canvas);
bool point_in_circle(const circle &c, float x, float y);  // inside or on the circle

// The part of the screen segment (x0, y0)–(x1, y1) inside the circle, as parameters
// (solved in double precision from |p0 + t·d − c|² = r², with the cancellation-free form
// of the quadratic's roots). Tangent segments and segments fully outside are invisible;
// a degenerate segment (a point) is visible iff the point is inside.
segment_clip clip_segment_circle(const circle &c, float x0, float y0, float x1, float y1);

// ---- frustum culling ----------------------------------------------------------------

// The six frustum planes of a clip matrix M in M's input space (Gribb & Hartmann: row 4 ±
// row i), each scaled so (a, b, c) is a unit vector: signed distance of p = a·x + b·y + c·z + d.
struct frustum {
    vec4_t plane[6];  // near, far, left, right, bottom, top
};
frustum frustum_from_matrix(const mat4_t &model_view_proj);

enum class cull_result { outside, intersecting, inside };
// Sphere against the frustum: outside if it lies wholly behind any plane, inside if it
// lies wholly in front of all six, intersecting otherwise (conservative near corners:
// may say intersecting for a sphere that is in fact outside). A sphere with negative
// radius (an empty mesh) is outside.
cull_result cull_sphere(const frustum &f, const bounding_sphere &s);

// ---- wireframes (src/wireframe/wireframe.cpp) ------------------------------------------

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
        float x, y;             // pixels (viewport convention above); 0 unless outcode is 0
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

}  // namespace tiny3d

#endif
