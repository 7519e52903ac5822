// float_range_test.cpp — sizes computed from coordinates over the whole float range:
// bounding spheres, the framing matrix, face and vertex normals at 1e-38, 1e38 and mixed
// scales; a framed mesh draws the same image at every scale (wireframe with frustum
// culling, filled); framing in double reaches what the float matrix cannot, and the programs
// frame triangles at 1e19 and 1e38 and any other extent instead of writing a blank frame.
//
// References: the same quantities recomputed in long double, and the image of the same mesh
// at scale 1 (a power-of-two scale changes every float operation by an exact factor, so the
// images must be identical bit for bit).
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "harness.h"
#include "program_runner.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"
#include "wireframe.h"

using namespace tiny3d;

namespace {

// The base shape: an icosphere (level 1) pushed off-centre, so centre and radius both matter.
mesh base_mesh() {
    mesh m = make_icosphere(1);
    for (vec3_t &p : m.positions) p = {p.x * 1.0f + 0.25f, p.y * 0.75f - 0.5f, p.z * 0.5f};
    return m;
}

mesh scaled(const mesh &m, double s) {
    mesh out = m;
    for (vec3_t &p : out.positions) p = {float(p.x * s), float(p.y * s), float(p.z * s)};
    return out;
}

// Largest distance from c of any position, in long double (the reference).
long double max_distance(const mesh &m, vec3_t c) {
    long double r = 0;
    for (const vec3_t &p : m.positions) {
        const long double dx = (long double)p.x - c.x, dy = (long double)p.y - c.y, dz = (long double)p.z - c.z;
        r = std::max(r, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
    return r;
}

// The sphere holds every position and its radius is the reference rounded up (≤ 1 ulp more).
void check_sphere(const mesh &m, const char *what) {
    const bounding_sphere s = mesh_bounding_sphere(m);
    const bounding_box box = mesh_bounding_box(m);
    const long double cx = ((long double)box.min.x + box.max.x) / 2;
    CHECK_MSG(std::fabs((long double)s.center.x - cx) <= std::fabs(cx) * 1e-7L + 1e-45L, what);
    const long double ref = max_distance(m, s.center);
    CHECK_MSG(std::isfinite(s.radius) && s.radius > 0.0f, what);
    CHECK_MSG((long double)s.radius >= ref, what);
    CHECK_MSG((long double)std::nextafter(s.radius, 0.0f) < ref, what);  // the smallest such float
}

// Positions mapped by the framing matrix lie in the unit sphere, the farthest on it.
void check_fit(const mesh &m, const char *what) {
    const result<mat4_t> fit = mat4_fit_unit_sphere(mesh_bounding_sphere(m));
    CHECK_MSG(fit.ok(), what);
    if (!fit) return;
    double farthest = 0;
    for (const vec3_t &p : m.positions) {
        const vec4_t q = mat4_mul_vec4(*fit, {p.x, p.y, p.z, 1.0f});
        farthest = std::max(farthest, std::sqrt(double(q.x) * q.x + double(q.y) * q.y + double(q.z) * q.z));
    }
    CHECK_MSG(std::fabs(farthest - 1.0) < 1e-5, std::string(what) + ": farthest " + std::to_string(farthest));
}

// The framed mesh seen by a fixed camera; `offset` moves it sideways so part of it leaves the
// view (frustum culling must then say "intersecting" and clip, at any scale).
canvas_ptr framed_wireframe(const mesh &m, float offset) {
    canvas_ptr c = make_canvas(64, 64).value();
    const mat4_t fit = mat4_fit_unit_sphere(mesh_bounding_sphere(m)).value();
    const mat4_t view = mat4_multiply(mat4_translate(offset, 0.0f, -3.0f), mat4_multiply(mat4_rotate_y(0.6f), fit));
    wireframe_options o;
    o.method = line_method::coverage;
    o.thickness = 1.0f;
    o.depth_cue = true;
    o.frustum_cull = true;
    wireframe_workspace ws;
    wireframe_stats stats;
    CHECK(render_wireframe(*c, m, mat4_multiply(mat4_perspective(1.0f, 1.0f, 0.5f, 10.0f), view), o, ws, &stats).ok());
    CHECK(stats.edges_drawn > 0);
    return c;
}

canvas_ptr framed_filled(const mesh &m, float offset, int threads) {
    canvas_ptr c = make_canvas(64, 64).value();
    const raster_mesh rm = make_raster_mesh(m, {}).value();  // flat normals from the mesh
    const light_t light = {{0.3f, 0.5f, 1.0f}, 0.8f};
    const light_rig rig = make_light_rig({&light, 1}, 0.1f).value();
    render_context ctx(threads);
    draw_params p;
    p.model = mat4_multiply(mat4_translate(offset, 0.0f, -3.0f),
                            mat4_multiply(mat4_rotate_y(0.6f), mat4_fit_unit_sphere(mesh_bounding_sphere(m)).value()));
    p.view_projection = mat4_perspective(1.0f, 1.0f, 0.5f, 10.0f);
    p.lights = rig;
    p.shade = shading::flat;
    p.cull = cull_mode::back;
    CHECK(ctx.begin_frame(*c).ok());
    ctx.draw(rm, p);
    ctx.end_frame();
    CHECK(ctx.stats().culled_frustum == 0);
    return c;
}

double max_difference(const canvas_t &a, const canvas_t &b) {
    double d = 0;
    for (int i = 0; i < a.width * a.height; ++i) d = std::max(d, double(std::fabs(a.data[i] - b.data[i])));
    return d;
}

std::size_t inked(const canvas_t &c) { return canvas_count_differing(&c, 0.0f); }

// Power-of-two scales across the normal float range, and decimal ones near its ends.
const double kExactScales[] = {0x1p-120, 0x1p-100, 0x1p-64, 0x1p40, 0x1p64, 0x1p100, 0x1p120};
const double kDecimalScales[] = {1e-38, 1e-30, 7e18, 1e19, 2e19, 1e30, 1e38, 2.5e38};

}  // namespace

TEST(bounding_sphere_is_tight_and_holds_every_position_at_any_scale) {
    const mesh base = base_mesh();
    check_sphere(base, "scale 1");
    for (double s : kExactScales) check_sphere(scaled(base, s), std::to_string(std::log2(s)).c_str());
    for (double s : kDecimalScales) check_sphere(scaled(base, s), std::to_string(std::log2(s)).c_str());
    // A power-of-two scale scales centre and radius exactly.
    const bounding_sphere one = mesh_bounding_sphere(base);
    for (double s : kExactScales) {
        const bounding_sphere b = mesh_bounding_sphere(scaled(base, s));
        CHECK_EQ(double(b.radius), double(one.radius) * s);
        CHECK_EQ(double(b.center.y), double(one.center.y) * s);
    }
}

TEST(bounding_sphere_of_triangles_at_extreme_scales) {
    // 1e19 (r² = 3e38 overflowed float to inf), 1e-38 apart (r² underflowed to 0), and 1e38.
    for (double s : {1e19, 1e-38, 1e38}) {
        mesh m;
        m.positions = {{float(s), 0, 0}, {0, float(s), 0}, {-float(s), -float(s), float(s)}};
        m.add_face({0, 1, 2});
        check_sphere(m, std::to_string(std::log2(s)).c_str());
        check_fit(m, std::to_string(std::log2(s)).c_str());
    }
}

TEST(bounding_sphere_of_mixed_magnitudes) {
    // 1e-38 and 1e38 side by side: the tiny ones sit at the centre of a 1e38 sphere.
    mesh m;
    m.positions = {{1e-38f, 0, 0}, {0, -1e-38f, 1e-38f}, {1e38f, 0, 0}, {-1e38f, 1e-30f, 0}, {0, 0, 1e38f}};
    m.add_face({0, 1, 2});
    m.add_face({2, 3, 4});
    check_sphere(m, "mixed");
    const bounding_sphere s = mesh_bounding_sphere(m);
    CHECK_NEAR(double(s.center.z), 5e37, 5e37 * 1e-7);
    CHECK_NEAR(double(s.radius), std::sqrt(1e76 + 0.25e76), 1e31);
    // Denormal spacing: still a positive radius holding both points.
    mesh d;
    d.positions = {{0, 0, 0}, {0x1p-149f, 0x1p-148f, 0}, {0x1p-147f, 0, 0}};
    d.add_face({0, 1, 2});
    check_sphere(d, "denormal");
}

TEST(bounding_sphere_beyond_the_float_range_is_infinite_and_not_framed) {
    mesh m;
    m.positions = {{3e38f, 3e38f, 3e38f}, {-3e38f, -3e38f, -3e38f}, {3e38f, -3e38f, 0}};
    m.add_face({0, 1, 2});
    const bounding_sphere s = mesh_bounding_sphere(m);
    CHECK_EQ(double(s.center.x), 0.0);
    CHECK(std::isinf(s.radius) && s.radius > 0);
    const result<mat4_t> fit = mat4_fit_unit_sphere(s);
    CHECK(!fit.ok());
    CHECK(!fit && fit.message().find("too large to frame") != std::string::npos);
    // Along one axis the same span still fits (radius 3e38 ≤ FLT_MAX): framed.
    mesh line;
    line.positions = {{3e38f, 0, 0}, {-3e38f, 0, 0}, {0, 1e38f, 0}};
    line.add_face({0, 1, 2});
    check_sphere(line, "±3e38");
    check_fit(line, "±3e38");
}

TEST(framing_errors_say_why) {
    auto reason = [](bounding_sphere s) {
        const result<mat4_t> r = mat4_fit_unit_sphere(s);
        return r ? std::string() : r.message();
    };
    CHECK(reason({{0, 0, 0}, -1.0f}).find("nothing to frame") != std::string::npos);
    CHECK(reason({{1, 2, 3}, 0.0f}).find("same point") != std::string::npos);
    CHECK(reason({{0, 0, 0}, 1e-40f}).find("coordinates span 2e-40: too small to frame") != std::string::npos);
    CHECK(reason({{NAN, 0, 0}, 1.0f}).find("nothing to frame") != std::string::npos);
    CHECK(reason({{0, 0, 0}, 3e-39f}).empty());  // 1/r = 3.3e38 still a float
    CHECK(reason({{0, 0, 0}, FLT_MAX}).empty());
    // The matrix itself: scale 1/r and translation −c/r.
    const mat4_t m = mat4_fit_unit_sphere({{2e30f, -4e30f, 0}, 1e30f}).value();
    CHECK_NEAR(double(m.m[0]), 1e-30, 1e-37);
    CHECK_NEAR(double(m.m[12]), -2.0, 1e-6);
    CHECK_NEAR(double(m.m[13]), 4.0, 1e-6);
    CHECK_EQ(double(m.m[15]), 1.0);
}

// Framing in double (mesh_fit_unit_sphere) where the float matrix cannot: a mesh ~2e-37
// across (1/r is a float but projection · model overflows), one beyond FLT_MAX, and one of
// denormals. Reference: (p − c)/r in long double.
TEST(framing_in_double_reaches_the_whole_float_range) {
    auto check_map = [](const mesh &before, const char *what) {
        mesh m = before;
        const result<unit_sphere_map> map = mesh_fit_unit_sphere(m);
        CHECK_MSG(map.ok(), what);
        if (!map) return m;
        const bounding_sphere s = mesh_bounding_sphere(before);
        const long double r = max_distance(before, s.center);
        double farthest = 0;
        for (std::size_t i = 0; i < m.positions.size(); ++i) {
            const vec3_t p = before.positions[i], q = m.positions[i];
            if (!std::isfinite(p.x)) continue;
            CHECK_NEAR(double(q.x), double(((long double)p.x - s.center.x) / r), 1e-7);
            CHECK_NEAR(double(q.y), double(((long double)p.y - s.center.y) / r), 1e-7);
            farthest = std::max(farthest, std::sqrt(double(q.x) * q.x + double(q.y) * q.y + double(q.z) * q.z));
        }
        CHECK_MSG(std::fabs(farthest - 1.0) < 1e-6, std::string(what) + ": farthest " + std::to_string(farthest));
        return m;
    };
    const mesh base = base_mesh();
    mesh unit = base;
    CHECK(mesh_fit_unit_sphere(unit).ok());
    const canvas_ptr reference = framed_filled(unit, 0.0f, 1);
    CHECK(inked(*reference) > 200);
    // Tiny (2^-122 ≈ 1.9e-37) and huge (2^126): the same image as scale 1 to float rounding.
    for (double scale : {std::ldexp(1.0, -122), std::ldexp(1.0, 126)}) {
        const mesh m = check_map(scaled(base, scale), "scaled");
        CHECK_MSG(max_difference(*framed_filled(m, 0.0f, 1), *reference) < 0.1, std::to_string(std::log2(scale)));
    }
    mesh wide;  // radius 5.2e38 > FLT_MAX: the float sphere is infinite, the map is not
    wide.positions = {{3e38f, 3e38f, 3e38f}, {-3e38f, -3e38f, -3e38f}, {3e38f, -3e38f, 0}};
    wide.add_face({0, 1, 2});
    check_map(wide, "±3e38");
    mesh denormal;  // the smallest float spacing
    const float d = std::numeric_limits<float>::denorm_min();
    denormal.positions = {{d, 0, 0}, {0, d, 0}, {0, 0, 0}, {NAN, 0, 0}};
    denormal.add_face({0, 1, 2});
    const mesh mapped = check_map(denormal, "denormals");
    CHECK(std::isnan(mapped.positions[3].x));  // non-finite positions stay so
    // What it refuses, in words; the mesh is then unchanged.
    mesh point;
    point.positions = {{1, 2, 3}, {1, 2, 3}, {1, 2, 3}};
    const result<unit_sphere_map> one = mesh_fit_unit_sphere(point);
    CHECK(!one && one.message().find("same point") != std::string::npos);
    CHECK_EQ(double(point.positions[0].x), 1.0);
    const vec3_t none[] = {{NAN, 0, 0}, {INFINITY, 0, 0}};
    const result<unit_sphere_map> empty = unit_sphere_map_of(none);
    CHECK(!empty && empty.message().find("no finite position") != std::string::npos);
}

TEST(raster_mesh_bounds_match_the_mesh_sphere) {
    for (double s : {1e-38, 1e19, 1e38}) {
        const mesh m = scaled(base_mesh(), s);
        const bounding_sphere b = mesh_bounding_sphere(m);
        const raster_mesh rm = make_raster_mesh(m, mesh_vertex_normals(m)).value();
        CHECK_EQ(double(rm.bound_radius), double(b.radius));
        CHECK_EQ(double(rm.bound_center.x), double(b.center.x));
    }
}

TEST(face_and_vertex_normals_at_extreme_scales) {
    // A right triangle in the plane x + y + z = const: normal (1, 1, 1)/√3 at every scale,
    // and a small face far from the origin (plain Σ p × q cancels there).
    const double k = 1.0 / std::sqrt(3.0);
    for (double s : {1e-38, 1e-30, 1e19, 1e30, 1e38}) {
        mesh m;
        m.positions = {{float(s), 0, 0}, {0, float(s), 0}, {0, 0, float(s)}};
        m.add_face({0, 1, 2});
        const vec3_t n = mesh_face_normals(m)[0];
        CHECK_NEAR(n.x, k, 1e-6);
        CHECK_NEAR(n.z, k, 1e-6);
        for (const vec3_t &v : mesh_vertex_normals(m)) CHECK_NEAR(v.y, k, 1e-6);
        const raster_mesh rm = make_raster_mesh(m, {}).value();  // flat: the face normal
        CHECK_NEAR(rm.normals[0].x, k, 1e-6);
    }
    // Side 1 at 1e6 from the origin (ulp 0.0625): Newell on p × q loses ~1e12 · 1e-16.
    mesh far;
    far.positions = {{1e6f, 1e6f, 0}, {1e6f + 1, 1e6f, 0}, {1e6f, 1e6f + 1, 0}};
    far.add_face({0, 1, 2});
    CHECK_NEAR(mesh_face_normals(far)[0].z, 1.0, 1e-12);
    CHECK_NEAR(mesh_face_normals(far)[0].x, 0.0, 1e-12);
    // Corners ±3e38 apart: their difference overflows float, the angle weights must not.
    mesh wide;
    wide.positions = {{-3e38f, 0, 0}, {3e38f, 0, 0}, {0, 3e38f, 0}};
    wide.add_face({0, 1, 2});
    for (const vec3_t &v : mesh_vertex_normals(wide)) CHECK_NEAR(v.z, 1.0, 1e-6);
}

TEST(a_framed_mesh_draws_the_same_image_at_every_scale) {
    const mesh base = base_mesh();
    for (float offset : {0.0f, 1.2f}) {  // 1.2: partly outside the view
        const canvas_ptr wire = framed_wireframe(base, offset), fill = framed_filled(base, offset, 1);
        CHECK(inked(*wire) > 200);
        CHECK(inked(*fill) > 200);
        for (double s : kExactScales) {
            const mesh m = scaled(base, s);
            CHECK_MSG(max_difference(*framed_wireframe(m, offset), *wire) == 0.0, "wireframe at " + std::to_string(std::log2(s)));
            CHECK_MSG(max_difference(*framed_filled(m, offset, 2), *fill) == 0.0, "filled at " + std::to_string(std::log2(s)));
        }
        for (double s : kDecimalScales) {
            const mesh m = scaled(base, s);
            const double dw = max_difference(*framed_wireframe(m, offset), *wire);
            const double df = max_difference(*framed_filled(m, offset, 1), *fill);
            // Different rounding of the scaled positions: a few hundredths on edge pixels.
            CHECK_MSG(dw < 0.1, "wireframe at " + std::to_string(std::log2(s)) + ": " + std::to_string(dw));
            CHECK_MSG(df < 0.1, "filled at " + std::to_string(std::log2(s)) + ": " + std::to_string(df));
        }
    }
}

// `program` (wireframe, or render with `mode_args`) on the triangle at several scales.
void check_program_at_scales(const std::string &program, const std::vector<std::string> &mode_args) {
    namespace pr = program_runner;
    pr::temp_dir dir;
    auto triangle = [&](const std::string &name, const std::string &a, const std::string &b) {
        const pr::fs::path p = dir.path / name;
        std::FILE *f = std::fopen(p.c_str(), "w");
        std::fprintf(f, "v %s 0 0\nv 0 %s 0\nv -%s -%s %s\nf 1 2 3\n", a.c_str(), a.c_str(), b.c_str(), b.c_str(),
                     b.c_str());
        std::fclose(f);
        return p.string();
    };
    std::vector<unsigned char> reference;
    for (const char *s : {"1", "7e18", "1e19", "1e38", "1e-38"}) {
        const pr::fs::path out = dir.path / (std::string("out_") + s);
        std::vector<std::string> args = {triangle(std::string(s) + ".obj", s, s), "--out", out.string(), "--frames",
                                          "3:3", "--size", "48x48"};
        args.insert(args.end(), mode_args.begin(), mode_args.end());
        const pr::run_result r = pr::run(pr::demo_path(program), args, dir.path);
        CHECK_MSG(r.exit_code == 0, program + " " + s + ": " + r.err);
        const pr::pgm_image img = pr::parse_pgm(pr::file_bytes(out / "frame_003.pgm"));
        CHECK_EQ(img.width, 48);
        const unsigned char background = img.pixels.empty() ? 0 : img.pixels[0];  // a corner
        const long lit =
            std::count_if(img.pixels.begin(), img.pixels.end(), [&](unsigned char v) { return v != background; });
        CHECK_MSG(lit > 60, program + " " + s + ": " + std::to_string(lit) + " pixels lit");
        if (reference.empty()) reference = img.pixels;
        int worst = 0;
        for (std::size_t i = 0; i < reference.size() && i < img.pixels.size(); ++i)
            worst = std::max(worst, std::abs(int(reference[i]) - int(img.pixels[i])));
        CHECK_MSG(worst <= 2, program + " " + s + ": differs from scale 1 by " + std::to_string(worst));
    }
    // Beyond FLT_MAX across, and the smallest denormal spacing: framed in double, drawn.
    for (const char *s : {"3e38", "1e-45"}) {
        const pr::fs::path out = dir.path / (std::string("edge_") + s);
        std::vector<std::string> args = {triangle(std::string("edge_") + s + ".obj", s, s), "--out", out.string(),
                                          "--frames", "0:0", "--size", "48x48"};
        args.insert(args.end(), mode_args.begin(), mode_args.end());
        const pr::run_result r = pr::run(pr::demo_path(program), args, dir.path);
        CHECK_MSG(r.exit_code == 0, program + " " + s + ": " + r.err);
        const pr::pgm_image img = pr::parse_pgm(pr::file_bytes(out / "frame_000.pgm"));
        const unsigned char background = img.pixels.empty() ? 0 : img.pixels[0];
        const long lit =
            std::count_if(img.pixels.begin(), img.pixels.end(), [&](unsigned char v) { return v != background; });
        CHECK_MSG(lit > 60, program + " " + s + ": " + std::to_string(lit) + " pixels lit");
    }
    // Every vertex the same point: an error, exit 1, no frame.
    const pr::fs::path out = dir.path / "bad_point";
    std::vector<std::string> args = {triangle("bad_point.obj", "0", "0"), "--out", out.string(), "--frames", "0:0",
                                      "--size", "48x48"};
    args.insert(args.end(), mode_args.begin(), mode_args.end());
    const pr::run_result r = pr::run(pr::demo_path(program), args, dir.path);
    CHECK_EQ(r.exit_code, 1);
    CHECK_MSG(r.err.find("same point") != std::string::npos, r.err);
    CHECK(pr::files_in(out).empty());
}

TEST(wireframe_program_frames_meshes_of_any_extent) { check_program_at_scales("wireframe", {}); }
TEST(render_program_frames_meshes_of_any_extent) {
    check_program_at_scales("render", {"--mode", "flat"});
    check_program_at_scales("render", {"--mode", "wireframe"});
}
