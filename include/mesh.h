// mesh.h — the mesh type shared by every stage (part of the renderer module; renderer.h
// includes it).
//
// A mesh is positions plus polygon faces (triangles and n-gons) stored flat:
// face f uses corners face_start[f] .. face_start[f+1]−1, and corner k refers to
// position indices[k]. Optional per-corner attributes (texture coordinates, normals,
// as OBJ's v/vt/vn gives them) are parallel to `indices`, so nothing is duplicated for
// seams. Edges (unique undirected pairs of position indices, each shared edge once) are
// derived once from the faces by tiny3d::mesh_derive_edges. Faces are counter-clockwise
// seen from outside (front facing).
#ifndef TINY3D_MESH_H
#define TINY3D_MESH_H

#include <array>
#include <cstdint>
#include <vector>

#include "math3d.h"

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

// Fan-triangulates every face (corner k0, k_i, k_{i+1}), keeping the winding.
inline std::vector<corner_triangle> mesh_triangles(const mesh &m) {
    std::vector<corner_triangle> tris;
    for (std::size_t f = 0; f < m.face_count(); ++f) {
        const std::uint32_t s = m.face_start[f], e = m.face_start[f + 1];
        for (std::uint32_t k = s + 1; k + 1 < e; ++k) tris.push_back({s, k, k + 1});
    }
    return tris;
}

}  // namespace tiny3d

#endif
