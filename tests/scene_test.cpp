// scene_test.cpp — the flat scene: camera, lit wireframes (both edge models), filled
// shading levels against hand-computed values, looped animation pixel-exact.
#include <cmath>
#include <vector>

#include "animation.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "pipeline.h"
#include "raster.h"
#include "scene.h"
#include "wireframe.h"
#include "harness.h"

namespace {

constexpr int SIDE = 96;

tiny3d::canvas_ptr blank() { return tiny3d::make_canvas(SIDE, SIDE).value(); }

double max_difference(const canvas_t &a, const canvas_t &b) {
    double worst = 0;
    for (int i = 0; i < a.width * a.height; ++i) worst = std::max(worst, double(std::fabs(a.data[i] - b.data[i])));
    return worst;
}

bool identical(const canvas_t &a, const canvas_t &b) {
    for (int i = 0; i < a.width * a.height; ++i)
        if (a.data[i] != b.data[i]) return false;
    return true;
}

// A scene looking at the origin from +z, one light and ambient.
void setup(tiny3d::scene &s, light_t light, float ambient) {
    s.cam.eye = {0, 0, 5};
    s.cam.fov_y = 0.7f;
    s.lights = {light};
    s.ambient = ambient;
}

// The same wireframe drawn directly with render_wireframe and the given per-edge inks.
tiny3d::canvas_ptr drawn_by_hand(const tiny3d::scene &s, const tiny3d::mesh &m, const mat4_t &model,
                                 const std::vector<float> &ink) {
    auto want = blank();
    tiny3d::wireframe_options o;
    o.method = tiny3d::line_method::coverage;
    o.edge_intensity = ink;
    tiny3d::wireframe_workspace ws;
    const mat4_t vp = tiny3d::camera_view_projection(s.cam, SIDE, SIDE).value();
    CHECK(tiny3d::render_wireframe(*want, m, mat4_multiply(vp, model), o, ws).ok());
    return want;
}

}  // namespace

TEST(camera_view_projection_checks_its_input) {
    tiny3d::camera cam;
    CHECK(tiny3d::camera_view_projection(cam, 100, 50).ok());
    CHECK(!tiny3d::camera_view_projection(cam, 0, 50).ok());
    cam.fov_y = 4.0f;  // > π
    CHECK(!tiny3d::camera_view_projection(cam, 100, 50).ok());
    cam.fov_y = 0.8f;
    cam.near_plane = -1;
    CHECK(!tiny3d::camera_view_projection(cam, 100, 50).ok());
    // The origin, straight ahead, lands on the canvas centre.
    cam = {};
    const mat4_t vp = tiny3d::camera_view_projection(cam, 100, 50).value();
    const auto p = tiny3d::project_point({0, 0, 0}, vp, 100, 50);
    CHECK_NEAR(p.x, 50.0, 1e-4);
    CHECK_NEAR(p.y, 25.0, 1e-4);
}

TEST(wireframe_edges_lit_by_mean_face_normal) {
    // Cube rotated so several edges face the light at different angles. Expected ink per edge,
    // computed here in double: a cube edge's normal is its midpoint direction (the mean of the
    // two face normals), rotated by the model; ink = ambient + I·max(0, n·L).
    const tiny3d::mesh cube = tiny3d::make_cube(1.0f);
    const mat4_t model = mat4_rotate_xyz(0.4f, 0.7f, 0.1f);
    const light_t light = {{0.3f, 0.8f, 0.5f}, 0.7f};
    tiny3d::scene s;
    setup(s, light, 0.15f);
    const auto id = s.add_object(cube, {});
    CHECK(id.ok());
    s.set_model(id.value(), model);
    auto got = blank();
    CHECK(s.render(*got).ok());

    const double llen = std::sqrt(0.09 + 0.64 + 0.25);
    std::vector<float> ink;
    for (const auto &e : cube.edges) {
        const vec3_t mid = (cube.positions[e.a] + cube.positions[e.b]) * 0.5f;  // (±1, ±1, 0) and permutations
        const vec3_t n = tiny3d::transform_direction(model, mid);
        const double len = std::sqrt(double(n.x) * n.x + double(n.y) * n.y + double(n.z) * n.z);
        const double cosine = (n.x * 0.3 + n.y * 0.8 + n.z * 0.5) / (len * llen);
        ink.push_back(float(std::min(1.0, 0.15 + 0.7 * std::max(0.0, cosine))));
    }
    CHECK_NEAR(max_difference(*got, *drawn_by_hand(s, cube, model, ink)), 0.0, 1e-5);
    // And something was drawn.
    double sum = 0;
    for (int i = 0; i < SIDE * SIDE; ++i) sum += got->data[i];
    CHECK(sum > 50);
}

TEST(wireframe_faithful_flag_uses_the_reports_lambert) {
    const tiny3d::mesh ball = tiny3d::make_soccer_ball(1.2f);
    const light_t light = {{1, 1, 1}, 1.0f};
    tiny3d::scene s;
    setup(s, light, 0.1f);
    s.edge_model = tiny3d::edge_lighting::faithful_lambert;
    const auto id = s.add_object(ball, {});
    const mat4_t model = mat4_translate(0.2f, -0.1f, 0.0f);
    s.set_model(id.value(), model);
    auto got = blank();
    CHECK(s.render(*got).ok());
    std::vector<float> ink;  // the report's formula on world-space endpoints, no ambient
    for (const auto &e : ball.edges)
        ink.push_back(lambert_intensity(apply_transform(model, ball.positions[e.a]), apply_transform(model, ball.positions[e.b]),
                                        {1, 1, 1}));
    std::size_t black = 0;
    for (float v : ink) black += v == 0.0f;
    CHECK(black > 30 && black < 60);  // about half of the 90 edges
    CHECK_NEAR(max_difference(*got, *drawn_by_hand(s, ball, model, ink)), 0.0, 1e-5);
}

TEST(filled_cube_flat_gouraud_phong_hand_values) {
    // Front face of an axis-aligned cube faces the camera (+z). Light along +z, I = 0.6,
    // ambient 0.2. Flat: n = +z → 0.8. Gouraud: every front vertex normal is (±1, ±1, 1)/√3
    // → 0.2 + 0.6/√3 everywhere on the face. Phong: the interpolated normal at the face
    // centre is +z again → 0.8.
    const tiny3d::mesh cube = tiny3d::make_cube(0.8f);
    const light_t light = {{0, 0, 1}, 0.6f};
    const double expect[3] = {0.8, 0.2 + 0.6 / std::sqrt(3.0), 0.8};
    const tiny3d::shading levels[3] = {tiny3d::shading::flat, tiny3d::shading::gouraud, tiny3d::shading::phong};
    for (int i = 0; i < 3; ++i) {
        tiny3d::scene s;
        setup(s, light, 0.2f);
        tiny3d::object_style style;
        style.mode = tiny3d::draw_mode::filled;
        style.shade = levels[i];
        CHECK(s.add_object(cube, style).ok());
        auto c = blank();
        CHECK(s.render(*c).ok());
        // The pixels at the centre straddle the face centre; the face spans ±15 px.
        CHECK_NEAR(get_pixel(c.get(), SIDE / 2, SIDE / 2), expect[i], 0.01);
        CHECK_NEAR(get_pixel(c.get(), 2, 2), 0.0, 0.0);  // background
    }
}

TEST(looped_animation_is_pixel_exact_after_one_period) {
    // Three objects on one clock: a path loop of 4 s, spins of 2 s and 4 s. Frame 0 and the
    // frame one period later (120 frames at 30 fps), and the same instant at 24 fps.
    const tiny3d::mesh ball = tiny3d::make_soccer_ball(0.6f), cube = tiny3d::make_cube(0.4f);
    const std::vector<vec3_t> loop = {{-1.5f, 0, 0}, {0, 1, -1}, {1.5f, 0, 0}, {0, -1, 1}};
    tiny3d::scene s;
    setup(s, {{1, 1, 1}, 0.8f}, 0.1f);
    std::vector<tiny3d::motion> motions(2);
    for (int i = 0; i < 2; ++i) {
        motions[i].path = tiny3d::looped_path::through_points(loop).value();
        motions[i].path_period_s = 4.0;
        motions[i].path_offset = 0.5 * i;
        motions[i].orientation = tiny3d::orientation_loop::spin({0.3f, 1, 0.2f}, i + 1).value();
        motions[i].orientation_period_s = 2.0 * (i + 1);
    }
    CHECK(s.add_object(ball, {}).ok());
    tiny3d::object_style filled;
    filled.mode = tiny3d::draw_mode::filled;
    CHECK(s.add_object(cube, filled).ok());
    auto render_at = [&](double t) {
        for (std::size_t i = 0; i < 2; ++i) s.set_model(i, tiny3d::motion_model_at(motions[i], t));
        auto c = blank();
        CHECK(s.render(*c).ok());
        return c;
    };
    const auto first = render_at(tiny3d::anim_clock::at_frame(0, 30).seconds);
    const auto later = render_at(tiny3d::anim_clock::at_frame(120, 30).seconds);
    CHECK(identical(*first, *later));
    const auto mid30 = render_at(tiny3d::anim_clock::at_frame(45, 30).seconds);
    const auto mid24 = render_at(tiny3d::anim_clock::at_frame(36, 24).seconds);
    CHECK(identical(*mid30, *mid24));
    CHECK(!identical(*first, *mid30));  // it does move
}

TEST(scene_reports_bad_input) {
    tiny3d::scene s;
    s.lights = {{{0, 0, 0}, 1.0f}};  // zero direction
    CHECK(s.add_object(tiny3d::make_cube(1.0f), {}).ok());
    auto c = blank();
    const auto st = s.render(*c);
    CHECK(!st.ok() && st.message().find("light 0") != std::string::npos);
    tiny3d::object_style bad;
    bad.line_thickness = -1;
    CHECK(!s.add_object(tiny3d::make_cube(1.0f), bad).ok());
    tiny3d::mesh broken;
    broken.positions = {{0, 0, 0}};
    broken.add_face({0, 1, 2});
    const auto r = s.add_object(broken, {});
    CHECK(!r.ok() && r.message().find("object 1") != std::string::npos);
}
