// generators.cpp — meshes computed from their definitions: cube, icosahedron / icosphere,
// UV sphere, torus, torus knot, soccer ball (truncated icosahedron). See include/mesh.h.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <unordered_map>

#include "mesh.h"

namespace tiny3d {

namespace {

constexpr double two_pi = 2.0 * M_PI;
constexpr int max_icosphere_level = 8;
constexpr int max_segments = 1 << 14;  // per direction, keeps counts far from 32-bit limits

// v / |v| in float (no zero guard: the generators never pass a zero vector).
vec3_t normalized(vec3_t v) { return v / std::sqrt(vec3_dot(v, v)); }

bool valid_size(float s) { return std::isfinite(s) && s > 0.0f; }
bool valid_count(int n, int minimum) { return n >= minimum && n <= max_segments; }

std::uint32_t u32(std::size_t i) { return static_cast<std::uint32_t>(i); }

// Appends a face from any list of position indices (and optional per-corner uvs).
template <std::size_t N>
void add_face_uv(mesh &m, const std::array<std::uint32_t, N> &corners, const std::array<vec2, N> *uvs) {
    for (std::size_t k = 0; k < N; ++k) {
        m.indices.push_back(corners[k]);
        if (uvs) m.corner_uvs.push_back((*uvs)[k]);
    }
    m.face_start.push_back(u32(m.indices.size()));
}

mesh finish(mesh m) {
    mesh_derive_edges(m);
    return m;
}

// The regular icosahedron on the unit sphere: vertices are the cyclic permutations of
// (±1, ±t, 0), t = golden ratio; faces are the vertex triples at mutual distance 2 (the
// edge length before normalising), oriented counter-clockwise seen from outside.
mesh unit_icosahedron() {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<std::array<double, 3>> raw;
    for (int axis = 0; axis < 3; ++axis)
        for (int s1 : {-1, 1})
            for (int s2 : {-1, 1}) {
                std::array<double, 3> p{};
                p[axis] = s1;
                p[(axis + 1) % 3] = s2 * t;
                raw.push_back(p);
            }
    auto dist2 = [&](int i, int j) {
        double d = 0;
        for (int c = 0; c < 3; ++c) d += (raw[i][c] - raw[j][c]) * (raw[i][c] - raw[j][c]);
        return d;
    };
    constexpr double edge2 = 4.0, tolerance = 1e-9;
    auto adjacent = [&](int i, int j) { return std::fabs(dist2(i, j) - edge2) < tolerance; };
    const double norm = std::sqrt(1.0 + t * t);
    mesh m;
    for (const auto &p : raw)
        m.positions.push_back({float(p[0] / norm), float(p[1] / norm), float(p[2] / norm)});
    for (int i = 0; i < 12; ++i)
        for (int j = i + 1; j < 12; ++j)
            for (int k = j + 1; k < 12; ++k) {
                if (!adjacent(i, j) || !adjacent(j, k) || !adjacent(i, k)) continue;
                const vec3_t a = m.positions[i], b = m.positions[j], c = m.positions[k];
                if (vec3_dot(vec3_cross(b - a, c - a), a) > 0.0f) m.add_face({u32(i), u32(j), u32(k)});
                else m.add_face({u32(i), u32(k), u32(j)});
            }
    return m;
}

// One 1→4 split of a triangle mesh on the unit sphere: midpoints shared (one per edge),
// pushed onto the sphere; each triangle (a, b, c) → (a, ab, ca), (b, bc, ab), (c, ca, bc),
// (ab, bc, ca), all keeping the winding.
mesh subdivide_on_sphere(const mesh &in) {
    mesh out;
    out.positions = in.positions;
    out.positions.reserve(in.positions.size() + in.indices.size() / 2);
    std::unordered_map<std::uint64_t, std::uint32_t> midpoint_of;
    midpoint_of.reserve(in.indices.size());
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
        const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
        auto [it, inserted] = midpoint_of.try_emplace(key, u32(out.positions.size()));
        if (inserted) out.positions.push_back(normalized((in.positions[a] + in.positions[b]) * 0.5f));
        return it->second;
    };
    out.indices.reserve(in.indices.size() * 4);
    out.face_start.reserve(in.face_count() * 4 + 1);
    for (std::size_t f = 0; f < in.face_count(); ++f) {
        const std::uint32_t s = in.face_start[f];
        const std::uint32_t a = in.indices[s], b = in.indices[s + 1], c = in.indices[s + 2];
        const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
        out.add_face({a, ab, ca});
        out.add_face({b, bc, ab});
        out.add_face({c, ca, bc});
        out.add_face({ab, bc, ca});
    }
    return out;
}

// Fills a (rows × columns) grid of quads whose corner (i, j) is position index(i, j),
// with per-corner uvs (i / rows, j / columns) when with_uvs, corner order
// (i, j), (i+1, j), (i+1, j+1), (i, j+1).
template <class Index>
void add_quad_grid(mesh &m, int rows, int columns, Index &&index, bool with_uvs) {
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < columns; ++j) {
            const std::array<std::uint32_t, 4> q{index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)};
            const float u0 = float(i) / rows, u1 = float(i + 1) / rows;
            const float v0 = float(j) / columns, v1 = float(j + 1) / columns;
            const std::array<vec2, 4> uv{vec2{u0, v0}, vec2{u1, v0}, vec2{u1, v1}, vec2{u0, v1}};
            add_face_uv(m, q, with_uvs ? &uv : nullptr);
        }
}

}  // namespace

mesh make_cube(float half_side) {
    if (!valid_size(half_side)) return {};
    mesh m;
    // Position index = bit 0: +x, bit 1: +y, bit 2: +z.
    for (std::uint32_t i = 0; i < 8; ++i)
        m.positions.push_back({(i & 1) ? half_side : -half_side, (i & 2) ? half_side : -half_side,
                               (i & 4) ? half_side : -half_side});
    const std::array<vec2, 4> uv{vec2{0, 0}, vec2{1, 0}, vec2{1, 1}, vec2{0, 1}};
    for (int axis = 0; axis < 3; ++axis) {
        // (u, v, axis) is a right-handed cyclic triple, so (−,−) (+,−) (+,+) (−,+) in (u, v)
        // runs counter-clockwise seen from +axis.
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (int side : {1, 0}) {
            auto corner = [&](int su, int sv) {
                return u32((side << axis) | (su << u) | (sv << v));
            };
            std::array<std::uint32_t, 4> q{corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
            if (!side) q = {corner(0, 0), corner(0, 1), corner(1, 1), corner(1, 0)};
            add_face_uv(m, q, &uv);
        }
    }
    return finish(std::move(m));
}

mesh make_icosphere(int level) {
    if (level < 0 || level > max_icosphere_level) return {};
    mesh m = unit_icosahedron();
    for (int l = 0; l < level; ++l) m = subdivide_on_sphere(m);
    return finish(std::move(m));
}

mesh make_uv_sphere(int slices, int stacks, float radius) {
    if (!valid_count(slices, 3) || !valid_count(stacks, 2) || !valid_size(radius)) return {};
    mesh m;
    const std::uint32_t north = 0, south = u32(std::size_t(slices) * (stacks - 1) + 1);
    m.positions.push_back({0.0f, 0.0f, radius});
    for (int k = 1; k < stacks; ++k)
        for (int j = 0; j < slices; ++j) {
            const double phi = M_PI * k / stacks, theta = two_pi * j / slices;
            m.positions.push_back({float(radius * std::sin(phi) * std::cos(theta)),
                                   float(radius * std::sin(phi) * std::sin(theta)), float(radius * std::cos(phi))});
        }
    m.positions.push_back({0.0f, 0.0f, -radius});
    // Ring k (1..stacks−1), column j (wraps): the seam column `slices` is column 0 again.
    auto ring = [&](int k, int j) { return u32(1 + std::size_t(k - 1) * slices + (j % slices)); };
    auto uv = [&](int k, int j) { return vec2{float(j) / slices, float(k) / stacks}; };
    for (int j = 0; j < slices; ++j) {
        const float pole_u = (j + 0.5f) / slices;
        const std::array<vec2, 3> top_uv{vec2{pole_u, 0.0f}, uv(1, j), uv(1, j + 1)};
        add_face_uv(m, std::array<std::uint32_t, 3>{north, ring(1, j), ring(1, j + 1)}, &top_uv);
    }
    for (int k = 1; k + 1 < stacks; ++k)
        for (int j = 0; j < slices; ++j) {
            // Down the meridian, then east: outward for a right-handed (−z) × (+azimuth) pair.
            const std::array<vec2, 4> q_uv{uv(k, j), uv(k + 1, j), uv(k + 1, j + 1), uv(k, j + 1)};
            add_face_uv(m, std::array<std::uint32_t, 4>{ring(k, j), ring(k + 1, j), ring(k + 1, j + 1), ring(k, j + 1)},
                        &q_uv);
        }
    for (int j = 0; j < slices; ++j) {
        const float pole_u = (j + 0.5f) / slices;
        const std::array<vec2, 3> bottom_uv{vec2{pole_u, 1.0f}, uv(stacks - 1, j + 1), uv(stacks - 1, j)};
        add_face_uv(m, std::array<std::uint32_t, 3>{south, ring(stacks - 1, j + 1), ring(stacks - 1, j)}, &bottom_uv);
    }
    return finish(std::move(m));
}

mesh make_torus(float major_radius, float minor_radius, int major_segments, int minor_segments) {
    if (!valid_size(major_radius) || !valid_size(minor_radius) || !(minor_radius < major_radius) ||
        !valid_count(major_segments, 3) || !valid_count(minor_segments, 3))
        return {};
    mesh m;
    for (int i = 0; i < major_segments; ++i)
        for (int j = 0; j < minor_segments; ++j) {
            const double theta = two_pi * i / major_segments, phi = two_pi * j / minor_segments;
            const double ring = major_radius + minor_radius * std::cos(phi);
            m.positions.push_back(
                {float(ring * std::cos(theta)), float(ring * std::sin(theta)), float(minor_radius * std::sin(phi))});
        }
    // Around the z axis, then around the tube: (+azimuth) × (+tube angle) points outward.
    add_quad_grid(
        m, major_segments, minor_segments,
        [&](int i, int j) { return u32(std::size_t(i % major_segments) * minor_segments + j % minor_segments); }, true);
    return finish(std::move(m));
}

mesh make_torus_knot(int p, int q, int segments, int sides, float tube_radius, float scale) {
    if (p < 1 || q < 1 || std::gcd(p, q) != 1 || !valid_count(segments, 3) || !valid_count(sides, 3) ||
        !valid_size(tube_radius) || !valid_size(scale))
        return {};
    auto curve = [&](double s) {
        const double r = 2.0 + std::cos(q * s);
        return std::array<double, 3>{r * std::cos(p * s) * scale / 3.0, r * std::sin(p * s) * scale / 3.0,
                                     std::sin(q * s) * scale / 3.0};
    };
    auto to_vec = [](const std::array<double, 3> &a) { return vec3_t{float(a[0]), float(a[1]), float(a[2])}; };
    std::vector<vec3_t> centre(segments), tangent(segments), normal(segments);
    for (int k = 0; k < segments; ++k) {
        const double s = two_pi * k / segments, h = two_pi / segments / 2.0;
        centre[k] = to_vec(curve(s));
        tangent[k] = normalized(to_vec(curve(s + h)) - to_vec(curve(s - h)));
    }
    // Parallel transport (projection form): carry the normal along, removing its tangent part.
    const vec3_t helper = std::fabs(tangent[0].z) < 0.9f ? vec3_t{0, 0, 1} : vec3_t{1, 0, 0};
    normal[0] = normalized(vec3_cross(vec3_cross(tangent[0], helper), tangent[0]));
    for (int k = 1; k < segments; ++k)
        normal[k] = normalized(normal[k - 1] - tangent[k] * vec3_dot(normal[k - 1], tangent[k]));
    // Holonomy: the transported normal comes back rotated by `closing` about the tangent;
    // undo it gradually so ring `segments` coincides with ring 0.
    const vec3_t back = normalized(normal[segments - 1] - tangent[0] * vec3_dot(normal[segments - 1], tangent[0]));
    const float closing = std::atan2(vec3_dot(vec3_cross(normal[0], back), tangent[0]), vec3_dot(normal[0], back));
    mesh m;
    for (int k = 0; k < segments; ++k) {
        const vec3_t binormal = vec3_cross(tangent[k], normal[k]);
        const double twist = -double(closing) * k / segments;
        for (int j = 0; j < sides; ++j) {
            const double a = two_pi * j / sides + twist;
            m.positions.push_back(centre[k] +
                                  (normal[k] * float(std::cos(a)) + binormal * float(std::sin(a))) * tube_radius);
        }
    }
    auto at = [&](int k, int j) { return u32(std::size_t(k % segments) * sides + j % sides); };
    for (int k = 0; k < segments; ++k)
        for (int j = 0; j < sides; ++j) {
            // Around the tube, then along the curve: (+tube angle) × (+tangent) points outward.
            m.add_face({at(k, j), at(k, j + 1), at(k + 1, j + 1)});
            m.add_face({at(k, j), at(k + 1, j + 1), at(k + 1, j)});
        }
    return finish(std::move(m));
}

mesh make_soccer_ball(float radius) {
    if (!valid_size(radius)) return {};
    const mesh ico = unit_icosahedron();
    // Around icosahedron vertex a, neighbour b is followed (counter-clockwise seen from
    // outside) by c whenever (a, b, c) is a face.
    std::array<std::array<int, 12>, 12> next{};
    for (auto &row : next) row.fill(-1);
    for (std::size_t f = 0; f < ico.face_count(); ++f) {
        const std::uint32_t *c = &ico.indices[ico.face_start[f]];
        for (int k = 0; k < 3; ++k) next[c[k]][c[(k + 1) % 3]] = int(c[(k + 2) % 3]);
    }
    // Cut point on edge a→b, a third of the way from a: vertex 5a + (rank of b around a).
    constexpr int corners_per_pentagon = 5;
    std::array<std::array<int, 12>, 12> cut{};
    mesh m;
    for (int a = 0; a < 12; ++a) {
        int b = int(std::find_if(next[a].begin(), next[a].end(), [](int n) { return n >= 0; }) - next[a].begin());
        std::array<std::uint32_t, corners_per_pentagon> pentagon{};
        for (int k = 0; k < corners_per_pentagon; ++k, b = next[a][b]) {
            cut[a][b] = int(m.positions.size());
            pentagon[k] = u32(m.positions.size());
            m.positions.push_back(ico.positions[a] + (ico.positions[b] - ico.positions[a]) / 3.0f);
        }
        add_face_uv<corners_per_pentagon>(m, pentagon, nullptr);
    }
    for (std::size_t f = 0; f < ico.face_count(); ++f) {
        const std::uint32_t *c = &ico.indices[ico.face_start[f]];
        const int a = int(c[0]), b = int(c[1]), d = int(c[2]);
        m.add_face({u32(cut[a][b]), u32(cut[b][a]), u32(cut[b][d]), u32(cut[d][b]), u32(cut[d][a]), u32(cut[a][d])});
    }
    // All 60 cut points are equidistant from the centre; put them on the sphere of `radius`.
    for (vec3_t &p : m.positions) p = normalized(p) * radius;
    return finish(std::move(m));
}

}  // namespace tiny3d

namespace {

// Edge i as two ints: the report's int[2] pairs, or a flat array of 2 ints per edge.
void put_edge(int (*pairs)[2], std::size_t i, int a, int b) {
    pairs[i][0] = a;
    pairs[i][1] = b;
}
void put_edge(int *flat, std::size_t i, int a, int b) {
    flat[2 * i] = a;
    flat[2 * i + 1] = b;
}

// m's positions and edges copied into malloc'd C arrays (EdgeStore: int[2] or int, see
// put_edge). Every given output is set to null / 0 first; false when a pointer is null or
// memory runs out (nothing is left allocated then).
template <class EdgeStore>
bool copy_to_c_arrays(const tiny3d::mesh &m, vec3_t **vertices, int *vertex_count, EdgeStore **edges,
                      int *edge_count) {
    if (vertices) *vertices = nullptr;
    if (edges) *edges = nullptr;
    if (vertex_count) *vertex_count = 0;
    if (edge_count) *edge_count = 0;
    if (!vertices || !vertex_count || !edges || !edge_count) return false;
    auto *v = static_cast<vec3_t *>(std::malloc(m.positions.size() * sizeof(vec3_t)));
    auto *e = static_cast<EdgeStore *>(std::malloc(m.edges.size() * 2 * sizeof(int)));
    if (!v || !e) {
        std::free(v);
        std::free(e);
        return false;
    }
    std::copy(m.positions.begin(), m.positions.end(), v);
    for (std::size_t i = 0; i < m.edges.size(); ++i) put_edge(e, i, int(m.edges[i].a), int(m.edges[i].b));
    *vertices = v;
    *edges = e;
    *vertex_count = int(m.positions.size());
    *edge_count = int(m.edges.size());
    return true;
}

}  // namespace

bool tiny3d::make_cube_arrays(vec3_t **vertices, int **edge_indices, int *vertex_count, int *edge_count) {
    return copy_to_c_arrays(make_cube(1.0f), vertices, vertex_count, edge_indices, edge_count);
}

bool tiny3d::soccer_ball_arrays(vec3_t **vertices, int *vertex_count, int (**edges)[2], int *edge_count) {
    return copy_to_c_arrays(make_soccer_ball(1.0f), vertices, vertex_count, edges, edge_count);
}

void free_soccer_ball(vec3_t *vertices, int (*edges)[2]) {
    std::free(vertices);
    std::free(edges);
}
