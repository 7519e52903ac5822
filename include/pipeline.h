// pipeline.h — the vertex stage both pipelines share (wireframe.h, raster.h): projection,
// viewport, clip outcodes, near-plane and frustum clipping of segments and triangles, the
// circular viewport, frustum culling. Implementations: src/pipeline/vertex_projection.cpp,
// src/pipeline/clipping.cpp, src/pipeline/clip_triangle.cpp.
//
// Stages, as data flows:
//   model space --model--> world --view--> camera --proj--> clip space (x, y, z, w)
//   --clip (near plane first, then the frustum; w > 0 afterwards)--> divide by w --> NDC
//   --viewport--> screen pixels --(optional circular viewport)--> lines (wireframe.h) or
//   triangles (raster.h) on the canvas.
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
//  * The report's viewport (project_vertex, wireframe.h's 7-argument render_wireframe; canvas.h's
//    report convention, integer coordinates are pixel centres), as the report's code:
//        sx = (ndc_x·0.5 + 0.5)·(width − 1),   sy = (1 − (ndc_y·0.5 + 0.5))·(height − 1),
//    NDC ±1 → the centres of the first and last pixels: the same picture as the library's
//    viewport, shrunk by one pixel about the canvas centre.
//  * Screen depth: NDC z remapped to [0, 1] (0 at the near plane, 1 at the far plane).
#ifndef TINY3D_PIPELINE_H
#define TINY3D_PIPELINE_H

#include "canvas.h"
#include "math3d.h"
#include "mesh.h"
#include "tiny3d_result.h"

#ifdef __cplusplus
#include <array>
#endif

// ---- the libtiny3d report's API (C linkage; all a C program sees from this header) -----
TINY3D_C_BEGIN

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
TINY3D_C_END

#ifdef __cplusplus
namespace tiny3d {

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

}  // namespace tiny3d
#endif  // __cplusplus

#endif
