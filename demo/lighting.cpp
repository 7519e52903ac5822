// lighting.cpp — the lit, animated multi-object demo (the report's Task 4).
//
// A wireframe soccer ball, torus and cube follow one closed Bezier loop round the whole
// frame, a third of it apart, while a Phong-shaded sphere runs a figure of eight through
// the middle; every object spins. Two lights plus ambient; the key light sweeps from the
// upper left to the upper right and back once per loop (the report's vec3_slerp), and
// each path is dotted in faintly (points from the report's vec3_bezier, placed with its
// project_vertex and set_pixel_f).
//
// Everything is placed by TIME: frame k shows the instant k / fps, so --fps changes how
// many frames the loop takes (period · fps) and never where things are at a given time
// (frame 10 at 30 fps is frame 20 at 60 fps). At the end the demo renders t = 0 and
// t = period and fails unless they are pixel-identical (the loop closes).
// --faithful-lambert lights the wireframes with the report's per-edge Lambert (about half
// of the edges go black) instead of the face-normal model.
//
//   lighting [--out DIR] [--frames A:B] [--size WxH] [--fps F] [--period S] [--faithful-lambert] [--aa N] [--png]
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/demo_cli.h"
#include "animation.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "pipeline.h"
#include "raster.h"
#include "scene.h"

namespace {

constexpr int DEFAULT_SIZE = 480;
constexpr double DEFAULT_PERIOD_S = 4.0;
constexpr float AMBIENT = 0.12f;
constexpr float TRAIL_INK = 0.2f;      // each dot of a path
constexpr int TRAIL_DOTS_PER_SEGMENT = 14;
constexpr double PI = 3.14159265358979323846;

struct actor {
    tiny3d::mesh shape;
    tiny3d::object_style style;
    int loop;              // index into loops()
    double path_offset;    // distance fraction along the loop at t = 0
    vec3_t spin_axis;
    int spin_turns;        // per period (any sign)
    float scale;
};

// The closed paths (world units; the camera frames x, y ∈ ±3 at z = 0): a rounded
// rectangle round the frame, nearer at the sides and farther at top and bottom, and a
// figure of eight through the middle, behind it.
std::vector<std::vector<vec3_t>> loops() {
    return {
        {{-2.1f, 2.0f, 0.0f}, {0.0f, 2.3f, -1.2f}, {2.1f, 2.0f, 0.0f}, {2.3f, 0.0f, 0.5f},
         {2.1f, -2.0f, 0.0f}, {0.0f, -2.3f, -1.2f}, {-2.1f, -2.0f, 0.0f}, {-2.3f, 0.0f, 0.5f}},
        {{0.0f, 0.0f, -0.8f}, {1.3f, 0.8f, -1.4f}, {1.5f, -0.6f, -1.8f}, {0.0f, 0.0f, -2.4f},
         {-1.5f, 0.6f, -1.8f}, {-1.3f, -0.8f, -1.4f}},
    };
}

std::vector<actor> cast() {
    tiny3d::object_style wire;
    wire.line_thickness = 1.2f;
    tiny3d::object_style solid;
    solid.mode = tiny3d::draw_mode::filled;
    solid.shade = tiny3d::shading::phong;
    return {
        {tiny3d::make_soccer_ball(1.0f), wire, 0, 0.0, {0.3f, 1.0f, 0.1f}, 1, 0.75f},
        {tiny3d::make_torus(1.0f, 0.35f, 24, 12), wire, 0, 1.0 / 3.0, {1.0f, 0.2f, 0.0f}, -1, 0.6f},
        {tiny3d::make_cube(1.0f), wire, 0, 2.0 / 3.0, {0.5f, 1.0f, 0.3f}, 1, 0.55f},
        {tiny3d::make_icosphere(3), solid, 1, 0.0, {0.0f, 0.0f, 1.0f}, 2, 0.6f},
    };
}

// The key light's direction at loop phase p: from the upper left (p = 0) to the upper
// right (p = ½) and back, eased (s = ½ − ½·cos 2πp), by the report's vec3_slerp.
vec3_t key_light_at(double phase) {
    const vec3_t upper_left = {-1.0f, 1.0f, 0.8f}, upper_right = {1.0f, 1.0f, 0.8f};
    const float s = float(0.5 - 0.5 * std::cos(2.0 * PI * phase));
    return vec3_slerp(upper_left, upper_right, s);
}

// The frames of one period at `fps`: the instants k / fps in [0, period).
int frames_per_period(double period_s, double fps) { return std::max(1, int(std::ceil(period_s * fps - 1e-9))); }

// Dots along each path: points from vec3_bezier on every segment, on screen through
// project_vertex (the report's viewport) and set_pixel_f (the report's pixel convention);
// with `depth` (the filled objects' window depths), a dot behind a filled object is hidden
// as the wireframes' edges are (depth_point_visible; window depth = 0.5·z/w + 0.5).
void draw_trails(canvas_t &canvas, const std::vector<tiny3d::looped_path> &paths, const mat4_t &view_proj,
                 const tiny3d::zbuffer *depth) {
    const mat4_t identity = mat4_identity();
    for (const tiny3d::looped_path &path : paths)
        for (std::size_t i = 0; i < path.segment_count(); ++i) {
            const tiny3d::cubic_bezier &c = path.segment(i);
            for (int k = 0; k < TRAIL_DOTS_PER_SEGMENT; ++k) {
                const vec3_t p = vec3_bezier(c.p0, c.p1, c.p2, c.p3, float(k) / TRAIL_DOTS_PER_SEGMENT);
                float x, y;
                if (!project_vertex(p, identity, view_proj, canvas.width, canvas.height, &x, &y)) continue;
                if (depth) {
                    const vec4_t clip = mat4_mul_vec4(view_proj, {p.x, p.y, p.z, 1.0f});
                    // project_vertex's viewport puts pixel centres at integers; the depth
                    // buffer's at +0.5.
                    if (!tiny3d::depth_point_visible(*depth, x + 0.5f, y + 0.5f, 0.5f * clip.z / clip.w + 0.5f))
                        continue;
                }
                set_pixel_f(&canvas, x, y, TRAIL_INK);
            }
        }
}

}  // namespace

int main(int argc, char **argv) {
    demo::command_line cli("lighting", "",
                           "The lit, animated scene (the report's Task 4): a wireframe soccer ball, torus and cube on\n"
                           "one closed Bezier loop round the frame and a Phong-shaded sphere on a figure of eight, two\n"
                           "lights plus ambient. Frame k shows the instant k / fps; one loop lasts --period seconds\n"
                           "(period · fps frames); at the end the demo checks that the loop closes.");
    bool faithful = false;
    double period = DEFAULT_PERIOD_S;
    const double &fps = cli.common.fps;  // --fps (demo_cli): frame k shows time k / fps
    cli.add_sequence_options([&] { return frames_per_period(period, fps); }, DEFAULT_SIZE, DEFAULT_SIZE);
    cli.number("--period", period, 0.1, 3600.0, "seconds per loop of every motion (default 4)");
    cli.flag("--faithful-lambert", faithful, "light the wireframes with the report's per-edge Lambert");
    cli.add_samples(tiny3d::sample_count::x4);
    if (const int status = cli.parse(argc, argv); status >= 0) return status;
    const demo::common_options &o = cli.common;

    tiny3d::scene scene;
    scene.cam.eye = {0.0f, 0.6f, 10.5f};
    scene.cam.fov_y = 0.75f;
    scene.ambient = AMBIENT;
    scene.samples = o.samples;
    scene.edge_model = faithful ? tiny3d::edge_lighting::faithful_lambert : tiny3d::edge_lighting::face_normals;
    // Key light from above (it sweeps left to right), fill light from the lower right front.
    scene.lights = {{key_light_at(0.0), 0.75f}, {{1.0f, -0.4f, 0.6f}, 0.3f}};

    std::vector<tiny3d::looped_path> paths;
    for (const std::vector<vec3_t> &points : loops()) {
        auto path = tiny3d::looped_path::through_points(points);
        if (!path) return cli.fail(path.message());
        paths.push_back(std::move(path.value()));
    }
    std::vector<tiny3d::motion> motions;
    for (const actor &a : cast()) {
        auto spin = tiny3d::orientation_loop::spin(a.spin_axis, a.spin_turns);
        if (!spin) return cli.fail(spin.message());
        motions.push_back({paths[std::size_t(a.loop)], period, a.path_offset, std::move(spin.value()), period, a.scale});
        if (auto id = scene.add_object(a.shape, a.style); !id) return cli.fail(id.message());
    }
    const auto view_proj = tiny3d::camera_view_projection(scene.cam, o.width, o.height);
    if (!view_proj) return cli.fail(view_proj.message());

    auto canvas = tiny3d::make_canvas(o.width, o.height);
    if (!canvas) return cli.fail(canvas.message());
    if (tiny3d::status s = demo::prepare_out_dir(o); !s) return cli.fail(s.message());
    auto render_at = [&](double seconds, canvas_t &target) {
        for (std::size_t i = 0; i < motions.size(); ++i) scene.set_model(i, tiny3d::motion_model_at(motions[i], seconds));
        scene.lights[0].direction = key_light_at(tiny3d::loop_phase(seconds, period));
        const tiny3d::status s = scene.render(target);
        if (s) draw_trails(target, paths, view_proj.value(), scene.depth());
        return s;
    };

    demo::progress timer("lighting", o);
    for (int frame = o.first_frame; frame <= o.last_frame; ++frame) {
        timer.start();
        const tiny3d::status s = render_at(tiny3d::anim_clock::at_frame(frame, fps).seconds, **canvas);
        timer.stop();
        if (!s) return cli.fail(s.message());
        if (tiny3d::status w = timer.save(**canvas, demo::frame_path(o, frame), o.png); !w) return cli.fail(w.message());
    }
    if (tiny3d::status done = timer.finish(); !done) return cli.fail(done.message());

    // The loop closes: t = 0 and t = period are the same image.
    auto again = tiny3d::make_canvas(o.width, o.height);
    if (!again) return cli.fail(again.message());
    if (auto s = render_at(0.0, **canvas); !s) return cli.fail(s.message());
    if (auto s = render_at(period, **again); !s) return cli.fail(s.message());
    const std::size_t pixels = static_cast<std::size_t>(o.width) * static_cast<std::size_t>(o.height);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < pixels; ++i) differing += (*canvas)->data[i] != (*again)->data[i];
    if (differing != 0)
        return cli.fail("loop does not close: " + std::to_string(differing) + " pixels differ between t = 0 and t = " +
                        std::to_string(period) + " s");
    std::fprintf(stderr, "lighting: loop closes: t = %.3f s (%d frames at %g fps) is pixel-identical to t = 0\n", period,
                 frames_per_period(period, fps), fps);
    return 0;
}
