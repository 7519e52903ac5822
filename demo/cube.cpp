// cube.cpp — the libtiny3d report's Task 2 demo: a ±1 wireframe cube turning about the
// y axis, 60 frames through one full turn (angle = 2π·k/60), 512×512 by default.
// Pipeline exactly as the report's: model = translate(0,0,−5)·rotate_xyz(0, angle, 0)·
// scale(1,1,1); mvp = frustum(−1,1,−1,1,1,10)·model; apply_transform (divides by w);
// NDC → pixels with x = (x+1)/2·W, y = (1 − (y+1)/2)·H; the 12 edges with draw_line_f
// at thickness 1.2. Frame k depends only on k (the angle is taken modulo one turn), so
// frame 0 and the frame one turn later are the same image (tests/math3d_test.cpp).
//
//   cube [--out DIR] [--frames A:B] [--size WxH] [--png]   → DIR/frame_000.pgm … frame_059.pgm
#include <cmath>
#include <string>

#include "canvas.h"
#include "lines.h"
#include "math3d.h"
#include "common/demo_cli.h"

namespace {

constexpr int kSize = 512;
constexpr int kFramesPerTurn = 60;
constexpr float kThickness = 1.2f;
constexpr float kDistance = 5.0f;  // the cube's centre sits at z = −5

constexpr vec3_t kCube[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                             {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                               {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

// Radians for frame k: 2π·(k mod N)/N, in double, rounded once.
float frame_angle(int frame) { return float(2.0 * M_PI * (frame % kFramesPerTurn) / kFramesPerTurn); }

void render_cube(canvas_t &canvas, float angle) {
    const mat4_t scale = mat4_scale(1.0f, 1.0f, 1.0f);
    const mat4_t rotate = mat4_rotate_xyz(0.0f, angle, 0.0f);
    const mat4_t translate = mat4_translate(0.0f, 0.0f, -kDistance);
    const mat4_t frustum = mat4_frustum_asymmetric(-1, 1, -1, 1, 1, 10);
    const mat4_t mvp = mat4_multiply(frustum, mat4_multiply(translate, mat4_multiply(rotate, scale)));
    vec3_t projected[8];
    for (int i = 0; i < 8; ++i) {
        vec3_t p = apply_transform(mvp, kCube[i]);
        p.x = (p.x + 1.0f) * 0.5f * float(canvas.width);
        p.y = (1.0f - (p.y + 1.0f) * 0.5f) * float(canvas.height);
        projected[i] = p;
    }
    for (const auto &edge : kEdges) {
        const vec3_t a = projected[edge[0]], b = projected[edge[1]];
        draw_line_f(&canvas, a.x, a.y, b.x, b.y, kThickness);
    }
}

}  // namespace

int main(int argc, char **argv) {
    demo::command_line cli("cube", "",
                           "The libtiny3d report's Task 2: a wireframe cube turning about the y axis, 60 frames for\n"
                           "one turn (frame_000.pgm ... frame_059.pgm), drawn with the report's draw_line_f.");
    cli.add_sequence_options(kFramesPerTurn, kSize, kSize);
    if (const int status = cli.parse(argc, argv); status >= 0) return status;
    const demo::common_options &o = cli.common;

    auto canvas = tiny3d::make_canvas(o.width, o.height);  // one canvas, cleared per frame
    if (!canvas) return cli.fail(canvas.message());
    if (tiny3d::status s = demo::prepare_out_dir(o); !s) return cli.fail(s.message());

    demo::progress timer("cube", o);
    for (int frame = o.first_frame; frame <= o.last_frame; ++frame) {
        timer.start();
        canvas_clear(canvas->get(), 0.0f);
        render_cube(**canvas, frame_angle(frame));
        timer.stop();
        if (tiny3d::status s = timer.save(**canvas, demo::frame_path(o, frame), o.png); !s) return cli.fail(s.message());
    }
    if (tiny3d::status done = timer.finish(); !done) return cli.fail(done.message());
    return 0;
}
