// triangulate_test.cpp — mesh_triangles: the fan for convex faces, ear clipping for
// concave and non-planar ones. Every case checks the triangles against independent
// references: the shoelace area of the polygon (double), triangles inside the polygon
// (their centroids pass an even-odd point-in-polygon test), winding kept (every triangle's
// normal along the face's), n − 2 triangles per face.
#include <cmath>
#include <random>
#include <vector>

#include "harness.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"

using namespace tiny3d;

namespace {

constexpr double AREA_TOLERANCE = 1e-9;  // relative, double sums of float coordinates

struct p2 {
    double x, y;
};

double shoelace(const std::vector<p2> &p) {
    double s = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const p2 a = p[i], b = p[(i + 1) % p.size()];
        s += a.x * b.y - b.x * a.y;
    }
    return 0.5 * s;
}

bool inside(const std::vector<p2> &poly, p2 q) {  // even-odd rule
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i].y > q.y) != (poly[j].y > q.y) &&
            q.x < (poly[j].x - poly[i].x) * (q.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
            in = !in;
    return in;
}

// A mesh of one planar face in z = 0 with the given corners (counter-clockwise).
mesh one_face(const std::vector<p2> &corners) {
    mesh m;
    for (const p2 &c : corners) m.positions.push_back({float(c.x), float(c.y), 0.0f});
    for (std::uint32_t k = 0; k < corners.size(); ++k) m.indices.push_back(k);
    m.face_start.push_back(std::uint32_t(corners.size()));
    return m;
}

double tri_area_z(const mesh &m, const corner_triangle &t) {
    const vec3_t a = m.positions[m.indices[t[0]]], b = m.positions[m.indices[t[1]]], c = m.positions[m.indices[t[2]]];
    return 0.5 * ((double(b.x) - a.x) * (double(c.y) - a.y) - (double(b.y) - a.y) * (double(c.x) - a.x));
}

// Checks the triangulation of a planar counter-clockwise polygon in z = 0.
void check_planar(const std::vector<p2> &given, int at) {
    const mesh m = one_face(given);
    std::vector<p2> poly;  // the corners as the mesh holds them (float)
    for (const vec3_t &p : m.positions) poly.push_back({p.x, p.y});
    const std::vector<corner_triangle> tris = mesh_triangles(m);
    if (tris.size() != poly.size() - 2) tiny_test::fail(__FILE__, at, "expected n - 2 triangles");
    double sum = 0;
    for (const corner_triangle &t : tris) {
        const double a = tri_area_z(m, t);
        if (a < 0) tiny_test::fail(__FILE__, at, "a triangle is clockwise (winding lost)");
        sum += a;
        if (a > 1e-12) {
            p2 c{0, 0};
            for (std::uint32_t k : t) c = {c.x + m.positions[m.indices[k]].x / 3.0, c.y + m.positions[m.indices[k]].y / 3.0};
            if (!inside(poly, c)) tiny_test::fail(__FILE__, at, "a triangle lies outside the polygon");
        }
    }
    const double expected = shoelace(poly);
    if (std::fabs(sum - expected) > AREA_TOLERANCE * std::fabs(expected))
        tiny_test::fail(__FILE__, at, "area " + tiny_test::show(sum) + " != shoelace " + tiny_test::show(expected));
}
#define CHECK_PLANAR(poly) check_planar(poly, __LINE__)

}  // namespace

TEST(convex_faces_keep_the_fan) {
    const mesh m = one_face({{0, 0}, {2, 0}, {3, 1}, {2, 2}, {0, 2}});
    const std::vector<corner_triangle> tris = mesh_triangles(m);
    const std::vector<corner_triangle> fan = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
    CHECK(tris == fan);
    CHECK_PLANAR(std::vector<p2>({{0, 0}, {2, 0}, {3, 1}, {2, 2}, {0, 2}}));
}

TEST(concave_polygons_are_ear_clipped) {
    // Assimp's concave_polygon.obj shape: an arrow whose fan from corner 0 leaves the face.
    CHECK_PLANAR(std::vector<p2>({{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}));
    // An L, a U, a comb, a star (concave corners first: the fan from corner 0 fails for each).
    CHECK_PLANAR(std::vector<p2>({{1, 1}, {1, 3}, {0, 3}, {0, 0}, {3, 0}, {3, 1}}));
    CHECK_PLANAR(std::vector<p2>({{1, 3}, {0, 3}, {0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}}));
    std::vector<p2> comb = {{0, -1}, {13, -1}, {13, 0}};  // teeth from right to left
    for (int k = 5; k >= 0; --k) comb.insert(comb.end(), {{2.0 * k + 1.5, 1}, {2.0 * k + 1, 5}, {2.0 * k, 0}});
    CHECK_PLANAR(comb);
    std::vector<p2> star;
    for (int k = 0; k < 10; ++k) {
        const double r = k % 2 ? 1.0 : 0.35, a = k * M_PI / 5;
        star.push_back({r * std::cos(a), r * std::sin(a)});
    }
    CHECK_PLANAR(star);
}

TEST(collinear_and_repeated_corners) {
    // Collinear corners along the edges of a concave shape and a corner repeated twice.
    CHECK_PLANAR(std::vector<p2>({{0, 0}, {1, 0}, {2, 0}, {4, 0}, {4, 4}, {2, 1}, {2, 1}, {0, 4}, {0, 2}}));
    CHECK_PLANAR(std::vector<p2>({{0, 0}, {0, 0}, {3, 0}, {3, 3}, {1.5, 1.5}, {0, 3}}));
    // Everything on one line: zero area, n - 2 triangles, no hang.
    const mesh flat = one_face({{0, 0}, {1, 0}, {2, 0}, {3, 0}});
    CHECK_EQ(mesh_triangles(flat).size(), 2u);
}

TEST(random_concave_polygons_match_the_shoelace_area) {
    // Star-shaped polygons around the origin with random radii: simple, mostly concave.
    std::mt19937 rng(20261201);
    std::uniform_real_distribution<double> radius(0.1, 1.0);
    for (int round = 0; round < 200; ++round) {
        const int n = 4 + int(rng() % 40);
        std::vector<p2> poly;
        for (int k = 0; k < n; ++k) {
            const double r = radius(rng), a = 2 * M_PI * k / n;
            poly.push_back({r * std::cos(a), r * std::sin(a)});
        }
        CHECK_PLANAR(poly);
    }
}

TEST(tilted_and_non_planar_faces) {
    // The arrow rotated out of z = 0 (normal along (1, 1, 1)/√3) and mirrored (clockwise
    // seen from +z): areas in 3D against the planar shoelace area.
    const std::vector<p2> arrow = {{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}};
    const double u[3] = {1 / std::sqrt(2.0), -1 / std::sqrt(2.0), 0}, v[3] = {1 / std::sqrt(6.0), 1 / std::sqrt(6.0), -2 / std::sqrt(6.0)};
    mesh m;
    for (const p2 &c : arrow)
        m.positions.push_back({float(c.x * u[0] + c.y * v[0]), float(c.x * u[1] + c.y * v[1]), float(c.x * u[2] + c.y * v[2])});
    for (std::uint32_t k = 0; k < 5; ++k) m.indices.push_back(k);
    m.face_start.push_back(5);
    double sum = 0;
    const std::vector<corner_triangle> tris = mesh_triangles(m);
    CHECK_EQ(tris.size(), 3u);
    const vec3_t n = mesh_face_normals(m)[0];
    for (const corner_triangle &t : tris) {
        const vec3_t a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
        const vec3_t e1 = b - a, e2 = c - a;
        const double cx = double(e1.y) * e2.z - double(e1.z) * e2.y, cy = double(e1.z) * e2.x - double(e1.x) * e2.z,
                     cz = double(e1.x) * e2.y - double(e1.y) * e2.x;
        const double along = 0.5 * (cx * n.x + cy * n.y + cz * n.z);
        CHECK(along > 0);  // every triangle faces the polygon's way
        sum += along;
    }
    CHECK_NEAR(sum, shoelace(arrow), 1e-5);  // float positions
    // A non-planar quad folded so that its projection is concave (corner 3 pushed inside
    // and lifted): ear clipping picks the diagonal that stays inside the projection.
    mesh q;
    q.positions = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {3, 1, 0.5f}};  // Newell normal (2, −2, 8)
    q.add_face({0, 1, 2, 3});
    const std::vector<corner_triangle> qt = mesh_triangles(q);
    CHECK_EQ(qt.size(), 2u);
    double projected = 0;
    for (const corner_triangle &t : qt) projected += tri_area_z(q, t);
    CHECK_NEAR(projected, shoelace({{0, 0}, {4, 0}, {4, 4}, {3, 1}}), 1e-12);
    for (const corner_triangle &t : qt) CHECK(tri_area_z(q, t) > 0);
    // A gently non-planar convex quad keeps the fan.
    mesh g;
    g.positions = {{0, 0, 0}, {1, 0, 0.1f}, {1, 1, 0}, {0, 1, 0.1f}};
    g.add_face({0, 1, 2, 3});
    CHECK(mesh_triangles(g) == (std::vector<corner_triangle>{{0, 1, 2}, {0, 2, 3}}));
}

TEST(many_faces_keep_their_corner_numbering) {
    // Two faces: triangles name corners (indices into mesh::indices), not positions.
    mesh m;
    m.positions = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {2, 1, 0}, {0, 4, 0}};
    m.add_face({0, 1, 2});
    m.add_face({0, 1, 2, 3, 4});
    const std::vector<corner_triangle> tris = mesh_triangles(m);
    CHECK_EQ(tris.size(), 4u);
    CHECK(tris[0] == (corner_triangle{0, 1, 2}));
    for (std::size_t t = 1; t < tris.size(); ++t)
        for (std::uint32_t k : tris[t]) CHECK(k >= 3 && k < 8);
    // Out-of-range indices are not read: the fan.
    mesh bad;
    bad.positions = {{0, 0, 0}};
    bad.add_face({0, 5, 6, 7});
    CHECK(mesh_triangles(bad) == (std::vector<corner_triangle>{{0, 1, 2}, {0, 2, 3}}));
}

TEST(the_renderers_fill_with_mesh_triangles) {
    // The arrow, shared vertices and per-corner vertices: make_raster_mesh's triangles are
    // mesh_triangles' (as position indices, or as corners), so no fill leaves the face.
    mesh m;
    m.positions = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {2, 1, 0}, {0, 4, 0}};
    m.add_face({0, 1, 2, 3, 4});
    const std::vector<corner_triangle> tris = mesh_triangles(m);
    const result<raster_mesh> shared = make_raster_mesh(m, mesh_vertex_normals(m));
    const result<raster_mesh> corners = make_raster_mesh(m, {});
    CHECK(shared.ok() && corners.ok());
    if (!shared.ok() || !corners.ok()) return;
    CHECK_EQ(shared->triangles.size(), tris.size());
    CHECK_EQ(corners->triangles.size(), tris.size());
    for (std::size_t t = 0; t < tris.size() && t < shared->triangles.size() && t < corners->triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            CHECK_EQ(shared->triangles[t][k], m.indices[tris[t][k]]);
            CHECK_EQ(corners->triangles[t][k], tris[t][k]);
        }
    CHECK(tris != (std::vector<corner_triangle>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));  // not the fan, which leaves the arrow
}

TEST(the_generators_meshes_keep_the_fan) {
    // Every generated mesh has convex faces: the triangles (and so the pixels of the demos
    // drawing them) are exactly the fan of before.
    const mesh meshes[] = {make_cube(1.0f), make_soccer_ball(1.0f), make_torus(1.0f, 0.4f, 24, 12),
                           make_uv_sphere(16, 8), make_icosphere(2), make_torus_knot(2, 3, 154, 12)};
    for (const mesh &m : meshes) {
        std::vector<corner_triangle> fan;
        for (std::size_t f = 0; f < m.face_count(); ++f)
            for (std::uint32_t k = m.face_start[f] + 1; k + 1 < m.face_start[f + 1]; ++k) fan.push_back({m.face_start[f], k, k + 1});
        CHECK(mesh_triangles(m) == fan);
    }
}
