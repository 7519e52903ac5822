// ply_render_test.cpp — the PLY ray-cast program: camera equations against hand values, the
// fast path equal to the per-pixel ray cast on shipped and generated meshes at several
// rotations, the same image from ascii, both binary byte orders and reordered headers,
// and the program's exit codes.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "harness.h"
#include "canvas.h"
#include "lab.h"
#include "math3d.h"
#include "mesh.h"

using namespace tiny3d;

namespace {

constexpr double DEG = M_PI / 180.0;

int differing(const lab_image &a, const lab_image &b) {
    if (a.pixels.size() != b.pixels.size()) return -1;
    int n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) n += a.pixels[i] != b.pixels[i];
    return n;
}

int lit(const lab_image &a) {
    int n = 0;
    for (std::uint8_t v : a.pixels) n += v != 0;
    return n;
}

// A PLY file's bytes for mesh m: ascii, or binary with the given byte order; `reorder` puts
// an extra property first and the face element's extra property after the list.
std::string ply_bytes(const mesh &m, const std::string &format, bool reorder) {
    std::string h = "ply\nformat " + format + " 1.0\ncomment test\n";
    h += "element vertex " + std::to_string(m.positions.size()) + "\n";
    if (reorder) h += "property float confidence\nproperty float z\nproperty float y\nproperty float x\n";
    else h += "property float x\nproperty float y\nproperty float z\n";
    h += "element face " + std::to_string(m.face_count()) + "\nproperty list uchar int vertex_indices\n";
    if (reorder) h += "property uchar flags\n";
    h += "end_header\n";
    const bool ascii = format == "ascii", big = format == "binary_big_endian";
    auto put = [&](const void *p, std::size_t n) {
        const char *c = static_cast<const char *>(p);
        for (std::size_t i = 0; i < n; ++i) h += c[big ? n - 1 - i : i];  // host is little-endian x86-64
    };
    for (const vec3_t &p : m.positions) {
        const float order[4] = {0.5f, p.z, p.y, p.x};
        const float *f = reorder ? order : order + 1;
        const int count = reorder ? 4 : 3;
        if (ascii) {
            for (int k = 0; k < count; ++k) h += std::to_string(reorder ? f[k] : (k == 0 ? p.x : k == 1 ? p.y : p.z)) + " ";
            h += "\n";
        } else {
            for (int k = 0; k < count; ++k) {
                const float v = reorder ? f[k] : (k == 0 ? p.x : k == 1 ? p.y : p.z);
                put(&v, 4);
            }
        }
    }
    for (std::size_t f = 0; f < m.face_count(); ++f) {
        const unsigned char n = static_cast<unsigned char>(m.face_size(f));
        if (ascii) h += std::to_string(n);
        else h += static_cast<char>(n);
        for (std::uint32_t k = m.face_start[f]; k < m.face_start[f + 1]; ++k) {
            const std::int32_t idx = static_cast<std::int32_t>(m.indices[k]);
            if (ascii) h += " " + std::to_string(idx);
            else put(&idx, 4);
        }
        if (reorder) {
            if (ascii) h += " 7";
            else h += static_cast<char>(7);
        }
        if (ascii) h += "\n";
    }
    return h;
}

}  // namespace

TEST(lab_camera_follows_equations_1_to_12) {
    mesh m;
    m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.add_face({0, 1, 2});
    const lab_camera c = ply_lab_camera(m, 0, 0, 0).value();
    CHECK_NEAR(c.extent, 2.0, 0);
    CHECK_NEAR(c.center[0], 1.0, 0);
    CHECK_NEAR(c.camera[0], 1.0 + 3.0, 1e-12);  // 1.5·E·⟨1,0,0⟩ + centre
    // left = up × (centre − camera) = ⟨0,0,1⟩ × ⟨−3,0,0⟩ = ⟨0,−3,0⟩, scaled to E/2 = 1.
    CHECK_NEAR(c.left[1], 0.5 - 1.0, 1e-12);
    CHECK_NEAR(c.right[1], 0.5 + 1.0, 1e-12);
    CHECK_NEAR(c.topleft[2], 0.5 + 1.0, 1e-12);
    // 90° about Z turns the camera to +y.
    const lab_camera r = ply_lab_camera(m, 0, 0, 90 * DEG).value();
    CHECK_NEAR(r.camera[1], 0.5 + 3.0, 1e-12);
    CHECK_NEAR(r.up[2], 1.0, 1e-12);
    CHECK(!ply_lab_camera(mesh{}, 0, 0, 0).ok());
}

TEST(fast_equals_raycast_on_shipped_and_generated_meshes) {
    std::vector<mesh> meshes;
    result<mesh> tetra = load_ply("tests/data/tetra_ascii.ply");
    CHECK_MSG(tetra.ok(), tetra.message());
    if (tetra) meshes.push_back(*tetra);
    meshes.push_back(make_soccer_ball(1.0f));   // pentagons and hexagons: fans
    meshes.push_back(make_torus(1.0f, 0.4f, 24, 12));
    meshes.push_back(make_icosphere(2));
    const double rotations[][3] = {{0, 0, 0}, {90, 45, -135}, {30, -60, 10}, {180, 0, 90}, {-45, 120, 33}};
    for (const mesh &m : meshes)
        for (const auto &rot : rotations) {
            const lab_camera cam = ply_lab_camera(m, rot[0] * DEG, rot[1] * DEG, rot[2] * DEG).value();
            const lab_image slow = raycast_lab(m, cam, 96), fast = render_lab_fast(m, cam, 96);
            CHECK_EQ(differing(slow, fast), 0);
            CHECK(lit(slow) > 96 * 96 / 20);
        }
    // At the lab's own size on the tetrahedron too.
    if (tetra) {
        const lab_camera cam = ply_lab_camera(*tetra, 90 * DEG, 45 * DEG, -135 * DEG).value();
        CHECK_EQ(differing(raycast_lab(*tetra, cam), render_lab_fast(*tetra, cam)), 0);
    }
}

TEST(lab_colours_and_background) {
    mesh m = make_soccer_ball(1.0f);
    const lab_camera cam = ply_lab_camera(m, 0, 0, 0).value();
    const lab_image img = render_lab_fast(m, cam, 64);
    CHECK_EQ(img.pixels[0], 0);  // a corner: background
    for (std::uint8_t v : img.pixels) CHECK(v == 0 || (v >= 155 && v < 255));
}

TEST(same_image_from_every_ply_encoding_and_header_order) {
    const mesh m = make_torus(1.0f, 0.4f, 16, 8);
    lab_image first;
    for (const char *format : {"ascii", "binary_little_endian", "binary_big_endian"})
        for (bool reorder : {false, true}) {
            result<mesh> parsed = parse_ply(ply_bytes(m, format, reorder), "gen.ply");
            CHECK_MSG(parsed.ok(), std::string(format) + ": " + parsed.message());
            if (!parsed) continue;
            const lab_camera cam = ply_lab_camera(*parsed, 90 * DEG, 45 * DEG, -135 * DEG).value();
            const lab_image img = render_lab_fast(*parsed, cam, 64);
            if (first.pixels.empty()) first = img;
            // ascii goes through decimal text: positions differ by < 1e-6, allow a few pixels.
            CHECK(differing(first, img) >= 0 && differing(first, img) <= 3);
        }
}

TEST(program_writes_ppm_and_pgm_and_rejects_bad_input) {
    const char *build = std::getenv("BUILD");
    const std::string exe = (build ? std::string(build) : std::string("build")) + "/demo/ply_render";
    if (std::FILE *f = std::fopen(exe.c_str(), "rb")) {
        std::fclose(f);
    } else {
        std::fprintf(stderr, "note: %s not built, skipping the program checks\n", exe.c_str());
        return;
    }
    const std::string out = "/tmp/tiny3d_ply_render_test.ppm";
    CHECK_EQ(std::system((exe + " tests/data/tetra_ascii.ply 90 45 -135 " + out + " >/dev/null 2>&1").c_str()), 0);
    std::FILE *f = std::fopen(out.c_str(), "rb");
    CHECK(f != nullptr);
    if (f) {
        char magic[3] = {};
        CHECK_EQ(std::fread(magic, 1, 2, f), std::size_t{2});
        CHECK(std::strcmp(magic, "P6") == 0);
        std::fclose(f);
        std::remove(out.c_str());
    }
    // The binary torus of `make demo` at --size 64x64: background corners, every lit pixel
    // 155 + (i mod 100), and many triangles' greys (the colour rule shows).
    const std::string pgm = "/tmp/tiny3d_ply_render_test.pgm";
    CHECK_EQ(std::system((exe + " tests/data/torus_binary.ply 0 60 20 " + pgm + " --size 64x64 >/dev/null 2>&1").c_str()), 0);
    result<canvas_ptr> image = load_pgm(pgm);
    CHECK_MSG(image.ok(), image.message());
    if (image) {
        const canvas_t &c = **image;
        CHECK(c.width == 64 && c.height == 64);
        CHECK_EQ(c.pixels[0][0], 0.0f);
        bool seen[256] = {};
        int distinct = 0, wrong = 0;
        for (int y = 0; y < c.height; ++y)
            for (int x = 0; x < c.width; ++x) {
                const int v = int(std::lround(c.pixels[y][x] * 255.0f));
                if (v != 0 && (v < 155 || v > 254)) ++wrong;
                if (v != 0 && !seen[v]) {
                    seen[v] = true;
                    ++distinct;
                }
            }
        CHECK_EQ(wrong, 0);
        CHECK_MSG(distinct >= 30, std::to_string(distinct) + " distinct greys");
        std::remove(pgm.c_str());
    }
    CHECK(std::system((exe + " tests/data/tetra_ascii.ply 90 45 >/dev/null 2>&1").c_str()) != 0);
    CHECK(std::system((exe + " tests/data/tetra_ascii.ply 90 x -135 /tmp/x.pgm >/dev/null 2>&1").c_str()) != 0);
    CHECK(std::system((exe + " /nonexistent.ply 0 0 0 /tmp/x.pgm >/dev/null 2>&1").c_str()) != 0);
}
