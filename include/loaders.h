// loaders.h — Wavefront OBJ and PLY meshes from files or memory (part of the renderer
// module; renderer.h includes it). Implementations: src/mesh/obj_loader.cpp,
// src/mesh/ply_loader.cpp, src/mesh/loader_common.cpp; files are read by
// read_file_bytes (canvas.h).
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
// Limits: files up to 2 GiB (regular files only: FIFOs, devices and directories are
// refused before anything is read, see read_file_bytes); at most 2^32 − 2 positions and
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
#ifndef TINY3D_LOADERS_H
#define TINY3D_LOADERS_H

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "canvas.h"
#include "mesh.h"
#include "tiny3d_result.h"

namespace tiny3d {

// A warning: what was skipped or repaired, where (same fields and message() as an error).
// Repeats of one kind (e.g. extra values on every line of an element) are one warning
// whose reason ends "(N more like it)", placed at the first occurrence.
using load_warning = error;

struct load_options {
    bool strict = false;             // the first warning is returned as the error instead
    std::size_t max_warnings = 100;  // warnings listed; any beyond are only counted
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

// load_obj or load_ply by the file's extension (case-insensitive .obj / .ply); anything
// else is an error naming the path.
result<loaded_mesh> load_mesh(const std::string &path, const load_options &options);
result<mesh> load_mesh(const std::string &path);

}  // namespace tiny3d

#endif
