// raster_mesh.cpp — tiny3d::mesh → raster_mesh (mesh_triangles over shared vertices).
#include <cmath>
#include <new>
#include <string>

#include "raster.h"

namespace tiny3d {

namespace {

error mesh_error(const std::string &reason) { return error{"", 0, -1, reason}; }

}  // namespace

namespace {

result<raster_mesh> build_raster_mesh(const mesh &m, std::span<const vec3_t> vertex_normals) {
    if (m.face_start.empty() || m.face_start.front() != 0 || m.face_start.back() != m.indices.size())
        return mesh_error("raster mesh: face_start does not match the corner list");
    for (std::size_t k = 0; k < m.indices.size(); ++k)
        if (m.indices[k] >= m.positions.size())
            return mesh_error("raster mesh: corner " + std::to_string(k) + " refers to position " +
                              std::to_string(m.indices[k]) + " of " + std::to_string(m.positions.size()));
    const bool corner_attrs = !m.corner_uvs.empty() || !m.corner_normals.empty();
    if (!m.corner_uvs.empty() && m.corner_uvs.size() != m.indices.size())
        return mesh_error("raster mesh: corner_uvs count differs from the corner count");
    if (!m.corner_normals.empty() && m.corner_normals.size() != m.indices.size())
        return mesh_error("raster mesh: corner_normals count differs from the corner count");
    if (!vertex_normals.empty() && vertex_normals.size() != m.positions.size())
        return mesh_error("raster mesh: " + std::to_string(vertex_normals.size()) + " vertex normals for " +
                          std::to_string(m.positions.size()) + " positions");

    raster_mesh r;
    // Flat normals only when the mesh gives no other normals (Newell in double, mesh.h).
    const std::vector<vec3_t> face_normals =
        m.corner_normals.empty() && vertex_normals.empty() ? mesh_face_normals(m) : std::vector<vec3_t>{};
    // Vertex of corner k: the position itself when shared, else a vertex per corner.
    auto corner_normal = [&](std::size_t f, std::uint32_t k) {
        if (!m.corner_normals.empty()) return m.corner_normals[k];
        if (!vertex_normals.empty()) return vertex_normals[m.indices[k]];
        return face_normals[f];
    };
    if (!corner_attrs && !vertex_normals.empty()) {
        r.positions = m.positions;
        r.normals.assign(vertex_normals.begin(), vertex_normals.end());
        r.uvs.assign(m.positions.size(), vec2{0, 0});
    } else {
        r.positions.reserve(m.indices.size());
        for (std::size_t f = 0; f < m.face_count(); ++f)
            for (std::uint32_t k = m.face_start[f]; k < m.face_start[f + 1]; ++k) {
                r.positions.push_back(m.positions[m.indices[k]]);
                r.normals.push_back(corner_normal(f, k));
                r.uvs.push_back(m.corner_uvs.empty() ? vec2{0, 0} : m.corner_uvs[k]);
            }
    }
    const bool shared = r.positions.size() == m.positions.size() && !corner_attrs && !vertex_normals.empty();
    // mesh_triangles: the fan where it stays inside a face, ear clipping for the others.
    r.triangles = mesh_triangles(m);
    if (shared)
        for (std::array<std::uint32_t, 3> &t : r.triangles) t = {m.indices[t[0]], m.indices[t[1]], m.indices[t[2]]};
    // Bounding sphere (finite positions only), in double like the mesh's own.
    if (const bounding_sphere b = bounding_sphere_of(r.positions); b.radius >= 0.0f) {
        r.bound_center = b.center;
        r.bound_radius = b.radius;
    }
    return r;
}

}  // namespace

result<raster_mesh> make_raster_mesh(const mesh &m, std::span<const vec3_t> vertex_normals) {
    try {
        return build_raster_mesh(m, vertex_normals);
    } catch (const std::bad_alloc &) {
        return mesh_error("raster mesh: out of memory for a mesh of " + std::to_string(m.indices.size()) +
                          " corners and " + std::to_string(m.positions.size()) + " positions");
    }
}

}  // namespace tiny3d
