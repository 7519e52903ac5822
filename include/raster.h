// raster.h — filled triangles: z-buffer, half-space and scan-line rasterizers, culling,
// shading levels, textures, transparency, multisampling, cluster culling, the render
// context (banded, multi-threaded) and its converged reference image. Triangles are
// clipped by the vertex stage (pipeline.h). Implementations: src/raster/.
//
// Conventions (pinned by tests/raster_test.cpp):
//  * Screen space: pixels, origin top-left, y down; pixel (x, y) covers [x, x+1) × [y, y+1)
//    and is "covered" by a triangle when its CENTRE (x + 0.5, y + 0.5) is inside.
//  * Vertices are snapped to a fixed-point grid of 1/16 pixel (RASTER_SUBPIXEL_BITS = 4;
//    1/256 px in a render context's 16-sample frames, sample_count below) before coverage
//    is decided; edge functions are exact integers, so the decision does
//    not depend on triangle order, threads or band boundaries.
//  * Top-left fill rule: a centre exactly on an edge belongs to the triangle when that edge
//    is a top edge (horizontal, interior below) or a left edge (interior to its right).
//    A mesh whose triangles share edges covers every pixel centre inside it exactly once.
//  * Front faces are counter-clockwise in clip/NDC space (y up), which is clockwise on the
//    y-down screen. Back-face culling removes the others.
//  * Depth: window depth = 0.5·z_ndc + 0.5 (0 at the near plane, 1 at the far plane), a
//    linear function of screen x, y (z/w is affine in screen space), stored as float.
//  * Attributes: screen-space barycentrics give AFFINE interpolation; perspective-correct
//    interpolation interpolates attr/w and 1/w and divides per pixel.
//  * Skipped silently (documented, never an error): triangles with zero snapped area,
//    any non-finite coordinate, or any screen coordinate beyond ±RASTER_MAX_COORD pixels
//    (the clip stage of render_context never produces such).
#ifndef TINY3D_RASTER_H
#define TINY3D_RASTER_H

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "canvas.h"
#include "lighting.h"
#include "material.h"
#include "math3d.h"
#include "mesh.h"
#include "tiny3d_result.h"

namespace tiny3d {

inline constexpr int RASTER_SUBPIXEL_BITS = 4;                       // 1/16 px snapping
inline constexpr int RASTER_SUBPIXEL_ONE = 1 << RASTER_SUBPIXEL_BITS;
inline constexpr float RASTER_MAX_COORD = 1 << 22;                   // px, |x|, |y| limit

// ---- depth buffer ---------------------------------------------------------------------

// Depth comparison: a fragment passes when `fragment OP stored` holds.
enum class depth_func { never, less, less_equal, equal, greater, greater_equal, not_equal, always };

// Float depth per pixel in ONE contiguous row-major block. resize() reallocates only when
// the pixel count grows; clear() never allocates.
class zbuffer {
public:
    // Error (and unchanged buffer) when a side is ≤ 0 or the size exceeds the canvas limits.
    status resize(int width, int height);
    void clear(float depth = 1.0f);                          // every pixel := depth
    void clear_rows(int y0, int y1, float depth = 1.0f);     // rows [y0, y1) only
    int width() const { return width_; }
    int height() const { return height_; }
    float *row(int y) { return data_.data() + static_cast<std::size_t>(y) * width_; }
    const float *row(int y) const { return data_.data() + static_cast<std::size_t>(y) * width_; }
    float at(int x, int y) const { return row(y)[x]; }

private:
    int width_ = 0, height_ = 0;
    std::vector<float> data_;
};

// ---- one triangle in screen space -----------------------------------------------------

struct screen_vertex {
    float x, y;    // pixels (centres at +0.5, y down)
    float z;       // window depth 0..1
    float inv_w;   // 1 / w_clip, > 0 (1 for a 2-D triangle)
};

// Which rows/columns a call may touch: [x0, x1) × [y0, y1), intersected with the target.
struct pixel_rect {
    int x0, y0, x1, y1;
};

// The snapped, oriented edge functions of one triangle, shared by every half-space path.
// Built by triangle_setup(); `valid` is false for the skipped triangles listed above.
enum class cull_mode { none, back, front };

struct triangle_edges {
    bool valid = false;
    bool culled = false;        // rejected by the cull mode given to triangle_setup
    bool front_facing = false;  // counter-clockwise in NDC (y up) = negative screen area
    int min_x = 0, max_x = -1, min_y = 0, max_y = -1;  // covered-pixel bounds (inclusive)
    // Edge k is opposite vertex k: E_k(px, py) = c[k] + a[k]·px + b[k]·py for pixel (px, py),
    // positive inside, biased by −1 on non-top-left edges so "inside" is E_k ≥ 0.
    // (The arrays below are left uninitialised when !valid: setup is on the hot path.)
    std::int64_t a[3], b[3], c[3];
    std::int64_t area2 = 0;  // twice the snapped area, in (1/16 px)², > 0
    std::int64_t span_x = 0, span_y = 0;  // snapped vertex box size, 1/16 px
    double x[3], y[3];                    // snapped vertices, px
};

// Snaps and orients a screen triangle, clamps its pixel bounds to `clip`. With a cull mode,
// a triangle facing the culled way comes back invalid with `culled` set (nothing else
// computed: the cheap early-out).
triangle_edges triangle_setup(const screen_vertex &v0, const screen_vertex &v1,
                              const screen_vertex &v2, pixel_rect clip, cull_mode cull = cull_mode::none);

// Calls fragment(x, y, l0, l1, l2) for every covered pixel of the triangle inside `clip`,
// rows top to bottom, left to right; l0..l2 are the screen-space (affine) barycentrics of
// the pixel centre w.r.t. the snapped vertices v0, v1, v2 (sum 1). Either winding.
// Exact 64-bit edge functions; the reference for the faster fills below.
template <class Fragment>
void rasterize_triangle(const screen_vertex &v0, const screen_vertex &v1, const screen_vertex &v2,
                        pixel_rect clip, Fragment &&fragment) {
    const triangle_edges t = triangle_setup(v0, v1, v2, clip);
    if (!t.valid) return;
    const double inv_area = 1.0 / static_cast<double>(t.area2);
    for (int y = t.min_y; y <= t.max_y; ++y) {
        std::int64_t e0 = t.c[0] + t.a[0] * t.min_x + t.b[0] * y;
        std::int64_t e1 = t.c[1] + t.a[1] * t.min_x + t.b[1] * y;
        std::int64_t e2 = t.c[2] + t.a[2] * t.min_x + t.b[2] * y;
        for (int x = t.min_x; x <= t.max_x; ++x, e0 += t.a[0], e1 += t.a[1], e2 += t.a[2]) {
            if ((e0 | e1 | e2) < 0) continue;
            // Unbiased edge values (the bias of −1 is < 1 area unit: barycentrics within 1e-9).
            const double l0 = static_cast<double>(e0) * inv_area;
            const double l1 = static_cast<double>(e1) * inv_area;
            fragment(x, y, static_cast<float>(l0), static_cast<float>(l1),
                     static_cast<float>(1.0 - l0 - l1));
        }
    }
}

// Half-space fill with depth test and an affine (screen-linear) intensity: writes
// intensity (clamped to 0..1) and depth where the test passes (depth written when
// depth_write). When the triangle spans < 2040 px: each row's pixel span from the edge
// crossings (double precision, exactly the integer edge test — documentation/raster.md),
// filled 4 pixels per SSE2 register; otherwise an exact 64-bit scalar loop (same
// coverage). `depth` may be null (no test, no write).
void fill_triangle(canvas_t &canvas, zbuffer *depth, const screen_vertex v[3],
                   const float intensity[3], depth_func test, bool depth_write, pixel_rect clip);

// The faithful variant (the classic edge-walking scan-line fill): sort the vertices by y,
// walk the long and the two short edges row by row (pixel-centre rows), fill each span
// between the edge crossings; intensity and depth by barycentrics per pixel. Float
// arithmetic on unsnapped vertices: shared edges can leave gaps or double hits (no
// guarantee; bench `fill`, row 'triangles scan-line (edge walking)', compares its coverage
// with a double-precision reference).
void fill_triangle_scanline(canvas_t &canvas, zbuffer *depth, const screen_vertex v[3],
                            const float intensity[3], depth_func test);

// ---- textures -------------------------------------------------------------------------

// nearest / bilinear: one lookup in the base level (bilinear is the faithful variant).
// trilinear: bilinear in the two mipmap levels around the level of detail, blended
// linearly (needs build_mipmaps; without levels it is bilinear in the base level). The
// render context computes the level of detail per pixel from the screen-space
// derivatives of (u, v) (texture_lod); texture_sample, which has no derivatives, treats
// trilinear as bilinear.
// anisotropic: up to draw_params::anisotropy trilinear lookups spread along the major axis
// of the pixel's footprint in texture space, the level chosen from the minor axis
// (texture_sample_anisotropic): sharp where trilinear blurs a surface seen at a grazing
// angle. texture_sample treats it as bilinear too.
enum class texture_filter { nearest, bilinear, trilinear, anisotropic };
enum class texture_wrap { repeat, clamp };

// One mipmap level: width × height texels, the same layout as the base level.
struct texture_level {
    int width = 0, height = 0;
    std::vector<float> texels;
};

// A grey texture: width × height texels in 0..1, row-major, row 0 = v near 0.
// Texel (i, j) has its centre at u = (i + 0.5)/width, v = (j + 0.5)/height (in every level
// with that level's size). `mipmaps` holds levels 1, 2, … (level 0 is `texels`) once
// build_mipmaps has run; change the texels and it must run again (stale levels are used as
// they are).
struct texture {
    int width = 0, height = 0;
    std::vector<float> texels;
    std::vector<texture_level> mipmaps;
};

// A texture from a canvas (copied), with its mipmaps. Error if the canvas is empty.
result<texture> texture_from_canvas(const canvas_t &canvas);
// Loads a PGM (P2/P5) as a texture, with its mipmaps; errors name the file and problem.
result<texture> load_texture_pgm(const std::string &path);

// Builds (replaces) tex.mipmaps: level k + 1 has max(1, ⌊w_k / 2⌋) × max(1, ⌊h_k / 2⌋)
// texels down to 1 × 1, each the exact box average of the level-k area it covers (the
// texel footprint [i·r, (i + 1)·r) with r = w_k / w_{k+1}, overlapping texels weighted by
// the overlap, per axis: a plain 2 × 2 mean for even sizes). Done once per texture,
// O(texels), allocates. Error (levels untouched) when the size is ≤ 0 or texels.size()
// differs from width · height.
status build_mipmaps(texture &tex);

// Level of detail λ = log2 ρ, ρ = max(|(∂u/∂x·w, ∂v/∂x·h)|, |(∂u/∂y·w, ∂v/∂y·h)|): texels of
// the base level per pixel step along the screen axis that stretches most (OpenGL's
// formula). Derivatives in texture units (1 = the whole texture) per pixel. λ ≤ 0 means
// magnification. −∞ for zero derivatives, NaN when a derivative is not finite.
float texture_lod(const texture &tex, float du_dx, float dv_dx, float du_dy, float dv_dy);

// Trilinear lookup at (u, v) and level of detail `lod`: λ clamped to [0, last level]
// (NaN → 0), bilinear in levels ⌊λ⌋ and ⌊λ⌋ + 1 blended by the fraction. Non-finite u or v
// returns 0, as texture_sample.
float texture_sample_trilinear(const texture &tex, float u, float v, float lod, texture_wrap wrap);

// Samples at (u, v) (1 = the full texture) in the base level. repeat wraps u, v modulo 1;
// clamp holds the edge texels. Non-finite u or v returns 0.
float texture_sample(const texture &tex, float u, float v, texture_filter filter, texture_wrap wrap);

// Anisotropic lookup at (u, v) for a pixel whose screen steps move (u, v) by (du_dx, dv_dx)
// and (du_dy, dv_dy) (texture units per pixel, as texture_lod): the footprint's axes in
// texels have lengths P_major ≥ P_minor (EXT_texture_filter_anisotropic); N = ⌈P_major /
// P_minor⌉ taps, clamped to 1..max_taps (max_taps clamped to 1..64), at level of detail
// log2(P_major / N), spaced evenly along the major axis across the footprint and averaged.
// An isotropic footprint gives one tap: texture_sample_trilinear. Non-finite u or v returns
// 0; non-finite derivatives give one lookup at the base level.
float texture_sample_anisotropic(const texture &tex, float u, float v, float du_dx, float dv_dx, float du_dy,
                                 float dv_dy, int max_taps, texture_wrap wrap);

// ---- meshes prepared for rasterization and the render context --------------------------

// Triangles over shared vertices, each vertex with a position, unit normal and uv.
struct raster_mesh {
    std::vector<vec3_t> positions;
    std::vector<vec3_t> normals;  // one per position (unit), used by Gouraud / Phong
    std::vector<vec2> uvs;        // one per position (zero when the mesh has none)
    std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise from outside
    vec3_t bound_center{0, 0, 0};
    float bound_radius = 0;       // bounding sphere, for frustum culling
};

// From a tiny3d::mesh: faces fan-triangulated; positions shared when the mesh has no
// per-corner attributes, otherwise one vertex per corner. `vertex_normals` (one per
// position, e.g. mesh_vertex_normals(m)) is used when the mesh has no corner normals; pass
// an empty span to use the face normal of each corner's face. Error when an index is out of
// range or the normals count is wrong.
result<raster_mesh> make_raster_mesh(const mesh &m, std::span<const vec3_t> vertex_normals);

// ---- cluster culling (optional, precomputed per mesh) ------------------------------------

// Bounds of one chunk of CONSECUTIVE triangles of a raster_mesh (the order is the mesh's:
// nothing is reordered), in object space, double precision:
//  * a bounding sphere of the chunk's vertices;
//  * a normal cone (Hill's / meshoptimizer's cone culling): every unit face normal n_i has
//    n_i · axis ≥ cone_cos (cone_cos > 0), and the apex lies on or behind every triangle's
//    plane: n_i · (p_i − apex) ≥ apex_margin (≈ 0, minus a slack for rounding) for a vertex
//    p_i of triangle i;
//  * the triangles' smallest double area and largest edge-to-area ratio, which bound how much
//    snapping to 1/16 px can change a projected triangle's area relative to the area itself.
// With those, for an eye e, every triangle's distance n_i · (p_i − e) is at least
// |v| · cos(α + θ) + apex_margin, v = apex − e, θ = angle(v, axis), α = the cone's half angle.
struct raster_cluster {
    std::uint32_t first = 0, count = 0;   // triangles [first, first + count)
    std::uint32_t vertex_first = 0, vertex_count = 0;  // its vertices: raster_clusters::vertices()[…]
    double center[3] = {0, 0, 0};
    double radius = 0;                    // +∞ when a vertex is not finite
    double axis[3] = {0, 0, 1};
    double cone_cos = 0, cone_sin = 1;    // of the half angle α (cone_cos rounded down, sin up)
    double apex[3] = {0, 0, 0};
    double apex_margin = 0;
    double min_double_area = 0;           // smallest |N| = |(p1 − p0) × (p2 − p0)|, object units²
    double edge_ratio = std::numeric_limits<double>::infinity();  // largest (|p1 − p0| + |p2 − p0|) / |N|
    bool cone_valid = false;              // false: wider than a hemisphere, degenerate or not finite
};

// Read-only once built (the draw relies on its invariants: chunks in order covering every
// triangle, vertex lists within the mesh).
class raster_clusters {
public:
    std::size_t vertex_count() const { return vertex_count_; }      // of the mesh built from
    std::size_t triangle_count() const { return triangle_count_; }
    const std::vector<raster_cluster> &clusters() const { return clusters_; }
    // Each chunk's distinct vertex indices, ascending (a draw transforms only the vertices of
    // the chunks it walks).
    const std::vector<std::uint32_t> &vertices() const { return vertices_; }

private:
    friend result<raster_clusters> make_raster_clusters(const raster_mesh &m, int triangles_per_cluster);
    std::size_t vertex_count_ = 0, triangle_count_ = 0;
    std::vector<raster_cluster> clusters_;
    std::vector<std::uint32_t> vertices_;
};

inline constexpr int RASTER_CLUSTER_TRIANGLES = 64;  // default chunk size (triangles)

// Builds the clusters of `m` (chunks of `triangles_per_cluster` consecutive triangles; the
// last may be shorter). O(triangles), allocates; build once, and again whenever the mesh's
// positions or triangles change (draw() ignores clusters whose vertex or triangle count
// differs from the mesh's, but cannot detect moved positions or re-indexed triangles: stale
// clusters would cull or draw wrongly, though never read or write out of bounds — every
// index is still checked per draw). Meshes whose consecutive triangles are spatially coherent (the subdivided
// icosphere, grids) give narrow cones and small spheres; others still draw correctly,
// only fewer chunks are skipped. Error when triangles_per_cluster < 1 or an index is out
// of range.
result<raster_clusters> make_raster_clusters(const raster_mesh &m, int triangles_per_cluster);
inline result<raster_clusters> make_raster_clusters(const raster_mesh &m) {
    return make_raster_clusters(m, RASTER_CLUSTER_TRIANGLES);
}

enum class shading { flat, gouraud, phong };

// What one draw call does. Shading (per the quality level), with the lighting module's
// model I = clamp01(ambient + Σ_k intensity_k · max(0, n · L_k)) in world space:
//   flat:    shade_flat of the world-space triangle, once per triangle;
//   gouraud: shade_gouraud_vertex per vertex, interpolated (screen-affine, like Scene S);
//   phong:   normal and position interpolated per pixel, shade_phong_pixel.
// With a material other than the default (material.h: kd = 1, ks = 0), every level lights
// with its Blinn-Phong model instead, V towards the eye of view_projection (viewer_of): at
// the triangle's centroid (flat), per vertex (gouraud) or per pixel (phong). The choice is
// made once per draw; the default material takes the diffuse-only code above unchanged.
// A material that fails check_material draws nothing.
// With a texture, the shaded intensity is multiplied by the sampled texel (uv interpolated
// perspective-correct or affine). alpha < 1: the triangles are queued and drawn at
// end_frame(), after every opaque one, sorted back to front by mean depth (stable), blended
// dst = alpha·src + (1 − alpha)·dst, depth tested but not written.
struct draw_params {
    mat4_t model = mat4_identity();            // object → world (default: identity)
    mat4_t view_projection = mat4_identity();  // world → clip, projection · view (default: identity)
    light_rig lights;        // make_light_rig(...)
    material surface;        // diffuse / specular / shininess (default: Lambert, no highlight)
    shading shade = shading::gouraud;
    cull_mode cull = cull_mode::back;
    depth_func depth = depth_func::less;
    float alpha = 1.0f;                            // < 1: translucent
    const texture *tex = nullptr;                  // optional, must outlive end_frame()
    texture_filter filter = texture_filter::bilinear;
    int anisotropy = 8;                            // most taps of texture_filter::anisotropic
    texture_wrap wrap = texture_wrap::repeat;
    bool perspective_correct = true;               // uv / normal interpolation
    // Optional, from make_raster_clusters(mesh); must outlive the draw call. Used for opaque
    // fast-path draws (flat or Gouraud, no texture): before any per-triangle work, a chunk
    // whose every triangle is inside the guard band and provably back-facing after
    // snapping (cull_mode::back) is skipped and counted in culled_backface, and a thread
    // skips a chunk whose projected sphere misses its bands. The image and the stats
    // (except backface_by_cluster) are bit-identical to drawing without clusters
    // (documentation/raster.md, "Cluster culling").
    const raster_clusters *clusters = nullptr;
};

struct frame_stats {
    std::size_t triangles_in = 0;       // submitted
    std::size_t culled_frustum = 0;     // whole draws rejected by bounding sphere, in triangles
    std::size_t culled_backface = 0;
    std::size_t clipped = 0;            // triangles that needed Sutherland–Hodgman
    std::size_t rasterized = 0;         // (sub-)triangles sent to the fill
    std::size_t backface_by_cluster = 0;  // of culled_backface: in chunks skipped whole (clusters)
};

// Samples per pixel of a frame's filled triangles (render_context::begin_frame).
//  x1: one sample at the pixel centre (the aliased image; the fastest).
//  x4, x8, x16: multisampling. Coverage is decided at each sample of a fixed pattern (the
//    4-sample rotated grid and the standard 8-sample pattern, offsets on the 1/16 px
//    snapping grid; for 16 a 4 × 4 grid rotated by atan(1/4), every row and column distinct,
//    centred on the pixel, its offsets odd multiples of 1/32 px; x16 frames snap vertices
//    to 1/256 px, so that the snap no longer moves silhouettes by up to 1/32 px) by the
//    same snapped edge functions and top-left rule as x1, so a mesh
//    that shares edges covers every SAMPLE exactly once; depth is interpolated and tested
//    per sample; the shading (intensity, texture, Phong) is evaluated once per pixel per
//    triangle, at the pixel centre; the pixel is the mean of its samples (box resolve).
enum class sample_count : int { x1 = 1, x4 = 4, x8 = 8, x16 = 16 };

// "1", "4", "8" or "16", optionally followed by 'x' ("4x"); an error naming the text
// otherwise (for command lines).
result<sample_count> parse_sample_count(const std::string &text);

// The instruction sets a render context's triangle fills can use.
//  Multisampled frames (x4, x8, x16): every one gives the same samples and images, bit for
//    bit (tests/antialias_test.cpp compares each this CPU runs with the portable one).
//  1-sample frames: sse2 runs the SSE2 kernels; avx2 and avx512 their own kernels for
//    triangles at most 16 px wide and SSE2's for the others; these give the same pixels,
//    bit for bit (tests/raster_threads_test.cpp). The portable kernel decides
//    the same coverage but may differ from them in the last bits of depth and intensity.
// They differ in speed (documentation/antialias.md, documentation/raster.md).
enum class raster_simd {
    portable,  // plain C++, 64-bit edge values, one sample at a time
    sse2,      // four samples per register (every x86-64 CPU)
    avx2,      // 4×: two pixels per register, 8×/16×: a pixel per one or two, 1×: two groups of four
               // columns of a narrow triangle's row per register; 1×, 4×, 8×: triangles set up
               // eight at a time (AVX2)
    avx512     // 4×: a 2 × 2 block per register, 8×/16×: a pixel per register, 1×: a row of a narrow
               // triangle per register; 1×, 4×, 8×: triangles set up eight at a time
               // (AVX-512 F/VL/DQ/BW)
};
// What a render context starts with: the best of them this CPU runs (CPUID, read by the
// compiler's runtime), unless the environment variable TINY3D_KERNELS names one this CPU
// runs ("portable", "sse2", "avx2" or "avx512"; for tests and benchmarks). Chosen once,
// when the process first asks; the line kernels (lines.h, best_line_simd) follow it.
raster_simd best_raster_simd();
// "portable", "sse2", "avx2" or "avx512".
const char *raster_simd_name(raster_simd simd);
// How best_raster_simd() was chosen: `requested` is TINY3D_KERNELS (empty when unset) and
// `honoured` false when it was set but named no instruction set this CPU runs (unknown, or
// not run here: the best one is used instead, never an error).
struct raster_simd_choice {
    raster_simd simd;
    std::string requested;
    bool honoured;
};
raster_simd_choice default_raster_simd();
// The names these had when they chose the multisampled frames' kernels only.
using multisample_simd = raster_simd;
inline multisample_simd best_multisample_simd() { return best_raster_simd(); }

// Owns every reusable buffer (depth, transformed vertices, triangle setups, the
// translucent queue) and a worker pool of threads − 1 threads created once. A frame:
//   begin_frame(canvas) → draw(...)* → end_frame().
// A draw's triangles are cut into pieces (runs of cluster chunks or of triangles) that the
// threads share out (each mostly its own run of neighbouring pieces) and set up once each,
// binned by horizontal 32-row bands of the canvas; then the threads claim bands (each those
// it drew in the frame before, then those holding most of its own triangles, first), each
// band drawn by one thread piece after piece in submission order, so the image (and the
// stats) are identical for any thread count (documentation/raster.md, "Threads and
// buffers"). A frame's work depends on its counts only (triangles, bands, threads), never
// on a clock.
// No allocation per frame once buffers have grown to the scene's size.
class render_context {
public:
    explicit render_context(int threads = 1);  // clamped to 1..16
    ~render_context();
    render_context(const render_context &) = delete;
    render_context &operator=(const render_context &) = delete;

    // The threads frames run on: the number asked for (clamped), or fewer (at least the
    // caller's own) when the system refused to create threads (a process limit such as
    // RLIMIT_NPROC): never an exception. A program compares it with what it asked for to
    // say so. The image does not depend on it.
    int threads() const;
    // Clears colour to clear_intensity and depth to 1 and sets the frame's samples per pixel
    // (sample_count above). Error if the canvas is invalid. With x4/x8/x16, every draw of the
    // frame goes to per-sample colour and depth buffers (grown once to the largest frame,
    // 8·samples bytes per pixel, kept); end_frame() resolves them into the canvas (the mean
    // of the samples) and depth() (the nearest sample's depth), so the canvas holds the
    // frame only after end_frame(). x1 frames are exactly as without this setting. The image
    // is identical for every thread count in every mode.
    status begin_frame(canvas_t &target, float clear_intensity = 0.0f, sample_count samples = sample_count::x1);
    // Transforms, culls, clips, shades and rasterizes (opaque) or queues (alpha < 1) the
    // mesh. Needs begin_frame first (otherwise does nothing). Triangles with a NaN or
    // infinite vertex (from a position or a non-finite matrix) are skipped, like zero-area
    // ones; the rest of the mesh is drawn (tests/hostile_test.cpp).
    void draw(const raster_mesh &mesh, const draw_params &params);
    // Draws the queued translucent triangles back to front (blended per sample when
    // multisampling) and resolves a multisampled frame.
    void end_frame();
    // The first failure of the frame since begin_frame: memory that ran out in a draw
    // ("out of memory drawing a mesh of N triangles and M vertices"; that draw is left out,
    // the context stays usable), otherwise ok. begin_frame returns its own errors
    // (including memory for the frame's buffers). A program checks it after end_frame.
    status frame_status() const;
    // Progress of the bands being drawn, for a program that shows it on long frames (a file
    // of a million full-screen triangles asks for minutes of work): after each band the
    // caller's own thread draws, report(p, user) is called on that thread with the bands of
    // the pass drawn so far (by every thread) of its total and the triangles the pass draws
    // (the draw's mesh in a 1-sample frame, every draw of the frame at a multisampled
    // end_frame). nullptr (the default) reports nothing. The library reads no clock: the
    // program decides when to show it. The image does not depend on it.
    struct progress {
        std::size_t triangles = 0;
        int bands_done = 0, bands_total = 0;
    };
    void report_progress(void (*report)(const progress &p, void *user), void *user);
    const zbuffer &depth() const;
    const frame_stats &stats() const;
    // The instruction set of the fills, in every frame (raster_simd above; best_raster_simd()
    // unless changed). use_simd returns false, changing nothing, for one this CPU does not
    // run, or between begin_frame and end_frame.
    raster_simd simd_in_use() const;
    bool use_simd(raster_simd simd);
    multisample_simd multisample_simd_in_use() const { return simd_in_use(); }  // the older names
    bool use_multisample_simd(multisample_simd simd) { return use_simd(simd); }
    // Whether 1-sample frames on several threads store the triangles a thread sets up for
    // bands another thread is likely to draw with streaming (non-temporal) stores. Off by
    // default. Streaming spares the drawing core the wait for cache lines another core
    // wrote, which pays where the two cores have separate caches and costs a trip to memory
    // where they share one (documentation/raster.md, "Threads and buffers"). Changes the
    // speed only, never a pixel. use_streaming_stores returns false, changing nothing,
    // between begin_frame and end_frame.
    bool use_streaming_stores(bool on);
    bool streaming_stores() const;

private:
    struct impl;
    std::unique_ptr<impl> impl_;
};

// ---- the reference image (src/raster/reference/raster_reference.cpp) ------------------
//
// The converged image of a filled scene: the yardstick every anti-aliasing mode and texture
// filter of the render context is measured against (tests/antialias_test.cpp,
// tests/bench/antialias.cpp).
//
// An independent, deliberately simple implementation in double precision: no snapping, no
// fixed point, no bands or threads. Each pixel gets N = n² samples on a rank-1 lattice:
// sample k of pixel (px, py) at (px + frac(½ + k/φ), py + (k + ½)/N), φ the golden ratio —
// one sample in each of the N rows of height 1/N, and well spread along x for every edge
// direction (a plain or sheared n × n grid counts edges near its own directions in steps
// of 1/n; this lattice has no such direction) — and every
// sample is depth-tested and shaded on its own (depth, barycentrics and attributes at the
// sample); the pixel is the box-filtered mean of its samples. Shading follows draw_params
// (above): flat per triangle, Gouraud intensities interpolated screen-affine, Phong
// position and normal interpolated per sample; a texture is looked up bilinearly in its
// BASE level at every sample (the supersampled texture, whatever the draw's filter);
// perspective_correct as in the draw. Clipping: near and far planes in clip space (double),
// attributes interpolated linearly in clip space; x and y are cut by the canvas.
// Cull mode and depth function as in each draw.

struct reference_draw {
    const raster_mesh *mesh = nullptr;
    draw_params params;
};

inline constexpr int REFERENCE_SAMPLES_PER_AXIS = 16;  // 256 samples per pixel

// Clears `target` to clear_intensity (depth to 1) and draws `draws` in order. Slow by design
// (every sample shaded in double) and allocating (a band of sample buffers); for tests and benchmarks.
// Errors: canvas without pixels, samples_per_axis outside 1..64, a null mesh, a mesh whose
// normals or uvs count differs from its positions, a triangle index out of range, a
// translucent draw (alpha < 1: not supported).
status render_reference(canvas_t &target, std::span<const reference_draw> draws, float clear_intensity = 0.0f,
                        int samples_per_axis = REFERENCE_SAMPLES_PER_AXIS);

}  // namespace tiny3d

#endif
