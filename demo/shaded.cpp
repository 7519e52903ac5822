// shaded — filled rendering: a rotating torus (top row) and soccer ball (middle row) in
// flat, Gouraud and Phong shading (left to right), two textured cubes (bottom row) mapped
// affine (left) and perspective-correct (right), and a translucent sphere drifting in front
// of them. 36 frames, 10° per frame, into build/frames/shaded/.
//   shaded [--out DIR] [--frames A:B] [--size WxH] [--threads N] [--aa N] [--png]
#include <cmath>
#include <string>
#include <vector>

#include "common/demo_cli.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"

namespace {

constexpr int FRAMES = 36;
constexpr float DEGREES_PER_FRAME = 10.0f;
constexpr int CHECKER_SIDE = 64, CHECKER_CELL = 8;

tiny3d::result<tiny3d::raster_mesh> smooth(const tiny3d::mesh &m) {
    tiny3d::mesh plain = m;
    plain.corner_uvs.clear();
    return tiny3d::make_raster_mesh(plain, tiny3d::mesh_vertex_normals(plain));
}

tiny3d::texture checker() {
    tiny3d::texture t;
    t.width = t.height = CHECKER_SIDE;
    for (int y = 0; y < CHECKER_SIDE; ++y)
        for (int x = 0; x < CHECKER_SIDE; ++x)
            t.texels.push_back(((x / CHECKER_CELL + y / CHECKER_CELL) % 2) ? 1.0f : 0.25f);
    (void)tiny3d::build_mipmaps(t);  // cannot fail: the size and texel count match
    return t;
}

float radians(float degrees) { return degrees * static_cast<float>(M_PI) / 180.0f; }

}  // namespace

int main(int argc, char **argv) {
    demo::command_line cli("shaded", "",
                           "Filled rendering: a torus (top row) and a soccer ball (middle row) in flat, Gouraud and\n"
                           "Phong shading (left to right), two textured cubes mapped affine and perspective-correct\n"
                           "(bottom row) and a translucent sphere in front: 36 frames, 10 degrees per frame.");
    cli.add_sequence_options(FRAMES, 960, 720);
    cli.add_threads(2);
    cli.add_samples(tiny3d::sample_count::x4);
    if (const int status = cli.parse(argc, argv); status >= 0) return status;
    const demo::common_options &o = cli.common;

    auto torus = smooth(tiny3d::make_torus(0.8f, 0.32f, 48, 24));
    auto ball = smooth(tiny3d::make_soccer_ball(0.95f));
    auto ball_faceted = tiny3d::make_raster_mesh(tiny3d::make_soccer_ball(0.95f), {});
    auto cube = tiny3d::make_raster_mesh(tiny3d::make_cube(0.85f), {});
    auto sphere = smooth(tiny3d::make_icosphere(3));
    for (const auto *m : {&torus, &ball, &ball_faceted, &cube, &sphere})
        if (!*m) return cli.fail(m->message());
    const tiny3d::texture tex = checker();
    auto canvas = tiny3d::make_canvas(o.width, o.height);
    if (!canvas) return cli.fail(canvas.message());
    if (tiny3d::status s = demo::prepare_out_dir(o); !s) return cli.fail(s.message());

    const light_t lights[2] = {{{1, 1, 1}, 0.85f}, {{-1, 0.2f, 0.4f}, 0.25f}};
    auto rig = tiny3d::make_light_rig(lights, 0.1f);
    if (!rig) return cli.fail(rig.message());
    const float aspect = static_cast<float>(o.width) / static_cast<float>(o.height);
    const mat4_t view_projection = mat4_multiply(tiny3d::mat4_perspective(radians(45), aspect, 0.1f, 100.0f),
                                                 tiny3d::mat4_look_at({0, 0, 11.5f}, {0, 0, 0}, {0, 1, 0}));
    tiny3d::render_context ctx(o.threads);
    demo::progress timer("shaded", o);
    for (int frame = o.first_frame; frame <= o.last_frame; ++frame) {
        const float angle = radians(DEGREES_PER_FRAME * static_cast<float>(frame));
        timer.start();
        if (tiny3d::status s = ctx.begin_frame(**canvas, 0.02f, o.samples); !s) return cli.fail(s.message());
        tiny3d::draw_params p;
        p.view_projection = view_projection;
        p.lights = *rig;
        const tiny3d::shading levels[3] = {tiny3d::shading::flat, tiny3d::shading::gouraud, tiny3d::shading::phong};
        for (int k = 0; k < 3; ++k) {
            const float x = 2.7f * static_cast<float>(k - 1);
            p.shade = levels[k];
            p.model = mat4_multiply(mat4_translate(x, 2.3f, 0), mat4_rotate_xyz(0.9f + angle, angle, 0));
            ctx.draw(*torus, p);
            p.model = mat4_multiply(mat4_translate(x, 0, 0), mat4_rotate_xyz(0.3f, angle, 0.2f));
            ctx.draw(k == 0 ? *ball_faceted : *ball, p);
        }
        p.shade = tiny3d::shading::flat;
        p.tex = &tex;
        p.filter = tiny3d::texture_filter::trilinear;  // mipmapped: no stripes on faces seen edge-on
        for (int k = 0; k < 2; ++k) {
            p.perspective_correct = k == 1;
            p.model = mat4_multiply(mat4_translate(k == 0 ? -1.9f : 1.9f, -2.4f, 0.0f),
                                    mat4_rotate_xyz(0.5f, angle, 0.1f));
            ctx.draw(*cube, p);
        }
        p.tex = nullptr;
        p.shade = tiny3d::shading::phong;
        p.alpha = 0.45f;
        p.model = mat4_multiply(mat4_translate(2.2f * std::sin(angle), -1.6f, 2.6f), mat4_scale(0.8f, 0.8f, 0.8f));
        ctx.draw(*sphere, p);
        ctx.end_frame();
        timer.stop();
        if (tiny3d::status s = timer.save(**canvas, demo::frame_path(o, frame), o.png); !s) return cli.fail(s.message());
    }
    if (tiny3d::status done = timer.finish(); !done) return cli.fail(done.message());
    return 0;
}
