// pipeline_test.cpp — projection, viewport, clipping (near plane, frustum, circle), frustum
// culling and wireframes, against double-precision / analytic references.
#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "harness.h"
#include "canvas.h"
#include "lines.h"
#include "math3d.h"
#include "mesh.h"
#include "pipeline.h"
#include "wireframe.h"

using namespace tiny3d;

namespace {

constexpr int W = 200, H = 100;
constexpr double n_plane = 1.0, f_plane = 10.0;

// glFrustum([-1, 1] × [-1, 1], n = 1, f = 10): NDC x = x / −z, y = y / −z.
mat4_t test_proj() { return mat4_frustum_asymmetric(-1, 1, -1, 1, float(n_plane), float(f_plane)); }

// The same projection and viewport in double, written out from the definitions.
struct ref_point {
    double x, y, depth;
};
ref_point ref_project(double x, double y, double z) {
    const double ndc_x = n_plane * x / -z, ndc_y = n_plane * y / -z;
    const double ndc_z = (-(f_plane + n_plane) / (f_plane - n_plane) * z - 2 * f_plane * n_plane / (f_plane - n_plane)) / -z;
    return {(ndc_x + 1) / 2 * W, (1 - ndc_y) / 2 * H, (ndc_z + 1) / 2};
}
// The report's viewport (project_vertex): NDC ±1 → 0 and W − 1 (pixel centres).
ref_point ref_report_project(double x, double y, double z) {
    const ref_point r = ref_project(x, y, z);
    return {r.x / W * (W - 1), r.y / H * (H - 1), r.depth};
}

struct canvas_holder {
    canvas_ptr c;
    canvas_holder(int w, int h) : c(create_canvas(w, h)) {}
    canvas_t &operator*() { return *c; }
    double sum() const {
        double s = 0;
        for (int i = 0; i < c->width * c->height; ++i) s += c->data[i];
        return s;
    }
};

mesh single_edge(vec3_t a, vec3_t b) {
    mesh m;
    m.positions = {a, b};
    m.edges = {{0, 1}};
    return m;
}

wireframe_options plain_options() {
    wireframe_options o;
    o.method = line_method::coverage;
    o.thickness = 1.5f;
    o.frustum_cull = false;
    return o;
}

}  // namespace

TEST(project_known_points) {
    const mat4_t proj = test_proj(), id = mat4_identity();
    float x = -7, y = -7;
    // project_vertex keeps the report's viewport: NDC ±1 → the centres of the first and
    // last pixels (0 and W − 1), the axis → (W − 1)/2.
    CHECK_EQ(project_vertex({0, 0, -5}, id, proj, W, H, &x, &y), 1);
    CHECK_NEAR(x, (W - 1) / 2.0, 1e-4);
    CHECK_NEAR(y, (H - 1) / 2.0, 1e-4);
    CHECK_EQ(project_vertex({-1, 1, -1}, id, proj, W, H, &x, &y), 1);
    CHECK_NEAR(x, 0.0, 1e-4);
    CHECK_NEAR(y, 0.0, 1e-4);
    CHECK_EQ(project_vertex({1, -1, -1}, id, proj, W, H, &x, &y), 1);
    CHECK_NEAR(x, double(W - 1), 1e-4);
    CHECK_NEAR(y, double(H - 1), 1e-4);
    // Far-plane corner.
    CHECK_EQ(project_vertex({10, 10, -10}, id, proj, W, H, &x, &y), 1);
    CHECK_NEAR(x, double(W - 1), 1e-3);
    CHECK_NEAR(y, 0.0, 1e-3);
    // The library's viewport: the same corners at the canvas edges.
    CHECK_NEAR(project_point({-1, 1, -1}, proj, W, H).x, 0.0, 1e-4);
    CHECK_NEAR(project_point({1, -1, -1}, proj, W, H).x, double(W), 1e-4);
    CHECK_NEAR(project_point({1, -1, -1}, proj, W, H).y, double(H), 1e-4);
    // Behind the camera and at the eye: 0, outputs untouched.
    x = y = -7;
    CHECK_EQ(project_vertex({0, 0, 1}, id, proj, W, H, &x, &y), 0);
    CHECK_EQ(project_vertex({0.5f, 0, 0}, id, proj, W, H, &x, &y), 0);
    CHECK_EQ(project_vertex({NAN, 0, -2}, id, proj, W, H, &x, &y), 0);
    CHECK(x == -7 && y == -7);
    CHECK_EQ(project_vertex({0, 0, -2}, id, proj, W, H, nullptr, nullptr), 1);
    // Random points in front against the double reference; the model matrix is applied first.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-3, 3), depth(-9.5f, -1.2f);
    const mat4_t model = mat4_translate(0.25f, -0.5f, -0.75f);
    for (int i = 0; i < 200; ++i) {
        const vec3_t p{u(rng), u(rng), depth(rng)};
        const ref_point r = ref_project(double(p.x) + 0.25, double(p.y) - 0.5, double(p.z) - 0.75);
        const ref_point rr = ref_report_project(double(p.x) + 0.25, double(p.y) - 0.5, double(p.z) - 0.75);
        CHECK_EQ(project_vertex(p, model, proj, W, H, &x, &y), 1);
        CHECK_NEAR(x, rr.x, 1e-3);
        CHECK_NEAR(y, rr.y, 1e-3);
        const screen_point s = project_point(p, mat4_multiply(proj, model), W, H);
        CHECK(!s.behind);
        CHECK_NEAR(s.depth, r.depth, 1e-5);
        CHECK_NEAR(s.x, r.x, 1e-3);
    }
    CHECK_NEAR(project_point({0, 0, -1}, proj, W, H).depth, 0.0, 1e-6);
    CHECK_NEAR(project_point({0, 0, -10}, proj, W, H).depth, 1.0, 1e-6);
    CHECK(project_point({0, 0, 3}, proj, W, H).behind);
}

TEST(near_plane_cut_at_the_exact_intersection) {
    const mat4_t proj = test_proj();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-0.8, 0.8), front(-6, -1.5), back(0.5, 6);
    for (int i = 0; i < 200; ++i) {
        const double a[3] = {u(rng), u(rng), front(rng)}, b[3] = {u(rng) * 4, u(rng) * 4, back(rng)};
        const vec4_t ca = mat4_mul_vec4(proj, {float(a[0]), float(a[1]), float(a[2]), 1});
        const vec4_t cb = mat4_mul_vec4(proj, {float(b[0]), float(b[1]), float(b[2]), 1});
        const segment_clip c = clip_segment(ca, cb, clip_near);
        CHECK(c.visible);
        // Exact: z = −n at t* = (−n − a.z) / (b.z − a.z).
        const double t_exact = (-n_plane - a[2]) / (b[2] - a[2]);
        CHECK_NEAR(c.t0, 0.0, 0.0);
        CHECK_NEAR(c.t1, t_exact, 1e-6);
        const ref_point end = ref_project(a[0] + t_exact * (b[0] - a[0]), a[1] + t_exact * (b[1] - a[1]), -n_plane);
        const screen_point s = clip_to_screen(lerp4(ca, cb, float(c.t1)), W, H);
        CHECK(!s.behind);
        CHECK_NEAR(s.x, end.x, 2e-3);
        CHECK_NEAR(s.y, end.y, 2e-3);
        CHECK_NEAR(s.depth, 0.0, 1e-5);
    }
    // Both behind: nothing; both in front: untouched.
    CHECK(!clip_segment(mat4_mul_vec4(proj, {0, 0, 1, 1}), mat4_mul_vec4(proj, {1, 0, 2, 1}), clip_near).visible);
    const segment_clip whole = clip_segment(mat4_mul_vec4(proj, {0, 0, -2, 1}), mat4_mul_vec4(proj, {0.5f, 0, -3, 1}));
    CHECK(whole.visible && whole.t0 == 0.0 && whole.t1 == 1.0);
    CHECK(!clip_segment({NAN, 0, 0, 1}, {0, 0, 0, 1}).visible);
    CHECK_EQ(clip_outcode({0, 0, 0, 1}), 0u);
    CHECK_EQ(clip_outcode({2, 0, 0, 1}), unsigned(clip_right));
    CHECK_EQ(clip_outcode({0, -3, -2, 1}), unsigned(clip_bottom | clip_near));
}

namespace {

// Inside test_proj()'s frustum, written from its definition in world space (double):
// n ≤ −z ≤ f, |x| ≤ −z, |y| ≤ −z.
bool ref_inside(const double p[3]) {
    const double depth = -p[2];
    return depth >= n_plane && depth <= f_plane && std::fabs(p[0]) <= depth && std::fabs(p[1]) <= depth;
}

// The smallest t with a + t·(b − a) inside, for `a` anywhere and `b` inside (the frustum is
// convex, so the inside part is [t, 1]): bisection on ref_inside, in double.
double ref_entry(const double a[3], const double b[3]) {
    const auto at = [&](double t) {
        const double p[3] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
        return ref_inside(p);
    };
    if (at(0.0)) return 0.0;
    double out = 0.0, in = 1.0;
    for (int i = 0; i < 80; ++i) {
        const double mid = 0.5 * (out + in);
        (at(mid) ? in : out) = mid;
    }
    return in;
}

}  // namespace

TEST(segment_entering_the_frustum_is_cut_where_it_enters) {
    // From anywhere (outside any plane, behind the camera, or inside) to a point well inside:
    // t0 is where the segment enters, found by bisection in world space; drawn the other way
    // round the same point is where it leaves (t1 = 1 − t0).
    const mat4_t proj = test_proj();
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> wide(-30, 30), behind_to_beyond(-30, 5), unit(-0.7, 0.7), depth(1.5, 9);
    int entered = 0;
    for (int i = 0; i < 400; ++i) {
        const double a[3] = {wide(rng), wide(rng), behind_to_beyond(rng)};
        const double d = depth(rng);
        const double b[3] = {unit(rng) * d, unit(rng) * d, -d};
        const vec4_t ca = mat4_mul_vec4(proj, {float(a[0]), float(a[1]), float(a[2]), 1});
        const vec4_t cb = mat4_mul_vec4(proj, {float(b[0]), float(b[1]), float(b[2]), 1});
        // The reference from the float coordinates the clipper sees.
        const double af[3] = {double(float(a[0])), double(float(a[1])), double(float(a[2]))};
        const double bf[3] = {double(float(b[0])), double(float(b[1])), double(float(b[2]))};
        const double t_entry = ref_entry(af, bf);
        entered += t_entry > 0.0;
        const segment_clip forward = clip_segment(ca, cb), backward = clip_segment(cb, ca);
        CHECK(forward.visible && backward.visible);
        CHECK_NEAR(forward.t0, t_entry, 1e-5);
        CHECK_NEAR(forward.t1, 1.0, 0.0);
        CHECK_NEAR(backward.t0, 0.0, 0.0);
        CHECK_NEAR(backward.t1, 1.0 - t_entry, 1e-5);
    }
    CHECK(entered > 300);  // most starts are outside: the entry is what is tested
}

TEST(triangle_beyond_the_far_plane_is_cut_at_it) {
    // World z of each vertex as attribute 0: clip space is linear in world space, so a
    // crossing of the far plane (world z = −f) carries attribute −f exactly.
    const mat4_t proj = test_proj();
    const auto vertex = [&](float x, float y, float z) {
        clip_vertex v;
        v.position = mat4_mul_vec4(proj, {x, y, z, 1});
        v.attr.fill(0.0f);
        v.attr[0] = z;
        return v;
    };
    const clip_vertex tri[3] = {vertex(-1, -1, -5), vertex(1, -1, -5), vertex(0, 1, -20)};
    for (const unsigned planes : {unsigned(clip_far), unsigned(clip_all)}) {
        clip_vertex out[CLIP_MAX_VERTICES];
        const int n = clip_polygon(tri, 3, planes, 1.0f, 1, out);
        CHECK_EQ(n, 4);
        std::vector<double> zs;
        for (int k = 0; k < n; ++k) {
            const vec4_t p = out[k].position;
            CHECK(p.w > 0.0f);
            CHECK(double(p.z) <= double(p.w) * (1.0 + 1e-6));  // NDC depth ≤ 1
            zs.push_back(out[k].attr[0]);
        }
        std::sort(zs.begin(), zs.end());
        if (zs.size() == 4) {
            CHECK_NEAR(zs[0], -f_plane, 1e-4);
            CHECK_NEAR(zs[1], -f_plane, 1e-4);
            CHECK_NEAR(zs[2], -5.0, 0.0);
            CHECK_NEAR(zs[3], -5.0, 0.0);
        }
    }
    // Wholly beyond the far plane: nothing.
    const clip_vertex far_off[3] = {vertex(-1, -1, -12), vertex(1, -1, -15), vertex(0, 1, -20)};
    clip_vertex out[CLIP_MAX_VERTICES];
    CHECK_EQ(clip_polygon(far_off, 3, clip_far, 1.0f, 1, out), 0);
    CHECK_EQ(clip_polygon(far_off, 3, clip_all, 1.0f, 1, out), 0);
}

TEST(edge_through_the_camera_plane_is_not_mirrored) {
    // From x = 0.5 at z = −2 (NDC x 0.25) to behind the camera: the naive divide would put
    // the back end at NDC x −0.25 (left half); the cut segment stays right of NDC 0.25.
    canvas_holder c(W, H);
    const mesh m = single_edge({0.5f, 0, -2}, {0.5f, 0, 2});
    wireframe_workspace ws;
    wireframe_options o = plain_options();
    CHECK(render_wireframe(*c, m, test_proj(), o, ws).ok());
    CHECK(c.sum() > 10.0);
    const int left_limit = int((0.25 + 1) / 2 * W - o.thickness);
    double left_ink = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < left_limit; ++x) left_ink += c.c->pixels[y][x];
    CHECK_NEAR(left_ink, 0.0, 0.0);
    // The visible part ends at the near plane, which is at NDC x = 0.5 → pixel 150.
    CHECK_EQ(ws.edges.size(), 1u);
    if (ws.edges.size() == 1) {
        CHECK_NEAR(std::max(ws.edges[0].x0, ws.edges[0].x1), 150.0, 1e-3);
        CHECK_NEAR(std::min(ws.edges[0].x0, ws.edges[0].x1), 125.0, 1e-3);
    }
    // The report's form draws the same cut segment.
    canvas_holder r(W, H);
    vec3_t verts[2] = {{0.5f, 0, -2}, {0.5f, 0, 2}};
    int edges[1][2] = {{0, 1}};
    render_wireframe(&*r, verts, 2, edges, 1, mat4_identity(), test_proj());
    double r_left = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < left_limit; ++x) r_left += r.c->pixels[y][x];
    CHECK(r.sum() > 10.0);
    CHECK_NEAR(r_left, 0.0, 0.0);
}

TEST(frustum_clip_ends_on_the_canvas_edge) {
    // (0, 0.2, −2) to (6, 0.2, −2): crosses the right plane at x = 2 (NDC 1) → screen x = W.
    const mat4_t proj = test_proj();
    const vec4_t a = mat4_mul_vec4(proj, {0, 0.2f, -2, 1}), b = mat4_mul_vec4(proj, {6, 0.2f, -2, 1});
    const segment_clip c = clip_segment(a, b);
    CHECK(c.visible);
    CHECK_NEAR(c.t1, 2.0 / 6.0, 1e-7);
    const screen_point e = clip_to_screen(lerp4(a, b, float(c.t1)), W, H);
    CHECK_NEAR(e.x, double(W), 1e-3);
    CHECK_NEAR(e.y, ref_project(2, 0.2, -2).y, 1e-3);
}

TEST(circle_clip_matches_the_analytic_intersection) {
    canvas_holder c(W, H);
    CHECK(clip_to_circular_viewport(&*c, 100, 50));
    CHECK(clip_to_circular_viewport(&*c, 150, 50));   // on the circle
    CHECK(!clip_to_circular_viewport(&*c, 150.01f, 50));
    CHECK(!clip_to_circular_viewport(&*c, 1, 1));
    CHECK(!clip_to_circular_viewport(&*c, NAN, 50));
    CHECK(!clip_to_circular_viewport(nullptr, 100, 50));
    const circle circ = circular_viewport(*c);
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> u(-300, 500);
    int crossing = 0, outside = 0;
    for (int i = 0; i < 2000; ++i) {
        const float x0 = u(rng), y0 = u(rng), x1 = u(rng), y1 = u(rng);
        const segment_clip k = clip_segment_circle(circ, x0, y0, x1, y1);
        // Reference in long double: the foot of the perpendicular plus/minus the half chord.
        const long double dx = (long double)x1 - x0, dy = (long double)y1 - y0;
        const long double fx = (long double)x0 - 100, fy = (long double)y0 - 50, len2 = dx * dx + dy * dy;
        const long double tc = -(fx * dx + fy * dy) / len2;
        const long double px = fx + tc * dx, py = fy + tc * dy, dist2 = px * px + py * py;
        if (dist2 >= 2500.0L * (1 - 1e-9L)) {
            CHECK(!k.visible || dist2 < 2500.0L * (1 + 1e-9L));
            ++outside;
            continue;
        }
        const long double half = std::sqrt((2500.0L - dist2) / len2);
        const long double t_in = std::max(0.0L, tc - half), t_out = std::min(1.0L, tc + half);
        if (t_in > t_out) {
            CHECK(!k.visible);
            ++outside;
            continue;
        }
        CHECK(k.visible);
        if (!k.visible) continue;
        ++crossing;
        // Endpoints within 1e-4 px of the analytic ones.
        CHECK_NEAR(double(x0 + k.t0 * dx), double(x0 + t_in * dx), 1e-4);
        CHECK_NEAR(double(y0 + k.t0 * dy), double(y0 + t_in * dy), 1e-4);
        CHECK_NEAR(double(x0 + k.t1 * dx), double(x0 + t_out * dx), 1e-4);
        CHECK_NEAR(double(y0 + k.t1 * dy), double(y0 + t_out * dy), 1e-4);
    }
    CHECK(crossing > 100);
    CHECK(outside > 100);
}

TEST(circular_viewport_wireframe_draws_up_to_the_circle_only) {
    // Orthographic-like: identity matrix, so NDC = model coordinates; canvas 200 × 100,
    // circle centre (100, 50), radius 50.
    canvas_holder c(W, H);
    wireframe_options o = plain_options();
    o.circular_viewport = true;
    wireframe_workspace ws;
    // Fully outside the circle (in the canvas corner): nothing.
    CHECK(render_wireframe(*c, single_edge({-0.95f, 0.9f, 0}, {-0.6f, 0.9f, 0}), mat4_identity(), o, ws).ok());
    CHECK_NEAR(c.sum(), 0.0, 0.0);
    // Half inside: from the centre to the right edge of the canvas → drawn from x=100 to 150.
    CHECK(render_wireframe(*c, single_edge({0, 0, 0}, {1, 0, 0}), mat4_identity(), o, ws).ok());
    CHECK_EQ(ws.edges.size(), 1u);
    if (ws.edges.size() == 1) CHECK_NEAR(std::max(ws.edges[0].x0, ws.edges[0].x1), 150.0, 1e-4);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            if (c.c->pixels[y][x] > 0) CHECK(x < 150 + 1 && x >= 100 - 1);
    // Ink along the segment: the coverage line of length 50 and width 1.5 with round caps.
    CHECK_NEAR(c.sum(), 50 * 1.5 + M_PI * 0.75 * 0.75, 0.05);
}

TEST(depth_order_far_to_near_and_depth_cue) {
    // Three horizontal edges at depths −2, −6, −4 (in that order in the mesh).
    mesh m;
    m.positions = {{-0.5f, 0.5f, -2}, {0.5f, 0.5f, -2}, {-2, 0, -6}, {2, 0, -6}, {-1, -1, -4}, {1, -1, -4}};
    m.edges = {{0, 1}, {2, 3}, {4, 5}};
    canvas_holder c(W, H);
    wireframe_workspace ws;
    wireframe_options o = plain_options();
    CHECK(render_wireframe(*c, m, test_proj(), o, ws).ok());
    CHECK_EQ(ws.edges.size(), 3u);
    if (ws.edges.size() == 3) {
        CHECK_EQ(ws.edges[0].edge, 1u);  // z = −6, farthest
        CHECK_EQ(ws.edges[1].edge, 2u);
        CHECK_EQ(ws.edges[2].edge, 0u);
        CHECK(ws.edges[0].depth > ws.edges[1].depth && ws.edges[1].depth > ws.edges[2].depth);
    }
    // Depth cue: the nearest edge gets full ink, the farthest depth_cue_far.
    std::vector<float> seen(3, -1);
    o.depth_cue = true;
    o.depth_cue_far = 0.25f;
    o.edge_intensity_fn = [&](std::uint32_t e) {
        seen[e] = 1;
        return 1.0f;
    };
    canvas_holder d(W, H);
    CHECK(render_wireframe(*d, m, test_proj(), o, ws).ok());
    CHECK(seen[0] == 1 && seen[1] == 1 && seen[2] == 1);
    // Each horizontal line covers whole pixel rows in its middle; the line at z = −2 sits at
    // screen y = 25 (rows 24..25 covered 0.75 + 0.75 → use the peak of the middle column).
    auto peak = [&](canvas_holder &h, int x) {
        float best = 0;
        for (int y = 0; y < H; ++y) best = std::max(best, h.c->pixels[y][x]);
        return best;
    };
    const float near_peak = peak(d, 100);          // x = 100 crosses all three lines
    CHECK_NEAR(near_peak, peak(c, 100), 1e-6);     // nearest edge at full ink
    // The farthest edge (z = −6) spans x 66.7..133.3, the others 75..125: column 70 has it alone.
    CHECK(peak(c, 70) > 0.5f);
    CHECK_NEAR(peak(d, 70) / peak(c, 70), 0.25, 1e-3);
}

TEST(per_edge_intensity_array_and_bad_inputs) {
    const mesh m = single_edge({-0.5f, 0, 0}, {0.5f, 0, 0});
    canvas_holder full(W, H), half(W, H);
    wireframe_workspace ws;
    wireframe_options o = plain_options();
    CHECK(render_wireframe(*full, m, mat4_identity(), o, ws).ok());
    const std::vector<float> ink = {0.5f};
    o.edge_intensity = ink;
    CHECK(render_wireframe(*half, m, mat4_identity(), o, ws).ok());
    CHECK_NEAR(half.sum() / full.sum(), 0.5, 0.02);  // "over" of a half-ink stroke: ≈ half the ink
    const std::vector<float> wrong = {0.5f, 0.5f};
    o.edge_intensity = wrong;
    CHECK(!render_wireframe(*half, m, mat4_identity(), o, ws).ok());
    o.edge_intensity = {};
    o.thickness = NAN;
    CHECK(!render_wireframe(*half, m, mat4_identity(), o, ws).ok());
    o.thickness = 1;
    mesh bad = m;
    bad.edges.push_back({0, 7});
    const status s = render_wireframe(*half, bad, mat4_identity(), o, ws);
    CHECK(!s.ok() && s.message().find("edge 1") != std::string::npos);
    o.hide_back_edges = true;
    CHECK(!render_wireframe(*half, m, mat4_identity(), o, ws).ok());  // no adjacency
}

// The 7-argument form is the report's loop: per edge project_vertex on both ends (the
// report's viewport), then draw_line_f at thickness 1 — bit for bit while no edge needs
// clipping (the cube lies inside the frustum).
TEST(report_render_wireframe_skips_bad_edges_and_matches_the_reports_loop) {
    const mesh cube = make_cube(1.0f);
    std::vector<vec3_t> verts = cube.positions;
    std::vector<std::array<int, 2>> pairs;
    for (const edge &e : cube.edges) pairs.push_back({int(e.a), int(e.b)});
    pairs.push_back({0, 99});
    pairs.push_back({-1, 2});
    const mat4_t model = mat4_multiply(mat4_translate(0, 0, -5), mat4_rotate_xyz(0.4f, 0.7f, 0.1f));
    const mat4_t proj = test_proj();
    canvas_holder a(W, H), b(W, H);
    render_wireframe(&*a, verts.data(), int(verts.size()), reinterpret_cast<int(*)[2]>(pairs.data()),
                     int(pairs.size()), model, proj);
    for (const edge &e : cube.edges) {
        float x0, y0, x1, y1;
        CHECK_EQ(project_vertex(verts[e.a], model, proj, W, H, &x0, &y0), 1);
        CHECK_EQ(project_vertex(verts[e.b], model, proj, W, H, &x1, &y1), 1);
        draw_line_f(&*b, x0, y0, x1, y1, 1.0f);
    }
    double diff = 0;
    for (int i = 0; i < W * H; ++i) diff = std::max(diff, double(std::fabs(a.c->data[i] - b.c->data[i])));
    CHECK_NEAR(diff, 0.0, 0.0);
    CHECK(a.sum() > 100);
    // Null and empty inputs are ignored.
    render_wireframe(nullptr, verts.data(), 8, reinterpret_cast<int(*)[2]>(pairs.data()), 12, model, proj);
    render_wireframe(&*a, nullptr, 8, nullptr, 12, model, proj);
    render_wireframe(&*a, verts.data(), -1, reinterpret_cast<int(*)[2]>(pairs.data()), 12, model, proj);
}

// The mesh form's faithful method hands draw_line_f the library's ends minus 0.5, so its
// line lies where the coverage line lies: the ink's centroid within 0.05 px of it.
TEST(faithful_method_lines_up_with_the_coverage_method) {
    const mesh m = single_edge({-0.6f, -0.3f, -2.0f}, {0.7f, 0.45f, -3.0f});
    const mat4_t proj = test_proj();
    double centroid[2][2];
    const line_method methods[2] = {line_method::faithful, line_method::coverage};
    for (int k = 0; k < 2; ++k) {
        canvas_holder c(W, H);
        wireframe_options o = plain_options();
        o.method = methods[k];
        wireframe_workspace ws;
        CHECK(render_wireframe(*c, m, proj, o, ws).ok());
        double sum = 0, sx = 0, sy = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const double v = c.c->pixels[y][x];
                sum += v, sx += v * (x + 0.5), sy += v * (y + 0.5);
            }
        CHECK(sum > 10);
        centroid[k][0] = sx / sum, centroid[k][1] = sy / sum;
    }
    CHECK_NEAR(centroid[0][0], centroid[1][0], 0.05);
    CHECK_NEAR(centroid[0][1], centroid[1][1], 0.05);
}

TEST(hidden_back_edges_match_a_world_space_reference) {
    const mesh cube = make_cube(1.0f);
    const edge_adjacency adj = mesh_edge_faces(cube);
    const std::vector<vec3_t> normals = mesh_face_normals(cube);
    wireframe_options o = plain_options();
    o.hide_back_edges = true;
    o.adjacency = &adj;
    o.depth_sort = false;
    wireframe_workspace ws;
    canvas_holder c(W, H);
    // Straight on from +z: the 4 edges of the front face stay, 8 are hidden.
    wireframe_stats st;
    CHECK(render_wireframe(*c, cube, mat4_multiply(test_proj(), mat4_translate(0, 0, -5)), o, ws, &st).ok());
    CHECK_EQ(st.edges_drawn, 4u);
    CHECK_EQ(st.edges_hidden, 8u);
    // Random orientations against dot(n, eye − p) in double, eye at the origin of view space.
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> angle(-3.1f, 3.1f);
    int compared = 0;
    for (int i = 0; i < 100; ++i) {
        const mat4_t rot = mat4_rotate_xyz(angle(rng), angle(rng), angle(rng));
        const mat4_t model = mat4_multiply(mat4_translate(0.3f, -0.2f, -6), rot);
        std::vector<int> front(cube.face_count());
        bool ambiguous = false;
        for (std::size_t f = 0; f < cube.face_count(); ++f) {
            const vec4_t p = mat4_mul_vec4(model, vec4_from_vec3(cube.positions[cube.indices[cube.face_start[f]]], 1));
            const vec4_t n = mat4_mul_vec4(model, vec4_from_vec3(normals[f], 0));
            const double facing = -(double(p.x) * n.x + double(p.y) * n.y + double(p.z) * n.z);
            ambiguous |= std::fabs(facing) < 1e-3;
            front[f] = facing > 0;
        }
        if (ambiguous) continue;
        std::set<std::uint32_t> expected;
        for (std::size_t e = 0; e < cube.edges.size(); ++e)
            if (front[adj.faces[adj.start[e]]] || front[adj.faces[adj.start[e] + 1]]) expected.insert(std::uint32_t(e));
        CHECK(render_wireframe(*c, cube, mat4_multiply(test_proj(), model), o, ws, &st).ok());
        std::set<std::uint32_t> drawn;
        for (const auto &d : ws.edges) drawn.insert(d.edge);
        CHECK(drawn == expected);
        ++compared;
    }
    CHECK(compared > 80);
}

TEST(frustum_culling_by_bounding_sphere) {
    const mat4_t proj = test_proj();
    const frustum f = frustum_from_matrix(proj);
    CHECK(cull_sphere(f, {{0, 0, -5}, 1}) == cull_result::inside);
    CHECK(cull_sphere(f, {{0, 0, 5}, 1}) == cull_result::outside);       // behind the camera
    CHECK(cull_sphere(f, {{0, 0, -20}, 1}) == cull_result::outside);     // beyond far
    CHECK(cull_sphere(f, {{20, 0, -5}, 1}) == cull_result::outside);
    CHECK(cull_sphere(f, {{5, 0, -5}, 0.5f}) == cull_result::intersecting);  // across the right plane x = −z
    CHECK(cull_sphere(f, {{0, 0, -5}, -1}) == cull_result::outside);
    // Plane distances are true distances: the right plane x + z = 0 normalised by √2.
    const float d = f.plane[3].x * 3 + f.plane[3].z * -5 + f.plane[3].w;
    CHECK_NEAR(d, 2 / std::sqrt(2.0), 1e-6);

    const mesh ball = make_soccer_ball();
    canvas_holder c(W, H);
    wireframe_options o = plain_options();
    o.frustum_cull = true;
    wireframe_workspace ws;
    wireframe_stats st;
    CHECK(render_wireframe(*c, ball, mat4_multiply(proj, mat4_translate(30, 0, -5)), o, ws, &st).ok());
    CHECK(st.mesh_culled);
    CHECK_NEAR(c.sum(), 0.0, 0.0);
    CHECK(render_wireframe(*c, ball, mat4_multiply(proj, mat4_translate(0, 0, -5)), o, ws, &st).ok());
    CHECK(!st.mesh_culled);
    CHECK_EQ(st.edges_drawn, 90u);
}

TEST(hostile_coordinates_draw_nothing_wrong) {
    mesh m;
    m.positions = {{NAN, 0, -2}, {0, 0, -2}, {1e30f, 1e30f, -2}, {0, 0, 1e30f}, {INFINITY, 0, -3}, {-1e-40f, 1e-40f, -2}};
    m.edges = {{0, 1}, {1, 2}, {1, 3}, {1, 4}, {1, 5}, {2, 3}};
    canvas_holder c(W, H);
    wireframe_workspace ws;
    wireframe_options o = plain_options();
    CHECK(render_wireframe(*c, m, test_proj(), o, ws).ok());
    for (int i = 0; i < W * H; ++i) CHECK(std::isfinite(c.c->data[i]) && c.c->data[i] >= 0 && c.c->data[i] <= 1);
    // Edge 1→2 goes off to the upper right: clipped at the canvas corner; edge 1→5 is a dot.
    for (const auto &d : ws.edges) {
        CHECK(std::isfinite(d.x0) && std::isfinite(d.y0) && std::isfinite(d.x1) && std::isfinite(d.y1));
        CHECK(d.x0 >= -1e-3 && d.x0 <= W + 1e-3 && d.x1 >= -1e-3 && d.x1 <= W + 1e-3);
    }
}

// workspace.vertices (filled four at a time with SSE2) against its scalar definition:
// clip_outcode of workspace.clip, then clip_to_screen for the inside points, bit for bit,
// and workspace.clip against mat4_mul_vec4. Random points around the frustum plus points
// exactly on its planes, at the eye (w = 0), behind it, huge, denormal and non-finite; an
// odd count, so the scalar tail runs too.
TEST(packed_vertices_match_outcode_and_screen_point_bit_for_bit) {
    std::mt19937 rng(20240611);
    std::uniform_real_distribution<float> u(-12.0f, 12.0f);
    mesh m;
    for (int i = 0; i < 997; ++i) m.positions.push_back({u(rng), u(rng), u(rng)});
    const float inf = INFINITY, nan = NAN;
    const std::vector<vec3_t> special = {{0, 0, 0},        {1, 0, -1},      {-1, 1, -1},   {10, -10, -10}, {0, 0, -10},
                                         {0, 0, 1},        {2, 0, 0},       {1e30f, 0, -2}, {0, 0, -1e30f}, {1e-40f, 0, -1e-39f},
                                         {0, 0, -1e-40f},  {nan, 0, -2},    {0, inf, -2},   {0, 0, -inf},   {-inf, 0, -5},
                                         {3e38f, 3e38f, -3e38f}, {0, 0, -2e38f}};
    for (int k = 0; k < 5; ++k) m.positions.insert(m.positions.end(), special.begin(), special.end());
    for (std::uint32_t i = 0; i + 1 < m.positions.size(); ++i) m.edges.push_back({i, i + 1});
    canvas_holder c(W, H);
    wireframe_workspace ws;
    wireframe_options o = plain_options();
    o.intensity = 0.0f;  // list only
    const bounding_sphere claimed_inside{{0, 0, -5}, 0.5f};
    mat4_t wide_w = mat4_identity();  // w × 10: (0, 0, −2e38) gets a finite z and w = +∞
    wide_w.m[15] = 10.0f;
    const mat4_t matrices[] = {test_proj(), mat4_identity(), mat4_multiply(test_proj(), tiny3d::mat4_rotate_y(0.7f)),
                               mat4_multiply(wide_w, test_proj())};
    std::size_t shown = 0, hidden = 0;
    for (const mat4_t &mvp : matrices)
        for (bool all_inside : {false, true}) {
            // A sphere declared inside the frustum makes every outcode 0 (no plane tests).
            o.frustum_cull = all_inside;
            o.bounds = all_inside ? &claimed_inside : nullptr;
            if (all_inside && cull_sphere(frustum_from_matrix(mvp), claimed_inside) != cull_result::inside) continue;
            CHECK(render_wireframe(*c, m, mvp, o, ws).ok());
            CHECK_EQ(ws.vertices.size(), m.positions.size());
            for (std::size_t i = 0; i < m.positions.size(); ++i) {
                const vec4_t want = mat4_mul_vec4(mvp, vec4_from_vec3(m.positions[i], 1.0f)), &got = ws.clip[i];
                auto same = [](float a, float b) { return a == b || (std::isnan(a) && std::isnan(b)); };
                CHECK(same(got.x, want.x) && same(got.y, want.y) && same(got.z, want.z) && same(got.w, want.w));
                const unsigned code = all_inside ? 0u : clip_outcode(want);
                const screen_point p = clip_to_screen(want, W, H);
                const auto &v = ws.vertices[i];
                if (code == 0 && !p.behind) {
                    ++shown;
                    CHECK_EQ(v.outcode, 0u);
                    CHECK(v.x == p.x && v.y == p.y && v.depth == p.depth);
                } else {
                    ++hidden;
                    CHECK_EQ(v.outcode, code != 0 ? code : unsigned(clip_all));
                    CHECK(v.x == 0.0f && v.y == 0.0f && v.depth == 0.0f);
                }
            }
        }
    CHECK(shown > 100 && hidden > 1000);
}

// An edge index past the positions is an error naming the first such edge, wherever it
// sits (the range check reads two edges at a time) and however large the index.
TEST(out_of_range_edge_is_named) {
    mesh m;
    m.positions = {{0, 0, -2}, {1, 0, -2}, {0, 1, -2}};
    canvas_holder c(W, H);
    wireframe_workspace ws;
    const wireframe_options o = plain_options();
    for (std::uint32_t bad : {3u, 0x80000000u, 0xFFFFFFFFu})
        for (std::size_t at : {0u, 3u, 4u}) {
            m.edges = {{0, 1}, {1, 2}, {0, 2}, {0, 1}, {1, 2}};
            m.edges[at].b = bad;
            const status s = render_wireframe(*c, m, test_proj(), o, ws);
            CHECK(!s.ok());
            CHECK_MSG(s.message().find("edge " + std::to_string(at) + " refers") != std::string::npos, s.message());
        }
    m.edges = {{0, 1}, {1, 2}, {0, 2}, {0, 1}, {1, 2}};
    CHECK(render_wireframe(*c, m, test_proj(), o, ws).ok());
}
