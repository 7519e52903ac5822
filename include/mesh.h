// mesh.h — the mesh type shared by every stage, its utilities (edges, normals, adjacency,
// bounds, triangulation, validation), the generators and the OBJ / PLY loaders.
// Implementations: src/mesh/.
//
// A mesh is positions plus polygon faces (triangles and n-gons) stored flat:
// face f uses corners face_start[f] .. face_start[f+1]−1, and corner k refers to
// position indices[k]. Optional per-corner attributes (texture coordinates, normals,
// as OBJ's v/vt/vn gives them) are parallel to `indices`, so nothing is duplicated for
// seams. Free line segments that belong to no face (OBJ `l` polylines) are `lines`.
// Edges (unique undirected pairs of position indices, each shared edge once) are derived
// once from the faces and the lines by tiny3d::mesh_derive_edges. Faces are
// counter-clockwise seen from outside (front facing).
#ifndef TINY3D_MESH_H
#define TINY3D_MESH_H

#include "math3d.h"
#include "tiny3d_result.h"

#ifdef __cplusplus
#include <array>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tiny3d {

struct vec2 {
    float x, y;
};

struct edge {
    std::uint32_t a, b;  // position indices, a < b
};

struct mesh {
    std::vector<vec3_t> positions;
    std::vector<std::uint32_t> face_start{0};  // size = face count + 1, face_start[0] = 0
    std::vector<std::uint32_t> indices;        // position index per face corner
    std::vector<vec2> corner_uvs;              // empty, or one per corner
    std::vector<vec3_t> corner_normals;        // empty, or one per corner
    std::vector<edge> edges;                   // derived: unique undirected edges
    std::vector<edge> lines;                   // free segments (no face), a < b

    std::size_t face_count() const { return face_start.empty() ? 0 : face_start.size() - 1; }
    std::uint32_t face_size(std::size_t f) const { return face_start[f + 1] - face_start[f]; }
    // Appends a face over the given position indices (no attributes).
    void add_face(std::initializer_list<std::uint32_t> corners) {
        for (std::uint32_t c : corners) indices.push_back(c);
        face_start.push_back(static_cast<std::uint32_t>(indices.size()));
    }
};

// A triangle as three corner indices (into mesh::indices and the corner attributes).
using corner_triangle = std::array<std::uint32_t, 3>;

// Triangulates every face, keeping the winding; corner k_i of a face is its i-th corner.
// Triangles are listed face by face, n − 2 for a face of n corners (none for a face of
// fewer than 3), as corner indices (into mesh::indices and the corner attributes).
// Faces whose fan (k0, k_i, k_{i+1}) stays inside them — all convex faces (the usual
// triangles and quads), and any face star-shaped around its first corner — give the fan,
// judged in the face's best plane (the projection along its Newell normal). Other faces —
// concave, or non-planar ones whose fan folds over in that plane — are triangulated by ear
// clipping in that plane, so every triangle lies inside the polygon and their areas sum
// to the polygon's (the shoelace area for planar faces). Collinear and repeated corners
// give zero-area triangles. A self-intersecting face, or a non-convex one of more than
// mesh_ear_clip_max_corners corners (ear clipping costs O(n²) to O(n³)), falls back to
// the fan. Faces with out-of-range indices get the fan (positions are not read; see
// mesh_validate).
inline constexpr std::uint32_t mesh_ear_clip_max_corners = 1024;
std::vector<corner_triangle> mesh_triangles(const mesh &m);

// ---- mesh utilities (src/mesh/mesh.cpp) -------------------------------------------

// Derives m.edges from the faces and m.lines: every unique undirected edge once, stored
// with a < b and sorted by (a, b). Sort-based, O(n log n) in the corner count. Degenerate
// corner pairs (a == b, e.g. a repeated index) give no edge. Replaces any previous m.edges.
void mesh_derive_edges(mesh &m);

// Unit normal of every face by Newell's method (the polygon's vector area, exact for planar
// n-gons, a best-fit plane for non-planar ones), oriented by the counter-clockwise rule.
// A degenerate face (zero area) gets (0, 0, 0). Indices out of range give (0, 0, 0) too.
std::vector<vec3_t> mesh_face_normals(const mesh &m);

// Unit normal per position: the ANGLE-WEIGHTED mean of the normals of the faces using it
// (Thürmer & Wüthrich 1998: each face contributes its unit normal times the corner's
// interior angle), which does not depend on how the faces are triangulated. Positions no
// face uses, or whose weighted sum vanishes, get (0, 0, 0).
std::vector<vec3_t> mesh_vertex_normals(const mesh &m);

// Unit normal per CORNER (parallel to m.indices, ready for m.corner_normals) that keeps
// creases: corners at the same position — compared by value, so a mesh whose patches repeat
// their seam vertices is smoothed across the seams as if welded — share the angle-weighted
// normal (as mesh_vertex_normals) of those faces there whose unit normal is within
// crease_degrees of the corner's own face's normal, and no other. So edges sharper than
// the crease stay sharp and smoother ones are shaded smooth. crease_degrees ≥ 180 (or NaN)
// smooths everywhere: the corner gets exactly mesh_vertex_normals' value when no two
// positions coincide; 0 gives each face its own normal (coplanar faces still share). A
// corner of a degenerate face (zero normal) takes every face at its position. Corners of
// faces with out-of-range indices, or a malformed face_start, get (0, 0, 0). Sort-based
// weld, then O(Σ valence²) over the welded positions.
std::vector<vec3_t> mesh_crease_normals(const mesh &m, float crease_degrees);
// The same normals stored in m.corner_normals (what make_raster_mesh then uses). Memory
// that runs out is an error naming the corner count, and m is left as it was (the vector
// form above lets std::bad_alloc through, as the standard containers do).
status mesh_set_crease_normals(mesh &m, float crease_degrees);

// Which faces border each edge of m.edges, in compressed rows: the faces of edge e are
// faces[start[e]] .. faces[start[e + 1] − 1] (a closed 2-manifold gives exactly 2 each;
// boundary edges 1; non-manifold edges more). Needs m.edges derived by mesh_derive_edges
// (any order is accepted); face edges missing from m.edges are ignored.
struct edge_adjacency {
    std::vector<std::uint32_t> start;  // size = edge count + 1
    std::vector<std::uint32_t> faces;
    std::uint32_t count(std::size_t e) const { return start[e + 1] - start[e]; }
    const std::uint32_t *begin(std::size_t e) const { return faces.data() + start[e]; }
    const std::uint32_t *end(std::size_t e) const { return faces.data() + start[e + 1]; }
};
edge_adjacency mesh_edge_faces(const mesh &m);

// Unit normal of every edge of m.edges (same order): the unit mean of the unit face normals
// (mesh_face_normals) of the faces that border it (two for a closed mesh) — the normal the
// lighting module's corrected edge model lights (shade_edge, lighting.h). An edge with no
// face, or whose faces' normals cancel, gets (0, 0, 0). Needs m.edges derived
// (mesh_derive_edges). Model space; computed once per mesh.
std::vector<vec3_t> mesh_edge_normals(const mesh &m);

struct bounding_box {
    vec3_t min, max;  // empty mesh: min = +inf, max = −inf
};
struct bounding_sphere {
    vec3_t center;
    float radius;  // empty mesh: radius −1
};
// Axis-aligned box of all positions (non-finite positions are skipped); exact.
bounding_box mesh_bounding_box(const mesh &m);
bounding_box bounding_box_of(std::span<const vec3_t> positions);
// A sphere holding every position: centre = the box centre, radius = the largest distance
// to it (at most √3 × the smallest sphere's radius; exact for symmetric meshes such as the
// generators' spheres). Non-finite positions are skipped. Correct over the whole float
// range (computed in double: tiny meshes keep a non-zero radius down to denormal spacing,
// huge ones a finite one); the radius is rounded up, so |p − centre| ≤ radius holds in
// exact arithmetic for every finite position, and it is +inf only when the distance
// itself exceeds FLT_MAX (positions near ±FLT_MAX on several axes).
bounding_sphere mesh_bounding_sphere(const mesh &m);
bounding_sphere bounding_sphere_of(std::span<const vec3_t> positions);

// The model matrix mapping the sphere onto the unit sphere at the origin, p' = (p − c)/r
// (scale 1/r and translation −c/r computed in double, rounded once to float), so a mesh
// of any size can be framed by a fixed camera: from radius ≈ 2.9e-39 (1/r still a float)
// up to FLT_MAX. Errors, with a sentence saying why: an empty or non-finite sphere ("nothing
// to frame"), radius 0 (every position the same point), radius +inf ("coordinates span
// more than 3.4e+38 …: too large to frame"), a radius below 1/FLT_MAX ("coordinates span
// 2e-40: too small to frame"), or a centre so far off that c/r overflows.
result<mat4_t> mat4_fit_unit_sphere(const bounding_sphere &s);

// The similarity p' = (p − c) / r, kept in double, that maps a mesh's bounding sphere (centre
// c = the box centre, as mesh_bounding_sphere; r = the largest distance to it, unrounded)
// onto the unit sphere at the origin. apply() evaluates it in double and rounds once, so the
// mapped positions are as exact as floats allow for a mesh of any extent — from denormal
// spacing up to ±FLT_MAX — where a float matrix (mat4_fit_unit_sphere) meets its limits.
struct unit_sphere_map {
    vec3_t center{0.0f, 0.0f, 0.0f};
    double inv_radius = 1.0;  // 1 / r
    vec3_t apply(vec3_t p) const;  // (p − c) / r; non-finite input gives non-finite output
};
// The map of the finite positions (non-finite ones are skipped). Errors, in words: no finite
// position ("nothing to frame: no finite position"), or all of them one point. Never fails
// for two or more distinct finite positions.
result<unit_sphere_map> unit_sphere_map_of(std::span<const vec3_t> positions);
// Frames a mesh in double: rewrites every finite position p of m as map.apply(p) and returns
// the map (apply it to eye or target points given in the file's coordinates). Normals and
// texture coordinates are unchanged (a uniform scale and a shift keep directions). Same
// errors as unit_sphere_map_of; on error m is unchanged.
result<unit_sphere_map> mesh_fit_unit_sphere(mesh &m);

// Checks the mesh's invariants: face_start starts at 0, is non-decreasing and ends at
// indices.size(); every face has ≥ 3 corners; every index < positions.size(); corner
// attribute arrays are empty or one per corner; every edge and line index in range. The error says
// which face / corner / edge is wrong.
status mesh_validate(const mesh &m);

// ---- generators (src/mesh/generators.cpp) ------------------------------------------
// Every generator computes its mesh from the definition (no pasted coordinate tables),
// gives faces counter-clockwise seen from outside, shares positions between faces, and
// derives the edges. Invalid parameters (counts below the stated minimum, non-positive or
// non-finite sizes) give an empty mesh (face_count() == 0).

// Axis-aligned cube centred on the origin, side 2·half_side: 8 positions, 6 quads, 12 edges,
// per-corner uvs (each face maps the unit square, u along the face's first edge).
mesh make_cube(float half_side = 1.0f);

// The unit icosphere of Scene S (documentation/benchmarks.md): the regular icosahedron
// (the 12 cyclic permutations of (±1, ±t, 0), t = (1+√5)/2, normalised), each triangle split
// into 4 by its edge midpoints `level` times, midpoints pushed onto the unit sphere and
// shared. level 0: 12 v / 20 t / 30 e; level L: 10·4^L + 2 v, 20·4^L t, 30·4^L e (level 5:
// 10,242 / 20,480 / 30,720; level 6: 40,962 / 81,920 / 122,880). 0 ≤ level ≤ 8.
mesh make_icosphere(int level);

// UV sphere of the given radius: `slices` meridians (≥ 3) and `stacks` bands (≥ 2), poles on
// ±z as single positions; triangles at the poles, quads between. Per-corner uvs
// (u = azimuth/2π from +x, v = polar angle/π from +z, the seam gets u = 1 on its far side).
// Positions: slices·(stacks − 1) + 2.
mesh make_uv_sphere(int slices, int stacks, float radius = 1.0f);

// Torus around the z axis: tube centre circle of radius `major_radius` in the x-y plane,
// tube radius `minor_radius` (0 < minor < major), `major_segments` × `minor_segments` quads
// (each ≥ 3), per-corner uvs. V = major·minor, E = 2·V, F = V.
mesh make_torus(float major_radius, float minor_radius, int major_segments, int minor_segments);

// A (p, q) torus knot tube (gcd(p, q) = 1, p, q ≥ 1): the centre curve
// r(s) = ((2 + cos qs) cos ps, (2 + cos qs) sin ps, sin qs)·scale/3, s in [0, 2π), swept with a
// circle of radius tube_radius in the curve's parallel-transported frame (closed by an
// angular correction so the tube joins without a twist seam). segments·sides·2 triangles
// (segments ≥ 3, sides ≥ 3); make_torus_knot(2, 3, 154, 12) gives the ~3,700-triangle
// irregular mesh of Scene S's small case (3,696 triangles).
mesh make_torus_knot(int p, int q, int segments, int sides, float tube_radius = 0.12f,
                     float scale = 1.0f);

// The soccer ball (truncated icosahedron) with circumradius `radius`: each vertex of the
// regular icosahedron cut off at a third of its edges. 60 positions, 90 edges, 12 pentagons
// (faces 0..11) + 20 hexagons (faces 12..31), all edges of length
// radius · 4 / sqrt(58 + 18·√5) ≈ 0.40355·radius, every vertex of degree 3.
mesh make_soccer_ball(float radius = 1.0f);

// ---- loaders: Wavefront OBJ and PLY meshes from files or memory ----------------------
// (src/mesh/obj_loader.cpp, src/mesh/ply_loader.cpp, src/mesh/loader_common.cpp; files are
// read by read_file_bytes, canvas.h: the library's one file reader)
//
// Every loader returns the mesh (faces as stored in the file, edges derived with
// mesh_derive_edges) or an error naming the file (`name` for the parse_* forms), the
// 1-based line (text) or byte offset (binary data), what was wrong and what was expected.
// Nothing is printed, nothing throws, no input crashes or yields garbage: out-of-range or
// negative indices, faces with fewer than 3 corners, truncated data, counts that disagree
// with the data, malformed or non-finite coordinates are all errors.
//
// Warnings: what the loaders read the way other loaders do but had to skip or repair
// (an unknown header line, extra values on a line, attribute indices into a list the file
// does not have, skipped statements) is reported beside the mesh as warnings — same
// fields as an error: file, line or byte, and what was skipped or repaired. The forms
// returning result<mesh> drop the warnings; the forms taking load_options return them in
// loaded_mesh. load_options::strict turns the first warning into the error.
//
// Limits: files and streams up to 2 GiB (regular files, pseudo-files and pipes, read to
// the end of the stream; devices and directories are refused before anything is read, see
// read_file_bytes); memory that runs out while the mesh is built is an error naming the
// input and its size ("out of memory holding the mesh of these N bytes"); at most 2^32 − 2 positions and
// corners (indices are 32-bit); counts announced in a PLY header are checked against the
// bytes left in the file BEFORE anything is allocated (a header announcing 2^40 vertices in
// a 100-byte file fails at once), and every size computation is overflow-checked.
//
// Text: a UTF-8 byte-order mark at the start is skipped; lines end in LF, CRLF or CR
// alone, mixed freely. UTF-16 text and NUL bytes are errors.
//
// OBJ (text): statements `v x y z [...]` (values after z — w, vertex colours — are ignored,
// whatever they hold), `vt u [v [...]]`, `vn x y z`, `f` with corners `v`, `v/vt`, `v//vn`,
// `v/vt/vn` (an empty trailing field, `v/`, `v//`, `v/vt/`, is accepted; forms may mix
// within a face), 1-based or negative (relative: −1 = the latest) indices, any number of
// corners ≥ 3; `l` polylines (corners `v` or `v/vt`) become mesh::lines, so a lines-only
// file is a wireframe. `#` starts a comment anywhere; a trailing `\` continues a line;
// blank lines and o, g, s, usemtl, mtllib are skipped silently; other statements (`p`
// points, free-form geometry, unknown keywords) are skipped with a warning. If any face
// gives texture coordinates (or normals), corner_uvs (corner_normals) hold one per corner
// and corners without one get (0, 0) ((0, 0, 0)). Faces naming texture (normal) indices in
// a file without any `vt` (`vn`) line keep their positions and lose that attribute, with a
// warning; an index out of range of existing `vt`/`vn` lines is an error.
//
// PLY: `format ascii 1.0`, `binary_little_endian 1.0`, `binary_big_endian 1.0`; `comment` and
// `obj_info` lines (other unknown header lines are skipped with a warning); elements and
// properties in any order; scalar types char/int8, uchar/uint8, short/int16, ushort/uint16,
// int/int32, uint/uint32, float/float32, double/float64. Element `vertex` must have x, y, z
// (any numeric type); its other properties (normals, colours, lists, …; non-finite values
// included) are skipped. Element `face` must have a list property `vertex_indices` or
// `vertex_index` (any count and index types); element `tristrips` with such a list gives
// triangle strips (−1 restarts a strip; the winding alternates along a strip as in OpenGL;
// triangles repeating an index, the joins of strips, are dropped); other face properties
// are skipped. Other elements are skipped whatever they hold. The header ends with
// `end_header` and the line end the `ply` line used. ASCII data: one entry per line (blank
// lines skipped); extra values at the end of a line are skipped with a warning ("line has
// 7 values, the header declares 4"), too few are an error; trailing data after the last
// element is an error in binary files and ignored if blank in ascii ones.
// A warning: what was skipped or repaired, where (same fields and message() as an error).
// Repeats of one kind (e.g. extra values on every line of an element) are one warning
// whose reason ends "(N more like it)", placed at the first occurrence.
using load_warning = error;

// Which parser load_mesh and parse_mesh use: by the name (.obj / .ply, otherwise by the
// content: a first line "ply" is PLY, a first statement of OBJ's — v, f, o, g, … — is OBJ),
// or the one given (a pipe or standard input has no telling name).
enum class mesh_format { by_name, obj, ply };

struct load_options {
    bool strict = false;             // the first warning is returned as the error instead
    std::size_t max_warnings = 100;  // warnings listed; any beyond are only counted
    mesh_format format = mesh_format::by_name;
};

struct loaded_mesh {
    mesh geometry;
    std::vector<load_warning> warnings;    // in file order, at most max_warnings
    std::size_t warnings_not_listed = 0;   // distinct warnings beyond max_warnings
};

// Parses OBJ text; `name` is used as the file name in error messages and warnings.
result<loaded_mesh> parse_obj(std::string_view text, const std::string &name, const load_options &options);
result<mesh> parse_obj(std::string_view text, const std::string &name = "<obj>");
// Reads and parses an OBJ file (read errors name the path and the reason).
result<loaded_mesh> load_obj(const std::string &path, const load_options &options);
result<mesh> load_obj(const std::string &path);

// Parses PLY bytes (ascii or binary); `name` is used as the file name in messages.
result<loaded_mesh> parse_ply(std::string_view bytes, const std::string &name, const load_options &options);
result<mesh> parse_ply(std::string_view bytes, const std::string &name = "<ply>");
// Reads and parses a PLY file.
result<loaded_mesh> load_ply(const std::string &path, const load_options &options);
result<mesh> load_ply(const std::string &path);

// load_obj or load_ply by options.format, else by the file's extension (case-insensitive
// .obj / .ply), else by the content (mesh_format above): a pipe, /dev/stdin or a /proc file
// is read to the end of its stream (read_file_bytes), within the same size limit. A file
// whose content is neither is an error naming the path.
result<loaded_mesh> load_mesh(const std::string &path, const load_options &options);
result<mesh> load_mesh(const std::string &path);
// The same on bytes already read (e.g. standard input); `name` names them in messages.
result<loaded_mesh> parse_mesh(std::string_view bytes, const std::string &name, const load_options &options);

// The soccer ball of generate_soccer_ball (below) as plain arrays: returns true on success,
// false (outputs NULL / 0 where given) when a pointer is NULL or memory runs out.
bool soccer_ball_arrays(vec3_t **vertices, int *vertex_count, int (**edges)[2], int *edge_count);

}  // namespace tiny3d
#endif  // __cplusplus

// ---- the libtiny3d report's generator (C and C++) ------------------------------------
//
// generate_soccer_ball(&vertices, &vertex_count, &edges, &edge_count), with
//     vec3_t *vertices; int vertex_count; int (*edges)[2]; int edge_count;
// On success *vertices holds 60 positions (the ball of circumradius 1, same order as
// tiny3d::make_soccer_ball), *edges 90 pairs of indices into them (each pair edges[i][0],
// edges[i][1], ready for render_wireframe), and the counts. Memory: both arrays come from
// malloc and belong to the caller, who frees them with free_soccer_ball(vertices, edges)
// (or free() on each); every call allocates new ones. On failure (a NULL pointer argument,
// no memory) the outputs are set to NULL / 0 where given and nothing is left allocated.
//
// The report printed its signature as
//     void generate_soccer_ball(vec3_t **vertices, int *vertex_count, int *edges[][2],
//                               int *edge_count)
// where `int *edges[][2]` is, as a parameter, `int *(*edges)[2]`: no usable out-parameter
// for an `int edges[][2]` array (its callers pass &edges as above). It is read here as what
// its callers pass: the address of the caller's `int (*)[2]`, which receives the pairs.
//  * C++: two overloads, ours returning 1 on success and 0 on failure, and the report's
//    form (void). Both are templates, so a program's own generate_soccer_ball — any
//    signature, static or not — is the one its calls reach.
//  * C (one function per name): declared without a prototype (before C23), returning void,
//    so both ways of writing the call compile, and so does a program's own definition of
//    any form returning void with pointer or int parameters (the report's own
//    demo/generate_soccer.c among them). Its success shows in *vertices != NULL. C23 has
//    no declarations without a prototype: there it is declared with `int (**edges)[2]`.
//  * The library's C symbol generate_soccer_ball is alone in its object file of the
//    archive, so a program that defines its own never links the library's.
TINY3D_C_BEGIN
void free_soccer_ball(vec3_t *vertices, int (*edges)[2]);  // NULLs are ignored
TINY3D_C_END

#ifdef __cplusplus
template <class = void>
int generate_soccer_ball(vec3_t **vertices, int *vertex_count, int (**edges)[2], int *edge_count) {
    return tiny3d::soccer_ball_arrays(vertices, vertex_count, edges, edge_count) ? 1 : 0;
}
// The report's printed form: `edges` is the address of the caller's int (*)[2] (above).
template <class = void>
void generate_soccer_ball(vec3_t **vertices, int *vertex_count, int *edges[][2], int *edge_count) {
    tiny3d::soccer_ball_arrays(vertices, vertex_count, reinterpret_cast<int (**)[2]>(edges), edge_count);
}
#else
#if defined(__STDC_VERSION__) && __STDC_VERSION__ >= 202311L
void generate_soccer_ball(vec3_t **vertices, int *vertex_count, int (**edges)[2], int *edge_count);
#else
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstrict-prototypes"
void generate_soccer_ball();
#pragma GCC diagnostic pop
#endif
#endif

#ifdef __cplusplus
#include "compat/mesh_alias.h"  // other libtiny3d programs' name create_cube(…)
#endif

#endif
