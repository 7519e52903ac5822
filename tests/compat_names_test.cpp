// compat_names_test.cpp — the alternate names that are also names programs give their own
// functions: save_canvas_pgm, save_canvas_as_pgm, canvas_save_to_pgm,
// save_canvas_to_pgm, the 7-argument draw_line_f, create_cube, the global mat4_perspective
// and vec3_normalize. They are in the normal headers and step aside for a program's own
// function of the same name (include/compat/user_first.h).
//
// Three user-style programs, built by `make tests` with g++ -std=c++20 -Wall -Wextra -Werror
// (tests/compat/compat.mk), are run and their output checked:
//  * peer_names.c calls each name through canvas.h, math3d.h and renderer.h — checked
//    against double-precision formulas, the cube's graph and hand-computed pixels;
//  * own_names.c defines its own function of each name with a slightly different signature
//    (char *, void result, double parameters called with floats and int literals, pointer
//    form, degrees) — checked that its own ran (its marker lines, values, P2 files);
//  * own_split/ declares its own in a header (two with C linkage) and defines them in
//    another file — checked the same way: it must link and call its own.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "compat_util.h"

namespace {

using namespace compat_util;

// The lines a program printed that start with "own " (its own functions announce
// themselves), in order.
std::vector<std::string> own_calls(const program_run &r) {
    std::vector<std::string> calls;
    for (const std::string &line : r.lines)
        if (line.rfind("own ", 0) == 0) calls.push_back(line.substr(4));
    return calls;
}

// gluPerspective(fovy radians, aspect, n, f), column-major, in double.
std::array<double, 16> perspective_ref(double fovy, double aspect, double n, double f) {
    std::array<double, 16> m{};
    const double cot = 1.0 / std::tan(fovy / 2);
    m[0] = cot / aspect;
    m[5] = cot;
    m[10] = (f + n) / (n - f);
    m[11] = -1;
    m[14] = 2 * f * n / (n - f);
    return m;
}

void check_matrix(const std::vector<double> &m, const std::array<double, 16> &expected) {
    for (std::size_t i = 0; i < m.size(); ++i) CHECK_NEAR(m[i], expected[i], kFloatTolerance * std::fmax(1.0, std::fabs(expected[i])));
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace

// ---- peer_names.c: each name through the normal headers ------------------------------------

TEST(peer_names_create_cube_gives_the_cube_graph_in_malloc_arrays) {
    scratch_dir dir;
    const program_run r = run_program("peer_names", dir);
    CHECK(single_row(r, "cube", 3) == (std::vector<double>{1, 8, 12}));
    CHECK(single_row(r, "cube_null_output", 1) == std::vector<double>{1});

    // Corner i: +1 on x when bit 0 of i is set, y bit 1, z bit 2 (−1 otherwise).
    const auto vertices = rows_of(r, "cube_vertex", 4);
    CHECK_EQ(vertices.size(), std::size_t(8));
    std::vector<dvec3> corner(8, dvec3{0, 0, 0});
    for (const auto &v : vertices) {
        const int i = int(v[0]);
        if (!CHECK(i >= 0 && i < 8)) continue;
        corner[std::size_t(i)] = row3(v, 1);
        CHECK_EQ(v[1], (i & 1) ? 1.0 : -1.0);
        CHECK_EQ(v[2], (i & 2) ? 1.0 : -1.0);
        CHECK_EQ(v[3], (i & 4) ? 1.0 : -1.0);
    }
    // 12 distinct edges a < b, each of length 2 along one axis, every corner of degree 3:
    // exactly the cube's 12 edges.
    const auto edges = rows_of(r, "cube_edge", 2);
    CHECK_EQ(edges.size(), std::size_t(12));
    std::set<std::pair<int, int>> distinct;
    std::array<int, 8> degree{};
    for (const auto &e : edges) {
        const int a = int(e[0]), b = int(e[1]);
        if (!CHECK(a >= 0 && a < b && b < 8)) continue;
        distinct.insert({a, b});
        ++degree[std::size_t(a)];
        ++degree[std::size_t(b)];
        const dvec3 d = corner[std::size_t(b)] - corner[std::size_t(a)];
        CHECK_NEAR(std::sqrt(dot(d, d)), 2.0, 0.0);
        CHECK_EQ(int(d.x != 0) + int(d.y != 0) + int(d.z != 0), 1);
    }
    CHECK_EQ(distinct.size(), std::size_t(12));
    for (int d : degree) CHECK_EQ(d, 3);
}

TEST(peer_names_perspective_and_normalize_match_double_formulas) {
    scratch_dir dir;
    const program_run r = run_program("peer_names", dir);
    // The program passes double and int literals; the alias takes floats, as the primary.
    check_matrix(single_row(r, "perspective", 16), perspective_ref(double(float(kPi / 3)), 1.5, double(0.5f), 50));
    check_matrix(single_row(r, "perspective_ints", 16), perspective_ref(1, 2, 1, 10));

    // The exact normalisation (tiny3d::vec3_normalize: 0.5 ulp), not the Quake one.
    const auto rows = rows_of(r, "normalize", 6);
    CHECK_EQ(rows.size(), std::size_t(3));
    if (rows.size() == 3) {
        check_near3(rows[0], 3, {3 / 13.0, 4 / 13.0, 12 / 13.0}, 6e-8);
        CHECK(std::vector<double>(rows[1].begin() + 3, rows[1].end()) == (std::vector<double>{0, 0, 0}));
        CHECK(std::vector<double>(rows[2].begin() + 3, rows[2].end()) == (std::vector<double>{0, -1, 0}));
    }
}

TEST(peer_names_lines_and_saves_match_the_primary_api_and_hand_computed_pixels) {
    scratch_dir dir;
    const program_run r = run_program("peer_names", dir);
    const char *names[] = {"save_canvas_pgm", "save_canvas_as_pgm", "canvas_save_to_pgm", "save_canvas_to_pgm"};
    const auto saves = rows_of(r, "save", 1);
    CHECK_EQ(saves.size(), std::size_t(4));
    for (const auto &s : saves) CHECK(s == std::vector<double>{0});
    CHECK(single_row(r, "failed_save", 1) == std::vector<double>{-1});
    CHECK(!fs::exists(dir.path / "no_such_folder"));
    const std::string first = file_bytes(dir.file("peer_save_canvas_pgm.pgm"));
    CHECK(first.rfind("P5\n96 64\n255\n", 0) == 0);  // binary PGM, as save_canvas writes
    for (const char *name : names) CHECK_MSG(file_bytes(dir.file(std::string("peer_") + name + ".pgm")) == first, name);

    // The same drawing through the primary API: the 7-argument line is draw_line_coverage
    // with round caps and the given intensity, its ends moved from the report's coordinates
    // (pixel centres on integers, as the six-argument draw_line_f) by +0.5 into the canvas's.
    const gray_image img = read_image(dir.file("peer_save_canvas_pgm.pgm"));
    CHECK_EQ(img.width, 96);
    CHECK_EQ(img.height, 64);
    if (img.width != 96 || img.height != 64) return;
    canvas_t *expected = create_canvas(96, 64);
    if (!CHECK(expected != nullptr)) return;
    const mat4_t mvp = mat4_multiply(tiny3d::mat4_perspective(float(kPi / 3), 1.5f, 0.5f, 50.0f),
                                     mat4_multiply(mat4_translate(0, 0, -4), mat4_rotate_xyz(0.4f, 0.6f, 0)));
    const tiny3d::mesh cube = tiny3d::make_cube(1.0f);
    tiny3d::line_style style;
    style.intensity = 0.75f;
    for (const tiny3d::edge &e : cube.edges) {
        const vec3_t a = apply_transform(mvp, cube.positions[e.a]), b = apply_transform(mvp, cube.positions[e.b]);
        tiny3d::draw_line_coverage(expected, (a.x + 1) * 0.5f * 96 + 0.5f, (1 - a.y) * 0.5f * 64 + 0.5f,
                                   (b.x + 1) * 0.5f * 96 + 0.5f, (1 - b.y) * 0.5f * 64 + 0.5f, 1.5f, style);
    }
    style.intensity = 0.5f;
    tiny3d::draw_line_coverage(expected, 10.5f, 60, 80.5f, 60, 2, style);
    CHECK_EQ(differing_pixels(img, *expected), 0);
    destroy_canvas(expected);

    // Hand-computed: the bar (10, 59.5)–(80, 59.5) is (10.5, 60)–(80.5, 60) on the canvas;
    // thickness 2, round caps, intensity 0.5: it covers y in [59, 61] — rows 59 and 60 —
    // fully from x = 10.5 to 80.5, so columns 11..79 of those rows hold 0.5 (127.5 before
    // rounding); rows 61..63 stay empty. Its ink is 0.5 × the capsule's area 70·2 + π·1²,
    // to within the 8-bit rounding of the ~146 pixels it touches.
    double bar_ink = 0;
    for (int x = 0; x < 96; ++x) {
        if (x >= 11 && x < 80) {
            CHECK(std::abs(2 * img.at(x, 59) - 255) <= 1);
            CHECK(std::abs(2 * img.at(x, 60) - 255) <= 1);
        }
        for (int y = 61; y < 64; ++y) CHECK_EQ(img.at(x, y), 0);
        bar_ink += (img.at(x, 59) + img.at(x, 60)) / 255.0;
    }
    CHECK_NEAR(bar_ink, 0.5 * (140 + kPi), 146 * 0.5 / 255);
    CHECK(img.at(9, 60) > 0 && img.at(81, 59) > 0);  // the caps reach x = 9.5 and 81.5
    CHECK_EQ(img.at(8, 60), 0);
    CHECK_EQ(img.at(82, 59), 0);
}

// ---- own_names.c: the program's own functions of those names -----------------------------------

TEST(own_names_program_calls_its_own_functions) {
    scratch_dir dir;
    const program_run r = run_program("own_names", dir);
    CHECK(own_calls(r) == (std::vector<std::string>{"create_cube", "mat4_perspective", "mat4_perspective",
                                                    "vec3_normalize", "draw_line_f 1", "draw_line_f 3",
                                                    "save_canvas_pgm", "save_canvas_as_pgm", "canvas_save_to_pgm"}));
    // Its cube is [0, 1]³ (the library's is [−1, 1]³).
    const auto vertices = rows_of(r, "cube_vertex", 4);
    CHECK_EQ(vertices.size(), std::size_t(8));
    for (const auto &v : vertices) {
        const int i = int(v[0]);
        CHECK_EQ(v[1], double((i & 1) ^ ((i >> 1) & 1)));
        CHECK_EQ(v[2], double((i >> 1) & 1));
        CHECK_EQ(v[3], double(i >> 2));
    }
    // Its perspective takes degrees (the library's radians would make 90 an invalid field of
    // view, and 60 another matrix).
    check_matrix(single_row(r, "perspective_ints", 16), perspective_ref(kPi / 2, 2, 1, 10));
    check_matrix(single_row(r, "perspective_floats", 16), perspective_ref(kPi / 3, 1.5, 0.5, 20));
    if (const auto v = single_row(r, "normalize", 6); !v.empty()) check_near3(v, 3, {0, 0.6, 0.8}, 1e-7);

    const auto saves = rows_of(r, "save", 1);
    CHECK_EQ(saves.size(), std::size_t(2));
    for (const auto &s : saves) CHECK(s == std::vector<double>{0});
    // Its own writer (ASCII P2) and its own line (pixels SET to the intensity, one per unit
    // step): (2, 3.5)–(20, 3.5) at 0.5 → row 3, columns 2..20 hold (int)(0.5·255 + 0.5) = 128;
    // (2, 10)–(2, 14) at 1 → column 2, rows 10..14 hold 255; nothing else.
    const std::string first = file_bytes(dir.file("own_save_canvas_pgm.pgm"));
    CHECK(first.rfind("P2\n24 16\n255\n", 0) == 0);
    for (const char *name : {"own_save_canvas_as_pgm.pgm", "own_canvas_save_to_pgm.pgm"})
        CHECK_MSG(file_bytes(dir.file(name)) == first, name);
    const gray_image img = read_image(dir.file("own_save_canvas_pgm.pgm"));
    CHECK_EQ(img.width, 24);
    CHECK_EQ(img.height, 16);
    if (img.width != 24 || img.height != 16) return;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 24; ++x) {
            const int expected = (y == 3 && x >= 2 && x <= 20) ? 128 : (x == 2 && y >= 10 && y <= 14) ? 255 : 0;
            CHECK_EQ(img.at(x, y), expected);
        }
}

// ---- own_split/: declared in the program's header, defined in its other file ---------------------

TEST(own_split_program_links_and_calls_its_own_functions) {
    scratch_dir dir;
    const program_run r = run_program("own_split", dir);
    CHECK(own_calls(r) == (std::vector<std::string>{"create_cube", "vec3_normalize", "vec3_normalize",
                                                    "mat4_perspective", "draw_line_f 2", "save_canvas_pgm"}));
    CHECK(single_row(r, "cube", 2) == (std::vector<double>{8, 12}));
    const auto vertices = rows_of(r, "cube_vertex", 4);
    CHECK_EQ(vertices.size(), std::size_t(8));
    for (const auto &v : vertices)
        for (std::size_t k = 1; k <= 3; ++k) CHECK_EQ(std::fabs(v[k]), 0.5);  // its cube has side 1
    // Its normalize maps zero to +z (the library's gives 0, 0, 0).
    const auto normals = rows_of(r, "normalize", 6);
    CHECK_EQ(normals.size(), std::size_t(2));
    if (normals.size() == 2) {
        CHECK(std::vector<double>(normals[0].begin() + 3, normals[0].end()) == (std::vector<double>{0, 0, 1}));
        CHECK(std::vector<double>(normals[1].begin() + 3, normals[1].end()) == (std::vector<double>{0, 0, -1}));
    }
    check_matrix(single_row(r, "perspective", 16), perspective_ref(kPi / 2, 1, 1, 3));  // 90 degrees
    CHECK(single_row(r, "save", 1) == std::vector<double>{0});
    // Its writer: P2 with its comment, 255 where a pixel is inked; its line set only the
    // pixels under its ends, (1, 1) and (6, 2).
    std::string expected = "P2\n# own_split\n8 4\n255\n";
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) expected += ((x == 1 && y == 1) || (x == 6 && y == 2)) ? "255\n" : "0\n";
    CHECK(file_bytes(dir.file("own_split.pgm")) == expected);
}

// ---- in-process: the aliases are the primary functions ----------------------------------------------

TEST(aliases_equal_the_primary_functions_with_int_and_double_literals) {
    // vec3_normalize: tiny3d::vec3_normalize, bit for bit, from a compound or braced argument.
    const vec3_t v = {0.3f, -2.0f, 7.5f};
    const vec3_t n = vec3_normalize(v), n_braced = vec3_normalize({0.3f, -2.0f, 7.5f});
    CHECK(n == tiny3d::vec3_normalize(v) && n_braced == n);
    const vec3_t n_ints = vec3_normalize({1, 2, 2});  // int literals
    CHECK_NEAR(n_ints.x, 1 / 3.0, 3e-8);
    CHECK_NEAR(n_ints.z, 2 / 3.0, 6e-8);

    // mat4_perspective: tiny3d::mat4_perspective, bit for bit; bad arguments give the identity.
    const mat4_t p = mat4_perspective(0.9, 4 / 3.0, 0.25, 40), q = tiny3d::mat4_perspective(0.9f, 4 / 3.0f, 0.25f, 40.0f);
    CHECK(std::memcmp(&p, &q, sizeof p) == 0);
    const mat4_t bad = mat4_perspective(1, 1, 0, 10), identity = mat4_identity();
    CHECK(std::memcmp(&bad, &identity, sizeof bad) == 0);

    // create_cube: the caller's free() releases both arrays; null outputs fail.
    vec3_t *vertices = nullptr;
    int *edges = nullptr, vertex_count = 0, edge_count = 0;
    CHECK_EQ(create_cube(&vertices, &edges, &vertex_count, &edge_count), 1);
    CHECK_EQ(vertex_count, 8);
    CHECK_EQ(edge_count, 12);
    const tiny3d::mesh cube = tiny3d::make_cube(1.0f);
    if (vertices && edges && vertex_count == 8 && edge_count == 12) {
        CHECK(std::equal(cube.positions.begin(), cube.positions.end(), vertices));
        for (int k = 0; k < 12; ++k) {
            CHECK_EQ(std::uint32_t(edges[2 * k]), cube.edges[std::size_t(k)].a);
            CHECK_EQ(std::uint32_t(edges[2 * k + 1]), cube.edges[std::size_t(k)].b);
        }
    }
    std::free(vertices);
    std::free(edges);
    CHECK_EQ(create_cube(static_cast<vec3_t **>(nullptr), &edges, &vertex_count, &edge_count), 0);
    CHECK(edges == nullptr && vertex_count == 0 && edge_count == 0);

    // draw_line_f with an intensity: draw_line_coverage with round caps, pixel for pixel,
    // half a pixel on (report coordinates → canvas coordinates).
    canvas_t *c = create_canvas(32, 24), *expected = create_canvas(32, 24);
    if (!CHECK(c && expected)) return;
    draw_line_f(c, 3, 4.25, 29, 19, 2.5, 0.6);  // int and double literals
    tiny3d::line_style style;
    style.intensity = 0.6f;
    tiny3d::draw_line_coverage(expected, 3.5f, 4.75f, 29.5f, 19.5f, 2.5f, style);
    CHECK(std::memcmp(c->data, expected->data, sizeof(float) * 32 * 24) == 0);
    CHECK(c->pixels[12][16] > 0.5f);  // the line passed here, so the comparison is not of blanks

    // Both draw_line_f forms put a line where the report's coordinates say: the ink of
    // (4, 5)–(20, 5) is centred on pixel centre (12, 5), i.e. canvas point (12.5, 5.5).
    for (int arguments : {6, 7}) {
        canvas_t *line = create_canvas(32, 12);
        if (!CHECK(line != nullptr)) break;
        if (arguments == 6)
            draw_line_f(line, 4, 5, 20, 5, 1.5f);
        else
            draw_line_f(line, 4, 5, 20, 5, 1.5f, 1);
        double ink = 0, mx = 0, my = 0;
        for (int y = 0; y < 12; ++y)
            for (int x = 0; x < 32; ++x) {
                ink += line->pixels[y][x];
                mx += line->pixels[y][x] * (x + 0.5);
                my += line->pixels[y][x] * (y + 0.5);
            }
        CHECK(ink > 10);
        CHECK_NEAR(mx / ink, 12.5, 1e-3);
        CHECK_NEAR(my / ink, 5.5, 1e-3);
        destroy_canvas(line);
    }

    // The save names: 0 on success, −1 on a null canvas or path.
    CHECK_EQ(save_canvas_pgm(static_cast<canvas_t *>(nullptr), "/tmp/never.pgm"), -1);
    CHECK_EQ(save_canvas_as_pgm(c, nullptr), -1);
    CHECK_EQ(canvas_save_to_pgm(static_cast<const canvas_t *>(nullptr), "/tmp/never.pgm"), -1);
    CHECK_EQ(save_canvas_to_pgm(c, nullptr), -1);
    destroy_canvas(c);
    destroy_canvas(expected);
}
