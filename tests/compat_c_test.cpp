// compat_c_test.cpp — the report's API and the other implementations' names as a C program
// gets them, and programs that bring their own function under one of the library's names.
//
// Two user-style programs, each built by `make tests` three times (tests/compat/compat.mk):
// by gcc as strict C11 ($BUILD/compat/c11/), by gcc in its default C dialect (gnu/), and by
// g++ as C++ ($BUILD/compat/). Every build is run and checked the same way:
//  * c_names.c calls the names C has from the normal headers (canvas_create,
//    canvas_clear(c, v), canvas_save_pgm, the four PPM saves, the global mat4_rotate_x/y/z,
//    mat4_mul, mat4_mul_vec3, mat4_transform_vec3, vec3_from_cartesian, bezier, …) —
//    checked against double-precision formulas, hand-computed pixels and the bytes a P6
//    file of its canvas holds; failed saves must return −1 and leave no file behind;
//  * own_forms/ defines its own mat4_mul_vec3, mat4_mul, canvas_clear, bezier,
//    generate_soccer_ball (the report's printed form, in its own file as the report's
//    demo/generate_soccer.c), vec3_normalize(vec3_t *), vec3_length, vec3_sub,
//    mat4_frustum (double) and clear_canvas (double), and in C++ also mat4_identity(&m),
//    canvas_clear(c), mat4_mul(&a, &b), mat4_mul_vec3(&m, v) and our generate_soccer_ball
//    form — each returns something the library's would not, and says "own <name>": the
//    program must link (the library's copy is never pulled in beside its own) and call its
//    own every time.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "compat_util.h"

namespace {

using namespace compat_util;

dvec3 rotate_x(dvec3 p, double a) { return {p.x, p.y * std::cos(a) - p.z * std::sin(a), p.y * std::sin(a) + p.z * std::cos(a)}; }
dvec3 rotate_y(dvec3 p, double a) { return {p.x * std::cos(a) + p.z * std::sin(a), p.y, -p.x * std::sin(a) + p.z * std::cos(a)}; }
dvec3 rotate_z(dvec3 p, double a) { return {p.x * std::cos(a) - p.y * std::sin(a), p.x * std::sin(a) + p.y * std::cos(a), p.z}; }

std::vector<std::string> files_in(const fs::path &folder) {
    std::vector<std::string> names;
    for (const auto &entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

TEST(c_names_values_match_double_formulas_in_c11_gnu_c_and_cxx) {
    std::vector<std::string> first_output;
    for (const std::string &program : c_and_cxx_builds("c_names")) {
        scratch_dir dir;
        const program_run r = run_program(program, dir);
        if (first_output.empty()) first_output = r.lines;
        CHECK_MSG(r.lines == first_output, program + " printed other lines than the C++ build");

        // The types' layout: the same in C as in C++ (this test's sizes).
        CHECK(single_row(r, "layout", 7) ==
              (std::vector<double>{double(sizeof(vec3_t)), double(sizeof(vec4_t)), double(sizeof(mat4_t)),
                                   double(sizeof(canvas_t)), double(offsetof(canvas_t, pixels)),
                                   double(sizeof(light_t)), double(offsetof(light_t, position))}));
        const double angle = double(float(M_PI / 5));  // the program's float angle
        if (const auto v = single_row(r, "angle", 1); !v.empty()) CHECK_EQ(float(v[0]), float(angle));  // %.9g: exact
        const dvec3 p{1, 2, 3};
        if (const auto v = single_row(r, "rotate_x", 3); !v.empty()) check_near3(v, 0, rotate_x(p, angle), 2e-6);
        if (const auto v = single_row(r, "rotate_y", 3); !v.empty()) check_near3(v, 0, rotate_y(p, angle), 2e-6);
        if (const auto v = single_row(r, "rotate_z", 3); !v.empty()) check_near3(v, 0, rotate_z(p, angle), 2e-6);
        // translate(0.5, −1, 2)·Rz(a)·Ry(−a)·p
        const dvec3 product = rotate_z(rotate_y(p, -angle), angle) + dvec3{0.5, -1, 2};
        if (const auto v = single_row(r, "product", 3); !v.empty()) check_near3(v, 0, product, 4e-6);

        // B(t) = (1−t)³p0 + 3(1−t)²t p1 + 3(1−t)t² p2 + t³p3 with p0 = 0, p1 = (1, 2, 0),
        // p2 = (3, 2, 1), p3 = (4, 0, 2).
        const auto bez = rows_of(r, "bezier", 4);
        CHECK_EQ(bez.size(), std::size_t(5));
        for (const auto &row : bez) {
            const double t = row[0] / 4, u = 1 - t;
            const dvec3 ref = (3 * u * u * t) * dvec3{1, 2, 0} + (3 * u * t * t) * dvec3{3, 2, 1} + (t * t * t) * dvec3{4, 0, 2};
            check_near3(row, 1, ref, 2e-6);
        }

        // Cleared to 0.25; the thickness-1 line along row 15 puts splats of 1 at every
        // half pixel: pixel (20, 15) gets 1 + 2 · 0.5 over its 0.25, clamped to 1.
        CHECK(numbers_after(r, "pixel") == (std::vector<std::vector<double>>{{0, 0, 0.25}, {20, 15, 1}}));

        // The PGM equals the same drawing through the report's API.
        canvas_t *expected = create_canvas(40, 30);
        CHECK(expected != nullptr);
        if (!expected) return;
        canvas_clear(expected, 0.25f);
        draw_line_f(expected, 5, 15, 35, 15, 1);
        CHECK_EQ(differing_pixels(read_image(dir.file("c_names.pgm")), *expected), 0);
        // Each PPM: binary P6, R = G = B = the PGM sample.
        std::string ppm = "P6\n40 30\n255\n";
        for (int y = 0; y < 30; ++y)
            for (int x = 0; x < 40; ++x) ppm.append(3, char(sample_of(expected->pixels[y][x])));
        destroy_canvas(expected);
        const std::vector<std::string> names = {"save_canvas_ppm", "save_canvas_to_ppm", "save_canvas_as_ppm",
                                                "canvas_save_ppm"};
        for (const std::string &name : names) {
            CHECK_MSG(file_bytes(dir.path / ("c_names_" + name + ".ppm")) == ppm, name + ": not the expected P6 file");
        }
        CHECK_EQ(file_bytes(dir.path / "c_names_direct.ppm"), ppm);
        const auto saves = numbers_after(r, "save");  // "save <name> <result>"
        CHECK_EQ(saves.size(), std::size_t(5));
        for (const auto &row : saves) CHECK_EQ(row, std::vector<double>{0});
        const auto failed = numbers_after(r, "failed_save");
        CHECK_EQ(failed.size(), std::size_t(4));
        for (const auto &row : failed) CHECK_EQ(row, (std::vector<double>{-1, -1}));
        CHECK_EQ(single_row(r, "direct", 1), std::vector<double>{0});
        // Failed saves leave nothing behind (no temporary file beside the others).
        std::vector<std::string> expected_files = {"c_names.pgm", "c_names_direct.ppm"};
        for (const std::string &name : names) expected_files.push_back("c_names_" + name + ".ppm");
        std::sort(expected_files.begin(), expected_files.end());
        CHECK(files_in(dir.path) == expected_files);
        CHECK(!r.lines.empty() && r.lines.back() == "done");
    }
}

namespace {

// What own_forms prints in C and in C++ (then the C++-only lines follow): the own
// functions' markers and results, hand-computed from own.c.
const std::vector<std::string> kOwnLines = {
    "own mat4_mul_vec3",
    "",  // mat4_mul_vec3 (numbers checked below)
    "own mat4_mul",
    "mat4_mul 2 0 0 0 0 2 0 0 0 0 2 0 2 4 6 1",  // own: S(2)·T(1, 2, 3), not T·S
    "own bezier",
    "bezier 2 1 0",  // own: the chord's midpoint
    "own vec3_normalize",
    "own vec3_length",
    "vec3_normalize 0 0 1",  // own: zero → +z (the library's gives 0 0 0)
    "own vec3_length",
    "vec3_length 6",  // own: the 1-norm of (1, −2, 3) (the library's: √14)
    "own vec3_sub",
    "vec3_sub 3 4 5",  // own: b − a
    "own mat4_frustum -1 1 -1 1 1 10",
    "mat4_frustum 2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 2",
    "own canvas_clear",
    "canvas_clear 0.25",  // own: value / 2
    "own clear_canvas",
    "clear_canvas 0.75",  // own: 1 − value
    "own generate_soccer_ball",
    "generate_soccer_ball 4 6 1 2 3",  // own tetrahedron: 4 vertices, 6 edges
    "lambert 1",                      // the library's lambert_intensity beside them
    "vec3_bezier 2 2 2",              // the library's vec3_bezier: 3·½·¼·4 + ⅛·4 = 2
};
const std::vector<std::string> kOwnCxxLines = {
    "own mat4_identity",
    "mat4_identity(&m) 3 0 0 0 0 3 0 0 0 0 3 0 0 0 0 3",
    "own canvas_clear(c)",
    "canvas_clear(c) 0.75",
    "own mat4_mul(&a, &b)",
    "mat4_mul(&a, &b) 3 0 0 0 0 3 0 0 0 0 3 0 1 2 3 2",
    "own mat4_mul_vec3(&m, v)",
    "mat4_mul_vec3(&m, v) 2 3 4",
    "own generate_soccer_ball(int (**)[2])",
    "generate_soccer_ball(int (**)[2]) 7",
};

}  // namespace

TEST(own_forms_links_and_calls_its_own_functions_in_c11_gnu_c_and_cxx) {
    for (const std::string &program : c_and_cxx_builds("own_forms")) {
        scratch_dir dir;
        const program_run r = run_program(program, dir);
        std::vector<std::string> expected = kOwnLines;
        if (program == "own_forms") expected.insert(expected.end(), kOwnCxxLines.begin(), kOwnCxxLines.end());
        CHECK_MSG(r.lines.size() == expected.size(), program + ": " + std::to_string(r.lines.size()) + " lines");
        for (std::size_t i = 0; i < std::min(r.lines.size(), expected.size()); ++i)
            if (!expected[i].empty()) CHECK_MSG(r.lines[i] == expected[i], program + ": '" + r.lines[i] + "'");
        // own mat4_mul_vec3 does not divide by w: glFrustum(−1, 1, −1, 1, 1, 10)·(0, 0, −2, 1)
        // has z = (−11/9)(−2) − 20/9 = 2/9 (w = 2; the library's would print 1/9).
        if (const auto v = single_row(r, "mat4_mul_vec3", 3); !v.empty()) check_near3(v, 0, {0, 0, 2.0 / 9}, 1e-6);
    }
}
