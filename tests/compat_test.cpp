// compat_test.cpp — libtiny3d as a drop-in for programs written against other libtiny3d
// implementations.
//
// The user-style programs tests/compat/*.c are compiled as C++ by `make tests` (g++
// -std=c++20 -Wall -Wextra -Werror) into $BUILD/compat/, and the C ones (report_demo,
// lit_bezier, own_helpers) as C too, into $BUILD/compat/c11/ and gnu/ (BUILD from the environment,
// default "build"); that they compile at all is half of the test (own_helpers.c defines its
// own vec3_normalize & co. against the normal headers). This program runs each of them and
// checks what they print against values computed here independently in double precision,
// and the images they write against hand-computed pixel values or against the same drawing
// done through the primary (report) API. It also calls every global name with int and
// double literals, so an overload that made such calls ambiguous would not compile.
// The programs calling (or defining their own) save_canvas_pgm & co., the 7-argument
// draw_line_f, create_cube, mat4_perspective and vec3_normalize are checked by
// tests/compat_names_test.cpp; the helpers both use are in tests/compat_util.h.
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "compat_util.h"

namespace {

using namespace compat_util;

// Rotations (right-handed, radians) in double.
dvec3 rotate_x(dvec3 p, double a) { return {p.x, p.y * std::cos(a) - p.z * std::sin(a), p.y * std::sin(a) + p.z * std::cos(a)}; }
dvec3 rotate_y(dvec3 p, double a) { return {p.x * std::cos(a) + p.z * std::sin(a), p.y, -p.x * std::sin(a) + p.z * std::cos(a)}; }
dvec3 rotate_z(dvec3 p, double a) { return {p.x * std::cos(a) - p.y * std::sin(a), p.x * std::sin(a) + p.y * std::cos(a), p.z}; }

// Cubic Bernstein form B(t) = (1−t)³p0 + 3(1−t)²t p1 + 3(1−t)t² p2 + t³p3.
dvec3 bezier_ref(dvec3 p0, dvec3 p1, dvec3 p2, dvec3 p3, double t) {
    const double u = 1 - t;
    return (u * u * u) * p0 + (3 * u * u * t) * p1 + (3 * u * t * t) * p2 + (t * t * t) * p3;
}

// Slerp of the unit directions of a and b (the exact great-circle formula).
dvec3 slerp_ref(dvec3 a, dvec3 b, double t) {
    const dvec3 ua = unit(a), ub = unit(b);
    const double theta = std::acos(std::fmax(-1.0, std::fmin(1.0, dot(ua, ub))));
    if (theta < 1e-12) return ua;
    return (std::sin((1 - t) * theta) / std::sin(theta)) * ua + (std::sin(t * theta) / std::sin(theta)) * ub;
}

}  // namespace

// ---- clock face: canvas_create / canvas_clear(c) / canvas_save_pgm / canvas_destroy -------------

TEST(clock_face_image_equals_primary_api_and_hand_computed_pixels) {
    scratch_dir dir;
    const program_run r = run_program("clock_face", dir);
    CHECK_MSG(single_row(r, "failed_save", 1) == std::vector<double>{-1},
              "canvas_save_pgm must return -1 for a path in a missing folder");
    CHECK(!fs::exists(dir.path / "no_such_folder"));

    const gray_image img = read_image(dir.file("clock_face.pgm"));
    CHECK_EQ(img.width, 400);
    CHECK_EQ(img.height, 400);
    if (img.width != 400 || img.height != 400) return;

    // The same drawing through the report's names.
    canvas_t *expected = create_canvas(400, 400);
    CHECK(expected != nullptr);
    if (!expected) return;
    const float cx = 200.0f, cy = 200.0f;
    for (int angle = 0; angle < 360; angle += 15) {
        const float rad = float(angle * M_PI / 180.0f);
        draw_line_f(expected, cx, cy, cx + 180.0f * std::cos(rad), cy + 180.0f * std::sin(rad), 1.5f);
    }
    CHECK_EQ(differing_pixels(img, *expected), 0);
    destroy_canvas(expected);

    // Hand-computed, in the report's convention (integer coordinates are pixel centres):
    // the 0° spoke runs along y = 200, the centre of row 200. Thickness 1.5 puts its disc
    // samples at y = 199.75 and 200.25 (kx, ky = ±0.25; ±0.75 fails kx² + ky² ≤ 0.5625);
    // each splats 0.75 onto row 200 and 0.25 onto row 199 or 201. Per pixel of length that
    // is 2 samples × 2 x offsets = 4 units of x weight: row 200 gets 6 (saturates), rows 199
    // and 201 get 4 × 0.25 = 1 (full, to float rounding); rows 198 and 202 nothing.
    // Columns 240..370 are > 10 px from the 15° and 345° spokes.
    for (int x = 240; x <= 370; ++x) {
        CHECK_EQ(img.at(x, 200), 255);
        CHECK(img.at(x, 199) >= 254);
        CHECK(img.at(x, 201) >= 254);
        CHECK_EQ(img.at(x, 198), 0);
        CHECK_EQ(img.at(x, 202), 0);
    }
    // Its end at x = 380 exactly: the last splats at x = 380 ± 0.25 reach columns 379..381.
    CHECK(img.at(381, 200) > 0);
    CHECK_EQ(img.at(382, 200), 0);
    CHECK_EQ(img.at(200, 200), 255);  // every spoke starts at the centre
    // Nothing beyond radius 180 + 0.75 (disc) + 1 (splat) + 1 (slack), pixel centres on integers.
    int ink_outside = 0;
    for (int y = 0; y < 400; ++y)
        for (int x = 0; x < 400; ++x)
            if (std::hypot(x - 200.0, y - 200.0) > 182.75 + 1.0) ink_outside += img.at(x, y) != 0;
    CHECK_EQ(ink_outside, 0);
}

// ---- rotating cube: mat4_mul / mat4_mul_vec3 / mat4_transform_vec3 ----------------------------

namespace {
constexpr int kCubeFrames = 8;
constexpr int kCubeSize = 128;
const std::array<dvec3, 8> kCube = {{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                     {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}};
const int kCubeEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                               {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
}  // namespace

TEST(rotating_cube_vertices_match_double_projection) {
    scratch_dir dir;
    const program_run r = run_program("rotating_cube", dir);
    CHECK_MSG(single_row(r, "transform_forms_agree", 1) == std::vector<double>{1},
              "mat4_mul_vec3 and mat4_transform_vec3 must give the same bits");
    const auto rows = rows_of(r, "vertex", 5);
    CHECK_EQ(rows.size(), std::size_t(kCubeFrames * 8));
    // glFrustum(−1, 1, −1, 1, 1, 10): x_ndc = x/−z, y_ndc = y/−z,
    // z_ndc = (−(f+n)/(f−n)·z − 2fn/(f−n)) / −z with n = 1, f = 10.
    const double n = 1, f = 10;
    for (const auto &row : rows) {
        const int frame = int(row[0]), i = int(row[1]);
        const double angle = double(float(frame * 2 * M_PI / kCubeFrames));  // the program's float angle
        dvec3 p = rotate_y(kCube[std::size_t(i)], angle);
        p.z -= 5;
        const double xn = p.x / -p.z, yn = p.y / -p.z;
        const double zn = (-(f + n) / (f - n) * p.z - 2 * f * n / (f - n)) / -p.z;
        CHECK_NEAR(row[2], (xn + 1) * 0.5 * kCubeSize, 1e-3);
        CHECK_NEAR(row[3], (1 - (yn + 1) * 0.5) * kCubeSize, 1e-3);
        CHECK_NEAR(row[4], zn, 1e-5);
    }
}

TEST(rotating_cube_image_equals_primary_api) {
    scratch_dir dir;
    const program_run r = run_program("rotating_cube", dir);
    const gray_image img = read_image(dir.file("rotating_cube.pgm"));
    canvas_t *expected = create_canvas(kCubeSize, kCubeSize);
    CHECK(expected != nullptr);
    if (!expected) return;
    const float angle = float(1 * 2 * M_PI / kCubeFrames);  // frame 1
    const mat4_t model = mat4_multiply(mat4_translate(0, 0, -5.0f),
                                       mat4_multiply(mat4_rotate_xyz(0, angle, 0), mat4_scale(1, 1, 1)));
    const mat4_t mvp = mat4_multiply(mat4_frustum_asymmetric(-1, 1, -1, 1, 1, 10), mat4_multiply(mat4_identity(), model));
    vec3_t screen[8];
    for (int i = 0; i < 8; ++i) {
        const dvec3 c = kCube[std::size_t(i)];
        const vec3_t ndc = apply_transform(mvp, {float(c.x), float(c.y), float(c.z)});
        screen[i] = {(ndc.x + 1) * 0.5f * kCubeSize, (1 - (ndc.y + 1) * 0.5f) * kCubeSize, ndc.z};
    }
    for (const auto &e : kCubeEdges)
        draw_line_f(expected, screen[e[0]].x, screen[e[0]].y, screen[e[1]].x, screen[e[1]].y, 1.2f);
    CHECK_EQ(differing_pixels(img, *expected), 0);
    destroy_canvas(expected);
}

// ---- spherical / slerp printout ------------------------------------------------------------------

TEST(spherical_and_slerp_printout_matches_double_formulas) {
    scratch_dir dir;
    const program_run r = run_program("spherical_slerp", dir);

    // x = r sinφ cosθ, y = r sinφ sinθ, z = r cosφ (θ azimuth, φ polar: the report's).
    const auto from = rows_of(r, "from_spherical", 6);
    CHECK_EQ(from.size(), std::size_t(5));
    for (const auto &v : from) {
        const double rr = v[0], th = v[1], ph = v[2], tol = kFloatTolerance * std::fmax(1.0, std::fabs(rr));
        check_near3(v, 3, {rr * std::sin(ph) * std::cos(th), rr * std::sin(ph) * std::sin(th), rr * std::cos(ph)}, tol);
    }

    const auto to = rows_of(r, "to_spherical", 6);
    CHECK_EQ(to.size(), std::size_t(4));
    for (const auto &v : to) {
        const dvec3 p = row3(v, 0);
        CHECK_NEAR(v[3], std::sqrt(dot(p, p)), kFloatTolerance * std::sqrt(dot(p, p)));
        CHECK_NEAR(v[4], std::atan2(p.y, p.x), kFloatTolerance);
        CHECK_NEAR(v[5], std::atan2(std::hypot(p.x, p.y), p.z), kFloatTolerance);
    }

    if (const auto v = single_row(r, "normalize_fast", 6); !v.empty())
        check_near3(v, 3, unit(row3(v, 0)), kQuakeTolerance);  // (3, 4, 12) / 13

    const auto slerps = rows_of(r, "slerp", 10);
    CHECK_EQ(slerps.size(), std::size_t(10));
    for (const auto &v : slerps) {
        check_near3(v, 7, slerp_ref(row3(v, 0), row3(v, 3), v[6]), kQuakeTolerance);
    }
}

// ---- lit Bezier animation -------------------------------------------------------------------------

namespace {
const dvec3 kP0 = {-1, -1, 0}, kP1 = {-2.5, 2.5, 0}, kP2 = {2.5, 2.5, 0}, kP3 = kP0;
constexpr int kBezierFrames = 24;
constexpr double kBezierSize = 200, kBezierScale = 70;
constexpr double kLightIntensity = 0.8;
const dvec3 kLightDirection = {1, 1, 0.5};
}  // namespace

TEST(lit_bezier_positions_and_edge_lighting_match_double) {
    for (const std::string &program : c_and_cxx_builds("lit_bezier")) {
        scratch_dir dir;
        const program_run r = run_program(program, dir);
        const auto frames = rows_of(r, "frame", 5);
        CHECK_EQ(frames.size(), std::size_t(kBezierFrames + 1));
        for (const auto &v : frames) {
            check_near3(v, 2, bezier_ref(kP0, kP1, kP2, kP3, v[1]), kFloatTolerance * 4);
        }
        // The loop closes exactly: B(1) = p3 = p0 = B(0).
        if (frames.size() == std::size_t(kBezierFrames + 1)) {
            CHECK_EQ(frames.front()[2], frames.back()[2]);
            CHECK_EQ(frames.front()[3], frames.back()[3]);
        }

        // Lit edge = intensity · clamp01(unit(b − a) · unit(L)) (the report's per-edge Lambert).
        const auto edges = rows_of(r, "edge", 9);
        CHECK_EQ(edges.size(), std::size_t(4 * (kBezierFrames + 1)));
        int lit = 0, dark = 0;
        for (const auto &v : edges) {
            const double cosine = dot(unit(row3(v, 5) - row3(v, 2)), unit(kLightDirection));
            const double expected = kLightIntensity * std::fmin(1.0, std::fmax(0.0, cosine));
            CHECK_NEAR(v[8], expected, kFloatTolerance);
            (expected > 0 ? lit : dark) += 1;
        }
        CHECK(lit > 0 && dark > 0);  // both branches of the clamp are exercised
    }
}

TEST(lit_bezier_image_stays_in_the_circular_viewport) {
    for (const std::string &program : c_and_cxx_builds("lit_bezier")) {
        scratch_dir dir;
        const program_run r = run_program(program, dir);
        const gray_image img = read_image(dir.file("lit_bezier.pgm"));
        CHECK_EQ(img.width, int(kBezierSize));
        if (img.width != int(kBezierSize)) return;
        const double centre = kBezierSize / 2, radius = kBezierSize / 2;
        // Segments join points inside the circle (convex), 1.5 px thick, splats reach 1 px more.
        const double reach = 0.75 + 1.0 + 0.71;  // + half a pixel diagonal (pixel centres)
        int ink_outside = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x)
                if (std::hypot(x + 0.5 - centre, y + 0.5 - centre) > radius + reach) ink_outside += img.at(x, y) != 0;
        CHECK_EQ(ink_outside, 0);

        // Every frame position well inside the circle is inked (its own splat puts ≥ 1/4 there);
        // some positions are outside, so the viewport test above is not vacuous.
        int outside = 0;
        for (int k = 0; k <= kBezierFrames; ++k) {
            const dvec3 p = bezier_ref(kP0, kP1, kP2, kP3, double(k) / kBezierFrames);
            const double sx = centre + kBezierScale * p.x, sy = centre - kBezierScale * p.y;
            const double d = std::hypot(sx - centre, sy - centre);
            if (d > radius) ++outside;
            if (d < radius - 1) CHECK_MSG(img.at(int(sx), int(sy)) > 0, "frame " + std::to_string(k));
        }
        CHECK(outside >= 3);
    }
}

// ---- a program with its own vec3_normalize & co. ----------------------------------------------------

TEST(own_helpers_program_compiles_and_reads_pixels_directly) {
    for (const std::string &program : c_and_cxx_builds("own_helpers")) {
        scratch_dir dir;
        const program_run r = run_program(program, dir);
        if (const auto v = single_row(r, "own_normalize", 6); !v.empty()) check_near3(v, 3, {0.6, 0.8, 0}, 1e-7);
        // Its own normalize leaves vectors shorter than 1e-6 alone (the library's would give
        // (1, 0, 0)), and its own save writes ASCII P2 (the library's: binary P5).
        if (const auto v = single_row(r, "own_normalize_tiny", 3); !v.empty())
            CHECK(float(v[0]) == 1e-7f && v[1] == 0 && v[2] == 0);  // %.9g round-trips a float
        CHECK(single_row(r, "own_cross", 9) == (std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, 1}));
        CHECK(single_row(r, "own_dot", 7) == (std::vector<double>{1, 2, 3, 4, 5, 6, 32}));
        CHECK(single_row(r, "own_add_scale", 3) == (std::vector<double>{2.5, 2, 1}));
        if (const auto v = single_row(r, "library_normalize_fast", 6); !v.empty())
            check_near3(v, 3, {0.6, 0.8, 0}, kQuakeTolerance);

        // The program's own P2 writer: set_pixel_f at a pixel centre (integer coordinates, the
        // report's convention) lands on that pixel only,
        // so row 3 holds (int)(x/15·255 + 0.5) and every other row 0.
        CHECK(file_bytes(dir.file("own_helpers.pgm")).rfind("P2\n16 8\n255\n", 0) == 0);
        const gray_image img = read_image(dir.file("own_helpers.pgm"));
        CHECK_EQ(img.width, 16);
        CHECK_EQ(img.height, 8);
        if (img.width != 16 || img.height != 8) return;
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 16; ++x) CHECK_EQ(img.at(x, y), y == 3 ? int(x / 15.0f * 255 + 0.5f) : 0);
    }
}

// ---- the opt-in header --------------------------------------------------------------------------------

TEST(compat_header_program_matches_double_and_saves_identical_files) {
    scratch_dir dir;
    const program_run r = run_program("compat_header", dir);

    // model = T(1, 2, 3) · Rz(0.3)·Ry(0.2)·Rx(0.1) · S(2): the point (1, 1, 1).
    if (const auto v = single_row(r, "model_point", 6); !v.empty())
        check_near3(v, 3, rotate_z(rotate_y(rotate_x({2, 2, 2}, double(0.1f)), double(0.2f)), double(0.3f)) + dvec3{1, 2, 3},
                    1e-5);
    const auto model = single_row(r, "model", 16);
    CHECK(!model.empty() && model == single_row(r, "identity_times_model", 16));

    // glFrustum(l, r, b, t, n, f) = (−1, 2, −0.5, 1.5, 1, 20), column-major.
    const double l = -1, rr = 2, b = -0.5, t = 1.5, n = 1, f = 20;
    std::array<double, 16> expected{};
    expected[0] = 2 * n / (rr - l);
    expected[5] = 2 * n / (t - b);
    expected[8] = (rr + l) / (rr - l);
    expected[9] = (t + b) / (t - b);
    expected[10] = -(f + n) / (f - n);
    expected[11] = -1;
    expected[14] = -2 * f * n / (f - n);
    for (const char *name : {"frustum", "frustum_out"}) {
        const auto m = single_row(r, name, 16);
        for (std::size_t i = 0; i < m.size(); ++i) CHECK_NEAR(m[i], expected[i], kFloatTolerance);
    }

    if (const auto v = single_row(r, "slerp_mid", 3); !v.empty())
        check_near3(v, 0, {std::sqrt(0.5), std::sqrt(0.5), 0}, kQuakeTolerance);
    CHECK(single_row(r, "update_spherical_unchanged", 1) == std::vector<double>{1});
    CHECK(single_row(r, "failed_save", 1) == std::vector<double>{-1});

    // The four save names write the same bytes. The 7-argument line (2, 10)–(30, 10) of
    // thickness 1 and intensity 0.5 is in the report's coordinates (pixel centres on
    // integers): in the canvas's it runs along y = 10.5 from x = 2.5 to 30.5 with round caps
    // of radius 0.5, covering row 10 (y in [10, 11)) completely from x = 2.5 to 30.5. So
    // columns 3..29 hold 0.5 → 127.5 before rounding, the caps end at x = 2 and 31 (columns
    // 0 and 31 stay empty), rows 9 and 11 get nothing.
    const auto saves = rows_of(r, "save", 1);
    CHECK_EQ(saves.size(), std::size_t(4));
    for (const auto &s : saves) CHECK(s == std::vector<double>{0});
    const std::string first = file_bytes(dir.file("compat_save_canvas_as_pgm.pgm"));
    CHECK(!first.empty());
    for (const char *name : {"compat_canvas_save_to_pgm.pgm", "compat_save_canvas_pgm.pgm", "compat_save_canvas_to_pgm.pgm"})
        CHECK_MSG(file_bytes(dir.file(name)) == first, name);
    const gray_image img = read_image(dir.file("compat_save_canvas_as_pgm.pgm"));
    CHECK_EQ(img.width, 32);
    CHECK_EQ(img.height, 20);
    if (img.width != 32 || img.height != 20) return;
    for (int x = 3; x <= 29; ++x) {
        CHECK(std::abs(2 * img.at(x, 10) - 255) <= 1);  // 127 or 128
        CHECK_EQ(img.at(x, 9), 0);
        CHECK_EQ(img.at(x, 11), 0);
    }
    CHECK_EQ(img.at(0, 10), 0);
    CHECK_EQ(img.at(31, 10), 0);
}

// ---- the report's own demo flow, with the report's names ---------------------------------------------

TEST(report_demo_soccer_ball_camera_lighting_match_hand_computed_values) {
    for (const std::string &program : c_and_cxx_builds("report_demo")) {
        scratch_dir dir;
        const program_run r = run_program(program, dir);
        CHECK(single_row(r, "soccer_counts", 2) == (std::vector<double>{60, 90}));
        // A truncated icosahedron of circumradius R has edge a = 4R / √(58 + 18√5) (R ≈ 2.478 a).
        const double edge = 4.0 / std::sqrt(58.0 + 18.0 * std::sqrt(5.0));
        for (double v : single_row(r, "soccer_radius", 2)) CHECK_NEAR(v, 1.0, kFloatTolerance);
        for (double v : single_row(r, "soccer_edge", 2)) CHECK_NEAR(v, edge, kFloatTolerance);
        // glFrustum(−1, 1, −1, 1, 1, 10) at z = −2.5: NDC z = ((f+n)/(f−n)·2.5 − 2fn/(f−n)) / 2.5 = 1/3.
        if (const auto v = single_row(r, "centre_ndc", 3); !v.empty()) check_near3(v, 0, {0, 0, 1.0 / 3.0}, kFloatTolerance);

        // The ball (radius 1, centre 2.5 in front of the camera) projects inside the circle of
        // NDC radius tan(asin(R/d)) = R/√(d² − R²) around the canvas centre; its silhouette
        // vertices lie on the sphere, so ink reaches that circle to within a few pixels.
        const gray_image img = read_image(dir.file("report_soccer.pgm"));
        CHECK_EQ(img.width, 200);
        if (img.width != 200 || img.height != 200) return;
        const double silhouette_px = 100.0 / std::sqrt(2.5 * 2.5 - 1.0);
        const double reach = 0.5 + 1.0 + 0.71;  // disc of thickness 1, splat, pixel-centre slack
        double farthest_ink = 0;
        for (int y = 0; y < 200; ++y)
            for (int x = 0; x < 200; ++x)
                if (img.at(x, y) != 0) farthest_ink = std::fmax(farthest_ink, std::hypot(x + 0.5 - 100, y + 0.5 - 100));
        CHECK(farthest_ink <= silhouette_px + reach);
        CHECK(farthest_ink >= silhouette_px - 3.0);

        if (const auto v = single_row(r, "light", 6); !v.empty()) {
            check_near3(v, 0, {std::sin(double(0.25f)), 0, std::cos(double(0.25f))}, kFloatTolerance);
            check_near3(v, 3, {1, 0, 0.25}, kFloatTolerance);
        }
        const dvec3 light = {std::sin(double(0.25f)), 0, std::cos(double(0.25f))};
        const auto lit = rows_of(r, "lit_edge", 8);
        CHECK_EQ(lit.size(), std::size_t(5));
        for (const auto &v : lit)  // Lambert of an edge does not depend on where it has moved
            CHECK_NEAR(v[7], std::fmax(0.0, dot(unit(row3(v, 4) - row3(v, 1)), light)), kFloatTolerance);
        const auto path = rows_of(r, "bezier", 4);
        CHECK_EQ(path.size(), std::size_t(5));
        for (const auto &v : path) check_near3(v, 1, bezier_ref({0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, 0}, v[0]), kFloatTolerance * 4);
        if (const auto v = single_row(r, "normalize_slerp", 6); !v.empty()) {
            check_near3(v, 0, {0, 0, 1}, kQuakeTolerance);
            check_near3(v, 3, {std::sqrt(0.5), 0, std::sqrt(0.5)}, kQuakeTolerance);
        }
    }
}

// ---- in-process: the aliases are the primary functions, and literals resolve -------------------------

TEST(aliases_agree_with_the_primary_functions) {
    const mat4_t a = mat4_rotate_xyz(0.3f, -1.1f, 2.0f), b = mat4_translate(1, -2, 3.5f);
    const mat4_t ab = mat4_multiply(a, b), ab_alias = mat4_mul(a, b);
    CHECK(std::memcmp(&ab, &ab_alias, sizeof ab) == 0);
    const mat4_t proj = mat4_frustum_asymmetric(-1, 1, -1, 1, 1, 10);
    const vec3_t p = {0.25f, -0.5f, -3.0f};
    const vec3_t q = apply_transform(proj, p), q1 = mat4_mul_vec3(proj, p), q2 = mat4_transform_vec3(proj, p);
    CHECK(q == q1 && q == q2);
    // "divide by w": w = 3 here, so NDC x = (1·0.25)/3.
    CHECK_NEAR(q1.x, 0.25 / 3.0, kFloatTolerance);
    const vec3 v = vec3_from_cartesian(1, 2.5, -3);  // int and double literals
    CHECK(v == (vec3_t{1.0f, 2.5f, -3.0f}));
    const vec3_t b0 = {0, 0, 0}, b1 = {1, 2, 0}, b2 = {3, -1, 1}, b3 = {4, 0, 2};
    for (float t : {0.0f, 0.3f, 1.0f}) CHECK(bezier(b0, b1, b2, b3, t) == vec3_bezier(b0, b1, b2, b3, t));

    canvas_t *c = canvas_create(4, 3);
    CHECK(c != nullptr);
    if (!c) return;
    clear_canvas(c, 2);  // clamps to 1
    CHECK_EQ(c->pixels[2][3], 1.0f);
    canvas_clear(c, 0.25);
    CHECK_EQ(c->pixels[1][1], 0.25f);
    canvas_clear(c);
    CHECK_EQ(c->pixels[0][0], 0.0f);
    CHECK_EQ(canvas_save_pgm(nullptr, "/tmp/never.pgm"), -1);
    CHECK_EQ(canvas_save_pgm(c, nullptr), -1);
    canvas_free(c);
    free_canvas(nullptr);  // null pointers are ignored by every destroy name
    canvas_destroy(nullptr);
    canvas_free(nullptr);
    destroy_canvas(nullptr);
}

TEST(int_and_double_literals_resolve_to_the_float_functions) {
    // Each call below would fail to compile if an overload made it ambiguous.
    canvas_t *c = create_canvas(20, 20);
    CHECK(c != nullptr);
    if (!c) return;
    set_pixel_f(c, 10, 10.5, 1);
    draw_line_f(c, 0, 0, 19, 19.0, 1);
    CHECK(clip_to_circular_viewport(c, 10, 10));
    CHECK(clip_to_circular_viewport(c, 10.5, 10));
    CHECK(!clip_to_circular_viewport(c, 0, 0));
    const vec3_t s = vec3_from_spherical(2, 0, M_PI / 2);  // (2, 0, 0)
    CHECK_NEAR(s.x, 2.0, kFloatTolerance);
    const vec3_t sl = vec3_slerp(vec3_t{1, 0, 0}, vec3_t{0, 1, 0}, 1);
    CHECK_NEAR(sl.y, 1.0, kQuakeTolerance);
    vec3_t n = {0, 3, 4};
    vec3_normalize_fast(&n);
    CHECK_NEAR(n.z, 0.8, kQuakeTolerance);
    const mat4_t m = mat4_mul(mat4_scale(2, 2.0, 2), mat4_rotate_xyz(0, M_PI, 0.0));
    CHECK_NEAR(m.m[0], -2.0, 1e-6);  // 2·cos π
    CHECK_NEAR(lambert_intensity(vec3_t{0, 0, 0}, vec3_t{1, 0, 0}, vec3_t{1, 0, 0}), 1.0, kFloatTolerance);
    const light_t light = {{0, 0, 1}, 1};
    CHECK_EQ(light.intensity, 1.0f);
    float x = -1, y = -1;
    CHECK_EQ(project_vertex(vec3_t{0, 0, -2}, mat4_identity(), mat4_frustum_asymmetric(-1, 1, -1, 1, 1, 10), 20, 20, &x, &y), 1);
    CHECK_NEAR(x, 9.5, 1e-4);  // the report's viewport: NDC 0 → (20 − 1)/2
    CHECK_NEAR(y, 9.5, 1e-4);
    clear_canvas(c, 0);
    canvas_destroy(c);
}
