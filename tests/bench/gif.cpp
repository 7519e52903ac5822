// gif.cpp — saving a sequence: the 36-frame torus turntable of
// `render tests/data/torus_binary.ply --size 512x512` (render's default scene, from
// demo/common/render_scene.h; --aa 4, 2 threads), rendered once and then saved as
// 36 PGM files (save_pgm, the report's format: the faithful row), as 36 PNG files
// (save_png) and as one animated GIF (gif_writer, lossless). Time per frame includes
// writing the file (and its fsync); the "error" columns hold the bytes per frame instead
// (the GIF's total / 36), as all three formats are lossless. The render row is the time
// of drawing one frame, for comparison (no file).
#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/bench.h"
#include "animation.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"
#include "../../demo/common/render_scene.h"

namespace {

using namespace demo::render_scene;  // render's default scene, constants, camera and lights

constexpr int kSide = 512, kFrames = 36;
constexpr double kNsPerMs = 1e6;

double file_size(const std::string &path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 ? double(st.st_size) : NAN;
}

// render's default camera and lights for a mesh fitted into the unit sphere, square view.
tiny3d::draw_params default_scene() {
    const camera cam = make_camera({}, {{0, 0, 0}, 1.0f}, 1.0f);
    tiny3d::draw_params p;
    p.view_projection = mat4_multiply(cam.projection, cam.view);
    p.lights = make_lights({}, kAmbient, cam).value();
    p.shade = tiny3d::shading::phong;
    p.surface.specular = kSpecular;
    p.surface.shininess = kShininess;
    return p;
}

}  // namespace

int main(int argc, char **argv) {
    const bench::options o = bench::parse_options(argc, argv);
    const int repeats = o.quick ? 1 : 5;
    auto loaded = tiny3d::load_mesh("tests/data/torus_binary.ply");
    if (!loaded) {
        std::fprintf(stderr, "gif: %s\n", loaded.message().c_str());
        return 1;
    }
    tiny3d::mesh &m = *loaded;
    if (auto fit = tiny3d::mesh_fit_unit_sphere(m); !fit) return 1;
    if (m.corner_normals.empty())
        if (tiny3d::status st = tiny3d::mesh_set_crease_normals(m, float(kCrease)); !st) return 1;
    const tiny3d::raster_mesh shape = tiny3d::make_raster_mesh(m, {}).value();
    tiny3d::draw_params params = default_scene();
    tiny3d::render_context ctx(2);

    // Render the turntable once, keeping every frame; time the rendering of each.
    std::vector<tiny3d::canvas_ptr> frames;
    std::vector<double> render_ms;
    for (int round = 0; round < repeats; ++round)
        for (int k = 0; k < kFrames; ++k) {
            if (round == 0) frames.push_back(tiny3d::make_canvas(kSide, kSide).value());
            const double t0 = tiny3d::frame_clock::steady_seconds();
            if (!ctx.begin_frame(*frames[std::size_t(k)], kBackground, tiny3d::sample_count::x4)) return 1;
            params.model = tiny3d::mat4_rotate_axis({0, 1, 0}, float(2.0 * kPi * k / kFrames));
            ctx.draw(shape, params);
            ctx.end_frame();
            render_ms.push_back(1e3 * (tiny3d::frame_clock::steady_seconds() - t0));
        }

    const std::string folder = o.out_dir + "/gif_frames";
    if (::mkdir(o.out_dir.c_str(), 0755) != 0 && errno != EEXIST) return 1;
    if (::mkdir(folder.c_str(), 0755) != 0 && errno != EEXIST) return 1;
    auto frame_file = [&](int k, const char *ext) {
        char name[32];
        std::snprintf(name, sizeof name, "/frame_%03d.%s", k, ext);
        return folder + name;
    };
    bool ok = true;
    const bench::timing pgm = bench::measure_ns(repeats, kFrames, [&] {
        for (int k = 0; k < kFrames; ++k) ok = tiny3d::save_pgm(*frames[std::size_t(k)], frame_file(k, "pgm")).ok() && ok;
    });
    const bench::timing png = bench::measure_ns(repeats, kFrames, [&] {
        for (int k = 0; k < kFrames; ++k) ok = tiny3d::save_png(*frames[std::size_t(k)], frame_file(k, "png")).ok() && ok;
    });
    const std::string gif_path = o.out_dir + "/gif_torus_turntable.gif";
    const bench::timing gif = bench::measure_ns(repeats, kFrames, [&] {
        auto writer = tiny3d::gif_writer::create(gif_path, kSide, kSide, {});
        ok = writer.ok() && ok;
        if (!writer) return;
        for (const tiny3d::canvas_ptr &f : frames) ok = writer->add_frame(*f).ok() && ok;
        ok = writer->finish().ok() && ok;
    });
    if (!ok) {
        std::fprintf(stderr, "gif: a file could not be written under %s\n", o.out_dir.c_str());
        return 1;
    }
    double pgm_bytes = 0, png_bytes = 0;
    for (int k = 0; k < kFrames; ++k) pgm_bytes += file_size(frame_file(k, "pgm")), png_bytes += file_size(frame_file(k, "png"));
    const double gif_bytes = file_size(gif_path);
    const auto ms = [](bench::timing t) { return bench::timing{t.median / kNsPerMs, t.min / kNsPerMs, t.max / kNsPerMs}; };
    const auto per_frame = [](double total) { return total / kFrames; };
    char share[160];
    std::snprintf(share, sizeof share, "one file of %.0f bytes: %.1f %% of the PGM files' %.0f", gif_bytes,
                  100.0 * gif_bytes / pgm_bytes, pgm_bytes);
    const std::string unit = "bytes/frame (file size, lossless)";
    std::vector<bench::row> rows = {
        {"gif", "PGM files (save_pgm)", "faithful", "ms/frame", ms(pgm), per_frame(pgm_bytes), per_frame(pgm_bytes), unit,
         "36 files, each written atomically (fsync)"},
        {"gif", "PNG files (save_png, stored deflate)", "other", "ms/frame", ms(png), per_frame(png_bytes),
         per_frame(png_bytes), unit, "36 files, each written atomically (fsync)"},
        {"gif", "animated GIF (gif_writer)", "fast", "ms/frame", ms(gif), per_frame(gif_bytes), per_frame(gif_bytes), unit,
         share},
        {"gif", "render the frame (--aa 4, 2 threads)", "reference", "ms/frame", bench::summarise(render_ms), NAN, NAN, unit,
         "drawing only, no file: what encoding is compared with"},
    };
    return bench::report(o, "gif", rows, "Saving the torus turntable (512x512): time per frame vs bytes per frame");
}
