// edge_lighting.cpp — the corrected per-edge model: edge normal = mean of adjacent face normals.
#include "lighting.h"

namespace tiny3d {

std::vector<vec3_t> edge_normals(const mesh &m) {
    const std::vector<vec3_t> face_normals = mesh_face_normals(m);
    const edge_adjacency adjacency = mesh_edge_faces(m);
    std::vector<vec3_t> normals(m.edges.size(), vec3_t{0.0f, 0.0f, 0.0f});
    for (std::size_t e = 0; e < m.edges.size(); ++e) {
        vec3_t sum = {0.0f, 0.0f, 0.0f};
        for (const std::uint32_t *f = adjacency.begin(e); f != adjacency.end(e); ++f) sum += face_normals[*f];
        normals[e] = unit_or_zero(sum);  // the mean's direction (its length is irrelevant)
    }
    return normals;
}

}  // namespace tiny3d
