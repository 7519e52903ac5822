// render_test.cpp — the render program (demo/render.cpp) run as a user runs it: frame counts
// and names, pixels against hand-computed shading (a cube face seen head-on in orthographic
// projection, lit by a light given on the command line), textures, the auto-framed
// turntable keeping a mesh inside every frame, hidden-line against wireframe, --info's
// counts, bad command lines (exit 2) and bad files (exit 1) writing nothing, and --gif (its
// frames decoded by tests/gif_decoder.h against the PGMs of the same run).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "harness.h"
#include "gif_decoder.h"
#include "program_runner.h"
#include "math3d.h"
#include "mesh.h"
#include "seam_split.h"

using namespace program_runner;

namespace {

const std::string cube_obj = "tests/data/cube_quads.obj";  // side 2, uvs and normals
constexpr int background = 10;                               // round(0.04 · 255)

bool render_built() {
    const bool ok = fs::exists(demo_path("render"));
    CHECK_MSG(ok, demo_path("render") + " is not built (make test builds the demos first)");
    return ok;
}

// Runs render with `args` and --out DIR/out; returns the result (files in DIR/out).
run_result render(const temp_dir &dir, std::vector<std::string> args) {
    args.insert(args.end(), {"--out", (dir.path / "out").string()});
    return run(demo_path("render"), args, dir.path);
}

pgm_image frame(const temp_dir &dir, const std::string &name) { return parse_pgm(file_bytes(dir.path / "out" / name)); }

// A mesh as OBJ text (positions and faces only).
std::string obj_text(const tiny3d::mesh &m) {
    std::string text;
    char line[128];
    for (const vec3_t &p : m.positions) {
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
        text += line;
    }
    for (std::size_t f = 0; f < m.face_count(); ++f) {
        text += "f";
        for (std::uint32_t k = m.face_start[f]; k < m.face_start[f + 1]; ++k) text += " " + std::to_string(m.indices[k] + 1);
        text += "\n";
    }
    return text;
}

void write_file(const fs::path &path, const std::string &bytes) {
    std::FILE *f = std::fopen(path.string().c_str(), "wb");
    CHECK(f != nullptr);
    if (!f) return;
    std::fwrite(bytes.data(), 1, bytes.size(), f);
    std::fclose(f);
}

// The cube's +z face head-on: eye on +z, orthographic, one frame.
// Diffuse only (--specular 0): the values are Lambert's.
const std::vector<std::string> head_on = {cube_obj, "--eye", "0,0,10", "--target", "0,0,0", "--ortho", "--turntable", "1",
                                          "--size", "64x64", "--specular", "0"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string> &more) {
    a.insert(a.end(), more.begin(), more.end());
    return a;
}

// m as OBJ text with one normal per position (vn, written to round-trip exactly).
std::string obj_text_with_normals(const tiny3d::mesh &m, const std::vector<vec3_t> &normals) {
    std::string text;
    char line[128];
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\nvn %.9g %.9g %.9g\n", m.positions[i].x, m.positions[i].y,
                      m.positions[i].z, normals[i].x, normals[i].y, normals[i].z);
        text += line;
    }
    for (std::size_t f = 0; f < m.face_count(); ++f) {
        text += "f";
        for (std::uint32_t k = m.face_start[f]; k < m.face_start[f + 1]; ++k)
            text += " " + std::to_string(m.indices[k] + 1) + "//" + std::to_string(m.indices[k] + 1);
        text += "\n";
    }
    return text;
}

// Renders the OBJ text `obj` as one frame with `args`; the frame, or an empty image.
pgm_image render_text(const std::string &obj, std::vector<std::string> args) {
    temp_dir dir;
    write_file(dir.path / "mesh.obj", obj);
    args.insert(args.begin(), (dir.path / "mesh.obj").string());
    const run_result r = render(dir, with(args, {"--turntable", "1"}));
    CHECK_MSG(r.exit_code == 0, r.err);
    return r.exit_code == 0 ? frame(dir, "frame_000.pgm") : pgm_image{};
}

struct image_difference {
    double mean = 1e9;
    int worst = 255, over_8 = 0;
};
image_difference compare(const pgm_image &a, const pgm_image &b) {
    image_difference d;
    if (a.pixels.empty() || a.pixels.size() != b.pixels.size()) return d;
    double sum = 0;
    d.worst = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const int e = std::abs(int(a.pixels[i]) - int(b.pixels[i]));
        sum += e;
        d.worst = std::max(d.worst, e);
        d.over_8 += e > 8;
    }
    d.mean = sum / double(a.pixels.size());
    return d;
}

}  // namespace

TEST(repeated_seam_vertices_render_as_the_welded_mesh) {
    if (!render_built()) return;
    // The teapot's case (its patches repeat the vertices of their seams), on a torus cut into
    // patches of 37 faces: rendered as the welded torus. The same patched mesh with its
    // per-position normals given as vn (what render drew before crease normals) shows seams.
    const tiny3d::mesh whole = tiny3d::make_torus(1.0f, 0.4f, 48, 24);
    const tiny3d::mesh patched = seam_split::split_into_patches(whole, 37);
    const std::vector<std::string> view = {"--size", "512x512", "--eye", "1,-3.5,3.5"};
    const pgm_image welded = render_text(obj_text(whole), view);
    const pgm_image seamed = render_text(obj_text(patched), view);
    const image_difference d = compare(welded, seamed);
    CHECK_MSG(d.mean <= 0.05 && d.worst <= 8,
              "mean " + std::to_string(d.mean) + ", worst " + std::to_string(d.worst));
    const image_difference old =
        compare(welded, render_text(obj_text_with_normals(patched, tiny3d::mesh_vertex_normals(patched)), view));
    CHECK_MSG(old.over_8 > 100, std::to_string(old.over_8) + " pixels off by more than 8");
}

TEST(a_cube_of_eight_shared_corners_shows_flat_faces) {
    if (!render_built()) return;
    // Orthographic, directional lights, flat normals: every face one grey level. Pixels whose
    // 5×5 neighbourhood is all ink (away from the silhouette) fall in at most 3 levels ±1
    // (3 faces visible), bar the blended 1-pixel lines where faces meet. Smooth normals
    // (--crease 180) shade a gradient across each face, which this test tells apart.
    for (const char *crease : {"60", "180"}) {
        const pgm_image img = render_text(obj_text(tiny3d::make_cube(1.0f)),
                                          {"--size", "128x128", "--ortho", "--eye", "3,2,4", "--crease", crease, "--specular", "0"});
        if (img.pixels.empty()) continue;
        std::map<int, int> levels;
        int interior = 0;
        for (int y = 2; y < img.height - 2; ++y)
            for (int x = 2; x < img.width - 2; ++x) {
                bool inked = true;
                for (int dy = -2; dy <= 2; ++dy)
                    for (int dx = -2; dx <= 2; ++dx) inked = inked && img.at(x + dx, y + dy) != background;
                if (!inked) continue;
                ++interior;
                ++levels[img.at(x, y)];
            }
        // The three most common levels, each with its ±1 neighbours.
        std::vector<std::pair<int, int>> by_count;
        for (const auto &[v, n] : levels) by_count.push_back({n, v});
        std::sort(by_count.rbegin(), by_count.rend());
        int covered = 0;
        for (const auto &[v, n] : levels)
            for (std::size_t i = 0; i < std::min<std::size_t>(3, by_count.size()); ++i)
                if (std::abs(v - by_count[i].second) <= 1) {
                    covered += n;
                    break;
                }
        const double fraction = interior > 0 ? double(covered) / interior : 0.0;
        if (std::string(crease) == "60") CHECK_MSG(fraction > 0.96, std::to_string(fraction));
        else CHECK_MSG(fraction < 0.5, std::to_string(fraction));
        CHECK(interior > 128 * 128 / 5);
    }
}

TEST(default_turntable_writes_36_frames_of_the_default_size) {
    if (!render_built()) return;
    temp_dir dir;
    const run_result r = render(dir, {cube_obj, "--size", "40x30"});
    CHECK_MSG(r.exit_code == 0, r.err);
    const auto files = files_in(dir.path / "out");
    CHECK_EQ(files.size(), std::size_t{36});
    CHECK(files.count("frame_000.pgm") == 1 && files.count("frame_035.pgm") == 1);
    const pgm_image img = frame(dir, "frame_017.pgm");
    CHECK_EQ(img.width, 40);
    CHECK_EQ(img.height, 30);
}

TEST(progress_of_a_frame_is_shown_on_stderr_when_asked_for_every_band) {
    // A long frame shows its progress; "--progress-every 0" shows every band of every frame,
    // so a short run exercises it without timing anything: the lines count up to the total.
    if (!render_built()) return;
    temp_dir dir;
    const run_result r = render(dir, {cube_obj, "--size", "40x200", "--turntable", "2", "--threads", "1", "--progress-every", "0"});
    CHECK_MSG(r.exit_code == 0, r.err);
    int lines = 0, finished = 0;
    for (std::size_t at = 0; (at = r.err.find("render: frame ", at)) != std::string::npos; ++at) {
        int frame = -1, done = 0, total = 0;
        if (std::sscanf(r.err.c_str() + at, "render: frame %d: %d of %d bands drawn", &frame, &done, &total) != 3) continue;
        ++lines;
        CHECK(done >= 1 && done <= total);
        finished += done == total;
    }
    CHECK(lines >= 4);  // two frames of several bands each, all drawn by the one (caller's) thread
    CHECK_EQ(finished, 2);
    const run_result quiet = render(dir, {cube_obj, "--size", "40x30", "--turntable", "1"});
    CHECK_MSG(quiet.err.find("bands drawn") == std::string::npos, quiet.err);  // a short frame by default: silent
}

TEST(flat_gouraud_phong_give_the_lambert_value_on_a_face_seen_head_on) {
    if (!render_built()) return;
    // I = ambient + intensity · n·L: n = +z (towards the camera), L from the command line
    // in the camera's frame. Light along the view axis: 0.25 + 0.5 · 1 = 0.75 → 191.
    // Light at 45° to the right: 0.25 + 0.5 · cos 45° = 0.60355 → 154.
    const struct {
        const char *light;
        int expected;
    } cases[] = {{"0,0,1,0.5", 191}, {"1,0,1,0.5", 154}, {"0,0,-1,0.5", 64}};  // from behind: ambient only
    for (const char *mode : {"flat", "gouraud", "phong"})
        for (const auto &c : cases) {
            temp_dir dir;
            const run_result r = render(dir, with(head_on, {"--mode", mode, "--light", c.light, "--ambient", "0.25"}));
            CHECK_MSG(r.exit_code == 0, r.err);
            const pgm_image img = frame(dir, "frame_000.pgm");
            CHECK_EQ(img.width, 64);
            if (img.width != 64) continue;
            // The face spans the middle ±1 of a view ±√3/0.85 high: pixels ~16..47.
            for (const int p : {24, 32, 40}) CHECK_EQ(int(img.at(p, 32)), c.expected);
            CHECK_EQ(int(img.at(0, 0)), background);
            CHECK_EQ(int(img.at(63, 63)), background);
        }
}

TEST(specular_adds_the_blinn_phong_highlight_by_hand) {
    if (!render_built()) return;
    // Orthographic, so V = +z everywhere; n = +z. I = 0.25 + 0.5·(n·L + ks·(n·h)^s):
    //  render's default (ks 0.25, s 40), light along the view: h = n, 0.25 + 0.5·1.25 = 0.875 → 223;
    //  ks 1, s 10, light 45° to the right: n·h = cos 22.5°, 0.25 + 0.5·(0.70711 + 0.45285) = 0.82998 → 212;
    //  the same light behind the face: no diffuse, no highlight: 0.25 → 64.
    const struct {
        std::vector<std::string> args;
        int expected;
    } cases[] = {{{"--light", "0,0,1,0.5"}, 223},
                 {{"--light", "1,0,1,0.5", "--specular", "1", "--shininess", "10"}, 212},
                 {{"--light", "1,0,-1,0.5", "--specular", "1", "--shininess", "10"}, 64}};
    std::vector<std::string> lit(head_on.begin(), head_on.end() - 2);  // without --specular 0
    for (const char *mode : {"flat", "gouraud", "phong"})
        for (const auto &c : cases) {
            temp_dir dir;
            const run_result r = render(dir, with(with(lit, {"--mode", mode, "--ambient", "0.25"}), c.args));
            CHECK_MSG(r.exit_code == 0, r.err);
            const pgm_image img = frame(dir, "frame_000.pgm");
            if (img.width != 64) continue;
            for (const int p : {24, 32, 40}) CHECK_EQ(int(img.at(p, 32)), c.expected);
        }
}

TEST(aa_blends_the_silhouette_and_keeps_the_interior) {
    if (!render_built()) return;
    // Head-on cube face, flat 0.75 (191) on 0.04 (10): one sample per pixel gives only those
    // two values; 16 samples give in-between values along the face's edges, the same
    // interior, and every value between the two.
    for (const char *aa : {"1", "16"}) {
        temp_dir dir;
        const run_result r =
            render(dir, with(head_on, {"--mode", "flat", "--light", "0,0,1,0.5", "--ambient", "0.25", "--aa", aa}));
        CHECK_MSG(r.exit_code == 0, r.err);
        const pgm_image img = frame(dir, "frame_000.pgm");
        CHECK_EQ(img.width, 64);
        if (img.width != 64) continue;
        int between = 0, outside = 0;
        for (const unsigned char v : img.pixels) {
            between += v > background && v < 191;
            outside += v < background || v > 191;
        }
        CHECK_EQ(outside, 0);
        CHECK_EQ(int(img.at(32, 32)), 191);
        if (std::string(aa) == "1") CHECK_EQ(between, 0);
        else CHECK_MSG(between >= 4 * 20, std::to_string(between) + " edge pixels blended");  // 4 edges, ~31 px each
    }
}

TEST(two_lights_without_intensity_share_the_default_total) {
    if (!render_built()) return;
    // Two lights along the view axis, 0.85 split evenly: 0.1 (ambient) + 0.85 = 0.95 → 242.
    temp_dir dir;
    const run_result r = render(dir, with(head_on, {"--mode", "flat", "--light", "0,0,1", "--light=0,0,2"}));
    CHECK_MSG(r.exit_code == 0, r.err);
    const pgm_image img = frame(dir, "frame_000.pgm");
    CHECK(img.width == 64 && int(img.at(32, 32)) == 242);
}

TEST(texture_multiplies_the_shading) {
    if (!render_built()) return;
    temp_dir dir;
    // 4 × 1 texels 0.2 0.2 1 1: bilinear gives exactly 0.2 for u in [1/8, 3/8] and 1 for
    // u in [5/8, 7/8]; the face maps u along +x.
    write_file(dir.path / "tex.pgm", std::string("P5\n4 1\n255\n") + char(51) + char(51) + char(255) + char(255));
    const run_result r = render(dir, with(head_on, {"--mode", "flat", "--light", "0,0,1,0.5", "--ambient", "0.25",
                                                    "--texture", (dir.path / "tex.pgm").string()}));
    CHECK_MSG(r.exit_code == 0, r.err);
    const pgm_image img = frame(dir, "frame_000.pgm");
    CHECK_EQ(img.width, 64);
    if (img.width != 64) return;
    CHECK_EQ(int(img.at(24, 32)), 38);   // round(0.75 · 0.2 · 255) = round(38.25)
    CHECK_EQ(int(img.at(40, 32)), 191);  // 0.75 · 1
}

TEST(texture_filters_minify_a_fine_checker_to_its_mean) {
    if (!render_built()) return;
    temp_dir dir;
    // A 256² checker of single texels (0 and 1) on the head-on face, ~32 px across: 8 texels
    // per pixel. Its mean is 0.5 at every mipmap level from 1 up, so trilinear (render's
    // default) and anisotropic give 0.75 · 0.5 → 96 everywhere inside the face; bilinear
    // and nearest read the base level and alias (values far from 96).
    std::string pgm = "P5\n256 256\n255\n";
    for (int j = 0; j < 256; ++j)
        for (int i = 0; i < 256; ++i) pgm += char((i + j) % 2 ? 255 : 0);
    write_file(dir.path / "checker.pgm", pgm);
    const std::vector<std::string> base = with(head_on, {"--mode", "flat", "--light", "0,0,1,0.5", "--ambient", "0.25",
                                                         "--texture", (dir.path / "checker.pgm").string()});
    for (const char *filter : {"", "trilinear", "anisotropic", "bilinear", "nearest"}) {
        const run_result r = render(dir, std::string(filter).empty() ? base : with(base, {"--filter", filter}));
        CHECK_MSG(r.exit_code == 0, r.err);
        const pgm_image img = frame(dir, "frame_000.pgm");
        if (img.width != 64) continue;
        int worst = 0;
        for (int y = 20; y < 44; ++y)
            for (int x = 20; x < 44; ++x) worst = std::max(worst, std::abs(int(img.at(x, y)) - 96));
        const bool mipmapped = std::string(filter).empty() || std::string(filter) == "trilinear" ||
                               std::string(filter) == "anisotropic";
        if (mipmapped) CHECK_MSG(worst <= 2, std::string(filter) + ": " + std::to_string(worst));
        else CHECK_MSG(worst > 30, std::string(filter) + ": " + std::to_string(worst));
    }
    for (const std::vector<std::string> &bad : {std::vector<std::string>{"--filter", "cubic"},
                                                std::vector<std::string>{"--anisotropy", "0"}}) {
        const run_result r = render(dir, with(base, bad));
        CHECK_EQ(r.exit_code, 2);
    }
}

TEST(auto_framing_keeps_the_mesh_inside_every_frame) {
    if (!render_built()) return;
    temp_dir dir;
    // A torus knot moved far off the origin and stretched: the framing follows its bounds.
    tiny3d::mesh knot = tiny3d::make_torus_knot(2, 3, 60, 8, 0.25f, 1.0f);
    for (vec3_t &p : knot.positions) p = vec3_t{p.x * 3.0f + 500.0f, p.y - 40.0f, p.z * 0.5f};
    write_file(dir.path / "knot.obj", obj_text(knot));
    for (const char *projection : {"--fov=40", "--ortho"}) {
        const run_result r = render(dir, {(dir.path / "knot.obj").string(), projection, "--turntable", "6", "--size", "80x60"});
        CHECK_MSG(r.exit_code == 0, r.err);
        for (int f = 0; f < 6; ++f) {
            char name[32];
            std::snprintf(name, sizeof name, "frame_%03d.pgm", f);
            const pgm_image img = frame(dir, name);
            CHECK_EQ(img.width, 80);
            if (img.width != 80) continue;
            int lit = 0, border_lit = 0;
            for (int y = 0; y < 60; ++y)
                for (int x = 0; x < 80; ++x) {
                    const bool on = img.at(x, y) != background;
                    lit += on;
                    border_lit += on && (x == 0 || y == 0 || x == 79 || y == 59);
                }
            CHECK_EQ(border_lit, 0);
            CHECK_MSG(lit > 80 * 60 / 50, std::string(projection) + " " + name + ": only " + std::to_string(lit) + " px lit");
        }
    }
}

TEST(hidden_line_leaves_out_the_back_face_that_wireframe_draws) {
    if (!render_built()) return;
    // Perspective from z = 10, fov 40°, 160 px: the back face's right edge (x = 1, z = −1)
    // projects to column (1 + (1/11)/tan 20°)/2 · 160 = 99.98, inside the front face (whose
    // edge is at column 104.4). Row 80 is the middle.
    const std::vector<std::string> view = {cube_obj, "--eye", "0,0,10", "--target", "0,0,0", "--turntable", "1",
                                           "--size", "160x160"};
    temp_dir wire_dir, hidden_dir;
    CHECK_EQ(render(wire_dir, with(view, {"--mode", "wireframe"})).exit_code, 0);
    CHECK_EQ(render(hidden_dir, with(view, {"--mode", "hidden-line", "--lines", "tabulated"})).exit_code, 0);
    const pgm_image wire = frame(wire_dir, "frame_000.pgm"), hidden = frame(hidden_dir, "frame_000.pgm");
    CHECK(wire.width == 160 && hidden.width == 160);
    if (wire.width != 160 || hidden.width != 160) return;
    CHECK(std::max(wire.at(99, 80), wire.at(100, 80)) > 40);  // depth-cued: the far edges are dimmer
    CHECK_EQ(int(hidden.at(99, 80)), background);
    CHECK_EQ(int(hidden.at(100, 80)), background);
    CHECK(std::max(hidden.at(104, 80), hidden.at(105, 80)) > 100);  // the front face's edge
}

TEST(hidden_line_hides_front_facing_edges_behind_the_surface) {
    if (!render_built()) return;
    // A big quad (z = 0, side 2) in front of a small one (z = −2, side 0.6), both facing the
    // eye at z = 10: the small quad's edges face the eye, so only the depth test hides them.
    // Its right edge (x = 0.3 at distance 12) projects to column (1 + (0.3/12)/tan 20°)/2 · 160
    // = 85.5, the big quad's (x = 1 at distance 10) to 102.0; row 80 is the middle.
    temp_dir dir;
    const fs::path obj = dir.path / "two_quads.obj";
    write_file(obj, "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                    "v -0.3 -0.3 -2\nv 0.3 -0.3 -2\nv 0.3 0.3 -2\nv -0.3 0.3 -2\n"
                    "f 1 2 3 4\nf 5 6 7 8\n");
    const std::vector<std::string> view = {obj.string(), "--eye", "0,0,10", "--target", "0,0,-1",
                                           "--turntable", "1", "--size", "160x160"};
    temp_dir wire_dir, hidden_dir;
    CHECK_EQ(render(wire_dir, with(view, {"--mode", "wireframe"})).exit_code, 0);
    CHECK_EQ(render(hidden_dir, with(view, {"--mode", "hidden-line"})).exit_code, 0);
    const pgm_image wire = frame(wire_dir, "frame_000.pgm"), hidden = frame(hidden_dir, "frame_000.pgm");
    CHECK(wire.width == 160 && hidden.width == 160);
    if (wire.width != 160 || hidden.width != 160) return;
    CHECK(std::max(wire.at(85, 80), wire.at(86, 80)) > 40);  // the far quad's edge, drawn
    CHECK_EQ(int(hidden.at(85, 80)), background);             // ... hidden behind the near quad
    CHECK_EQ(int(hidden.at(86, 80)), background);
    CHECK(std::max(hidden.at(101, 80), hidden.at(102, 80)) > 100);  // the near quad's edge
}

TEST(info_prints_counts_bounds_and_warnings_and_renders_nothing) {
    if (!render_built()) return;
    temp_dir dir;
    const run_result r = render(dir, {cube_obj, "--info"});
    CHECK_EQ(r.exit_code, 0);
    for (const char *line : {"vertices   8\n", "faces      6\n", "triangles  12\n", "edges      12\n",
                             "bounds     min (-1, -1, -1)  max (1, 1, 1)\n", "uvs        yes", "warnings   "})
        CHECK_MSG(r.out.find(line) != std::string::npos, std::string("missing '") + line + "' in:\n" + r.out);
    CHECK(!fs::exists(dir.path / "out"));
    const run_result ply = render(dir, {"tests/data/tetra_ascii.ply", "--info"});
    CHECK_EQ(ply.exit_code, 0);
    CHECK(ply.out.find("faces      4\n") != std::string::npos && ply.out.find("edges      6\n") != std::string::npos);
    CHECK(ply.out.find("warnings   none\n") != std::string::npos);
    // The loader's warnings, each with file and line; a lines-only file is drawn as a wireframe.
    const std::string lines_obj = (dir.path / "lines.obj").string();
    write_file(lines_obj, "v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2 3 1\nfrobnicate 3\n");
    const run_result warned = render(dir, {lines_obj, "--info"});
    CHECK_EQ(warned.exit_code, 0);
    CHECK_MSG(warned.out.find("warnings   1\n  " + lines_obj + ":5: ") != std::string::npos, warned.out);
    CHECK(warned.out.find("lines      3") != std::string::npos);
    const run_result drawn = render(dir, {lines_obj, "--turntable", "1", "--size", "32x32"});
    CHECK_MSG(drawn.exit_code == 0, drawn.err);
    CHECK(drawn.err.find(lines_obj + ":5: ") != std::string::npos && drawn.err.find("wireframe") != std::string::npos);
    const pgm_image img = frame(dir, "frame_000.pgm");
    int lit = 0;
    for (const unsigned char v : img.pixels) lit += v > background + 20;
    CHECK(img.width == 32 && lit > 20);
}

TEST(bad_command_lines_exit_2_and_bad_files_exit_1_writing_nothing) {
    if (!render_built()) return;
    const std::vector<std::vector<std::string>> usage_errors = {
        {cube_obj, "--mode", "splat"},          {cube_obj, "--turntable", "0"},
        {cube_obj, "--turntable", "4", "--frames", "0:4"}, {cube_obj, "--frames", "0:36"},
        {cube_obj, "--light", "0,0,0"},         {cube_obj, "--light", "1,2"},
        {cube_obj, "--light", "1,2,3,nan"},     {cube_obj, "--fov", "180"},
        {cube_obj, "--eye", "1,2,3x"},          {cube_obj, "--up", "0,0,0"},
        {cube_obj, "--ambient", "1e999"},       {cube_obj, "--threads", "0"},
        {cube_obj, "--aa", "3"},                {cube_obj, "--aa", ""},
        {cube_obj, "--mode", "wireframe", "--texture", "t.pgm"}, {},
        {cube_obj, "other.obj"},
    };
    for (const auto &args : usage_errors) {
        temp_dir dir;
        const run_result r = render(dir, args);
        std::string line;
        for (const std::string &a : args) line += " " + a;
        CHECK_MSG(r.exit_code == 2, "render" + line + ": exit " + std::to_string(r.exit_code) + ": " + r.err);
        CHECK_MSG(!fs::exists(dir.path / "out"), "render" + line + " wrote files");
    }
    temp_dir dir;
    write_file(dir.path / "bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
    const std::vector<std::vector<std::string>> run_errors = {
        {"/nonexistent.obj"},
        {(dir.path / "bad.obj").string()},
        {"tests/data/tetra_ascii.ply", "--texture", cube_obj},                 // a mesh without uvs
        {cube_obj, "--texture", (dir.path / "missing.pgm").string()},
    };
    for (const auto &args : run_errors) {
        const run_result r = render(dir, args);
        CHECK_MSG(r.exit_code == 1, "render " + args[0] + ": exit " + std::to_string(r.exit_code) + ": " + r.err);
        CHECK_MSG(!r.err.empty(), "no message");
        CHECK(!fs::exists(dir.path / "out"));
    }
}

TEST(gif_holds_the_frames_of_the_range_byte_for_byte) {
    if (!render_built()) return;
    temp_dir dir;
    const std::string gif = (dir.path / "turn.gif").string();
    const run_result r = render(dir, {cube_obj, "--size", "40x30", "--turntable", "6", "--frames", "1:4", "--fps", "20",
                                      "--gif", gif});
    CHECK_MSG(r.exit_code == 0, r.err);
    CHECK(r.out.find("wrote " + gif) != std::string::npos);
    const gif_decoder::decoded_gif g = gif_decoder::decode_gif(file_bytes(gif));
    CHECK_MSG(g.problem.empty(), g.problem);
    CHECK_EQ(g.frames.size(), std::size_t{4});
    CHECK_EQ(g.loop_count, 0);
    for (std::size_t k = 0; k < g.frames.size(); ++k) {
        const pgm_image img = frame(dir, "frame_00" + std::to_string(k + 1) + ".pgm");
        CHECK_EQ(img.width, 40);
        CHECK_MSG(std::equal(img.pixels.begin(), img.pixels.end(), g.frames[k].begin(), g.frames[k].end()),
                  "frame " + std::to_string(k + 1) + " differs from its PGM");
        CHECK_EQ(g.delays[k], 5);  // 20 fps: 5 hundredths each
    }
}

TEST(gif_alone_writes_no_frames_and_its_errors_leave_nothing) {
    if (!render_built()) return;
    temp_dir dir;
    const std::string gif = (dir.path / "only.gif").string();
    run_result r = run(demo_path("render"), {cube_obj, "--size", "24x24", "--turntable", "3", "--gif", gif}, dir.path);
    CHECK_MSG(r.exit_code == 0, r.err);
    const auto files = files_in(dir.path);
    CHECK(files.count("only.gif") == 1);
    CHECK(!fs::exists(dir.path / "out"));
    CHECK_EQ(gif_decoder::decode_gif(files.at("only.gif")).frames.size(), std::size_t{3});

    temp_dir empty;
    r = render(empty, {cube_obj, "--size", "24x24", "--gif", (empty.path / "x.gif").string(), "--fps", "60"});
    CHECK_EQ(r.exit_code, 2);  // GIF delays cannot make 60 fps: refused before anything is written
    CHECK(r.err.find("--fps 60") != std::string::npos);
    const std::string missing = (empty.path / "no_folder" / "x.gif").string();
    r = render(empty, {cube_obj, "--size", "24x24", "--turntable", "2", "--gif", missing});
    CHECK_EQ(r.exit_code, 1);
    CHECK_MSG(r.err.find(missing) != std::string::npos, r.err);
    CHECK(!fs::exists(missing));
    CHECK(!fs::exists(missing + ".tmp"));
}
