// lighting.cpp — the lit, animated multi-object demo (the report's Task 4).
//
// The soccer ball, a torus (both wireframes) and a filled Phong-shaded icosphere travel
// along closed Bezier loops on ONE clock in seconds, each spinning, lit by two lights plus
// ambient. 120 frames at --fps (default 30) are one period: the loop closes, and the demo
// checks it at the end by rendering the instant one period after frame 0 and comparing
// pixel by pixel. --faithful-lambert lights the wireframes with the report's per-edge
// Lambert (about half of the edges go black) instead of the face-normal model.
//
//   lighting [--out DIR] [--frames A:B] [--size WxH] [--fps F] [--faithful-lambert] [--png]
#include <cstdio>
#include <string>
#include <vector>

#include "common/demo_cli.h"
#include "animation.h"
#include "scene.h"

namespace {

constexpr int FRAME_COUNT = 120;  // one full period
constexpr int DEFAULT_SIZE = 480;
constexpr double DEFAULT_FPS = 30.0;
constexpr float AMBIENT = 0.12f;

struct actor {
    tiny3d::mesh shape;
    tiny3d::object_style style;
    std::vector<vec3_t> loop;  // points the closed path passes through
    double path_offset;        // distance fraction at t = 0
    vec3_t spin_axis;
    int spin_turns;            // per period (any sign)
    float scale;
};

std::vector<actor> cast() {
    tiny3d::object_style wire;
    wire.line_thickness = 1.2f;
    tiny3d::object_style solid;
    solid.mode = tiny3d::draw_mode::filled;
    solid.shade = tiny3d::shading::phong;
    return {
        {tiny3d::make_soccer_ball(1.0f), wire, {{-1.6f, 0.2f, 0.5f}, {0.0f, 1.3f, -0.6f}, {1.6f, 0.3f, 0.4f}, {0.0f, -1.0f, 1.0f}},
         0.0, {0.3f, 1.0f, 0.1f}, 1, 0.9f},
        {tiny3d::make_torus(1.0f, 0.35f, 24, 12), wire,
         {{1.8f, -1.2f, -1.0f}, {-1.8f, -1.4f, 0.0f}, {-1.2f, 1.4f, -1.4f}, {1.4f, 1.2f, -0.4f}}, 0.25, {1.0f, 0.2f, 0.0f}, -1,
         0.6f},
        {tiny3d::make_icosphere(2), solid, {{0.0f, 0.0f, -2.5f}, {2.2f, 0.0f, -1.5f}, {0.0f, 0.3f, -0.8f}, {-2.2f, 0.0f, -1.5f}},
         0.5, {0.0f, 0.0f, 1.0f}, 2, 0.5f},
    };
}

}  // namespace

int main(int argc, char **argv) {
    demo::command_line cli("lighting", "",
                           "The lit, animated scene (the report's Task 4): the soccer ball and a torus (wireframes)\n"
                           "and a Phong-shaded icosphere on closed Bezier loops, two lights plus ambient, 120 frames\n"
                           "for one period; at the end the demo checks that the loop closes.");
    bool faithful = false;
    double fps = DEFAULT_FPS;
    cli.add_sequence_options(FRAME_COUNT, DEFAULT_SIZE, DEFAULT_SIZE);
    cli.number("--fps", fps, 0.001, 1000.0, "frames per second (default 30)");
    cli.flag("--faithful-lambert", faithful, "light the wireframes with the report's per-edge Lambert");
    if (const int status = cli.parse(argc, argv); status >= 0) return status;
    const demo::common_options &o = cli.common;

    // One period = the whole sequence: every motion repeats after FRAME_COUNT frames.
    const double period = tiny3d::anim_clock::at_frame(FRAME_COUNT, fps).seconds;
    tiny3d::scene scene;
    scene.cam.eye = {0.0f, 1.0f, 8.0f};
    scene.cam.fov_y = 0.75f;
    scene.ambient = AMBIENT;
    scene.edge_model = faithful ? tiny3d::edge_lighting::faithful_lambert : tiny3d::edge_lighting::face_normals;
    // Key light from the upper left front, fill light from the right (towards the lights).
    scene.lights = {{{-1.0f, 1.0f, 0.8f}, 0.75f}, {{1.0f, -0.2f, 0.6f}, 0.35f}};

    std::vector<tiny3d::motion> motions;
    for (const actor &a : cast()) {
        auto path = tiny3d::looped_path::through_points(a.loop);
        if (!path) return cli.fail(path.message());
        auto spin = tiny3d::orientation_loop::spin(a.spin_axis, a.spin_turns);
        if (!spin) return cli.fail(spin.message());
        motions.push_back({std::move(path.value()), period, a.path_offset, std::move(spin.value()), period, a.scale});
        if (auto id = scene.add_object(a.shape, a.style); !id) return cli.fail(id.message());
    }

    auto canvas = tiny3d::make_canvas(o.width, o.height);
    if (!canvas) return cli.fail(canvas.message());
    if (tiny3d::status s = demo::prepare_out_dir(o); !s) return cli.fail(s.message());
    auto render_at = [&](double seconds, canvas_t &target) {
        for (std::size_t i = 0; i < motions.size(); ++i) scene.set_model(i, tiny3d::motion_model_at(motions[i], seconds));
        return scene.render(target);
    };

    demo::progress timer("lighting", o.frames_to_render());
    for (int frame = o.first_frame; frame <= o.last_frame; ++frame) {
        timer.start();
        const tiny3d::status s = render_at(tiny3d::anim_clock::at_frame(frame, fps).seconds, **canvas);
        timer.stop();
        if (!s) return cli.fail(s.message());
        if (tiny3d::status w = timer.save(**canvas, demo::frame_path(o, frame), o.png); !w) return cli.fail(w.message());
    }
    timer.finish();

    // The loop closes: frame 0 and the instant one period later are the same image.
    auto again = tiny3d::make_canvas(o.width, o.height);
    if (!again) return cli.fail(again.message());
    if (auto s = render_at(tiny3d::anim_clock::at_frame(0, fps).seconds, **canvas); !s) return cli.fail(s.message());
    if (auto s = render_at(tiny3d::anim_clock::at_frame(FRAME_COUNT, fps).seconds, **again); !s)
        return cli.fail(s.message());
    const std::size_t pixels = static_cast<std::size_t>(o.width) * static_cast<std::size_t>(o.height);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < pixels; ++i) differing += (*canvas)->data[i] != (*again)->data[i];
    if (differing != 0)
        return cli.fail("loop does not close: " + std::to_string(differing) + " pixels differ between frame 0 and frame " +
                                 std::to_string(FRAME_COUNT));
    std::fprintf(stderr, "lighting: loop closes: frame %d (t = %.3f s) is pixel-identical to frame 0\n", FRAME_COUNT, period);
    return 0;
}
