// raster_mesh.cpp — tiny3d::mesh → raster_mesh (mesh_triangles over shared vertices).
#include <algorithm>
#include <array>
#include <bit>
#include <compare>
#include <cstdint>
#include <vector>
#include <new>
#include <string>

#include "raster.h"

namespace tiny3d {

namespace {

error mesh_error(const std::string &reason) { return error{"", 0, -1, reason}; }

// A corner's vertex attributes as bits: corners with equal keys are the same vertex.
struct corner_key {
    std::uint32_t position;
    std::array<std::uint32_t, 5> attributes;  // normal x, y, z and uv x, y, bit for bit
    auto operator<=>(const corner_key &) const = default;
};

std::uint32_t bits_of(float v) { return std::bit_cast<std::uint32_t>(v); }

// One vertex per distinct (position, normal, uv) among the corners, numbered in the order of
// each one's first corner; returns every corner's vertex. Corners that agree bit for bit
// share a vertex, so a smooth mesh is transformed per vertex, not per corner, with the same
// image.
template <class CornerNormal>
std::vector<std::uint32_t> weld_corners(const mesh &m, CornerNormal &&corner_normal, raster_mesh &r) {
    const std::size_t n = m.indices.size();
    std::vector<corner_key> keys(n);
    for (std::size_t f = 0; f < m.face_count(); ++f)
        for (std::uint32_t k = m.face_start[f]; k < m.face_start[f + 1]; ++k) {
            const vec3_t nk = corner_normal(f, k);
            const vec2 uv = m.corner_uvs.empty() ? vec2{0, 0} : m.corner_uvs[k];
            keys[k] = {m.indices[k], {bits_of(nk.x), bits_of(nk.y), bits_of(nk.z), bits_of(uv.x), bits_of(uv.y)}};
        }
    std::vector<std::uint32_t> vertex(n);  // first the corners sorted by key, then each corner's vertex
    for (std::size_t k = 0; k < n; ++k) vertex[k] = static_cast<std::uint32_t>(k);
    std::stable_sort(vertex.begin(), vertex.end(), [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
    // first[k]: the first corner (smallest index: the sort is stable) with k's key.
    std::vector<std::uint32_t> first(n);
    for (std::size_t i = 0; i < n; ++i)
        first[vertex[i]] = (i > 0 && keys[vertex[i]] == keys[vertex[i - 1]]) ? first[vertex[i - 1]] : vertex[i];
    keys = {};
    std::size_t count = 0;
    for (std::size_t k = 0; k < n; ++k) count += first[k] == k;
    r.positions.reserve(count);
    r.normals.reserve(count);
    r.uvs.reserve(count);
    for (std::size_t f = 0; f < m.face_count(); ++f)
        for (std::uint32_t k = m.face_start[f]; k < m.face_start[f + 1]; ++k) {
            if (first[k] != k) {
                vertex[k] = vertex[first[k]];  // first[k] < k: already numbered
                continue;
            }
            vertex[k] = static_cast<std::uint32_t>(r.positions.size());
            r.positions.push_back(m.positions[m.indices[k]]);
            r.normals.push_back(corner_normal(f, k));
            r.uvs.push_back(m.corner_uvs.empty() ? vec2{0, 0} : m.corner_uvs[k]);
        }
    return vertex;
}

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
    auto corner_normal = [&](std::size_t f, std::uint32_t k) {
        if (!m.corner_normals.empty()) return m.corner_normals[k];
        if (!vertex_normals.empty()) return vertex_normals[m.indices[k]];
        return face_normals[f];
    };
    // mesh_triangles: the fan where it stays inside a face, ear clipping for the others; its
    // triangles name corners.
    r.triangles = mesh_triangles(m);
    if (!corner_attrs && !vertex_normals.empty()) {  // the positions themselves are the vertices
        r.positions = m.positions;
        r.normals.assign(vertex_normals.begin(), vertex_normals.end());
        r.uvs.assign(m.positions.size(), vec2{0, 0});
        for (std::array<std::uint32_t, 3> &t : r.triangles) t = {m.indices[t[0]], m.indices[t[1]], m.indices[t[2]]};
    } else {
        const std::vector<std::uint32_t> vertex = weld_corners(m, corner_normal, r);
        for (std::array<std::uint32_t, 3> &t : r.triangles) t = {vertex[t[0]], vertex[t[1]], vertex[t[2]]};
    }
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
