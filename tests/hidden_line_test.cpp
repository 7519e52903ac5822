// hidden_line_test.cpp — wireframes over filled objects (wireframe_options::depth_test): an
// edge behind a filled surface is hidden, one in front or on it is drawn as without the
// test, and "always on top" (no buffer) draws everything; the same test for one point
// (depth_point_visible) and the depth buffer a scene exposes for it (scene::depth).
#include <algorithm>
#include <cmath>

#include "harness.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"
#include "scene.h"
#include "wireframe.h"

using namespace tiny3d;

namespace {

constexpr int W = 64, H = 32;

// A filled quad over the left half of the canvas (clip x ∈ [−1, 0]) at NDC depth 0 (window
// depth 0.5), drawn flat by the render context with identity matrices.
void fill_left_half(canvas_t &canvas, render_context &ctx) {
    raster_mesh q;
    q.positions = {{-1, -1, 0}, {0, -1, 0}, {0, 1, 0}, {-1, 1, 0}};
    q.normals.assign(4, vec3_t{0, 0, 1});
    q.uvs.assign(4, vec2{0, 0});
    q.triangles = {{0, 1, 2}, {0, 2, 3}};
    q.bound_center = {-0.5f, 0, 0};
    q.bound_radius = 2;
    draw_params p;
    p.model = mat4_identity();
    p.view_projection = mat4_identity();
    p.lights = make_light_rig(std::span<const light_t>(), 0.2f).value();
    p.shade = shading::flat;
    CHECK(ctx.begin_frame(canvas).ok());
    ctx.draw(q, p);
    ctx.end_frame();
}

// One horizontal edge across the canvas at NDC depth z (and a slanted one from z_left to
// z_right, when given), drawn with the coverage line.
mesh edge_at(float z_left, float z_right) {
    mesh m;
    m.positions = {{-0.9f, 0.1f, z_left}, {0.9f, 0.1f, z_right}};
    m.edges = {{0, 1}};
    return m;
}

// Ink (intensity above the quad's 0.2 or the background's 0) in the columns [x0, x1).
double ink(const canvas_t &c, const canvas_t &base, int x0, int x1) {
    double sum = 0;
    for (int y = 0; y < H; ++y)
        for (int x = x0; x < x1; ++x) sum += std::fabs(c.pixels[y][x] - base.pixels[y][x]);
    return sum;
}

struct frame {
    canvas_ptr filled = make_canvas(W, H).value(), with_lines = make_canvas(W, H).value();
};

frame draw(const mesh &m, bool depth_tested, float bias = 1e-4f) {
    frame f;
    render_context ctx(1);
    fill_left_half(*f.filled, ctx);
    fill_left_half(*f.with_lines, ctx);
    wireframe_options o;
    o.method = line_method::coverage;
    o.thickness = 1.5f;
    o.depth_sort = false;
    o.depth_test = depth_tested ? &ctx.depth() : nullptr;
    o.depth_bias = bias;
    wireframe_workspace ws;
    CHECK(render_wireframe(*f.with_lines, m, mat4_identity(), o, ws).ok());
    return f;
}

}  // namespace

TEST(an_edge_behind_a_filled_surface_is_hidden) {
    const frame behind = draw(edge_at(0.5f, 0.5f), true);  // window depth 0.75 > 0.5
    // Hidden over the quad, up to ~1.5 px from its edge (test points whose 2 × 2 pixels reach
    // the background, half a step, the round cap).
    CHECK_NEAR(ink(*behind.with_lines, *behind.filled, 0, W / 2 - 3), 0.0, 1e-6);
    CHECK(ink(*behind.with_lines, *behind.filled, W / 2 + 1, W) > 20);            // drawn beside it
    // Always on top: drawn over the quad too.
    const frame on_top = draw(edge_at(0.5f, 0.5f), false);
    CHECK(ink(*on_top.with_lines, *on_top.filled, 0, W / 2 - 1) > 20);
}

TEST(an_edge_in_front_of_or_on_a_surface_is_drawn_as_without_the_test) {
    for (float z : {-0.5f, 0.0f}) {  // in front; on the surface (depth equal: kept by the bias)
        const frame tested = draw(edge_at(z, z), true), plain = draw(edge_at(z, z), false);
        int differ = 0;
        for (int i = 0; i < W * H; ++i) differ += tested.with_lines->data[i] != plain.with_lines->data[i];
        CHECK_EQ(differ, 0);
    }
    // With no bias, an edge on the surface is still kept where it lies exactly on it.
    const frame on = draw(edge_at(0.0f, 0.0f), true, 0.0f);
    CHECK(ink(*on.with_lines, *on.filled, 0, W / 2 - 1) > 20);
}

TEST(a_slanted_edge_is_cut_where_it_passes_behind) {
    // NDC depth from −0.5 at x = −0.9 to +0.5 at x = 0.9: in front of the quad (depth 0)
    // for x < 0, behind it for x > 0 — but the quad ends at x = 0, so only its left part
    // is over the quad, in front: all visible. Reversed (behind on the left): the left part
    // is hidden, the right part (off the quad) drawn.
    const frame front = draw(edge_at(-0.5f, 0.5f), true), plain = draw(edge_at(-0.5f, 0.5f), false);
    CHECK_NEAR(ink(*front.with_lines, *plain.with_lines, 0, W), 0.0, 1e-6);
    const frame back = draw(edge_at(0.5f, -0.5f), true);
    CHECK_NEAR(ink(*back.with_lines, *back.filled, 0, W / 2 - 3), 0.0, 1e-6);
    CHECK(ink(*back.with_lines, *back.filled, W / 2 + 1, W) > 20);
}

TEST(depth_test_buffer_of_another_size_is_an_error) {
    canvas_ptr c = make_canvas(W, H).value(), small = make_canvas(8, 8).value();
    render_context ctx(1);
    CHECK(ctx.begin_frame(*small).ok());
    ctx.end_frame();
    wireframe_options o;
    o.depth_test = &ctx.depth();
    wireframe_workspace ws;
    CHECK(!render_wireframe(*c, edge_at(0, 0), mat4_identity(), o, ws).ok());
    render_context big(1);
    CHECK(big.begin_frame(*c).ok());
    big.end_frame();
    o.depth_test = &big.depth();
    o.depth_bias = NAN;
    CHECK(!render_wireframe(*c, edge_at(0, 0), mat4_identity(), o, ws).ok());
    o.depth_bias = 0;
    CHECK(render_wireframe(*c, edge_at(0, 0), mat4_identity(), o, ws).ok());
}

// The scene draws wireframes hidden behind its filled objects (scene::hidden_lines), or on
// top when asked: a wireframe sphere behind a filled one leaves the filled disc untouched.
TEST(scene_hides_wireframe_edges_behind_filled_objects) {
    constexpr int S = 96;
    auto render = [&](bool with_wire, bool hidden) {
        scene sc;
        sc.lights = {{{1, 1, 1}, 1.0f}};
        sc.hidden_lines = hidden;
        object_style filled;
        filled.mode = draw_mode::filled;
        const std::size_t ball = sc.add_object(make_icosphere(3), filled).value();
        sc.set_model(ball, mat4_identity());
        if (with_wire) {
            const std::size_t wire = sc.add_object(make_icosphere(2), object_style{}).value();
            sc.set_model(wire, mat4_multiply(mat4_translate(0, 0, -4), mat4_scale(3, 3, 3)));
        }
        canvas_ptr c = make_canvas(S, S).value();
        CHECK(sc.render(*c).ok());
        return c;
    };
    const canvas_ptr alone = render(false, true), hidden = render(true, true), on_top = render(true, false);
    double hidden_diff = 0, on_top_diff = 0;
    for (int y = S / 2 - 12; y < S / 2 + 12; ++y)  // well inside the filled sphere's disc
        for (int x = S / 2 - 12; x < S / 2 + 12; ++x) {
            hidden_diff += std::fabs(hidden->pixels[y][x] - alone->pixels[y][x]);
            on_top_diff += std::fabs(on_top->pixels[y][x] - alone->pixels[y][x]);
        }
    CHECK_NEAR(hidden_diff, 0.0, 1e-6);
    CHECK(on_top_diff > 1.0);
}

// depth_point_visible, the hidden-line test for one point, on a hand-made buffer: the
// largest of the 2 × 2 stored depths around the point plus the bias decides; positions are
// clamped to the buffer; NaN is hidden; an empty buffer hides nothing.
TEST(depth_point_visible_takes_the_largest_of_the_four_pixels_around_the_point) {
    zbuffer z;
    CHECK(z.resize(4, 3).ok());
    z.clear(0.5f);
    z.row(1)[2] = 0.7f;  // pixel centre (2.5, 1.5)
    // (2.0, 1.0) lies between the centres of pixels (1..2) × (0..1): the 0.7 is among them.
    CHECK(depth_point_visible(z, 2.0f, 1.0f, 0.69f, 0.0f));
    CHECK(depth_point_visible(z, 2.0f, 1.0f, 0.7f, 0.0f));
    CHECK(!depth_point_visible(z, 2.0f, 1.0f, 0.71f, 0.0f));
    CHECK(depth_point_visible(z, 2.0f, 1.0f, 0.71f, 0.02f));  // the bias
    // (1.2, 1.0): pixels (0..1) × (0..1), all 0.5.
    CHECK(depth_point_visible(z, 1.2f, 1.0f, 0.5f, 0.0f));
    CHECK(!depth_point_visible(z, 1.2f, 1.0f, 0.51f, 0.0f));
    CHECK(depth_point_visible(z, 1.2f, 1.0f, 0.50009f, 1e-4f));  // the default bias's size
    // Off the buffer: clamped to the last column (x = 3, all 0.5; the 0.7 at x = 2 is not
    // among them) and the first.
    CHECK(depth_point_visible(z, 100.0f, 1.5f, 0.5f, 0.0f));
    CHECK(!depth_point_visible(z, 100.0f, 1.5f, 0.6f, 0.0f));
    CHECK(!depth_point_visible(z, -100.0f, 1.5f, 0.6f, 0.0f));
    CHECK(!depth_point_visible(z, NAN, 1.0f, 0.1f, 0.0f));
    CHECK(!depth_point_visible(z, 1.0f, 1.0f, NAN, 0.0f));
    CHECK(depth_point_visible(zbuffer{}, 1.0f, 1.0f, 0.9f, 0.0f));
}

// scene::depth: the filled objects' window depths of the last render (null before it and
// after a render without filled objects): at the centre of a sphere of radius 1 seen from
// z = 5, the front point (0, 0, 1) at window depth 0.5·z_ndc + 0.5 of the camera's
// perspective (near 0.1, far 100), to the tessellation's error.
TEST(scene_depth_holds_the_filled_objects_window_depths) {
    constexpr int S = 64;
    scene sc;
    sc.cam.eye = {0, 0, 5};
    sc.lights = {{{0, 0, 1}, 1.0f}};
    CHECK(sc.depth() == nullptr);
    object_style filled;
    filled.mode = draw_mode::filled;
    const std::size_t ball = sc.add_object(make_icosphere(4), filled).value();
    canvas_ptr c = make_canvas(S, S).value();
    CHECK(sc.render(*c).ok());
    const zbuffer *z = sc.depth();
    CHECK(z != nullptr);
    if (!z) return;
    CHECK_EQ(z->width(), S);
    CHECK_EQ(z->height(), S);
    const double n = sc.cam.near_plane, f = sc.cam.far_plane, d = 4.0;  // eye-space distance of (0, 0, 1)
    const double z_ndc = (f + n) / (f - n) - 2 * f * n / ((f - n) * d);
    const double centre = std::max({z->at(S / 2 - 1, S / 2 - 1), z->at(S / 2, S / 2 - 1), z->at(S / 2 - 1, S / 2),
                                    z->at(S / 2, S / 2)});
    CHECK_NEAR(centre, 0.5 * z_ndc + 0.5, 2e-5);  // the flat facets lie ≤ 0.002 behind the sphere
    CHECK_EQ(z->at(0, 0), 1.0f);  // background
    // A point inside the sphere (its centre) is hidden, the front point is not.
    const double d0 = 5.0, z0 = 0.5 * ((f + n) / (f - n) - 2 * f * n / ((f - n) * d0)) + 0.5;
    CHECK(!depth_point_visible(*z, S / 2.0f, S / 2.0f, static_cast<float>(z0)));
    CHECK(depth_point_visible(*z, S / 2.0f, S / 2.0f, static_cast<float>(0.5 * z_ndc + 0.5)));
    sc.style(ball).mode = draw_mode::wireframe;
    CHECK(sc.render(*c).ok());
    CHECK(sc.depth() == nullptr);
}
