// triangulate.cpp — mesh_triangles: the fan where it stays inside the face, ear clipping
// in the face's best plane for the others. See include/mesh.h.
#include <cmath>
#include <vector>

#include "mesh.h"
#include "mesh_internal.h"

namespace tiny3d {

namespace {

struct point2 {
    double u, v;
};

// Twice the signed area of (a, b, c): > 0 counter-clockwise, 0 collinear.
double turn(point2 a, point2 b, point2 c) { return (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u); }

void fan(std::uint32_t s, std::uint32_t e, std::vector<corner_triangle> &out) {
    for (std::uint32_t k = s + 1; k + 1 < e; ++k) out.push_back({s, k, k + 1});
}

// Face f projected onto the coordinate plane most facing its Newell normal, oriented so
// the polygon is counter-clockwise there (an affine map of the best-plane projection:
// convexity, ears and area ratios are the same). False if the normal is 0 or not finite.
bool project_face(const mesh &m, std::size_t f, std::vector<point2> &pts) {
    const std::array<double, 3> n = newell_vector(m, f);
    const double ax = std::fabs(n[0]), ay = std::fabs(n[1]), az = std::fabs(n[2]);
    if (!(ax + ay + az > 0.0) || !std::isfinite(ax + ay + az)) return false;
    // Drop the dominant axis: (y, z) for x, (z, x) for y, (x, y) for z — each keeps the
    // right-handed order, so the normal's sign says whether to mirror.
    const int drop = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
    const bool mirror = n[drop] < 0.0;
    pts.clear();
    for (std::uint32_t k = m.face_start[f]; k < m.face_start[f + 1]; ++k) {
        const vec3_t &p = m.positions[m.indices[k]];
        const double c[3] = {p.x, p.y, p.z};
        const double u = c[(drop + 1) % 3], v = c[(drop + 2) % 3];
        pts.push_back(mirror ? point2{v, u} : point2{u, v});
    }
    return true;
}

// True if every fan triangle (p0, p_i, p_{i+1}) turns counter-clockwise (or is flat):
// the polygon is then star-shaped around its first corner — every convex polygon is — and
// the fan lies inside it. (A per-corner convexity test would be fooled by repeated
// corners, whose turns are 0.)
bool fan_stays_inside(const std::vector<point2> &p) {
    for (std::size_t i = 1; i + 1 < p.size(); ++i)
        if (turn(p[0], p[i], p[i + 1]) < 0.0) return false;
    return true;
}

// Ear clipping over a doubly linked ring of the corners. Each ear test scans the ring for
// blocking corners (O(n)); after a clip only the two neighbours are re-tested, and all
// corners again when a full turn finds no ear (at most once per corner turning convex):
// O(n²) for most polygons, O(n³) at worst, hence mesh_ear_clip_max_corners.
class ear_clipper {
public:
    ear_clipper(const std::vector<point2> &p) : p_(p), n_(p.size()), prev_(n_), next_(n_), ear_(n_) {
        for (std::size_t i = 0; i < n_; ++i) {
            prev_[i] = (i + n_ - 1) % n_;
            next_[i] = (i + 1) % n_;
        }
        for (std::size_t i = 0; i < n_; ++i) ear_[i] = is_ear(i);
    }

    // Appends the triangles (corner s + local index) to out.
    void run(std::uint32_t s, std::vector<corner_triangle> &out) {
        std::size_t cur = 0, left = n_, scanned = 0;
        while (left > 3) {
            if (ear_[cur]) {
                const std::size_t a = prev_[cur], b = next_[cur];
                out.push_back({s + std::uint32_t(a), s + std::uint32_t(cur), s + std::uint32_t(b)});
                next_[a] = b;
                prev_[b] = a;
                --left;
                ear_[a] = is_ear(a);
                ear_[b] = is_ear(b);
                cur = a;
                scanned = 0;
                continue;
            }
            cur = next_[cur];
            if (++scanned <= left) continue;
            // A full turn without an ear. Flags may be stale: a corner that turned convex
            // no longer blocks its neighbours' ears. Re-test all once; if still none, the
            // polygon is self-intersecting: fan the rest.
            bool any = false;
            for (std::size_t k = next_[cur], i = 0; i < left; k = next_[k], ++i) any |= (ear_[k] = is_ear(k));
            scanned = 0;
            if (any) continue;
            for (std::size_t k = next_[cur]; next_[k] != cur; k = next_[k])
                out.push_back({s + std::uint32_t(cur), s + std::uint32_t(k), s + std::uint32_t(next_[k])});
            return;
        }
        out.push_back({s + std::uint32_t(prev_[cur]), s + std::uint32_t(cur), s + std::uint32_t(next_[cur])});
    }

private:
    // Corner i is an ear if its turn is counter-clockwise (or zero: a collinear or
    // repeated corner is clipped as a zero-area triangle) and no other corner that is not
    // convex lies inside or on the triangle (corners at the triangle's own points aside).
    bool is_ear(std::size_t i) const {
        const std::size_t a = prev_[i], b = next_[i];
        const point2 pa = p_[a], pi = p_[i], pb = p_[b];
        const double t = turn(pa, pi, pb);
        if (t < 0.0) return false;
        if (t == 0.0) return true;
        for (std::size_t k = next_[b]; k != a; k = next_[k]) {
            const point2 q = p_[k];
            if (turn(p_[prev_[k]], q, p_[next_[k]]) > 0.0) continue;  // convex corners cannot block
            if ((q.u == pa.u && q.v == pa.v) || (q.u == pi.u && q.v == pi.v) || (q.u == pb.u && q.v == pb.v)) continue;
            if (turn(pa, pi, q) >= 0.0 && turn(pi, pb, q) >= 0.0 && turn(pb, pa, q) >= 0.0) return false;
        }
        return true;
    }

    const std::vector<point2> &p_;
    std::size_t n_;
    std::vector<std::size_t> prev_, next_;
    std::vector<bool> ear_;
};

// Appends face f's triangles; `pts` is scratch space for its projected corners.
void face_triangles(const mesh &m, std::size_t f, std::vector<point2> &pts, std::vector<corner_triangle> &out) {
    const std::uint32_t s = m.face_start[f], e = m.face_start[f + 1];
    if (e < s + 3) return;
    if (e == s + 3) {
        out.push_back({s, s + 1, s + 2});
        return;
    }
    if (e - s > mesh_ear_clip_max_corners || !face_in_range(m, f) || !project_face(m, f, pts) || fan_stays_inside(pts)) {
        fan(s, e, out);
        return;
    }
    ear_clipper(pts).run(s, out);
}

}  // namespace

std::vector<corner_triangle> mesh_triangles(const mesh &m) {
    std::vector<corner_triangle> tris;
    tris.reserve(m.indices.size() >= 2 * m.face_count() ? m.indices.size() - 2 * m.face_count() : 0);
    std::vector<point2> pts;
    for (std::size_t f = 0; f < m.face_count(); ++f) face_triangles(m, f, pts, tris);
    return tris;
}

}  // namespace tiny3d
