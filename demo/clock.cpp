// clock.cpp — the libtiny3d report's clock face: lines every 15° from the canvas centre,
// radius 200 px, thickness 1.5, drawn twice on 512×512 canvases: with the report's
// draw_line_f (clock_lines.pgm) and with the exact-coverage line (clock_lines_fast.pgm).
//
//   clock [--out DIR] [--size WxH] [--png]   (clock --help lists the options)
#include <cmath>
#include <string>

#include "canvas.h"
#include "lines.h"
#include "common/demo_cli.h"

namespace {

constexpr int kSize = 512;
constexpr float kRadius = 200.0f;
constexpr float kThickness = 1.5f;
constexpr int kStepDegrees = 15;
constexpr double kPi = 3.14159265358979323846;

// The report's spokes, computed as its main.c does (float radians from a double product,
// cosf / sinf), so clock_lines.pgm is the report's image bit for bit. `offset` moves them
// into another pixel convention: 0 for draw_line_f (integer coordinates are pixel
// centres, the report's), 0.5 for the library's lines (pixel centres at +0.5), so both
// images show the same spokes on the same pixels.
template <class DrawLine>
void draw_clock(canvas_t &canvas, float offset, DrawLine &&draw_line) {
    const float cx = float(canvas.width) / 2.0f, cy = float(canvas.height) / 2.0f;  // as in the report
    for (int degrees = 0; degrees < 360; degrees += kStepDegrees) {
        const float rad = float(degrees * kPi / 180.0f);
        const float x = cx + kRadius * std::cos(rad), y = cy + kRadius * std::sin(rad);
        draw_line(&canvas, cx + offset, cy + offset, x + offset, y + offset);
    }
}

}  // namespace

int main(int argc, char **argv) {
    demo::command_line cli("clock", "",
                           "The libtiny3d report's clock face: lines every 15 degrees from the centre, radius 200 px,\n"
                           "thickness 1.5, drawn with the report's draw_line_f (clock_lines.pgm) and with the exact\n"
                           "coverage line (clock_lines_fast.pgm).");
    cli.add_out();
    cli.add_size(kSize, kSize);
    cli.add_png();
    if (const int status = cli.parse(argc, argv); status >= 0) return status;
    const demo::common_options &o = cli.common;

    auto faithful = tiny3d::make_canvas(o.width, o.height);
    auto fast = tiny3d::make_canvas(o.width, o.height);
    if (!faithful) return cli.fail(faithful.message());
    if (!fast) return cli.fail(fast.message());
    if (tiny3d::status s = demo::prepare_out_dir(o); !s) return cli.fail(s.message());

    demo::progress timer("clock", 2);
    timer.start();
    draw_clock(**faithful, 0.0f, [](canvas_t *c, float x0, float y0, float x1, float y1) {
        draw_line_f(c, x0, y0, x1, y1, kThickness);
    });
    timer.stop();
    timer.start();
    draw_clock(**fast, 0.5f, [](canvas_t *c, float x0, float y0, float x1, float y1) {
        tiny3d::draw_line_coverage(c, x0, y0, x1, y1, kThickness);
    });
    timer.stop();

    if (tiny3d::status s = timer.save(**faithful, o.out_dir + "/clock_lines.pgm", o.png); !s) return cli.fail(s.message());
    if (tiny3d::status s = timer.save(**fast, o.out_dir + "/clock_lines_fast.pgm", o.png); !s) return cli.fail(s.message());
    timer.finish();
    return 0;
}
