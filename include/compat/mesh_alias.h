// compat/mesh_alias.h — the mesh generator other libtiny3d programs call.
//
// Included at the end of mesh.h (and self-contained). documentation/compat.md has the full
// table.
#ifndef TINY3D_COMPAT_MESH_ALIAS_H
#define TINY3D_COMPAT_MESH_ALIAS_H

#include "../mesh.h"
#include "user_first.h"

namespace tiny3d {
// tiny3d::make_cube(1) as C arrays: on success *vertices holds its 8 corners (±1 on each
// axis; corner i has +x when bit 0 of i is set, +y for bit 1, +z for bit 2), *edge_indices
// its 12 edges as 24 ints (edge k joins corners edge_indices[2k] < edge_indices[2k + 1],
// each of length 2), *vertex_count = 8, *edge_count = 12, and it returns true. Both arrays
// come from malloc: the caller frees them with free(). Returns false, with the outputs
// set to NULL / 0 where given, when a pointer argument is NULL or memory runs out.
bool make_cube_arrays(vec3_t **vertices, int **edge_indices, int *vertex_count, int *edge_count);
}  // namespace tiny3d

// tiny3d::make_cube_arrays under the name other programs call, returning 1 on success and
// 0 on failure (the C convention of generate_soccer_ball). A template: a program's own
// create_cube of the same or another signature wins (compat/user_first.h).
template <class = void>
int create_cube(vec3_t **vertices, int **edges, int *vertex_count, int *edge_count) {
    return tiny3d::make_cube_arrays(vertices, edges, vertex_count, edge_count) ? 1 : 0;
}

#endif
