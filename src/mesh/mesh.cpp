// mesh.cpp — mesh utilities: unique edges, face / vertex / edge normals, edge adjacency, bounds,
// validation. See include/mesh.h. Triangulation: triangulate.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <new>
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

// The unit vector from a to b, the difference in double (in float, 3e38 − (−3e38)
// overflows); (0, 0, 0) when a = b.
vec3_t unit_from_to(vec3_t a, vec3_t b) {
    const double x = double(b.x) - a.x, y = double(b.y) - a.y, z = double(b.z) - a.z;
    const double len = std::sqrt(x * x + y * y + z * z);
    if (!(len > 0.0) || !std::isfinite(len)) return {0.0f, 0.0f, 0.0f};
    return {float(x / len), float(y / len), float(z / len)};
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
    // Newell: n = Σ (y_k − y_{k+1})(z_k + z_{k+1}), … is twice the polygon's vector area.
    // In double, the difference and sum of two floats are exact (unless their magnitudes
    // differ by more than 2^29) and their products never overflow or underflow (1e30·1e30
    // and 1e-30·1e-30 both fit), so huge and tiny faces keep their normal, and a small face
    // far from the origin is not lost to the cancellation of the plain Σ p_k × p_{k+1} form.
    double sx = 0.0, sy = 0.0, sz = 0.0;
    for_each_face_edge(m, f, [&](std::uint32_t a, std::uint32_t b) {
        const vec3_t &p = m.positions[a], &q = m.positions[b];
        sx += (double(p.y) - q.y) * (double(p.z) + q.z);
        sy += (double(p.z) - q.z) * (double(p.x) + q.x);
        sz += (double(p.x) - q.x) * (double(p.y) + q.y);
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

namespace {

// Calls fn(corner, face, angle) for every corner of every in-range face, face by face: the
// corner's interior angle, its weight in the angle-weighted normal (Thürmer & Wüthrich 1998).
template <class Fn>
void for_each_corner_angle(const mesh &m, Fn &&fn) {
    for (std::size_t f = 0; f < m.face_count(); ++f) {
        if (!face_in_range(m, f)) continue;
        const std::uint32_t s = m.face_start[f], e = m.face_start[f + 1], n = e - s;
        for (std::uint32_t k = 0; k < n; ++k) {
            const vec3_t p = m.positions[m.indices[s + k]];
            const vec3_t to_prev = unit_from_to(p, m.positions[m.indices[s + (k + n - 1) % n]]);
            const vec3_t to_next = unit_from_to(p, m.positions[m.indices[s + (k + 1) % n]]);
            // Interior angle at the corner; atan2(|u×v|, u·v) is accurate at every angle.
            const float angle = std::atan2(std::sqrt(vec3_dot(vec3_cross(to_prev, to_next), vec3_cross(to_prev, to_next))),
                                           vec3_dot(to_prev, to_next));
            fn(s + k, static_cast<std::uint32_t>(f), angle);
        }
    }
}

// For every position, the lowest index of a position with the same coordinates (compared
// as values, so −0 = +0); a non-finite position is its own. Sorts copies of the finite
// positions (contiguous, not through an index) by value, then index.
std::vector<std::uint32_t> weld_by_value(const std::vector<vec3_t> &positions) {
    struct keyed {
        float x, y, z;
        std::uint32_t index;
    };
    std::vector<keyed> sorted;
    sorted.reserve(positions.size());
    std::vector<std::uint32_t> first(positions.size());
    for (std::uint32_t i = 0; i < positions.size(); ++i) {
        first[i] = i;
        if (finite3(positions[i])) sorted.push_back({positions[i].x, positions[i].y, positions[i].z, i});
    }
    std::sort(sorted.begin(), sorted.end(), [](const keyed &a, const keyed &b) {
        if (a.x != b.x) return a.x < b.x;
        if (a.y != b.y) return a.y < b.y;
        if (a.z != b.z) return a.z < b.z;
        return a.index < b.index;
    });
    for (std::size_t i = 1; i < sorted.size(); ++i) {
        const keyed &p = sorted[i - 1], &q = sorted[i];
        if (p.x == q.x && p.y == q.y && p.z == q.z) first[q.index] = first[p.index];
    }
    return first;
}

}  // namespace

std::vector<vec3_t> mesh_vertex_normals(const mesh &m) {
    std::vector<vec3_t> sums(m.positions.size(), vec3_t{0.0f, 0.0f, 0.0f});
    const std::vector<vec3_t> face_normals = mesh_face_normals(m);
    for_each_corner_angle(m, [&](std::uint32_t k, std::uint32_t f, float angle) {
        sums[m.indices[k]] += face_normals[f] * angle;
    });
    for (vec3_t &v : sums) v = vec3_normalize(v);
    return sums;
}

status mesh_set_crease_normals(mesh &m, float crease_degrees) {
    try {
        m.corner_normals = mesh_crease_normals(m, crease_degrees);
    } catch (const std::bad_alloc &) {
        return error{"", 0, -1, "crease normals: out of memory for a mesh of " + std::to_string(m.indices.size()) +
                                    " corners"};
    }
    return {};
}

std::vector<vec3_t> mesh_crease_normals(const mesh &m, float crease_degrees) {
    std::vector<vec3_t> normals(m.indices.size(), vec3_t{0.0f, 0.0f, 0.0f});
    if (m.face_start.empty() || m.face_start.back() != m.indices.size()) return normals;
    const std::vector<vec3_t> face_normals = mesh_face_normals(m);
    const std::vector<std::uint32_t> weld = weld_by_value(m.positions);
    // The corners at each welded position as compressed rows, in corner order (= face
    // order, the order in which mesh_vertex_normals sums, so sums round alike), each entry
    // with what the inner loop reads (contiguous: no lookups through faces).
    struct entry {  // plain floats: the array is not zeroed before it is filled
        float normal[3];  // the face's unit normal, or zero for a degenerate face
        float angle;      // the corner's
        std::uint32_t corner;
        vec3_t face_normal() const { return {normal[0], normal[1], normal[2]}; }
        vec3_t weighted() const { return face_normal() * angle; }  // as mesh_vertex_normals
    };
    std::vector<std::uint32_t> start(m.positions.size() + 1, 0);
    for (std::size_t f = 0; f < m.face_count(); ++f)
        if (face_in_range(m, f))
            for (std::uint32_t k = m.face_start[f]; k < m.face_start[f + 1]; ++k) ++start[weld[m.indices[k]] + 1];
    for (std::size_t p = 0; p < m.positions.size(); ++p) start[p + 1] += start[p];
    const std::unique_ptr<entry[]> entries(new entry[start.back()]);
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for_each_corner_angle(m, [&](std::uint32_t k, std::uint32_t f, float angle) {
        const vec3_t n = face_normals[f];
        entries[fill[weld[m.indices[k]]]++] = {{n.x, n.y, n.z}, angle, k};
    });

    // A face g joins corner k's normal when the angle between the face normals is at most the
    // crease: n_f · n_g ≥ cos(crease) (three.js toCreasedNormals' rule); the corner's own face
    // always does (n_f · n_f ≈ 1). A small slack keeps coplanar faces (whose normals round
    // apart) together at a crease of 0. At 180° or more every face joins; a degenerate face
    // (zero normal) takes every face at the position.
    const bool smooth_everywhere = !(crease_degrees < 180.0f);
    const float min_cosine =
        std::cos(std::clamp(crease_degrees, 0.0f, 180.0f) * float(3.14159265358979323846 / 180.0)) - 1e-6f;
    for (std::size_t p = 0; p < m.positions.size(); ++p) {
        const entry *row = entries.get() + start[p], *row_end = entries.get() + start[p + 1];
        if (row == row_end) continue;
        vec3_t all = {0.0f, 0.0f, 0.0f};
        for (const entry *e = row; e != row_end; ++e) all += e->weighted();
        const vec3_t all_unit = vec3_normalize(all);
        for (const entry *a = row; a != row_end; ++a) {
            const vec3_t own = a->face_normal();
            bool every_face = smooth_everywhere || (own.x == 0.0f && own.y == 0.0f && own.z == 0.0f);
            vec3_t sum = {0.0f, 0.0f, 0.0f};
            if (!every_face) {
                every_face = true;
                for (const entry *b = row; b != row_end; ++b)
                    if (vec3_dot(own, b->face_normal()) >= min_cosine) sum += b->weighted();
                    else every_face = false;
            }
            // Every face joined: the sum is `all`, added in the same order (same bits).
            normals[a->corner] = every_face ? all_unit : vec3_normalize(sum);
        }
    }
    return normals;
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

std::vector<vec3_t> mesh_edge_normals(const mesh &m) {
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

bounding_box bounding_box_of(std::span<const vec3_t> positions) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    bounding_box box{{inf, inf, inf}, {-inf, -inf, -inf}};
    for (const vec3_t &p : positions) {
        if (!finite3(p)) continue;
        box.min = {std::min(box.min.x, p.x), std::min(box.min.y, p.y), std::min(box.min.z, p.z)};
        box.max = {std::max(box.max.x, p.x), std::max(box.max.y, p.y), std::max(box.max.z, p.z)};
    }
    return box;
}

bounding_box mesh_bounding_box(const mesh &m) { return bounding_box_of(m.positions); }

namespace {

// The box centre (rounded to a float: it lies between two floats' extremes) and the largest
// distance to it, in double. radius < 0 when no position is finite.
struct sphere_in_double {
    vec3_t center;
    double radius;
};

sphere_in_double measure_sphere(std::span<const vec3_t> positions) {
    const bounding_box box = bounding_box_of(positions);
    if (!(box.min.x <= box.max.x)) return {{0.0f, 0.0f, 0.0f}, -1.0};
    // Centre and distances in double: in float, (lo + hi) overflows for coordinates near
    // ±FLT_MAX, and |p − c|² overflows from |p − c| ≈ 1.8e19 and underflows below ≈ 1e-19.
    // The centre lies between lo and hi, so it is a finite float; the distances are taken
    // from that rounded centre, exactly as a caller would measure them.
    auto mid = [](float lo, float hi) { return float(0.5 * (double(lo) + double(hi))); };
    const vec3_t center{mid(box.min.x, box.max.x), mid(box.min.y, box.max.y), mid(box.min.z, box.max.z)};
    double r2 = 0.0;
    for (const vec3_t &p : positions) {
        if (!finite3(p)) continue;
        const double dx = double(p.x) - center.x, dy = double(p.y) - center.y, dz = double(p.z) - center.z;
        r2 = std::max(r2, dx * dx + dy * dy + dz * dz);
    }
    return {center, std::sqrt(r2)};
}

}  // namespace

bounding_sphere bounding_sphere_of(std::span<const vec3_t> positions) {
    const sphere_in_double s = measure_sphere(positions);
    if (s.radius < 0.0) return {s.center, -1.0f};
    // The radius rounded up to a float, so every position tests inside; +inf when the
    // distance itself exceeds the float range (positions near ±FLT_MAX on several axes).
    constexpr float inf = std::numeric_limits<float>::infinity();
    if (s.radius > double(std::numeric_limits<float>::max())) return {s.center, inf};
    float radius = float(s.radius);
    if (double(radius) < s.radius) radius = std::nextafter(radius, inf);
    return {s.center, radius};
}

vec3_t unit_sphere_map::apply(vec3_t p) const {
    return {float((double(p.x) - center.x) * inv_radius), float((double(p.y) - center.y) * inv_radius),
            float((double(p.z) - center.z) * inv_radius)};
}

result<unit_sphere_map> unit_sphere_map_of(std::span<const vec3_t> positions) {
    auto fail = [](std::string why) { return result<unit_sphere_map>(error{"", 0, -1, std::move(why)}); };
    const sphere_in_double s = measure_sphere(positions);
    if (s.radius < 0.0) return fail("nothing to frame: no finite position");
    if (s.radius == 0.0) return fail("nothing to frame: every position is the same point");
    // Positions are floats, so r ≤ √3 · 2 · FLT_MAX and r ≥ the smallest denormal spacing
    // (1.4e-45): 1/r and (p − c)/r are finite doubles for every finite mesh.
    return unit_sphere_map{s.center, 1.0 / s.radius};
}

result<unit_sphere_map> mesh_fit_unit_sphere(mesh &m) {
    result<unit_sphere_map> map = unit_sphere_map_of(m.positions);
    if (!map) return map;
    for (vec3_t &p : m.positions)
        if (finite3(p)) p = map->apply(p);
    return map;
}

bounding_sphere mesh_bounding_sphere(const mesh &m) { return bounding_sphere_of(m.positions); }

result<mat4_t> mat4_fit_unit_sphere(const bounding_sphere &s) {
    auto fail = [](std::string why) { return result<mat4_t>(error{"", 0, -1, std::move(why)}); };
    auto g3 = [](double v) {
        char text[32];
        std::snprintf(text, sizeof text, "%.3g", v);
        return std::string(text);
    };
    if (!(s.radius >= 0.0f) || !finite3(s.center)) return fail("nothing to frame: no finite position");
    if (s.radius == 0.0f) return fail("nothing to frame: every position is the same point");
    if (!std::isfinite(s.radius))
        return fail("coordinates span more than 3.4e+38 (beyond float): too large to frame");
    // p' = (p − c) / r as one float matrix: diag(1/r) and translation −c/r, each computed in
    // double and rounded once. 1/r must be a float (r ≥ 1/FLT_MAX ≈ 2.9e-39); c/r is then
    // finite too unless the mesh lies ~1e38 radii from the origin.
    const double inv = 1.0 / double(s.radius);
    const double tx = -double(s.center.x) * inv, ty = -double(s.center.y) * inv, tz = -double(s.center.z) * inv;
    constexpr double float_max = std::numeric_limits<float>::max();
    if (!(inv <= float_max)) return fail("coordinates span " + g3(2.0 * s.radius) + ": too small to frame");
    if (!(std::fabs(tx) <= float_max && std::fabs(ty) <= float_max && std::fabs(tz) <= float_max))
        return fail("coordinates span " + g3(2.0 * s.radius) + " but lie " +
                    g3(std::max({std::fabs(s.center.x), std::fabs(s.center.y), std::fabs(s.center.z)})) +
                    " from the origin: too far off to frame");
    const float k = float(inv);
    mat4_t m = mat4_scale(k, k, k);
    m.m[12] = float(tx);
    m.m[13] = float(ty);
    m.m[14] = float(tz);
    return m;
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
