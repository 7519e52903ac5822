// shaded — filled rendering: a rotating torus (top row) and soccer ball (middle row) in
// flat, Gouraud and Phong shading (left to right), two textured cubes (bottom row) mapped
// affine (left) and perspective-correct (right), and a translucent sphere drifting in front
// of them. 36 frames, 10° per frame, into build/frames/shaded/.
//   shaded [--out DIR] [--frames A:B] [--size WxH] [--threads N]
#include <cmath>
#include <string>
#include <vector>

#include "common/demo_cli.h"
#include "renderer.h"

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
    return t;
}

float radians(float degrees) { return degrees * static_cast<float>(M_PI) / 180.0f; }

}  // namespace

int main(int argc, char **argv) {
    auto parsed = demo::parse(argc, argv, "shaded", 960, 720, FRAMES);
    if (!parsed) return demo::fail("shaded", parsed.message());
    demo::options &o = *parsed;
    int threads = 2;
    if (auto t = demo::take_value(o, "--threads")) threads = std::atoi(t->c_str());
    if (tiny3d::status s = demo::check_no_rest(o, "shaded [--out DIR] [--frames A:B] [--size WxH] [--threads N]"); !s)
        return demo::fail(o, s.message());
    if (threads < 1) return demo::fail(o, "--threads must be a positive integer");
    if (tiny3d::status s = demo::prepare_out_dir(o); !s) return demo::fail(o, s.message());

    auto torus = smooth(tiny3d::make_torus(0.8f, 0.32f, 48, 24));
    auto ball = smooth(tiny3d::make_soccer_ball(0.95f));
    auto ball_faceted = tiny3d::make_raster_mesh(tiny3d::make_soccer_ball(0.95f), {});
    auto cube = tiny3d::make_raster_mesh(tiny3d::make_cube(0.85f), {});
    auto sphere = smooth(tiny3d::make_icosphere(3));
    for (const auto *m : {&torus, &ball, &ball_faceted, &cube, &sphere})
        if (!*m) return demo::fail(o, m->message());
    const tiny3d::texture tex = checker();
    auto canvas = tiny3d::make_canvas(o.width, o.height);
    if (!canvas) return demo::fail(o, canvas.message());

    const light_t lights[2] = {{{1, 1, 1}, 0.85f}, {{-1, 0.2f, 0.4f}, 0.25f}};
    auto rig = tiny3d::make_light_rig(lights, 0.1f);
    if (!rig) return demo::fail(o, rig.message());
    const float aspect = static_cast<float>(o.width) / static_cast<float>(o.height);
    const mat4_t view_projection = mat4_multiply(tiny3d::mat4_perspective(radians(45), aspect, 0.1f, 100.0f),
                                                 tiny3d::mat4_look_at({0, 0, 9.5f}, {0, 0, 0}, {0, 1, 0}));
    tiny3d::render_context ctx(threads);
    demo::frame_timer timer("shaded", o.last_frame - o.first_frame + 1);
    for (int frame = o.first_frame; frame <= o.last_frame; ++frame) {
        const float angle = radians(DEGREES_PER_FRAME * static_cast<float>(frame));
        timer.start();
        if (tiny3d::status s = ctx.begin_frame(**canvas, 0.02f); !s) return demo::fail(o, s.message());
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
        if (tiny3d::status s = demo::save_frame(**canvas, demo::frame_path(o, frame)); !s) return demo::fail(o, s.message());
    }
    timer.report();
    return 0;
}
