// soccer.cpp — the libtiny3d report's Task 3 demo: the soccer ball (truncated icosahedron,
// 60 vertices, 90 edges, from the report's generate_soccer_ball) turning inside a circular
// viewport, 60 frames per full turn about the y axis (frame k at angle 2π·k/60, so frame 60
// would equal frame 0), 512×512 default. The ball also comes nearer and goes back once per
// turn (its image from 90 % to 130 % of the circle's radius), so in the middle of the loop
// the circular viewport visibly cuts its silhouette. By default edges are clipped in clip space, then
// to the circle inscribed in the canvas (the report's circular viewport), drawn far to near
// with anti-aliased coverage lines and depth cueing (far edges dimmer). With --report the
// ball is drawn as the report's demo drew it: its 7-argument render_wireframe
// (project_vertex, draw_line_f at thickness 1, the report's pixels). Either way the
// circle's rim is drawn as a thin ring.
//
//   soccer [--out DIR] [--frames A:B] [--size WxH] [--report] [--png]   → DIR/frame_000.pgm … frame_059.pgm
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "common/demo_cli.h"
#include "canvas.h"
#include "lines.h"
#include "math3d.h"
#include "mesh.h"
#include "pipeline.h"
#include "wireframe.h"

namespace {

constexpr int kSize = 512;
constexpr int kFramesPerTurn = 60;
constexpr float kTilt = 0.35f;          // radians about x, so the poles are not edge-on
constexpr float kBallFill = 0.9f;       // at frame 0 the ball's image spans 90 % of the circle's radius,
constexpr float kNearFill = 1.3f;       // half a turn later 130 %: the circle cuts the silhouette
constexpr float kFovY = 0.75f;          // radians
constexpr float kEdgeThickness = 1.6f;  // px
constexpr float kFarInk = 0.3f;         // depth cue: ink of the farthest edges
constexpr float kRimThickness = 1.0f;
constexpr float kRimInk = 0.5f;
constexpr int kRimSegments = 180;

// generate_soccer_ball's arrays, freed when it goes.
struct report_ball {
    vec3_t *vertices = nullptr;
    int (*edges)[2] = nullptr;
    int vertex_count = 0, edge_count = 0;
    ~report_ball() { free_soccer_ball(vertices, edges); }
};

float frame_angle(int frame) { return float(2.0 * M_PI * (frame % kFramesPerTurn) / kFramesPerTurn); }

// The share of the circle's radius the ball's image spans: kBallFill at frame 0, kNearFill
// half a turn later, eased by e² with e = (1 − cos)/2 so the loop closes smoothly and the
// ball stays inside the circle for the first and last sixths of it.
float ball_fill(int frame) {
    const float e = 0.5f * (1.0f - std::cos(frame_angle(frame)));
    return kBallFill + (kNearFill - kBallFill) * e * e;
}

// The circular viewport's rim as a polygon of short coverage lines.
void draw_rim(canvas_t &canvas) {
    const tiny3d::circle c = tiny3d::circular_viewport(canvas);
    const float r = c.radius - kRimThickness;
    tiny3d::line_style style;
    style.intensity = kRimInk;
    for (int i = 0; i < kRimSegments; ++i) {
        const double a0 = 2.0 * M_PI * i / kRimSegments, a1 = 2.0 * M_PI * (i + 1) / kRimSegments;
        tiny3d::draw_line_coverage(&canvas, c.cx + r * float(std::cos(a0)), c.cy + r * float(std::sin(a0)),
                                   c.cx + r * float(std::cos(a1)), c.cy + r * float(std::sin(a1)), kRimThickness,
                                   style);
    }
}

// The circular viewport as a mask: each pixel keeps the share of it inside the circle
// (clamp(r − d + ½, 0, 1), d its centre's distance from the circle's centre: the exact
// share for a straight edge through the pixel), so nothing drawn — not the round ends of
// thick edges clipped at the circle — shows outside it.
void mask_to_circle(canvas_t &canvas) {
    const tiny3d::circle c = tiny3d::circular_viewport(canvas);
    for (int y = 0; y < canvas.height; ++y)
        for (int x = 0; x < canvas.width; ++x) {
            const float d = std::hypot(float(x) + 0.5f - c.cx, float(y) + 0.5f - c.cy);
            canvas.pixels[y][x] *= std::clamp(c.radius - d + 0.5f, 0.0f, 1.0f);
        }
}

}  // namespace

int main(int argc, char **argv) {
    demo::command_line cli("soccer", "",
                           "The libtiny3d report's Task 3: the soccer ball (truncated icosahedron, 90 edges) turning\n"
                           "inside a circular viewport, anti-aliased edges with depth cueing, 60 frames for one turn.");
    bool report_lines = false;
    cli.add_sequence_options(kFramesPerTurn, kSize, kSize);
    cli.flag("--report", report_lines, "draw the ball with the report's render_wireframe (draw_line_f, its pixels)");
    if (const int status = cli.parse(argc, argv); status >= 0) return status;
    const demo::common_options &o = cli.common;
    auto canvas = tiny3d::make_canvas(o.width, o.height);
    if (!canvas) return cli.fail(canvas.message());
    if (tiny3d::status s = demo::prepare_out_dir(o); !s) return cli.fail(s.message());

    // The report's generator: 60 positions and 90 edges as plain arrays (the same ball as
    // tiny3d::make_soccer_ball, whose faces the wireframe does not need).
    report_ball arrays;
    if (!generate_soccer_ball(&arrays.vertices, &arrays.vertex_count, &arrays.edges, &arrays.edge_count))
        return cli.fail("out of memory");
    tiny3d::mesh ball;
    ball.positions.assign(arrays.vertices, arrays.vertices + arrays.vertex_count);
    for (int i = 0; i < arrays.edge_count; ++i)
        ball.edges.push_back({std::uint32_t(arrays.edges[i][0]), std::uint32_t(arrays.edges[i][1])});
    const tiny3d::bounding_sphere bounds = tiny3d::mesh_bounding_sphere(ball);
    const mat4_t proj = tiny3d::mat4_perspective(kFovY, float(o.width) / float(o.height), 0.1f, 100.0f);
    // Distance at which the bounding sphere's silhouette (half-angle asin(R/d)) spans
    // `fill` of the half field of view: d = R / sin(atan(fill·tan(fov/2))).
    auto distance = [&](float fill) { return bounds.radius / std::sin(std::atan(fill * std::tan(0.5f * kFovY))); };
    tiny3d::wireframe_options options;
    options.method = tiny3d::line_method::coverage;
    options.thickness = kEdgeThickness;
    options.depth_cue = true;
    options.depth_cue_far = kFarInk;
    options.circular_viewport = true;
    options.bounds = &bounds;
    tiny3d::wireframe_workspace workspace;

    demo::progress timer("soccer", o);
    for (int frame = o.first_frame; frame <= o.last_frame; ++frame) {
        timer.start();
        canvas_clear(canvas->get(), 0.0f);
        const mat4_t model = mat4_multiply(mat4_translate(0, 0, -distance(ball_fill(frame))),
                                           mat4_multiply(mat4_rotate_xyz(kTilt, 0, 0), tiny3d::mat4_rotate_y(frame_angle(frame))));
        if (report_lines) {
            render_wireframe(canvas->get(), arrays.vertices, arrays.vertex_count, arrays.edges, arrays.edge_count, model, proj);
        } else if (tiny3d::status s = tiny3d::render_wireframe(**canvas, ball, mat4_multiply(proj, model), options, workspace);
                   !s) {
            return cli.fail(s.message());
        }
        draw_rim(**canvas);
        mask_to_circle(**canvas);
        timer.stop();
        if (tiny3d::status s = timer.save(**canvas, demo::frame_path(o, frame), o.png); !s) return cli.fail(s.message());
    }
    if (tiny3d::status done = timer.finish(); !done) return cli.fail(done.message());
    return 0;
}
