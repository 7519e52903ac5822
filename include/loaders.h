// loaders.h — Wavefront OBJ and PLY meshes from files or memory (part of the renderer
// module; renderer.h includes it). Implementations: src/mesh/obj_loader.cpp,
// src/mesh/ply_loader.cpp, src/mesh/loader_common.cpp.
//
// Every loader returns tiny3d::result<mesh>: the mesh (faces as stored in the file, edges
// derived with mesh_derive_edges), or an error naming the file (`name` for the parse_*
// forms) and the 1-based line (text) or byte offset (binary data) and what was wrong.
// Nothing is printed, nothing throws, no input crashes or yields garbage: out-of-range or
// negative indices, faces with fewer than 3 corners, truncated data, counts that disagree
// with the data, malformed or non-finite numbers are all errors.
//
// Limits: files up to 2 GiB; at most 2^32 − 2 positions and corners (indices are 32-bit);
// counts announced in a PLY header are checked against the bytes left in the file BEFORE
// anything is allocated (a header announcing 2^40 vertices in a 100-byte file fails at
// once), and every size computation is overflow-checked.
//
// OBJ (text): statements `v x y z [w]` (w ignored), `vt u [v [w]]`, `vn x y z`, `f` with
// corners `v`, `v/vt`, `v//vn`, `v/vt/vn` (forms may mix within a face), 1-based or negative
// (relative: −1 = the latest) indices, any number of corners ≥ 3. `#` starts a comment
// anywhere; a trailing `\` continues a line; blank lines, CRLF line ends and unknown
// statements (o, g, s, usemtl, mtllib, l, p, …) are skipped. If any face gives texture
// coordinates (or normals), corner_uvs (corner_normals) hold one per corner and corners
// without one get (0, 0) ((0, 0, 0)).
//
// PLY: `format ascii 1.0`, `binary_little_endian 1.0`, `binary_big_endian 1.0`; `comment` and
// `obj_info` lines; elements and properties in any order; scalar types char/int8,
// uchar/uint8, short/int16, ushort/uint16, int/int32, uint/uint32, float/float32,
// double/float64. Element `vertex` must have x, y, z (any numeric type); its other
// properties (normals, colours, lists, …) are skipped. Element `face` must have a list
// property `vertex_indices` or `vertex_index` (any count and index types); other face
// properties are skipped. Other elements are skipped whatever they hold. The header ends
// with `end_header` followed by LF (or CRLF for ascii). ASCII data is read as whitespace-
// separated tokens (the line of the offending token is reported); trailing data after the
// last element is an error in binary files and ignored if blank in ascii ones.
#ifndef TINY3D_LOADERS_H
#define TINY3D_LOADERS_H

#include <cstddef>
#include <string>
#include <string_view>

#include "mesh.h"
#include "tiny3d_result.h"

namespace tiny3d {

// Parses OBJ text; `name` is used as the file name in error messages.
result<mesh> parse_obj(std::string_view text, const std::string &name = "<obj>");
// Reads and parses an OBJ file (read errors name the path and the reason).
result<mesh> load_obj(const std::string &path);

// Parses PLY bytes (ascii or binary); `name` is used as the file name in error messages.
result<mesh> parse_ply(std::string_view bytes, const std::string &name = "<ply>");
// Reads and parses a PLY file.
result<mesh> load_ply(const std::string &path);

// load_obj or load_ply by the file's extension (case-insensitive .obj / .ply); anything
// else is an error naming the path.
result<mesh> load_mesh(const std::string &path);

// Reads a whole file into memory (at most 2 GiB). Errors name the path and the reason.
result<std::string> read_file_bytes(const std::string &path);

}  // namespace tiny3d

#endif
