// mesh_test.cpp — mesh utilities and generators against counts, analytic geometry and
// double-precision recomputation.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <utility>

#include "harness.h"
#include "math3d.h"
#include "mesh.h"
#include "seam_split.h"

using namespace tiny3d;

namespace {

double dot_d(vec3_t a, vec3_t b) { return double(a.x) * b.x + double(a.y) * b.y + double(a.z) * b.z; }
double length_d(vec3_t v) { return std::sqrt(dot_d(v, v)); }

// Every directed edge appears exactly once and its reverse exactly once: the surface is
// closed and consistently oriented.
bool closed_and_oriented(const mesh &m) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (std::size_t f = 0; f < m.face_count(); ++f)
        for (std::uint32_t k = m.face_start[f]; k < m.face_start[f + 1]; ++k) {
            const std::uint32_t next = k + 1 < m.face_start[f + 1] ? k + 1 : m.face_start[f];
            ++directed[{m.indices[k], m.indices[next]}];
        }
    for (const auto &[e, n] : directed) {
        auto rev = directed.find({e.second, e.first});
        if (n != 1 || rev == directed.end() || rev->second != 1) return false;
    }
    return true;
}

// Signed volume by the divergence theorem over fan triangles (double): positive when the
// faces are counter-clockwise seen from outside.
double signed_volume(const mesh &m) {
    double v = 0;
    for (const corner_triangle &t : mesh_triangles(m)) {
        const vec3_t a = m.positions[m.indices[t[0]]], b = m.positions[m.indices[t[1]]],
                     c = m.positions[m.indices[t[2]]];
        v += (double(a.x) * (double(b.y) * c.z - double(b.z) * c.y) - double(a.y) * (double(b.x) * c.z - double(b.z) * c.x) +
              double(a.z) * (double(b.x) * c.y - double(b.y) * c.x)) /
             6.0;
    }
    return v;
}

long euler_characteristic(const mesh &m) {
    return long(m.positions.size()) - long(m.edges.size()) + long(m.face_count());
}

}  // namespace

TEST(derive_edges_unique_sorted_and_shared_once) {
    mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};
    m.add_face({0, 1, 2, 3});
    m.add_face({1, 4, 2});
    m.add_face({2, 2, 3});  // degenerate corner pair 2-2 gives no edge
    mesh_derive_edges(m);
    const std::vector<std::pair<std::uint32_t, std::uint32_t>> expected = {{0, 1}, {0, 3}, {1, 2}, {1, 4},
                                                                            {2, 3}, {2, 4}};
    CHECK_EQ(m.edges.size(), expected.size());
    for (std::size_t i = 0; i < std::min(expected.size(), m.edges.size()); ++i) {
        CHECK_EQ(m.edges[i].a, expected[i].first);
        CHECK_EQ(m.edges[i].b, expected[i].second);
    }
    const edge_adjacency adj = mesh_edge_faces(m);
    CHECK_EQ(adj.count(2), 2u);  // edge 1-2 borders the quad and the triangle
    CHECK_EQ(adj.count(0), 1u);
    CHECK_EQ(adj.count(4), 2u);  // edge 2-3: the quad and the degenerate face
}

TEST(soccer_ball_topology_and_equal_edges) {
    const mesh ball = make_soccer_ball(1.0f);
    CHECK_EQ(ball.positions.size(), 60u);
    CHECK_EQ(ball.edges.size(), 90u);
    CHECK_EQ(ball.face_count(), 32u);
    CHECK_EQ(euler_characteristic(ball), 2L);
    int pentagons = 0, hexagons = 0;
    for (std::size_t f = 0; f < ball.face_count(); ++f) {
        pentagons += ball.face_size(f) == 5;
        hexagons += ball.face_size(f) == 6;
    }
    CHECK_EQ(pentagons, 12);
    CHECK_EQ(hexagons, 20);
    std::vector<int> degree(60, 0);
    for (const edge &e : ball.edges) ++degree[e.a], ++degree[e.b];
    CHECK(std::all_of(degree.begin(), degree.end(), [](int d) { return d == 3; }));
    // Edge length of the truncated icosahedron with circumradius 1: 4 / sqrt(58 + 18√5).
    const double expected = 4.0 / std::sqrt(58.0 + 18.0 * std::sqrt(5.0));
    for (const edge &e : ball.edges)
        CHECK_NEAR(length_d(ball.positions[e.a] - ball.positions[e.b]) / expected, 1.0, 1e-5);
    for (const vec3_t &p : ball.positions) CHECK_NEAR(length_d(p), 1.0, 1e-6);
    CHECK(closed_and_oriented(ball));
    CHECK(signed_volume(ball) > 0.0);
    CHECK(mesh_validate(ball).ok());
}

TEST(soccer_ball_c_api) {
    vec3_t *v = nullptr;
    int (*e)[2] = nullptr;
    int vc = -1, ec = -1;
    CHECK_EQ(generate_soccer_ball(&v, &vc, &e, &ec), 1);
    CHECK_EQ(vc, 60);
    CHECK_EQ(ec, 90);
    std::set<std::pair<int, int>> unique;
    for (int i = 0; i < ec; ++i) {
        CHECK(e[i][0] >= 0 && e[i][0] < vc && e[i][1] >= 0 && e[i][1] < vc);
        unique.insert({std::min(e[i][0], e[i][1]), std::max(e[i][0], e[i][1])});
    }
    CHECK_EQ(unique.size(), 90u);
    free_soccer_ball(v, e);
    CHECK_EQ(generate_soccer_ball(nullptr, &vc, &e, &ec), 0);
    CHECK(e == nullptr);
    CHECK_EQ(ec, 0);
}

TEST(icosphere_counts_sphere_and_orientation) {
    for (int level = 0; level <= 6; ++level) {
        const mesh s = make_icosphere(level);
        const std::size_t four_l = std::size_t(1) << (2 * level);
        CHECK_EQ(s.positions.size(), 10 * four_l + 2);
        CHECK_EQ(s.face_count(), 20 * four_l);
        CHECK_EQ(s.edges.size(), 30 * four_l);
        CHECK_EQ(euler_characteristic(s), 2L);
        double worst = 0;
        for (const vec3_t &p : s.positions) worst = std::max(worst, std::fabs(length_d(p) - 1.0));
        CHECK_NEAR(worst, 0.0, 1e-6);
        if (level <= 3) CHECK(closed_and_oriented(s));
        CHECK(signed_volume(s) > 0.0);
    }
    // The level-6 sphere's volume approaches 4π/3 from below (inscribed polyhedron).
    const double v6 = signed_volume(make_icosphere(6));
    CHECK(v6 < 4.0 * M_PI / 3.0);
    CHECK_NEAR(v6, 4.0 * M_PI / 3.0, 4e-3);
    // The 12 base vertices: cyclic permutations of (±1, ±t, 0), normalised.
    const mesh ico = make_icosphere(0);
    const double t = (1 + std::sqrt(5.0)) / 2, n = std::sqrt(1 + t * t);
    for (const vec3_t &p : ico.positions) {
        double a[3] = {std::fabs(p.x) * n, std::fabs(p.y) * n, std::fabs(p.z) * n};
        std::sort(a, a + 3);
        CHECK_NEAR(a[0], 0.0, 1e-6);
        CHECK_NEAR(a[1], 1.0, 1e-6);
        CHECK_NEAR(a[2], t, 1e-6);
    }
    CHECK_EQ(make_icosphere(-1).face_count(), 0u);
    CHECK_EQ(make_icosphere(9).face_count(), 0u);
}

TEST(cube_uv_sphere_torus_knot_closed_and_outward) {
    const mesh cube = make_cube(0.5f);
    CHECK_EQ(cube.positions.size(), 8u);
    CHECK_EQ(cube.edges.size(), 12u);
    CHECK_EQ(cube.face_count(), 6u);
    CHECK_EQ(cube.corner_uvs.size(), 24u);
    CHECK(closed_and_oriented(cube));
    CHECK_NEAR(signed_volume(cube), 1.0, 1e-6);
    // Each face normal points along the axis of its centroid.
    const std::vector<vec3_t> fn = mesh_face_normals(cube);
    for (std::size_t f = 0; f < 6; ++f) {
        vec3_t c{0, 0, 0};
        for (std::uint32_t k = cube.face_start[f]; k < cube.face_start[f + 1]; ++k) c += cube.positions[cube.indices[k]];
        CHECK_NEAR(dot_d(fn[f], c / 4.0f), 0.5, 1e-6);
    }

    const mesh uv = make_uv_sphere(24, 12, 2.0f);
    CHECK_EQ(uv.positions.size(), 24u * 11 + 2);
    CHECK_EQ(euler_characteristic(uv), 2L);
    CHECK(closed_and_oriented(uv));
    CHECK(mesh_validate(uv).ok());
    CHECK(signed_volume(uv) > 0.9 * 4.0 / 3.0 * M_PI * 8.0);

    const float R = 1.0f, r = 0.25f;
    const mesh torus = make_torus(R, r, 48, 16);
    CHECK_EQ(torus.positions.size(), 48u * 16);
    CHECK_EQ(torus.edges.size(), 2u * 48 * 16);
    CHECK_EQ(euler_characteristic(torus), 0L);
    CHECK(closed_and_oriented(torus));
    CHECK_NEAR(signed_volume(torus) / (2 * M_PI * M_PI * R * r * r), 1.0, 0.03);

    const mesh knot = make_torus_knot(2, 3, 154, 12);
    CHECK_EQ(mesh_triangles(knot).size(), 3696u);
    CHECK_EQ(euler_characteristic(knot), 0L);
    CHECK(closed_and_oriented(knot));
    CHECK(signed_volume(knot) > 0.0);
    CHECK_EQ(make_torus_knot(2, 4, 100, 8).face_count(), 0u);  // gcd 2: not a knot
    CHECK_EQ(make_torus(1.0f, 2.0f, 8, 8).face_count(), 0u);    // minor ≥ major
    CHECK_EQ(make_cube(NAN).face_count(), 0u);
}

TEST(vertex_normals_angle_weighted) {
    // On a sphere the angle-weighted normal approaches the radial direction.
    const mesh s = make_icosphere(3);
    const std::vector<vec3_t> n = mesh_vertex_normals(s);
    double worst = 0;
    for (std::size_t i = 0; i < s.positions.size(); ++i) worst = std::max(worst, 1.0 - dot_d(n[i], s.positions[i]));
    CHECK(worst < 1e-3);
    // Cube corner: three faces at 90° each → (1, 1, 1)/√3 regardless of quad vs triangles.
    const mesh cube = make_cube(1.0f);
    const std::vector<vec3_t> cn = mesh_vertex_normals(cube);
    CHECK_NEAR(cn[7].x, 1.0 / std::sqrt(3.0), 1e-6);
    CHECK_NEAR(cn[7].y, 1.0 / std::sqrt(3.0), 1e-6);
    CHECK_NEAR(cn[0].z, -1.0 / std::sqrt(3.0), 1e-6);
    // Split one quad of the cube into two triangles: angle weighting keeps the normal.
    mesh split = cube;
    split.face_start = {0};
    split.indices.clear();
    split.corner_uvs.clear();
    for (const corner_triangle &t : mesh_triangles(cube))
        split.add_face({cube.indices[t[0]], cube.indices[t[1]], cube.indices[t[2]]});
    const std::vector<vec3_t> sn = mesh_vertex_normals(split);
    for (std::size_t i = 0; i < 8; ++i) CHECK_NEAR(dot_d(sn[i], cn[i]), 1.0, 1e-6);
    // A degenerate face has a zero normal, not NaN.
    mesh flat;
    flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    flat.add_face({0, 1, 2});
    const vec3_t z = mesh_face_normals(flat)[0];
    CHECK(z.x == 0 && z.y == 0 && z.z == 0);
}

TEST(crease_normals_at_180_are_the_vertex_normals_bit_for_bit) {
    // No repeated positions: a full crease gives every corner its position's normal exactly.
    for (const mesh &m : {make_icosphere(2), make_torus(1.0f, 0.4f, 24, 12), make_cube(1.0f)}) {
        const std::vector<vec3_t> per_position = mesh_vertex_normals(m);
        for (float crease : {180.0f, 400.0f, NAN}) {
            const std::vector<vec3_t> per_corner = mesh_crease_normals(m, crease);
            CHECK_EQ(per_corner.size(), m.indices.size());
            int differing = 0;
            for (std::size_t k = 0; k < m.indices.size(); ++k) {
                const vec3_t a = per_corner[k], b = per_position[m.indices[k]];
                differing += a.x != b.x || a.y != b.y || a.z != b.z;
            }
            CHECK_EQ(differing, 0);
        }
    }
}

TEST(crease_normals_keep_a_cubes_edges_sharp) {
    // 8 shared corners, faces at 90°: any crease below 90° gives each corner its face's normal
    // (quads or their triangles alike); 90° and more blend the three faces, as (1,1,1)/√3.
    const mesh cube = make_cube(1.0f);
    const std::vector<vec3_t> face = mesh_face_normals(cube);
    for (float crease : {0.0f, 30.0f, 60.0f, 89.0f}) {
        const std::vector<vec3_t> n = mesh_crease_normals(cube, crease);
        for (std::size_t f = 0; f < cube.face_count(); ++f)
            for (std::uint32_t k = cube.face_start[f]; k < cube.face_start[f + 1]; ++k)
                CHECK_NEAR(dot_d(n[k], face[f]), 1.0, 1e-6);
    }
    const std::vector<vec3_t> smooth = mesh_crease_normals(cube, 91.0f);
    for (std::size_t k = 0; k < cube.indices.size(); ++k) {
        const vec3_t p = cube.positions[cube.indices[k]];  // corner (±1, ±1, ±1)
        CHECK_NEAR(dot_d(smooth[k], p), std::sqrt(3.0), 1e-5);
    }
}

TEST(crease_normals_smooth_across_repeated_seam_vertices) {
    // A torus cut into patches of 37 faces (the teapot's case: seams repeat their vertices).
    // Per-position normals crease along the seams; crease normals are the welded mesh's.
    const mesh whole = make_torus(1.0f, 0.4f, 32, 16);
    const mesh patched = seam_split::split_into_patches(whole, 37);
    CHECK(patched.positions.size() > whole.positions.size() + 100);
    const std::vector<vec3_t> welded = mesh_crease_normals(whole, 60.0f);
    const std::vector<vec3_t> seamed = mesh_crease_normals(patched, 60.0f);
    const std::vector<vec3_t> old_style = mesh_vertex_normals(patched);
    double worst = 0, worst_old = 0;
    for (std::size_t k = 0; k < whole.indices.size(); ++k) {
        worst = std::max(worst, 1.0 - dot_d(welded[k], seamed[k]));
        worst_old = std::max(worst_old, 1.0 - dot_d(welded[k], old_style[patched.indices[k]]));
    }
    CHECK(worst < 1e-7);
    CHECK(worst_old > 1e-3);  // the seams the per-position normals show
    // Neighbouring faces of this torus meet at 32° at most (22.5° around the tube, both
    // steps on the diagonal): a 45° crease is as smooth as 60°, and 0° gives every corner its
    // own face's normal (a faceted torus).
    const std::vector<vec3_t> face = mesh_face_normals(whole);
    const std::vector<vec3_t> faceted = mesh_crease_normals(patched, 0.0f);
    for (std::size_t f = 0; f < whole.face_count(); ++f)
        for (std::uint32_t k = whole.face_start[f]; k < whole.face_start[f + 1]; ++k)
            CHECK_NEAR(dot_d(faceted[k], face[f]), 1.0, 1e-6);
    const std::vector<vec3_t> at45 = mesh_crease_normals(patched, 45.0f);
    for (std::size_t k = 0; k < whole.indices.size(); ++k) CHECK_NEAR(dot_d(at45[k], welded[k]), 1.0, 1e-7);
}

TEST(crease_normals_of_bad_meshes_are_zero_not_nan) {
    mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    m.add_face({0, 1, 2});  // degenerate: takes every face at its positions
    m.add_face({0, 1, 3});
    m.add_face({0, 1, 9});  // out of range
    const std::vector<vec3_t> n = mesh_crease_normals(m, 10.0f);
    CHECK_EQ(n.size(), 9u);
    CHECK_NEAR(n[0].z, 1.0, 1e-6);  // face 1's normal, +z
    CHECK(n[2].x == 0 && n[2].y == 0 && n[2].z == 0);  // position 2: only the degenerate face
    for (int k = 6; k < 9; ++k) CHECK(n[k].x == 0 && n[k].y == 0 && n[k].z == 0);
    m.face_start.back() = 99;  // malformed
    for (const vec3_t &v : mesh_crease_normals(m, 60.0f)) CHECK(v.x == 0 && v.y == 0 && v.z == 0);
}

TEST(adjacency_closed_meshes_two_faces_per_edge) {
    for (const mesh &m : {make_soccer_ball(), make_icosphere(2), make_torus(1, 0.3f, 12, 8)}) {
        const edge_adjacency adj = mesh_edge_faces(m);
        CHECK_EQ(adj.start.size(), m.edges.size() + 1);
        for (std::size_t e = 0; e < m.edges.size(); ++e) {
            CHECK_EQ(adj.count(e), 2u);
            // Both faces really contain both endpoints.
            for (const std::uint32_t *f = adj.begin(e); f != adj.end(e); ++f) {
                int hits = 0;
                for (std::uint32_t k = m.face_start[*f]; k < m.face_start[*f + 1]; ++k)
                    hits += m.indices[k] == m.edges[e].a || m.indices[k] == m.edges[e].b;
                CHECK_EQ(hits, 2);
            }
        }
    }
}

TEST(bounds_and_validation) {
    mesh m = make_torus(2.0f, 0.5f, 16, 8);
    const bounding_box box = mesh_bounding_box(m);
    CHECK_NEAR(box.max.x, 2.5, 1e-6);
    CHECK_NEAR(box.min.z, -0.5, 1e-3);
    const bounding_sphere s = mesh_bounding_sphere(m);
    for (const vec3_t &p : m.positions) CHECK(length_d(p - s.center) <= s.radius);
    CHECK_NEAR(s.radius, 2.5, 1e-5);
    m.positions.push_back({NAN, 0, 0});
    CHECK_NEAR(mesh_bounding_sphere(m).radius, 2.5, 1e-5);
    CHECK(mesh_bounding_sphere(mesh{}).radius < 0);

    mesh bad = make_cube();
    bad.indices[5] = 99;
    const status st = mesh_validate(bad);
    CHECK(!st.ok());
    CHECK(!st.ok() && st.message().find("face 1") != std::string::npos);
    mesh short_face;
    short_face.positions = {{0, 0, 0}, {1, 0, 0}};
    short_face.add_face({0, 1});
    CHECK(!mesh_validate(short_face).ok());
}
