// mesh.cpp — mesh utilities: unique edges, face / vertex normals, edge adjacency, bounds,
// validation. See include/mesh.h. Triangulation: triangulate.cpp.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <string>

#include "mesh.h"
#include "mesh_internal.h"

namespace tiny3d {

namespace {

// An undirected edge as one sortable 64-bit key: smaller index in the high half.
std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
    const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
    return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

bool finite3(vec3_t v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Calls fn(a, b) for every corner pair (k, k+1 wrapping) of face f.
template <class Fn>
void for_each_face_edge(const mesh &m, std::size_t f, Fn &&fn) {
    const std::uint32_t s = m.face_start[f], e = m.face_start[f + 1];
    for (std::uint32_t k = s; k < e; ++k) fn(m.indices[k], m.indices[k + 1 < e ? k + 1 : s]);
}

}  // namespace

std::array<double, 3> newell_vector(const mesh &m, std::size_t f) {
    // Newell: n = Σ (p_k × p_{k+1}) is twice the polygon's vector area. Summed in double:
    // products of float coordinates never overflow or underflow there (1e30·1e30 and
    // 1e-30·1e-30 both fit), so huge and tiny faces keep their normal.
    double sx = 0.0, sy = 0.0, sz = 0.0;
    for_each_face_edge(m, f, [&](std::uint32_t a, std::uint32_t b) {
        const vec3_t &p = m.positions[a], &q = m.positions[b];
        sx += double(p.y) * q.z - double(p.z) * q.y;
        sy += double(p.z) * q.x - double(p.x) * q.z;
        sz += double(p.x) * q.y - double(p.y) * q.x;
    });
    return {sx, sy, sz};
}

bool face_in_range(const mesh &m, std::size_t f) {
    for (std::uint32_t k = m.face_start[f]; k < m.face_start[f + 1]; ++k)
        if (m.indices[k] >= m.positions.size()) return false;
    return true;
}

void mesh_derive_edges(mesh &m) {
    std::vector<std::uint64_t> keys;
    keys.reserve(m.indices.size() + m.lines.size());
    for (std::size_t f = 0; f < m.face_count(); ++f)
        for_each_face_edge(m, f, [&](std::uint32_t a, std::uint32_t b) {
            if (a != b) keys.push_back(edge_key(a, b));
        });
    for (const edge &l : m.lines)
        if (l.a != l.b) keys.push_back(edge_key(l.a, l.b));
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    m.edges.resize(keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i)
        m.edges[i] = {static_cast<std::uint32_t>(keys[i] >> 32), static_cast<std::uint32_t>(keys[i])};
}

std::vector<vec3_t> mesh_face_normals(const mesh &m) {
    std::vector<vec3_t> normals(m.face_count(), vec3_t{0.0f, 0.0f, 0.0f});
    for (std::size_t f = 0; f < m.face_count(); ++f) {
        if (!face_in_range(m, f)) continue;
        const std::array<double, 3> n = newell_vector(m, f);
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len > 0.0 && std::isfinite(len)) normals[f] = {float(n[0] / len), float(n[1] / len), float(n[2] / len)};
    }
    return normals;
}

std::vector<vec3_t> mesh_vertex_normals(const mesh &m) {
    std::vector<vec3_t> sums(m.positions.size(), vec3_t{0.0f, 0.0f, 0.0f});
    const std::vector<vec3_t> face_normals = mesh_face_normals(m);
    for (std::size_t f = 0; f < m.face_count(); ++f) {
        if (!face_in_range(m, f)) continue;
        const std::uint32_t s = m.face_start[f], e = m.face_start[f + 1], n = e - s;
        for (std::uint32_t k = 0; k < n; ++k) {
            const vec3_t p = m.positions[m.indices[s + k]];
            const vec3_t to_prev = vec3_normalize(m.positions[m.indices[s + (k + n - 1) % n]] - p);
            const vec3_t to_next = vec3_normalize(m.positions[m.indices[s + (k + 1) % n]] - p);
            // Interior angle at the corner; atan2(|u×v|, u·v) is accurate at every angle.
            const float angle = std::atan2(std::sqrt(vec3_dot(vec3_cross(to_prev, to_next), vec3_cross(to_prev, to_next))),
                                           vec3_dot(to_prev, to_next));
            sums[m.indices[s + k]] += face_normals[f] * angle;
        }
    }
    for (vec3_t &v : sums) v = vec3_normalize(v);
    return sums;
}

edge_adjacency mesh_edge_faces(const mesh &m) {
    // Sorted (key, edge index) lets each face edge find its edge by binary search.
    std::vector<std::pair<std::uint64_t, std::uint32_t>> lookup(m.edges.size());
    for (std::size_t e = 0; e < m.edges.size(); ++e)
        lookup[e] = {edge_key(m.edges[e].a, m.edges[e].b), static_cast<std::uint32_t>(e)};
    std::sort(lookup.begin(), lookup.end());
    auto find_edge = [&](std::uint32_t a, std::uint32_t b) -> long long {
        const std::uint64_t key = edge_key(a, b);
        auto it = std::lower_bound(lookup.begin(), lookup.end(), std::make_pair(key, std::uint32_t{0}));
        return (it != lookup.end() && it->first == key) ? static_cast<long long>(it->second) : -1;
    };

    constexpr std::uint32_t no_face = std::numeric_limits<std::uint32_t>::max();
    edge_adjacency adj;
    adj.start.assign(m.edges.size() + 1, 0);
    // Pass 1 counts faces per edge, pass 2 fills the rows.
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<std::uint32_t> fill;
        if (pass == 1) {
            for (std::size_t e = 0; e < m.edges.size(); ++e) adj.start[e + 1] += adj.start[e];
            adj.faces.resize(adj.start.back());
            fill.assign(adj.start.begin(), adj.start.end() - 1);
        }
        // A face that repeats an edge (a degenerate polygon) borders it once.
        std::vector<std::uint32_t> last_face(m.edges.size(), no_face);
        for (std::size_t f = 0; f < m.face_count(); ++f)
            for_each_face_edge(m, f, [&](std::uint32_t a, std::uint32_t b) {
                if (a == b) return;
                const long long e = find_edge(a, b);
                if (e < 0 || last_face[e] == f) return;
                last_face[e] = static_cast<std::uint32_t>(f);
                if (pass == 0) ++adj.start[e + 1];
                else adj.faces[fill[e]++] = static_cast<std::uint32_t>(f);
            });
    }
    return adj;
}

bounding_box mesh_bounding_box(const mesh &m) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    bounding_box box{{inf, inf, inf}, {-inf, -inf, -inf}};
    for (const vec3_t &p : m.positions) {
        if (!finite3(p)) continue;
        box.min = {std::min(box.min.x, p.x), std::min(box.min.y, p.y), std::min(box.min.z, p.z)};
        box.max = {std::max(box.max.x, p.x), std::max(box.max.y, p.y), std::max(box.max.z, p.z)};
    }
    return box;
}

bounding_sphere mesh_bounding_sphere(const mesh &m) {
    const bounding_box box = mesh_bounding_box(m);
    if (!(box.min.x <= box.max.x)) return {{0.0f, 0.0f, 0.0f}, -1.0f};
    const vec3_t center = (box.min + box.max) * 0.5f;
    float r2 = 0.0f;
    for (const vec3_t &p : m.positions)
        if (finite3(p)) r2 = std::max(r2, vec3_dot(p - center, p - center));
    // One ulp-ish of slack so every position tests inside despite rounding of the sqrt.
    constexpr float radius_slack = 1.0f + 4.0f * std::numeric_limits<float>::epsilon();
    return {center, std::sqrt(r2) * radius_slack};
}

status mesh_validate(const mesh &m) {
    auto fail = [](std::string why) { return status(error{"", 0, -1, std::move(why)}); };
    if (m.face_start.empty() || m.face_start[0] != 0) return fail("mesh: face_start must begin with 0");
    if (m.face_start.back() != m.indices.size())
        return fail("mesh: face_start ends at " + std::to_string(m.face_start.back()) + " but there are " +
                    std::to_string(m.indices.size()) + " corners");
    for (std::size_t f = 0; f < m.face_count(); ++f) {
        if (m.face_start[f + 1] < m.face_start[f] || m.face_size(f) < 3)
            return fail("mesh: face " + std::to_string(f) + " has fewer than 3 corners");
        for (std::uint32_t k = m.face_start[f]; k < m.face_start[f + 1]; ++k)
            if (m.indices[k] >= m.positions.size())
                return fail("mesh: face " + std::to_string(f) + " corner " + std::to_string(k) +
                            " refers to position " + std::to_string(m.indices[k]) + " of " +
                            std::to_string(m.positions.size()));
    }
    if (!m.corner_uvs.empty() && m.corner_uvs.size() != m.indices.size())
        return fail("mesh: corner_uvs has " + std::to_string(m.corner_uvs.size()) + " entries for " +
                    std::to_string(m.indices.size()) + " corners");
    if (!m.corner_normals.empty() && m.corner_normals.size() != m.indices.size())
        return fail("mesh: corner_normals has " + std::to_string(m.corner_normals.size()) + " entries for " +
                    std::to_string(m.indices.size()) + " corners");
    for (std::size_t e = 0; e < m.edges.size(); ++e)
        if (m.edges[e].a >= m.positions.size() || m.edges[e].b >= m.positions.size())
            return fail("mesh: edge " + std::to_string(e) + " refers to a position out of range");
    for (std::size_t l = 0; l < m.lines.size(); ++l)
        if (m.lines[l].a >= m.positions.size() || m.lines[l].b >= m.positions.size())
            return fail("mesh: line " + std::to_string(l) + " refers to a position out of range");
    return {};
}

}  // namespace tiny3d
