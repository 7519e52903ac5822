// hostile_test.cpp — hostile inputs to the loaders, the canvas, the math and the renderers.
// Runs plain and under ASan + UBSan (`make test`). Every case asserts the outcome the
// headers promise — an error with a reason, an unchanged canvas, finite values in range —
// never just "it did not crash".
//
// Loader limits are checked with the replaced operator new of alloc_tracker.h: a header
// announcing more data than a small file holds must fail before any large allocation.
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "alloc_tracker.h"
#include "harness.h"
#include "temp_folder.h"
#include "tiny3d.h"

namespace {

constexpr float NaN = std::numeric_limits<float>::quiet_NaN();
constexpr float INF = std::numeric_limits<float>::infinity();
constexpr float HUGE_COORD = 1e30f;
constexpr float DENORMAL = 1e-40f;
// A parse of a tiny hostile file may allocate strings and small vectors, never anything
// near what its header announces.
constexpr std::size_t SMALL_ALLOCATION = 1 << 16;
constexpr int SIDE = 32;  // px, the test canvases

tiny3d::canvas_ptr blank(int side = SIDE) { return std::move(tiny3d::make_canvas(side, side).value()); }

// Sum of the canvas, and whether every pixel is in 0..1.
double ink(const canvas_t &c) {
    double s = 0;
    for (int i = 0; i < c.width * c.height; ++i) s += c.data[i];
    return s;
}
bool all_in_range(const canvas_t &c) {
    for (int i = 0; i < c.width * c.height; ++i)
        if (!(c.data[i] >= 0.0f && c.data[i] <= 1.0f)) return false;
    return true;
}
bool same_pixels(const canvas_t &a, const canvas_t &b) {
    for (int i = 0; i < a.width * a.height; ++i)
        if (a.data[i] != b.data[i]) return false;
    return true;
}
bool finite3(vec3_t v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
double len(vec3_t v) { return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z); }

using alloc_tracker::largest_allocation_during;

// The perspective used by the renderer cases: 90° vertical field of view, near 1, far 100.
mat4_t projection() { return tiny3d::mat4_perspective(float(M_PI / 2), 1.0f, 1.0f, 100.0f); }
constexpr float NEAR_PLANE = 1.0f;

}  // namespace

// ---- loader limits ------------------------------------------------------------------

TEST(ply_header_announcing_2_pow_40_vertices_fails_without_allocating) {
    const std::string ply =
        "ply\nformat binary_little_endian 1.0\nelement vertex 1099511627776\nproperty float x\n"
        "property float y\nproperty float z\nend_header\n0123456789";
    tiny3d::result<tiny3d::mesh> r = tiny3d::error{};
    const std::size_t biggest = largest_allocation_during([&] { r = tiny3d::parse_ply(ply, "big.ply"); });
    CHECK(!r.ok());
    if (!r.ok()) {
        CHECK_EQ(r.err().file, std::string("big.ply"));
        CHECK_EQ(r.err().line, 3L);  // the element line
    }
    CHECK_MSG(biggest < SMALL_ALLOCATION, std::to_string(biggest) + " bytes allocated");
}

TEST(ply_counts_whose_products_overflow_are_errors) {
    // 2^62 entries of 8 bytes: count × size wraps 64 bits; 2^63 − 1 faces; a list of 2^32 − 1.
    const char *headers[] = {
        "ply\nformat binary_little_endian 1.0\nelement vertex 4611686018427387904\nproperty double x\n"
        "property double y\nproperty double z\nend_header\n",
        "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 9223372036854775807\nproperty list uchar int vertex_indices\nend_header\n",
        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
        "element junk 3074457345618258603\nproperty uchar a\nproperty uchar b\nproperty uchar c\nend_header\n",
        "ply\nformat ascii 1.0\nelement vertex 99999999999999999999\nproperty float x\nend_header\n",
        "ply\nformat ascii 1.0\nelement vertex -5\nproperty float x\nend_header\n",
    };
    for (const char *h : headers) {
        tiny3d::result<tiny3d::mesh> r = tiny3d::error{};
        const std::size_t biggest = largest_allocation_during([&] { r = tiny3d::parse_ply(std::string(h) + "0 0 0\n"); });
        CHECK_MSG(!r.ok(), h);
        CHECK_MSG(biggest < SMALL_ALLOCATION, std::to_string(biggest) + " bytes for " + h);
    }
    // A binary list announcing 2^32 − 1 indices in a 1-face file.
    std::string ply =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n";
    ply.append(36, '\0');               // three zero vertices
    ply.append("\xff\xff\xff\xff", 4);  // list length 2^32 − 1
    ply.append(12, '\0');
    tiny3d::result<tiny3d::mesh> r = tiny3d::error{};
    const std::size_t biggest = largest_allocation_during([&] { r = tiny3d::parse_ply(ply, "list.ply"); });
    CHECK(!r.ok());
    if (!r.ok()) CHECK_MSG(r.err().byte_offset > 0, r.message());
    CHECK_MSG(biggest < SMALL_ALLOCATION, std::to_string(biggest));
}

TEST(obj_indices_beyond_64_bits_and_out_of_range_are_errors) {
    const char *bad[] = {
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9223372036854775807\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9223372036854775808\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999999\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/9 2 3\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n",
        "v 0 0 nan\n",
        "v 0 0 1e39\n",
        "v 0 0 inf\nf 1 1 1\n",
    };
    for (const char *text : bad) {
        const tiny3d::result<tiny3d::mesh> r = tiny3d::parse_obj(text, "bad.obj");
        CHECK_MSG(!r.ok(), text);
        if (!r.ok()) CHECK_MSG(r.err().file == "bad.obj" && r.err().line >= 1, r.message());
    }
}

TEST(pgm_headers_beyond_limits_fail_before_allocating) {
    temp_folder tmp;
    struct bad_file {
        const char *leaf;
        std::string bytes;
    };
    const bad_file cases[] = {
        {"huge.pgm", "P5\n16384 16384\n255\n" + std::string(20, 'x')},  // legal size, 20 bytes of data
        {"toobig.pgm", "P5\n40000 10\n255\n0"},                          // side > CANVAS_MAX_SIDE
        {"pixels.pgm", "P5\n32768 32768\n255\n0"},                       // 2^30 pixels > 2^28
        {"overflow.pgm", "P2\n4294967297 1\n255\n0"},                    // 2^32 + 1 wraps 32 bits
        {"maxval0.pgm", "P2\n1 1\n0\n0\n"},
        {"maxval.pgm", "P5\n1 1\n65536\n00"},
        {"zero.pgm", "P5\n0 7\n255\n"},
        {"ascii.pgm", "P2\n16000 16000\n255\n1 2 3\n"},
        {"sample.pgm", "P2\n1 1\n7\n8\n"},
    };
    for (const bad_file &c : cases) {
        const std::string path = tmp.file(c.leaf, c.bytes);
        tiny3d::result<tiny3d::canvas_ptr> r = tiny3d::error{};
        const std::size_t biggest = largest_allocation_during([&] { r = tiny3d::load_pgm(path); });
        CHECK_MSG(!r.ok(), c.leaf);
        if (!r.ok()) CHECK_MSG(r.err().file == path && !r.err().reason.empty(), r.message());
        CHECK_MSG(biggest < SMALL_ALLOCATION, std::string(c.leaf) + ": " + std::to_string(biggest) + " bytes");
    }
}

// ---- canvas -------------------------------------------------------------------------

TEST(canvas_sizes_zero_negative_and_beyond_the_limit_are_refused) {
    const int bad[][2] = {{0, 5},
                          {5, 0},
                          {-3, 4},
                          {4, -3},
                          {std::numeric_limits<int>::min(), 1},
                          {CANVAS_MAX_SIDE + 1, 1},
                          {CANVAS_MAX_SIDE, CANVAS_MAX_SIDE},  // 2^30 pixels > CANVAS_MAX_PIXELS
                          {std::numeric_limits<int>::max(), std::numeric_limits<int>::max()}};
    for (const auto &s : bad) {
        const std::size_t biggest = largest_allocation_during([&] { CHECK(create_canvas(s[0], s[1]) == nullptr); });
        CHECK(biggest < SMALL_ALLOCATION);
        CHECK(!tiny3d::check_canvas_size(s[0], s[1]).ok());
        const tiny3d::result<tiny3d::canvas_ptr> r = tiny3d::make_canvas(s[0], s[1]);
        CHECK(!r.ok());
        if (!r.ok()) CHECK(!r.err().reason.empty());
    }
    // The largest legal canvas is accepted by the check (not allocated here).
    CHECK(tiny3d::check_canvas_size(CANVAS_MAX_SIDE, int(CANVAS_MAX_PIXELS / CANVAS_MAX_SIDE)).ok());
    destroy_canvas(nullptr);  // documented no-op
}

TEST(lines_of_thickness_zero_negative_nan_draw_nothing) {
    tiny3d::canvas_ptr c = blank();
    for (float t : {0.0f, -1.0f, -INF, NaN}) {
        draw_line_f(c.get(), 2, 2, 30, 20, t);
        tiny3d::draw_line_coverage(c.get(), 2, 2, 30, 20, t);
    }
    CHECK_EQ(ink(*c), 0.0);
}

TEST(non_finite_points_and_lines_draw_nothing) {
    tiny3d::canvas_ptr c = blank();
    for (float bad : {NaN, INF, -INF}) {
        set_pixel_f(c.get(), bad, 3, 1);
        set_pixel_f(c.get(), 3, bad, 1);
        set_pixel_f(c.get(), 3, 3, bad);
        draw_line_f(c.get(), bad, 3, 10, 10, 1.5f);
        draw_line_f(c.get(), 3, 3, 10, bad, 1.5f);
        tiny3d::draw_line_coverage(c.get(), 3, bad, 10, 10, 2.0f);
        tiny3d::draw_line_wu(c.get(), bad, 3, 10, 10);
    }
    CHECK_EQ(ink(*c), 0.0);
    draw_line_f(nullptr, 0, 0, 5, 5, 1);  // null canvas: ignored
    set_pixel_f(nullptr, 1, 1, 1);
}

TEST(lines_with_coordinates_of_1e30_match_the_clipped_line) {
    // A horizontal line from x = −1e30 to 1e30 at y = 10.5 is, on the canvas, the line across
    // it: the same pixels as the one from x = −5 to SIDE + 5, all finite and in 0..1.
    tiny3d::canvas_ptr huge = blank(), ref = blank();
    tiny3d::draw_line_coverage(huge.get(), -HUGE_COORD, 10.5f, HUGE_COORD, 10.5f, 2.0f);
    tiny3d::draw_line_coverage(ref.get(), -5.0f, 10.5f, SIDE + 5.0f, 10.5f, 2.0f);
    CHECK(all_in_range(*huge));
    for (int x = 0; x < SIDE; ++x) {
        CHECK_NEAR(huge->pixels[10][x], 1.0, 1e-5);       // the row the line covers
        CHECK_NEAR(huge->pixels[9][x], 0.5, 1e-4);        // half-covered rows either side
        CHECK_NEAR(huge->pixels[3][x], 0.0, 0.0);
    }
    CHECK(same_pixels(*huge, *ref));
    tiny3d::canvas_ptr faithful = blank();
    draw_line_f(faithful.get(), -HUGE_COORD, 10.5f, HUGE_COORD, 10.5f, 1.5f);
    CHECK(all_in_range(*faithful));
    CHECK(faithful->pixels[10][SIDE / 2] > 0.5f);
    CHECK_EQ(faithful->pixels[0][SIDE / 2], 0.0f);
}

TEST(lines_mixing_extreme_and_tiny_coordinates_stay_in_range) {
    // Found by a stress run: from (−1.97e30, −3.4e38) to (−1e-30, 1e20) the line passes
    // ~5.8e11 px beside the canvas, but the clip parameters round to 1 and Liang–Barsky
    // accepted it; the clipped end then fed a float→int conversion out of range. It must
    // draw nothing, like the reference.
    {
        tiny3d::canvas_ptr c = tiny3d::make_canvas(42, 37).value();
        const float x0 = -0x1.93e594p+99f, y0 = -0x1.ff933cp+127f, x1 = -0x1.4484cp-100f, y1 = 0x1.5af1d8p+66f;
        tiny3d::draw_line_coverage(c.get(), x0, y0, x1, y1, 6.0f);
        std::vector<double> ref;
        tiny3d::line_coverage_reference(ref, 42, 37, x0, y0, x1, y1, 6.0);
        double ink = 0.0, ref_ink = 0.0;
        for (int i = 0; i < 42 * 37; ++i) {
            ink += c->data[i];
            ref_ink += ref[std::size_t(i)];
        }
        CHECK_EQ(ink, 0.0);
        CHECK_EQ(ref_ink, 0.0);
    }
    // Seeded mixes of ±3.4e38, 1e30, 2^31, 2^24, denormals, zeros and ordinary values for
    // the ends and the thickness, both caps: every pixel stays finite and in 0..1.
    const float specials[] = {0.0f,  1e-40f, 1e-30f, 0.5f, 3.0f,  1e3f,   1e6f,        1e9f,
                              1e20f, 1e30f,  3.4e38f, 16777216.0f, 16777217.0f, 2147483648.0f};
    std::mt19937 rng(77u);
    std::uniform_real_distribution<float> ordinary(-40.0f, 80.0f);
    bool in_range = true;
    for (int k = 0; k < 20000 && in_range; ++k) {
        float v[5];
        for (float &x : v)
            x = rng() % 3 == 0 ? specials[rng() % std::size(specials)] * (rng() % 2 ? 1.0f : -1.0f) : ordinary(rng);
        const float thickness = rng() % 2 ? std::fabs(v[4]) : float(rng() % 1000) / 100.0f;
        tiny3d::canvas_ptr c = tiny3d::make_canvas(1 + int(rng() % 40), 1 + int(rng() % 40)).value();
        const tiny3d::line_style style{rng() % 3 ? tiny3d::line_cap::round : tiny3d::line_cap::butt, 1.0f};
        tiny3d::draw_line_coverage(c.get(), v[0], v[1], v[2], v[3], thickness, style);
        in_range = all_in_range(*c);
    }
    CHECK(in_range);
}

TEST(zero_length_lines_are_a_dot_or_nothing) {
    tiny3d::canvas_ptr c = blank();
    tiny3d::draw_line_coverage(c.get(), 10.5f, 10.5f, 10.5f, 10.5f, 2.0f);  // round caps: disc of radius 1
    CHECK(all_in_range(*c));
    CHECK_NEAR(ink(*c), M_PI, 1e-3);  // area of the disc, in pixels
    tiny3d::canvas_ptr butt = blank();
    tiny3d::line_style flat;
    flat.cap = tiny3d::line_cap::butt;
    tiny3d::draw_line_coverage(butt.get(), 10.5f, 10.5f, 10.5f, 10.5f, 2.0f, flat);
    CHECK_NEAR(ink(*butt), 0.0, 1e-6);  // a zero-length rectangle has no area
}

// ---- math ---------------------------------------------------------------------------

TEST(normalize_of_zero_denormal_nan_inf) {
    using fn = vec3_t (*)(vec3_t);
    const fn variants[] = {static_cast<fn>(&vec3_normalize_fast), &tiny3d::vec3_normalize,
                           &tiny3d::vec3_normalize_fast_accurate};
    const double tolerance[] = {2e-3, 1e-7, 3e-7};  // per the header of each variant
    for (int k = 0; k < 3; ++k) {
        const fn f = variants[k];
        CHECK(f({0, 0, 0}) == (vec3_t{0, 0, 0}));
        CHECK(f({-0.0f, 0.0f, -0.0f}) == (vec3_t{0, 0, 0}));
        CHECK(f({NaN, 1, 1}) == (vec3_t{0, 0, 0}));
        const vec3_t d = f({DENORMAL, 0, 0});
        CHECK_NEAR(d.x, 1.0, tolerance[k]);
        CHECK_EQ(d.y, 0.0f);
        const vec3_t dd = f({DENORMAL, -DENORMAL, 0});
        CHECK_NEAR(dd.x, std::sqrt(0.5), tolerance[k]);
        CHECK_NEAR(dd.y, -std::sqrt(0.5), tolerance[k]);
        const vec3_t big = f({std::numeric_limits<float>::max(), std::numeric_limits<float>::max(), 0});
        CHECK_NEAR(big.x, std::sqrt(0.5), tolerance[k]);
        const vec3_t i = f({INF, 5, -INF});
        CHECK_NEAR(i.x, std::sqrt(0.5), tolerance[k]);
        CHECK_NEAR(i.y, 0.0, 0.0);
        CHECK_NEAR(i.z, -std::sqrt(0.5), tolerance[k]);
    }
}

TEST(slerp_of_zero_nan_and_antipodal_vectors) {
    const vec3_t zero{0, 0, 0}, x{1, 0, 0}, y{0, 2, 0};
    for (float t : {0.0f, 0.3f, 1.0f}) {
        // A zero input takes the other input's direction; both zero gives zero.
        const vec3_t a = vec3_slerp(zero, y, t), b = tiny3d::vec3_slerp_robust(zero, y, t);
        CHECK_NEAR(a.x, 0.0, 1e-6);
        CHECK_NEAR(a.y, 1.0, 4e-3);
        CHECK_NEAR(b.x, 0.0, 1e-6);
        CHECK_NEAR(b.y, 2.0 * t, 1e-6);  // length interpolated from 0 to |y| = 2
        CHECK(vec3_slerp(zero, zero, t) == zero);
        CHECK(tiny3d::vec3_slerp_robust(zero, zero, t) == zero);
        CHECK(tiny3d::vec3_slerp_robust({NaN, 0, 0}, x, t) == zero);
        CHECK(tiny3d::vec3_slerp_robust(x, y, NaN) == zero);
        CHECK(finite3(vec3_slerp({NaN, 0, 0}, x, t)));
    }
    // Exactly antipodal: a unit result perpendicular to both at t = 1/2.
    for (const vec3_t &a : {vec3_t{1, 0, 0}, vec3_t{0, 0, -3}, vec3_t{0.6f, 0.8f, 0}}) {
        const vec3_t m = tiny3d::vec3_slerp_robust(a, -a, 0.5f), f = vec3_slerp(a, -a, 0.5f);
        CHECK_NEAR(len(m), len(a), 1e-5 * len(a));
        CHECK_NEAR(tiny3d::vec3_dot(m, a), 0.0, 1e-5 * len(a) * len(a));
        CHECK(finite3(f));
        CHECK_NEAR(len(f), 1.0, 5e-3);
        CHECK_NEAR(tiny3d::vec3_dot(f, a) / len(a), 0.0, 5e-3);
    }
}

TEST(non_finite_and_singular_matrices) {
    mat4_t nan_m = mat4_identity();
    nan_m.m[5] = NaN;
    CHECK(!tiny3d::mat4_inverse(nan_m).ok());
    mat4_t inf_m = mat4_identity();
    inf_m.m[12] = INF;
    CHECK(!tiny3d::mat4_inverse(inf_m).ok());
    CHECK(!tiny3d::mat4_inverse(mat4_scale(1, 0, 1)).ok());
    // Tiny but regular: the scale-free singularity test accepts it.
    CHECK(tiny3d::mat4_inverse(mat4_scale(1e-20f, 1e-20f, 1e-20f)).ok());
    CHECK(!tiny3d::perspective_checked(0.0f, 1.0f, 1.0f, 10.0f).ok());
    CHECK(!tiny3d::perspective_checked(1.0f, 1.0f, 0.0f, 10.0f).ok());
    CHECK(!tiny3d::frustum_checked(-1, 1, -1, 1, NaN, 10).ok());
    CHECK(!tiny3d::frustum_checked(1, 1, -1, 1, 1, 10).ok());
    // Rotation about a zero or non-finite axis: the identity.
    const mat4_t r = tiny3d::mat4_rotate_axis({0, 0, 0}, 1.0f), q = tiny3d::mat4_rotate_axis({NaN, 1, 0}, 1.0f);
    for (int i = 0; i < 16; ++i) {
        CHECK_EQ(r.m[i], mat4_identity().m[i]);
        CHECK_EQ(q.m[i], mat4_identity().m[i]);
    }
}

TEST(normals_and_flat_shading_of_huge_and_tiny_faces) {
    // A right triangle in the x-y plane scaled by s: its normal is +z at every scale. In
    // float the cross products overflow (s ≥ 1e19) or underflow (s ≤ 1e-19) to a "zero"
    // normal; the face is not degenerate, so the normal must survive.
    const light_t light = {{0, 0, 1}, 1.0f};
    const tiny3d::light_rig rig = tiny3d::make_light_rig({&light, 1}, 0.0f).value();
    for (float s : {1.0f, HUGE_COORD, 1e-30f, DENORMAL * 1e6f, 1e38f}) {
        tiny3d::mesh m;
        m.positions = {{0, 0, 0}, {s, 0, 0}, {0, s, 0}};
        m.add_face({0, 1, 2});
        const vec3_t n = tiny3d::mesh_face_normals(m)[0], v = tiny3d::mesh_vertex_normals(m)[2];
        CHECK_MSG(n == (vec3_t{0, 0, 1}), "face normal at scale " + std::to_string(s));
        CHECK_MSG(v == (vec3_t{0, 0, 1}), "vertex normal at scale " + std::to_string(s));
        CHECK_NEAR(tiny3d::shade_flat(rig, m.positions[0], m.positions[1], m.positions[2]), 1.0, 1e-6);
    }
    // A truly degenerate face (collinear) still gets the zero normal.
    tiny3d::mesh line;
    line.positions = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    line.add_face({0, 1, 2});
    CHECK(tiny3d::mesh_face_normals(line)[0] == (vec3_t{0, 0, 0}));
}

// ---- projection and wireframes ----------------------------------------------------

TEST(project_vertex_behind_on_camera_and_nan) {
    const mat4_t id = mat4_identity(), proj = projection();
    float x = -7, y = -7;
    CHECK_EQ(project_vertex({0, 0, 5}, id, proj, SIDE, SIDE, &x, &y), 0);  // behind the camera
    CHECK_EQ(project_vertex({0, 0, 0}, id, proj, SIDE, SIDE, &x, &y), 0);  // at the eye: w = 0
    CHECK_EQ(project_vertex({NaN, 0, -5}, id, proj, SIDE, SIDE, &x, &y), 0);
    mat4_t bad = id;
    bad.m[0] = NaN;
    CHECK_EQ(project_vertex({1, 0, -5}, bad, proj, SIDE, SIDE, &x, &y), 0);
    CHECK_EQ(x, -7.0f);  // outputs untouched on failure
    CHECK_EQ(y, -7.0f);
    // Exactly on the near plane, on the axis: the canvas centre (the report's viewport:
    // pixel centres 0 … SIDE − 1, so the centre is (SIDE − 1)/2).
    CHECK_EQ(project_vertex({0, 0, -NEAR_PLANE}, id, proj, SIDE, SIDE, &x, &y), 1);
    CHECK_NEAR(x, (SIDE - 1) / 2.0, 1e-4);
    CHECK_NEAR(y, (SIDE - 1) / 2.0, 1e-4);
    CHECK_EQ(project_vertex({0, 0, -5}, id, proj, SIDE, SIDE, nullptr, nullptr), 1);
}

TEST(report_wireframe_with_hostile_vertices_and_arguments) {
    // A triangle in front of the camera, one entirely behind, one with a NaN vertex, one
    // with a vertex at 1e30, and a zero-length edge.
    vec3_t v[] = {{-1, -1, -5}, {1, -1, -5}, {0, 1, -5},       // 0..2 visible
                  {-1, -1, 5},  {1, -1, 5},  {0, 1, 5},        // 3..5 behind
                  {NaN, 0, -5}, {0, HUGE_COORD, -5}, {0, 0, -NEAR_PLANE}};
    int visible[][2] = {{0, 1}, {1, 2}, {2, 0}};
    int hostile[][2] = {{3, 4}, {4, 5}, {5, 3}, {6, 0}, {6, 1}, {2, 2}, {-1, 0}, {0, 99}};
    const mat4_t id = mat4_identity(), proj = projection();
    tiny3d::canvas_ptr ref = blank(), c = blank();
    render_wireframe(ref.get(), v, 9, visible, 3, id, proj);
    CHECK(ink(*ref) > 10.0);
    render_wireframe(c.get(), v, 9, visible, 3, id, proj);
    render_wireframe(c.get(), v, 9, hostile, 8, id, proj);  // adds nothing
    CHECK(same_pixels(*c, *ref));
    // Huge and near-plane vertices: clipped, finite, in range, something drawn.
    int far_edges[][2] = {{0, 7}, {8, 1}};
    tiny3d::canvas_ptr h = blank();
    render_wireframe(h.get(), v, 9, far_edges, 2, id, proj);
    CHECK(all_in_range(*h));
    CHECK(ink(*h) > 5.0);
    // An edge to a vertex 1e30 away beyond the far plane draws the same listed either way
    // round (it vanished when the far end came first: the clipped end cancelled).
    vec3_t far_pair[] = {{1, -1, -2}, {0, HUGE_COORD, -HUGE_COORD}};
    int forward[][2] = {{0, 1}}, backward[][2] = {{1, 0}};
    tiny3d::canvas_ptr fw = blank(), bw = blank();
    render_wireframe(fw.get(), far_pair, 2, forward, 1, id, proj);
    render_wireframe(bw.get(), far_pair, 2, backward, 1, id, proj);
    CHECK(ink(*fw) > 20.0);
    CHECK_NEAR(ink(*bw), ink(*fw), 1e-3);
    // Bad arguments: nothing drawn.
    tiny3d::canvas_ptr n = blank();
    render_wireframe(n.get(), nullptr, 9, visible, 3, id, proj);
    render_wireframe(n.get(), v, -1, visible, 3, id, proj);
    render_wireframe(n.get(), v, 9, nullptr, 3, id, proj);
    render_wireframe(n.get(), v, 9, visible, -3, id, proj);
    mat4_t nan_model = id;
    nan_model.m[13] = NaN;
    render_wireframe(n.get(), v, 9, visible, 3, nan_model, proj);
    render_wireframe(nullptr, v, 9, visible, 3, id, proj);
    CHECK_EQ(ink(*n), 0.0);
}

TEST(tiny3d_wireframe_rejects_bad_thickness_and_skips_hostile_geometry) {
    tiny3d::mesh m;
    m.positions = {{-1, -1, -5}, {1, -1, -5}, {0, 1, -5}};
    m.add_face({0, 1, 2});
    tiny3d::mesh_derive_edges(m);
    tiny3d::wireframe_workspace ws;
    tiny3d::canvas_ptr c = blank();
    for (float t : {0.0f, -1.0f, NaN, INF}) {
        tiny3d::wireframe_options o;
        o.thickness = t;
        CHECK(!tiny3d::render_wireframe(*c, m, projection(), o, ws).ok());
    }
    CHECK_EQ(ink(*c), 0.0);
    // NaN in the matrix: nothing drawn (every edge invisible), no error needed.
    mat4_t bad = projection();
    bad.m[0] = NaN;
    (void)tiny3d::render_wireframe(*c, m, bad, {}, ws);
    CHECK_EQ(ink(*c), 0.0);
    // A NaN position inside the view (it passes the bounding-sphere test, which skips it):
    // its edges are skipped, the others drawn exactly as without it.
    tiny3d::canvas_ptr ref = blank();
    CHECK(tiny3d::render_wireframe(*ref, m, projection(), {}, ws).ok());
    tiny3d::mesh with_nan = m;
    with_nan.positions.push_back({NaN, 0, -5});
    with_nan.add_face({0, 1, 3});
    tiny3d::mesh_derive_edges(with_nan);
    tiny3d::canvas_ptr n = blank();
    CHECK(tiny3d::render_wireframe(*n, with_nan, projection(), {}, ws).ok());
    CHECK(ink(*ref) > 5.0);
    CHECK(same_pixels(*n, *ref));
    // The whole triangle behind the camera: nothing drawn.
    tiny3d::mesh behind = m;
    for (vec3_t &p : behind.positions) p.z = 5;
    CHECK(tiny3d::render_wireframe(*c, behind, projection(), {}, ws).ok());
    CHECK_EQ(ink(*c), 0.0);
}

// ---- filled triangles -----------------------------------------------------------------

namespace {

struct raster_fixture {
    tiny3d::render_context ctx{1};
    tiny3d::canvas_ptr canvas = blank();
    tiny3d::light_rig rig;
    raster_fixture() {
        const light_t l = {{0, 0, 1}, 1.0f};
        rig = tiny3d::make_light_rig({&l, 1}, 0.2f).value();
    }
    // Renders the triangles (one raster_mesh) with an identity model; returns the canvas.
    const canvas_t &render(const std::vector<vec3_t> &pos, const std::vector<std::array<std::uint32_t, 3>> &tris,
                           const mat4_t &model = mat4_identity()) {
        tiny3d::raster_mesh rm;
        rm.positions = pos;
        rm.normals.assign(pos.size(), vec3_t{0, 0, 1});
        rm.uvs.assign(pos.size(), tiny3d::vec2{0, 0});
        rm.triangles = tris;
        rm.bound_center = {0, 0, -5};
        rm.bound_radius = 1e9f;  // never frustum-culled as a whole
        CHECK(ctx.begin_frame(*canvas).ok());
        tiny3d::draw_params p{};
        p.model = model;
        p.view_projection = projection();
        p.lights = rig;
        p.shade = tiny3d::shading::flat;
        p.cull = tiny3d::cull_mode::none;
        ctx.draw(rm, p);
        ctx.end_frame();
        return *canvas;
    }
};

const std::vector<vec3_t> GOOD = {{-1, -1, -2}, {1, -1, -2}, {0, 1, -2}};  // ~130 px on the canvas

}  // namespace

TEST(raster_skips_nan_degenerate_and_behind_triangles) {
    raster_fixture f;
    tiny3d::canvas_ptr ref = blank();
    std::memcpy(ref->data, f.render(GOOD, {{0, 1, 2}}).data, sizeof(float) * SIDE * SIDE);
    CHECK(ink(*ref) > 20.0);
    std::vector<vec3_t> pos = GOOD;
    pos.insert(pos.end(), {{NaN, 0, -5}, {INF, 1, -5}, {0, 0, -5}, {0, 0, -5}, {1, 1, -5}, {2, 2, -5},
                           {-1, -1, 5}, {1, -1, 5}, {0, 1, 5}});
    // NaN / inf corners, a zero-area point triangle, a collinear one, one entirely behind.
    const std::vector<std::array<std::uint32_t, 3>> hostile = {
        {0, 1, 2}, {3, 1, 2}, {0, 4, 2}, {5, 6, 5}, {5, 7, 8}, {9, 10, 11}};
    CHECK(same_pixels(f.render(pos, hostile), *ref));
    CHECK(f.ctx.stats().rasterized <= 2);  // the good triangle (possibly split by clipping)
    // Only hostile triangles: the cleared canvas.
    CHECK_EQ(ink(f.render(pos, {{3, 1, 2}, {5, 6, 5}, {5, 7, 8}, {9, 10, 11}})), 0.0);
    // A NaN model matrix: nothing.
    mat4_t bad = mat4_identity();
    bad.m[14] = NaN;
    CHECK_EQ(ink(f.render(GOOD, {{0, 1, 2}}, bad)), 0.0);
}

TEST(raster_near_plane_and_huge_coordinates_stay_finite) {
    raster_fixture f;
    // A vertex exactly on the near plane; vertices 1e30 away, sideways and up-and-back
    // (beyond the far plane): clipped, drawn, in range. Each triangle alone must cover its
    // visible area, computed from the clipped geometry by hand:
    //  * {0, 1, 2}: the near-plane vertex projects to the centre (16, 16); the others to
    //    (24, 24) and (8, 24): area 64 px², lit fully by the head-on light only in part;
    //  * {2, 4, 1}: the far-plane crossing sits at y_ndc ≈ 0.97: a band 16 px wide from
    //    y = 24 up to y ≈ 0.5: ≥ 150 px covered.
    const std::vector<vec3_t> pos = {{0, 0, -NEAR_PLANE}, {1, -1, -2}, {-1, -1, -2}, {HUGE_COORD, HUGE_COORD, -2},
                                     {0, HUGE_COORD, -HUGE_COORD}};
    CHECK(all_in_range(f.render(pos, {{0, 1, 2}})));
    CHECK_MSG(ink(*f.canvas) > 10.0, std::to_string(ink(*f.canvas)));
    int covered = 0;
    f.render(pos, {{2, 4, 1}});
    CHECK(all_in_range(*f.canvas));
    for (int i = 0; i < SIDE * SIDE; ++i) covered += f.canvas->data[i] > 0.0f;
    CHECK_MSG(covered >= 150, std::to_string(covered) + " px covered");  // was 0: far-plane clip cancelled
    CHECK(all_in_range(f.render(pos, {{2, 1, 3}})));
    CHECK_MSG(ink(*f.canvas) > 10.0, std::to_string(ink(*f.canvas)));
    // Screen coordinates beyond RASTER_MAX_COORD (and NaN) are skipped by fill_triangle.
    tiny3d::canvas_ptr d = blank();
    const float intensity[3] = {1, 1, 1};
    const tiny3d::pixel_rect all{0, 0, SIDE, SIDE};
    const tiny3d::screen_vertex far_tri[3] = {{0, 0, 0.5f, 1}, {2 * tiny3d::RASTER_MAX_COORD, 0, 0.5f, 1},
                                              {0, 20, 0.5f, 1}};
    const tiny3d::screen_vertex nan_tri[3] = {{0, 0, 0.5f, 1}, {NaN, 0, 0.5f, 1}, {0, 20, 0.5f, 1}};
    const tiny3d::screen_vertex flat_tri[3] = {{0, 0, 0.5f, 1}, {10, 10, 0.5f, 1}, {20, 20, 0.5f, 1}};
    for (const auto *t : {far_tri, nan_tri, flat_tri}) {
        tiny3d::fill_triangle(*d, nullptr, t, intensity, tiny3d::depth_func::always, false, all);
        tiny3d::fill_triangle_scanline(*d, nullptr, t, intensity, tiny3d::depth_func::always);
    }
    CHECK_EQ(ink(*d), 0.0);
}

TEST(render_context_and_zbuffer_refuse_invalid_sizes) {
    tiny3d::zbuffer z;
    CHECK(!z.resize(0, 5).ok());
    CHECK(!z.resize(-1, -1).ok());
    CHECK(!z.resize(CANVAS_MAX_SIDE + 1, 1).ok());
    CHECK_EQ(z.width(), 0);
    tiny3d::render_context ctx(1);
    canvas_t empty{0, 0, nullptr, nullptr};
    CHECK(!ctx.begin_frame(empty).ok());
    canvas_t negative{-4, 4, nullptr, nullptr};
    CHECK(!ctx.begin_frame(negative).ok());
}
