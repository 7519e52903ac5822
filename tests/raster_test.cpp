// raster_test.cpp — filled triangles: coverage (watertight, top-left), fast fill vs the
// 64-bit reference, depth, perspective-correct uv against the analytic value, culling,
// near-plane clipping against a double-precision ray cast, thread-count invariance,
// textures, transparency, degenerate / NaN input.
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "harness.h"
#include "renderer.h"

using namespace tiny3d;

namespace {

constexpr int W = 64, H = 48;

// Hit counts of a list of screen triangles through the reference visitor.
std::vector<int> count_hits(const std::vector<std::array<screen_vertex, 3>> &tris, int w, int h) {
    std::vector<int> hits(static_cast<std::size_t>(w) * h, 0);
    for (const auto &t : tris)
        rasterize_triangle(t[0], t[1], t[2], {0, 0, w, h},
                           [&](int x, int y, float, float, float) { ++hits[static_cast<std::size_t>(y) * w + x]; });
    return hits;
}

screen_vertex sv(double x, double y, double z = 0.5) {
    return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z), 1.0f};
}

light_rig constant_light(float ambient) {  // shade = ambient everywhere
    return make_light_rig(std::span<const light_t>(), ambient).value();
}

}  // namespace

TEST(watertight_jittered_grid_covers_every_pixel_once) {
    // A grid of quads over (and beyond) the canvas, vertices jittered at sub-pixel positions
    // (some exactly on pixel centres), each quad split into two triangles, alternating
    // diagonals and both windings.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-2.0, 2.0);
    constexpr int N = 9;
    double gx[N + 1][N + 1], gy[N + 1][N + 1];
    for (int j = 0; j <= N; ++j)
        for (int i = 0; i <= N; ++i) {
            const bool border = i == 0 || j == 0 || i == N || j == N;
            gx[j][i] = -4.0 + i * (W + 8.0) / N + (border ? 0 : jitter(rng));
            gy[j][i] = -4.0 + j * (H + 8.0) / N + (border ? 0 : jitter(rng));
            if ((i + j) % 3 == 0 && !border) gx[j][i] = std::floor(gx[j][i]) + 0.5, gy[j][i] = std::floor(gy[j][i]) + 0.5;
        }
    std::vector<std::array<screen_vertex, 3>> tris;
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            const screen_vertex a = sv(gx[j][i], gy[j][i]), b = sv(gx[j][i + 1], gy[j][i + 1]),
                                c = sv(gx[j + 1][i + 1], gy[j + 1][i + 1]), d = sv(gx[j + 1][i], gy[j + 1][i]);
            if ((i + j) % 2) {
                tris.push_back({a, b, c});
                tris.push_back({a, d, c});  // opposite winding
            } else {
                tris.push_back({a, b, d});
                tris.push_back({b, c, d});
            }
        }
    const std::vector<int> hits = count_hits(tris, W, H);
    int wrong = 0;
    for (int h : hits) wrong += h != 1;
    CHECK_EQ(wrong, 0);
}

TEST(watertight_fan_around_a_pixel_centre) {
    // 16 triangles sharing the vertex (20.5, 20.5), a pixel centre: exactly one owns it.
    std::vector<std::array<screen_vertex, 3>> tris;
    const double cx = 20.5, cy = 20.5, r = 15.0;
    constexpr int K = 16;
    for (int k = 0; k < K; ++k) {
        const double a0 = 2 * M_PI * k / K, a1 = 2 * M_PI * (k + 1) / K;
        tris.push_back({sv(cx, cy), sv(cx + r * std::cos(a0), cy + r * std::sin(a0)),
                        sv(cx + r * std::cos(a1), cy + r * std::sin(a1))});
    }
    const std::vector<int> hits = count_hits(tris, W, H);
    CHECK_EQ(hits[20 * W + 20], 1);
    int doubles = 0;
    for (int h : hits) doubles += h > 1;
    CHECK_EQ(doubles, 0);
    // Every pixel whose centre is well inside the polygon (inscribed radius r·cos(π/K)) is hit.
    int holes = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            if (std::hypot(x + 0.5 - cx, y + 0.5 - cy) < r * std::cos(M_PI / K) - 0.1) holes += hits[y * W + x] != 1;
    CHECK_EQ(holes, 0);
}

TEST(top_left_rule_on_ties) {
    // The square [0.5, 2.5]² (centres on all four sides): top and left sides are in,
    // right and bottom out — exactly pixels (0..1) × (0..1).
    const std::vector<std::array<screen_vertex, 3>> square = {{sv(0.5, 0.5), sv(2.5, 0.5), sv(2.5, 2.5)},
                                                              {sv(0.5, 0.5), sv(2.5, 2.5), sv(0.5, 2.5)}};
    const std::vector<int> hits = count_hits(square, W, H);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) CHECK_EQ(hits[y * W + x], (x < 2 && y < 2) ? 1 : 0);
    // A triangle with a horizontal bottom edge through centres and a top edge: (10.5,10.5)
    // is on the top edge of this one → owned.
    const std::vector<std::array<screen_vertex, 3>> top = {{sv(10.5, 10.5), sv(14.5, 10.5), sv(10.5, 14.5)}};
    const std::vector<int> h2 = count_hits(top, W, H);
    CHECK_EQ(h2[10 * W + 10], 1);  // top-left corner
    CHECK_EQ(h2[10 * W + 14], 0);  // right end of the top edge: on the hypotenuse (right edge)
    CHECK_EQ(h2[14 * W + 10], 0);  // bottom end of the left edge: on the hypotenuse
    CHECK_EQ(h2[12 * W + 12], 0);  // on the hypotenuse (a right/bottom edge)
    CHECK_EQ(h2[11 * W + 12], 1);
}

TEST(fast_fill_matches_reference_coverage_and_attributes) {
    // Random triangles, small and huge (the 64-bit path): fill_triangle covers exactly the
    // pixels rasterize_triangle visits and writes the affine intensity within 1e-4.
    std::mt19937 rng(11);
    canvas_ptr c = make_canvas(W, H).value();
    for (int trial = 0; trial < 300; ++trial) {
        const double scale = trial % 10 == 0 ? 5000.0 : (trial % 3 == 0 ? 60.0 : 12.0);
        std::uniform_real_distribution<double> pos(-scale, scale);
        const double ox = 20 + pos(rng) * 0.2, oy = 20 + pos(rng) * 0.2;
        screen_vertex v[3];
        float in[3];
        for (int k = 0; k < 3; ++k) {
            v[k] = sv(ox + pos(rng), oy + pos(rng));
            in[k] = std::uniform_real_distribution<float>(0.1f, 0.9f)(rng);
        }
        canvas_clear(c.get(), 0.0f);
        fill_triangle(*c, nullptr, v, in, depth_func::always, false, {0, 0, W, H});
        // Reference: coverage from the 64-bit visitor, value from the plane through the
        // snapped vertices evaluated in double at the pixel centre.
        double X[3], Y[3];
        for (int k = 0; k < 3; ++k) X[k] = std::nearbyint(v[k].x * 16.0) / 16, Y[k] = std::nearbyint(v[k].y * 16.0) / 16;
        const double det = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
        std::vector<float> expect(W * H, 0.0f);
        rasterize_triangle(v[0], v[1], v[2], {0, 0, W, H}, [&](int x, int y, float, float, float) {
            const double px = x + 0.5, py = y + 0.5;
            const double l1 = ((px - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (py - Y[0])) / det;
            const double l2 = ((X[1] - X[0]) * (py - Y[0]) - (px - X[0]) * (Y[1] - Y[0])) / det;
            expect[y * W + x] = static_cast<float>((1 - l1 - l2) * in[0] + l1 * in[1] + l2 * in[2]);
        });
        int wrong = 0;
        double worst = 0;
        for (int i = 0; i < W * H; ++i) {
            const bool a = c->data[i] > 0, b = expect[i] > 0;
            wrong += a != b;
            if (a && b) worst = std::max(worst, std::fabs(static_cast<double>(c->data[i]) - expect[i]));
        }
        CHECK_EQ(wrong, 0);
        CHECK_MSG(worst < 2e-4, std::to_string(worst) + " trial " + std::to_string(trial));
    }
}

TEST(fast_fill_exact_on_edges_through_pixel_centres) {
    // The fast fill finds each row's first and last pixel from the edge crossings in double
    // precision; ties must still follow the integer edge test exactly. Vertices on a 1/4-px
    // lattice (exact after snapping) make edges pass exactly through many pixel centres,
    // and 1/16-px offsets give nearly horizontal and vertical edges. Coverage must equal the
    // 64-bit reference visitor's, and the lattice must really produce such ties.
    std::mt19937 rng(23);
    std::uniform_int_distribution<int> quarter(-8, 4 * W + 8), quarter_y(-8, 4 * H + 8), nudge(-1, 1);
    canvas_ptr c = make_canvas(W, H).value();
    long wrong = 0, ties = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        int X[3], Y[3];  // 1/16 px
        for (int k = 0; k < 3; ++k) X[k] = 4 * quarter(rng), Y[k] = 4 * quarter_y(rng);
        if (trial % 4 == 1) Y[1] = Y[0] + nudge(rng), X[2] = X[0] + nudge(rng);  // near-horizontal / vertical
        if (trial % 4 == 2)  // small triangles, as in a dense mesh
            for (int k = 1; k < 3; ++k) X[k] = X[0] + 4 * (quarter(rng) % 24), Y[k] = Y[0] + 4 * (quarter_y(rng) % 24);
        screen_vertex v[3];
        for (int k = 0; k < 3; ++k) v[k] = sv(X[k] / 16.0, Y[k] / 16.0);
        const float in[3] = {0.5f, 0.5f, 0.5f};
        canvas_clear(c.get(), 0.0f);
        fill_triangle(*c, nullptr, v, in, depth_func::always, false, {0, 0, W, H});
        std::vector<char> expect(W * H, 0);
        rasterize_triangle(v[0], v[1], v[2], {0, 0, W, H}, [&](int x, int y, float, float, float) { expect[y * W + x] = 1; });
        for (int i = 0; i < W * H; ++i) wrong += (c->data[i] > 0) != (expect[i] != 0);
        for (int y = 0; y < H; ++y)  // centres exactly on an edge line, counted in integers
            for (int x = 0; x < W; ++x)
                for (int k = 0; k < 3; ++k) {
                    const int a = k, b = (k + 1) % 3;
                    const long e = static_cast<long>(X[b] - X[a]) * (16 * y + 8 - Y[a]) -
                                   static_cast<long>(Y[b] - Y[a]) * (16 * x + 8 - X[a]);
                    ties += e == 0;
                }
    }
    CHECK_EQ(wrong, 0L);
    CHECK(ties > 1000);
}

TEST(intersecting_triangles_resolved_per_pixel_by_depth) {
    canvas_ptr c = make_canvas(W, H).value();
    zbuffer z;
    CHECK(z.resize(W, H).ok());
    z.clear(1.0f);
    // A: depth rises left→right, z = 0.2 + 0.3·x/64; B falls, z = 0.2 + 0.3·(64 − x)/64.
    // Both cover most of the canvas; they cross at x = 32.
    const screen_vertex a[3] = {sv(0, 0, 0.2), sv(128, 0, 0.8), sv(0, 96, 0.2)};
    const screen_vertex b[3] = {sv(64, 0, 0.2), sv(64, 96, 0.2), sv(-64, 0, 0.8)};
    const float ia[3] = {0.25f, 0.25f, 0.25f}, ib[3] = {0.75f, 0.75f, 0.75f};
    fill_triangle(*c, &z, a, ia, depth_func::less, true, {0, 0, W, H});
    fill_triangle(*c, &z, b, ib, depth_func::less, true, {0, 0, W, H});
    int checked = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            const double ea = 1 - px / 128 - py / 96, eb = 1 - (64 - px) / 128 - py / 96;  // > 0 inside
            const double za = 0.2 + 0.3 * px / 64, zb = 0.2 + 0.3 * (64 - px) / 64;
            if (ea < 0.02 || eb < 0.02 || std::fabs(za - zb) < 1e-3) continue;
            CHECK_EQ(c->pixels[y][x], za < zb ? 0.25f : 0.75f);
            CHECK_NEAR(z.at(x, y), std::min(za, zb), 1e-5);
            ++checked;
        }
    CHECK(checked > 50);
}

TEST(scanline_fill_agrees_with_half_space_away_from_edges) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> pos(-10.0f, 70.0f);
    canvas_ptr a = make_canvas(W, H).value(), b = make_canvas(W, H).value();
    long mismatched = 0, covered = 0;
    for (int trial = 0; trial < 100; ++trial) {
        screen_vertex v[3];
        for (auto &p : v) p = {pos(rng), pos(rng), 0.5f, 1.0f};
        const float in[3] = {1, 1, 1};
        canvas_clear(a.get(), 0);
        canvas_clear(b.get(), 0);
        fill_triangle(*a, nullptr, v, in, depth_func::always, false, {0, 0, W, H});
        fill_triangle_scanline(*b, nullptr, v, in, depth_func::always);
        for (int i = 0; i < W * H; ++i) {
            covered += a->data[i] > 0;
            mismatched += (a->data[i] > 0) != (b->data[i] > 0);
        }
    }
    CHECK(covered > 10000);
    // Only centres within float rounding / 1/16 px snapping of an edge may differ.
    CHECK(mismatched * 100 < covered);
}

namespace {

// A quad facing the camera (at the origin looking down −z): y = −1 at z = −1.5, y = 1 at
// z = −6, x in [−1, 1]; u runs along the depth (u = (y + 1)/2).
raster_mesh tilted_quad() {
    raster_mesh m;
    m.positions = {{-1, -1, -1.5f}, {1, -1, -1.5f}, {1, 1, -6}, {-1, 1, -6}};
    m.normals.assign(4, {0, 0, 1});
    m.uvs = {{0, 0}, {0, 0}, {1, 0}, {1, 0}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    m.bound_center = {0, 0, -3.75f};
    m.bound_radius = 3;
    return m;
}

}  // namespace

TEST(perspective_correct_uv_matches_the_analytic_value) {
    constexpr int S = 256;
    const float fov = static_cast<float>(M_PI / 2);
    texture ramp;  // texel value = u (bilinear of a linear ramp reproduces u exactly)
    ramp.width = 4096;
    ramp.height = 1;
    for (int i = 0; i < ramp.width; ++i) ramp.texels.push_back((i + 0.5f) / ramp.width);
    const raster_mesh quad = tilted_quad();
    double worst_persp = 0, worst_affine = 0;
    int samples = 0;
    for (bool perspective : {true, false}) {
        canvas_ptr c = make_canvas(S, S).value();
        render_context ctx(1);
        draw_params p;
        p.model = mat4_identity();
        p.view_projection = mat4_perspective(fov, 1.0f, 0.1f, 100.0f);
        p.lights = constant_light(1.0f);
        p.shade = shading::flat;
        p.tex = &ramp;
        p.wrap = texture_wrap::clamp;
        p.perspective_correct = perspective;
        CHECK(ctx.begin_frame(*c).ok());
        ctx.draw(quad, p);
        ctx.end_frame();
        for (int y = 4; y < S - 4; y += 5)
            for (int x = 4; x < S - 4; x += 5) {
                // Ray through the pixel centre; plane z = −3.75 − 2.25·y.
                const double dx = ((x + 0.5) / S * 2 - 1), dy = 1 - (y + 0.5) / S * 2;  // tan(45°) = 1
                const double t = 3.75 / (1 - 2.25 * dy);
                const double hx = t * dx, hy = t * dy;
                if (std::fabs(hx) > 0.95 || std::fabs(hy) > 0.95) continue;  // keep off the quad's edges
                const double u = (hy + 1) / 2;
                const double err = std::fabs(c->pixels[y][x] - u);
                if (perspective) {
                    worst_persp = std::max(worst_persp, err);
                    ++samples;
                } else {
                    worst_affine = std::max(worst_affine, err);
                }
            }
    }
    CHECK(samples > 100);
    CHECK_NEAR(worst_persp, 0.0, 1e-3);
    CHECK(worst_affine > 0.05);  // affine mapping is visibly wrong on this slanted quad
}

TEST(backface_culling_removes_exactly_the_clockwise_ones) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> pos(-1.0f, 1.0f);
    raster_mesh m;
    int clockwise = 0;
    for (int k = 0; k < 200; ++k) {
        vec3_t a{pos(rng), pos(rng), -3}, b{pos(rng), pos(rng), -3}, c{pos(rng), pos(rng), -3};
        // Orientation as seen by the camera (x right, y up): cross z of (b − a) × (c − a).
        const double cz = static_cast<double>(b.x - a.x) * (c.y - a.y) - static_cast<double>(b.y - a.y) * (c.x - a.x);
        if (std::fabs(cz) < 1e-3) continue;  // keep clear of degenerate snapping
        clockwise += cz < 0;
        const std::uint32_t i = static_cast<std::uint32_t>(m.positions.size());
        m.positions.insert(m.positions.end(), {a, b, c});
        m.triangles.push_back({i, i + 1, i + 2});
    }
    m.normals.assign(m.positions.size(), {0, 0, 1});
    m.uvs.assign(m.positions.size(), {0, 0});
    m.bound_center = {0, 0, -3};
    m.bound_radius = 2;
    canvas_ptr c = make_canvas(256, 256).value();
    render_context ctx(1);
    draw_params p;
    p.model = mat4_identity();
    p.view_projection = mat4_perspective(static_cast<float>(M_PI / 2), 1.0f, 0.1f, 100.0f);
    p.lights = constant_light(0.5f);
    CHECK(ctx.begin_frame(*c).ok());
    ctx.draw(m, p);
    ctx.end_frame();
    CHECK_EQ(ctx.stats().culled_backface, static_cast<std::size_t>(clockwise));
    CHECK_EQ(ctx.stats().rasterized, m.triangles.size() - clockwise);
}

TEST(vertex_behind_the_camera_renders_only_the_visible_part) {
    constexpr int S = 96;
    const double near_plane = 0.1;
    raster_mesh m;
    // One vertex far in front, two behind the camera (z > 0), one of them off to the side.
    m.positions = {{0.0f, -0.5f, -4.0f}, {1.5f, 0.8f, 2.0f}, {-1.0f, 0.3f, 1.0f}};
    m.normals.assign(3, {0, 0, 1});
    m.uvs.assign(3, {0, 0});
    m.triangles = {{0, 1, 2}};
    m.bound_center = {0, 0, 0};
    m.bound_radius = 5;
    canvas_ptr c = make_canvas(S, S).value();
    render_context ctx(1);
    draw_params p;
    p.model = mat4_identity();
    p.view_projection = mat4_perspective(static_cast<float>(M_PI / 2), 1.0f, static_cast<float>(near_plane), 100.0f);
    p.lights = constant_light(1.0f);
    p.cull = cull_mode::none;
    CHECK(ctx.begin_frame(*c).ok());
    ctx.draw(m, p);
    ctx.end_frame();
    CHECK_EQ(ctx.stats().clipped, std::size_t{1});
    // Double-precision ray cast (Möller–Trumbore) per pixel centre: hit with −z ≥ near.
    auto sub = [](vec3_t a, vec3_t b) { return std::array<double, 3>{a.x - b.x + 0.0, a.y - b.y + 0.0, a.z - b.z + 0.0}; };
    auto crs = [](std::array<double, 3> a, std::array<double, 3> b) {
        return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    auto dt = [](std::array<double, 3> a, std::array<double, 3> b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    const auto e1 = sub(m.positions[1], m.positions[0]), e2 = sub(m.positions[2], m.positions[0]);
    int covered = 0, wrong = 0;
    for (int y = 0; y < S; ++y)
        for (int x = 0; x < S; ++x) {
            const std::array<double, 3> d{(x + 0.5) / S * 2 - 1, 1 - (y + 0.5) / S * 2, -1};
            const auto pv = crs(d, e2);
            const double det = dt(e1, pv);
            const std::array<double, 3> o{-m.positions[0].x + 0.0, -m.positions[0].y + 0.0, -m.positions[0].z + 0.0};
            const double u = dt(o, pv) / det;
            const auto q = crs(o, e1);
            const double v = dt(d, q) / det, t = dt(e2, q) / det;
            constexpr double MARGIN = 0.02;  // barycentric margin: keep off the edges
            const bool inside = u > MARGIN && v > MARGIN && u + v < 1 - MARGIN && t > near_plane * 1.05;
            const bool outside = u < -MARGIN || v < -MARGIN || u + v > 1 + MARGIN || t < near_plane * 0.95;
            const bool drawn = c->pixels[y][x] > 0.5f;
            covered += drawn;
            if ((inside && !drawn) || (outside && drawn)) ++wrong;
        }
    CHECK(covered > 200);
    CHECK_EQ(wrong, 0);
}

TEST(clip_polygon_against_the_near_plane) {
    clip_vertex in[3];
    in[0].position = {0, 0, 0.5f, 1};    // inside
    in[1].position = {1, 0, -3, -1};     // behind (z < −w)
    in[2].position = {0, 1, 0.5f, 1};    // inside
    for (int k = 0; k < 3; ++k) in[k].attr.fill(static_cast<float>(k));
    clip_vertex out[CLIP_MAX_VERTICES];
    const int n = clip_polygon(in, 3, clip_near, 1.0f, 1, out);
    CHECK_EQ(n, 4);
    for (int k = 0; k < n; ++k) CHECK(out[k].position.z + out[k].position.w >= -1e-6f);
    // Crossing on edge 0→1: d0 = 1.5, d1 = −4 → t = 1.5/5.5.
    CHECK_NEAR(out[1].attr[0], 1.5 / 5.5, 1e-6);
    CHECK_EQ(clip_outcode({NAN, 0, 0, 1}, 1.0f) != 0u, true);
    // All behind: nothing left.
    for (auto &v : in) v.position = {0, 0, -2, -1};
    CHECK_EQ(clip_polygon(in, 3, clip_near, 1.0f, 0, out), 0);
}

TEST(degenerate_and_non_finite_triangles_are_skipped) {
    const pixel_rect all{0, 0, W, H};
    CHECK(!triangle_setup(sv(1, 1), sv(5, 5), sv(9, 9), all).valid);      // collinear
    CHECK(!triangle_setup(sv(1, 1), sv(1, 1), sv(9, 2), all).valid);      // repeated vertex
    CHECK(!triangle_setup(sv(NAN, 1), sv(5, 5), sv(9, 1), all).valid);
    CHECK(!triangle_setup(sv(INFINITY, 1), sv(5, 5), sv(9, 1), all).valid);
    CHECK(!triangle_setup(sv(1e30, 1), sv(5, 5), sv(9, 1), all).valid);
    CHECK(!triangle_setup(sv(1, 1), sv(1 + 1e-9, 1), sv(1, 1 + 1e-9), all).valid);  // below the snap grid
    CHECK(triangle_setup(sv(1, 1), sv(30, 2), sv(3, 40), all).valid);
    // Denormal-sized coordinates snap to the same point: skipped, no crash.
    CHECK(!triangle_setup(sv(1e-40, 0), sv(0, 1e-40), sv(1e-39, 1e-39), all).valid);
}

TEST(two_threads_give_the_same_image_as_one) {
    mesh torus = make_torus(1.0f, 0.35f, 40, 20);
    const std::vector<vec3_t> normals = mesh_vertex_normals(torus);
    tiny3d::mesh plain = torus;
    plain.corner_uvs.clear();
    const raster_mesh shared = make_raster_mesh(plain, normals).value();
    const raster_mesh cornered = make_raster_mesh(torus, {}).value();
    texture checker;
    checker.width = checker.height = 8;
    for (int i = 0; i < 64; ++i) checker.texels.push_back(((i + i / 8) % 2) ? 1.0f : 0.3f);
    light_t lights[2] = {{{1, 1, 1}, 0.8f}, {{-1, 0, 0.5f}, 0.3f}};
    const light_rig rig = make_light_rig(lights, 0.1f).value();
    std::vector<float> images[3];
    frame_stats stats[3];
    for (int threads = 1; threads <= 3; ++threads) {
        canvas_ptr c = make_canvas(257, 193).value();
        render_context ctx(threads);
        for (int frame = 0; frame < 2; ++frame) {
            CHECK(ctx.begin_frame(*c, 0.05f).ok());
            draw_params p;
            p.view_projection = mat4_multiply(mat4_perspective(0.8f, 257.0f / 193, 0.1f, 50),
                                              mat4_look_at({0, 0.5f, 3}, {0, 0, 0}, {0, 1, 0}));
            p.lights = rig;
            const shading levels[3] = {shading::flat, shading::gouraud, shading::phong};
            for (int k = 0; k < 3; ++k) {
                p.model = mat4_multiply(mat4_translate(-1.2f + 1.2f * k, 0, -0.5f * k), mat4_rotate_xyz(0.7f, 0.3f * frame, 0));
                p.shade = levels[k];
                ctx.draw(shared, p);
            }
            p.model = mat4_multiply(mat4_translate(0, 0.6f, 0.8f), mat4_rotate_xyz(1.2f, 0, 0));
            p.tex = &checker;
            p.shade = shading::gouraud;
            ctx.draw(cornered, p);
            p.alpha = 0.5f;
            p.model = mat4_multiply(mat4_translate(0.3f, -0.4f, 1.2f), mat4_rotate_xyz(0.2f, 0.5f, 0));
            ctx.draw(cornered, p);
            // Through the near plane and beyond the guard band: clipped triangles.
            p.tex = nullptr;
            p.alpha = 1.0f;
            p.model = mat4_multiply(mat4_translate(0.2f, 0, 2.6f), mat4_rotate_xyz(1.4f, 0.2f * frame, 0));
            ctx.draw(shared, p);
            ctx.end_frame();
        }
        images[threads - 1].assign(c->data, c->data + 257 * 193);
        stats[threads - 1] = ctx.stats();
    }
    CHECK(images[0] == images[1]);
    CHECK(images[0] == images[2]);
    CHECK(stats[0].clipped > 0);
    for (int k = 1; k < 3; ++k) {  // every triangle counted once, whatever thread handled it
        CHECK_EQ(stats[k].triangles_in, stats[0].triangles_in);
        CHECK_EQ(stats[k].culled_backface, stats[0].culled_backface);
        CHECK_EQ(stats[k].clipped, stats[0].clipped);
        CHECK_EQ(stats[k].rasterized, stats[0].rasterized);
    }
    double sum = 0;
    for (float v : images[0]) sum += v;
    CHECK(sum > 257 * 193 * 0.1);  // something was drawn
}

TEST(translucent_layers_blend_back_to_front) {
    raster_mesh quad;
    quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    quad.normals.assign(4, {0, 0, 1});
    quad.uvs.assign(4, {0, 0});
    quad.triangles = {{0, 1, 2}, {0, 2, 3}};
    quad.bound_radius = 1.5f;
    canvas_ptr c = make_canvas(32, 32).value();
    render_context ctx(2);
    CHECK(ctx.begin_frame(*c, 0.2f).ok());
    draw_params p;
    p.view_projection = mat4_perspective(static_cast<float>(M_PI / 2), 1, 0.1f, 10);
    p.alpha = 0.5f;
    // Submitted front first: the back one must still be blended first.
    p.model = mat4_translate(0, 0, -2);
    p.lights = constant_light(1.0f);
    ctx.draw(quad, p);
    p.model = mat4_translate(0, 0, -3);
    p.lights = constant_light(0.6f);
    ctx.draw(quad, p);
    ctx.end_frame();
    const double back = 0.5 * 0.6 + 0.5 * 0.2, front = 0.5 * 1.0 + 0.5 * back;
    CHECK_NEAR(c->pixels[16][16], front, 1e-6);
    CHECK_NEAR(ctx.depth().at(16, 16), 1.0, 0.0);  // translucent draws do not write depth
}

TEST(texture_sampling_nearest_bilinear_wrap_clamp) {
    texture t;
    t.width = 2;
    t.height = 2;
    t.texels = {0.0f, 1.0f, 0.5f, 0.25f};
    CHECK_EQ(texture_sample(t, 0.25f, 0.25f, texture_filter::nearest, texture_wrap::repeat), 0.0f);
    CHECK_EQ(texture_sample(t, 0.75f, 0.75f, texture_filter::nearest, texture_wrap::repeat), 0.25f);
    CHECK_EQ(texture_sample(t, 1.75f, -0.25f, texture_filter::nearest, texture_wrap::repeat), 0.25f);
    CHECK_EQ(texture_sample(t, 5.0f, 0.25f, texture_filter::nearest, texture_wrap::clamp), 1.0f);
    // Bilinear at the centre of the four texel centres: their mean.
    CHECK_NEAR(texture_sample(t, 0.5f, 0.5f, texture_filter::bilinear, texture_wrap::clamp), 0.4375, 1e-6);
    // Clamp: left of the first centre holds the edge texels; repeat wraps to the far column.
    CHECK_NEAR(texture_sample(t, 0.0f, 0.25f, texture_filter::bilinear, texture_wrap::clamp), 0.0, 1e-6);
    CHECK_NEAR(texture_sample(t, 0.0f, 0.25f, texture_filter::bilinear, texture_wrap::repeat), 0.5, 1e-6);
    CHECK_EQ(texture_sample(t, NAN, 0.5f, texture_filter::bilinear, texture_wrap::repeat), 0.0f);
    CHECK_EQ(texture_sample(t, 1e30f, 0.5f, texture_filter::nearest, texture_wrap::repeat) >= 0.0f, true);
}

TEST(zbuffer_resize_and_clear) {
    zbuffer z;
    CHECK(!z.resize(0, 5).ok());
    CHECK(z.resize(8, 4).ok());
    z.clear(0.25f);
    CHECK_EQ(z.at(7, 3), 0.25f);
    const float *block = z.row(0);
    CHECK(z.resize(4, 8).ok());  // same pixel count: same block
    CHECK(z.row(0) == block);
    z.clear_rows(2, 4, 0.5f);
    CHECK_EQ(z.at(0, 1), 0.25f);
    CHECK_EQ(z.at(3, 3), 0.5f);
}

// ---- cluster culling: the same frame with and without clusters -----------------------------

namespace {

struct rendered {
    std::vector<float> colour, depth;
    frame_stats stats;
};

rendered render_frame(render_context &ctx, canvas_t &c, const raster_mesh &m, const draw_params &p) {
    rendered r;
    if (!ctx.begin_frame(c, 0.05f).ok()) return r;
    ctx.draw(m, p);
    ctx.end_frame();
    const std::size_t n = static_cast<std::size_t>(c.width) * c.height;
    r.colour.assign(c.data, c.data + n);
    r.depth.assign(ctx.depth().row(0), ctx.depth().row(0) + n);
    r.stats = ctx.stats();
    return r;
}

// Bit-identical pixels and depths, and equal stats apart from the cluster share.
bool same_frame(const rendered &a, const rendered &b) {
    auto bits_equal = [](const std::vector<float> &x, const std::vector<float> &y) {
        return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(float)) == 0;
    };
    return bits_equal(a.colour, b.colour) && bits_equal(a.depth, b.depth) && a.stats.triangles_in == b.stats.triangles_in &&
           a.stats.culled_frustum == b.stats.culled_frustum && a.stats.culled_backface == b.stats.culled_backface &&
           a.stats.clipped == b.stats.clipped && a.stats.rasterized == b.stats.rasterized;
}

draw_params scene_s_params() {
    draw_params p;
    const light_t light = {{1, 1, 1}, 1.0f};
    p.lights = make_light_rig(std::span<const light_t>(&light, 1), 0.1f).value();
    p.view_projection = mat4_multiply(mat4_perspective(static_cast<float>(M_PI / 4), 1.0f, 0.1f, 100.0f),
                                      mat4_look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}));
    return p;
}

raster_mesh smooth_raster_mesh(const mesh &m) { return make_raster_mesh(m, mesh_vertex_normals(m)).value(); }

}  // namespace

TEST(cluster_bounds_hold_for_every_triangle) {
    const raster_mesh m = smooth_raster_mesh(make_icosphere(4));
    CHECK(!make_raster_clusters(m, 0).ok());
    raster_mesh bad = m;
    bad.triangles[7][1] = static_cast<std::uint32_t>(m.positions.size());
    CHECK(!make_raster_clusters(bad, 64).ok());
    const raster_clusters cl = make_raster_clusters(m, 64).value();
    CHECK_EQ(cl.clusters().size(), std::size_t{5120 / 64});
    CHECK_EQ(cl.triangle_count(), m.triangles.size());
    std::size_t next = 0, with_cone = 0;
    for (const raster_cluster &c : cl.clusters()) {
        CHECK_EQ(std::size_t{c.first}, next);  // in order, no gap
        next = c.first + c.count;
        with_cone += c.cone_valid;
        for (std::uint32_t i = c.first; i < c.first + c.count; ++i) {
            // Recomputed independently in long double.
            long double p[3][3];
            for (int k = 0; k < 3; ++k) {
                const vec3_t v = m.positions[m.triangles[i][k]];
                p[k][0] = v.x, p[k][1] = v.y, p[k][2] = v.z;
                const long double d = std::sqrt((p[k][0] - c.center[0]) * (p[k][0] - c.center[0]) +
                                                (p[k][1] - c.center[1]) * (p[k][1] - c.center[1]) +
                                                (p[k][2] - c.center[2]) * (p[k][2] - c.center[2]));
                CHECK(d <= c.radius);
            }
            const long double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
            const long double v[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
            const long double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
            const long double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            CHECK(len >= c.min_double_area);
            const long double edges = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) + std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            CHECK(edges / len <= c.edge_ratio);
            if (!c.cone_valid) continue;
            const long double along = (n[0] * c.axis[0] + n[1] * c.axis[1] + n[2] * c.axis[2]) / len;
            CHECK(along >= c.cone_cos);
            const long double behind = (n[0] * (p[0][0] - c.apex[0]) + n[1] * (p[0][1] - c.apex[1]) + n[2] * (p[0][2] - c.apex[2])) / len;
            CHECK(behind >= c.apex_margin);
        }
    }
    CHECK_EQ(next, m.triangles.size());
    CHECK_EQ(with_cone, cl.clusters().size());  // every level-4 chunk of 64 is a small smooth patch
    CHECK(cl.clusters()[3].cone_cos > 0.9);
}

TEST(clusters_give_the_same_scene_s_frames_for_any_thread_count) {
    const raster_mesh m = smooth_raster_mesh(make_icosphere(6));
    const raster_clusters cl = make_raster_clusters(m, RASTER_CLUSTER_TRIANGLES).value();
    canvas_ptr c = make_canvas(1024, 1024).value();
    draw_params p = scene_s_params();
    rendered first_with[3];
    for (int threads = 1; threads <= 3; ++threads) {
        render_context ctx(threads);
        for (int degrees : {0, 37, 90}) {
            p.model = mat4_rotate_y(static_cast<float>(degrees * M_PI / 180));
            p.clusters = nullptr;
            const rendered plain = render_frame(ctx, *c, m, p);
            p.clusters = &cl;
            const rendered with = render_frame(ctx, *c, m, p);
            CHECK(same_frame(plain, with));
            CHECK_EQ(plain.stats.backface_by_cluster, std::size_t{0});
            // Two thirds of the sphere face away from a camera at distance 3; most of them
            // lie in chunks the cone proves back-facing (90.6 % at level 6, chunks of 64).
            CHECK(with.stats.culled_backface > m.triangles.size() / 2);
            CHECK(with.stats.backface_by_cluster > with.stats.culled_backface * 85 / 100);
            if (degrees == 0) first_with[threads - 1] = with;
        }
    }
    for (int k = 1; k < 3; ++k) {
        CHECK(same_frame(first_with[0], first_with[k]));
        CHECK_EQ(first_with[k].stats.backface_by_cluster, first_with[0].stats.backface_by_cluster);
    }
}

TEST(clusters_never_change_a_frame_random_meshes_cameras_and_projections) {
    std::mt19937 rng(2026);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * unit(rng); };
    // Meshes: coherent (bumpy icospheres, a torus knot) and incoherent (a random soup).
    std::vector<raster_mesh> meshes;
    for (float bump : {0.0f, 0.05f, 0.3f}) {
        mesh s = make_icosphere(3);
        for (vec3_t &v : s.positions) v = v * (1.0f + bump * (unit(rng) - 0.5f));
        meshes.push_back(smooth_raster_mesh(s));
    }
    meshes.push_back(smooth_raster_mesh(make_torus_knot(2, 3, 60, 8)));
    raster_mesh soup;
    for (int k = 0; k < 300; ++k) {
        const vec3_t a{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        const std::uint32_t i = static_cast<std::uint32_t>(soup.positions.size());
        soup.positions.insert(soup.positions.end(), {a, a + vec3_t{uniform(-0.2f, 0.2f), uniform(-0.2f, 0.2f), uniform(-0.2f, 0.2f)},
                                                     a + vec3_t{uniform(-0.2f, 0.2f), uniform(-0.2f, 0.2f), uniform(-0.2f, 0.2f)}});
        soup.triangles.push_back({i, i + 1, i + 2});
    }
    soup.normals.assign(soup.positions.size(), {0, 0, 1});
    soup.uvs.assign(soup.positions.size(), {0, 0});
    soup.bound_radius = 2;
    meshes.push_back(soup);
    const int cluster_sizes[4] = {1, 5, 64, 256};
    std::size_t by_cluster = 0, cases = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const raster_mesh &m = meshes[trial % meshes.size()];
        const raster_clusters cl = make_raster_clusters(m, cluster_sizes[(trial / 5) % 4]).value();
        const int w = 40 + static_cast<int>(unit(rng) * 260), h = 40 + static_cast<int>(unit(rng) * 260);
        canvas_ptr c = make_canvas(w, h).value();
        draw_params p = scene_s_params();
        p.shade = trial % 3 == 0 ? shading::flat : shading::gouraud;
        p.cull = trial % 7 == 3 ? cull_mode::front : (trial % 7 == 5 ? cull_mode::none : cull_mode::back);
        // Camera from inside the mesh (distance 0.3) to far away; fields of view from 1° to
        // 160°; near planes from 1e-3 to 0.5.
        const float distance = std::exp(uniform(std::log(0.3f), std::log(60.0f)));
        const float yaw = uniform(0, 6.3f), pitch = uniform(-1.5f, 1.5f);
        const vec3_t eye{distance * std::cos(pitch) * std::cos(yaw), distance * std::sin(pitch), distance * std::cos(pitch) * std::sin(yaw)};
        const vec3_t look{uniform(-0.8f, 0.8f), uniform(-0.8f, 0.8f), uniform(-0.8f, 0.8f)};
        const float fov = std::exp(uniform(std::log(0.0175f), std::log(2.8f)));
        p.view_projection = mat4_multiply(mat4_perspective(fov, static_cast<float>(w) / h, std::exp(uniform(std::log(1e-3f), std::log(0.5f))), 1000.0f),
                                          mat4_look_at(eye, look, {0, 1, 0}));
        // Rotations, non-uniform and (every 11th) mirroring scales, offsets.
        const float mirror = trial % 11 == 4 ? -1.0f : 1.0f;
        p.model = mat4_multiply(mat4_translate(uniform(-0.5f, 0.5f), uniform(-0.5f, 0.5f), uniform(-0.5f, 0.5f)),
                                mat4_multiply(mat4_rotate_xyz(uniform(0, 6.3f), uniform(0, 6.3f), uniform(0, 6.3f)),
                                              mat4_scale(mirror * uniform(0.5f, 1.5f), uniform(0.5f, 1.5f), uniform(0.5f, 1.5f))));
        for (int threads : {1, 2, 3}) {
            render_context ctx(threads);
            p.clusters = nullptr;
            const rendered plain = render_frame(ctx, *c, m, p);
            p.clusters = &cl;
            const rendered with = render_frame(ctx, *c, m, p);
            CHECK_MSG(same_frame(plain, with), "trial " + std::to_string(trial) + ", " + std::to_string(threads) + " threads");
            if (p.cull != cull_mode::back || mirror < 0) CHECK_EQ(with.stats.backface_by_cluster, std::size_t{0});
            by_cluster += with.stats.backface_by_cluster;
            ++cases;
        }
    }
    CHECK(by_cluster > 0);  // the skip path was taken
    CHECK_EQ(cases, std::size_t{180});
}

TEST(clusters_near_the_silhouette_and_close_cameras) {
    // Grazing chunks: a camera just outside the sphere sees most triangles nearly edge-on;
    // every tenth of a degree of rotation moves the silhouette through the chunks.
    const raster_mesh m = smooth_raster_mesh(make_icosphere(4));
    const raster_clusters small = make_raster_clusters(m, 4).value(), large = make_raster_clusters(m, 64).value();
    canvas_ptr c = make_canvas(160, 120).value();
    render_context one(1), two(2);
    std::size_t by_cluster = 0;
    for (float distance : {1.02f, 1.1f, 1.5f, 3.0f, 40.0f}) {
        draw_params p = scene_s_params();
        p.view_projection = mat4_multiply(mat4_perspective(2.0f * std::atan(1.2f / distance), 160.0f / 120, 0.01f, 100.0f),
                                          mat4_look_at({0, 0, distance}, {0, 0, 0}, {0, 1, 0}));
        for (int step = 0; step < 12; ++step) {
            p.model = mat4_rotate_xyz(0.0017f * step, 0.1f * step, 0);
            for (const raster_clusters *cl : {&small, &large}) {
                for (render_context *ctx : {&one, &two}) {
                    p.clusters = nullptr;
                    const rendered plain = render_frame(*ctx, *c, m, p);
                    p.clusters = cl;
                    const rendered with = render_frame(*ctx, *c, m, p);
                    CHECK(same_frame(plain, with));
                    by_cluster += with.stats.backface_by_cluster;
                }
            }
        }
    }
    CHECK(by_cluster > 0);
}

TEST(clusters_of_another_mesh_are_ignored) {
    const raster_mesh m = smooth_raster_mesh(make_icosphere(4)), other = smooth_raster_mesh(make_icosphere(3));
    const raster_clusters stale = make_raster_clusters(other, 64).value();
    canvas_ptr c = make_canvas(128, 128).value();
    render_context ctx(2);
    draw_params p = scene_s_params();
    p.model = mat4_identity();
    const rendered plain = render_frame(ctx, *c, m, p);
    p.clusters = &stale;
    const rendered with = render_frame(ctx, *c, m, p);
    CHECK(same_frame(plain, with));
    CHECK_EQ(with.stats.backface_by_cluster, std::size_t{0});
}

TEST(clusters_with_hostile_vertices_and_matrices) {
    // Non-finite, huge, denormal and coincident vertices, degenerate triangles, and matrices
    // with NaN or a zero row: every chunk test must fail safe (walk the chunk), never skip
    // wrongly, and the frame must equal the frame without clusters.
    raster_mesh m = smooth_raster_mesh(make_icosphere(3));
    m.positions[5] = {NAN, 0, 0};
    m.positions[40] = {1e30f, -1e30f, 0};
    m.positions[77] = {1e-40f, 1e-41f, -1e-40f};
    m.positions[90] = m.positions[91];
    m.triangles[300] = {7, 7, 8};
    m.triangles[301] = {9, 10, 9};
    const raster_clusters cl = make_raster_clusters(m, 16).value();
    std::size_t without_cone = 0;
    for (const raster_cluster &c : cl.clusters()) without_cone += !c.cone_valid;
    CHECK(without_cone >= 3);  // the chunks holding the NaN, the 1e30 and the degenerate triangles
    canvas_ptr c = make_canvas(96, 80).value();
    render_context ctx(2);
    draw_params p = scene_s_params();
    mat4_t nan_matrix = p.view_projection, flat_matrix = p.view_projection;
    nan_matrix.m[5] = NAN;
    for (int col = 0; col < 4; ++col) flat_matrix.m[col * 4 + 3] = 0.0f;  // w row zero
    std::size_t by_cluster = 0;
    for (const mat4_t &vp : {p.view_projection, nan_matrix, flat_matrix}) {
        p.view_projection = vp;
        for (float angle : {0.0f, 1.0f, 2.5f}) {
            p.model = mat4_rotate_xyz(angle, 0.3f * angle, 0);
            p.clusters = nullptr;
            const rendered plain = render_frame(ctx, *c, m, p);
            p.clusters = &cl;
            const rendered with = render_frame(ctx, *c, m, p);
            CHECK(same_frame(plain, with));
            by_cluster += with.stats.backface_by_cluster;
        }
    }
    CHECK(by_cluster > 0);  // the finite, regular chunks still cull under the ordinary matrix
}

TEST(a_vertex_index_out_of_range_draws_nothing) {
    // The index check runs four indices at a time: put the bad one in the vector part, in the
    // scalar tail, at the boundary value and at the top of the unsigned range.
    const raster_mesh good = smooth_raster_mesh(make_icosphere(2));  // 320 triangles = 960 indices
    const std::uint32_t count = static_cast<std::uint32_t>(good.positions.size());
    canvas_ptr c = make_canvas(64, 64).value();
    render_context ctx(2);
    draw_params p = scene_s_params();
    p.model = mat4_identity();
    CHECK(render_frame(ctx, *c, good, p).stats.rasterized > 0);
    for (std::size_t at : {std::size_t{5}, std::size_t{319}}) {
        for (std::uint32_t bad : {count, count + 1, 0xffffffffu}) {
            raster_mesh m = good;
            m.triangles[at][at % 3] = bad;
            const rendered r = render_frame(ctx, *c, m, p);
            CHECK_EQ(r.stats.rasterized, std::size_t{0});
            CHECK_EQ(r.stats.triangles_in, m.triangles.size());
        }
    }
    raster_mesh tail = good;
    tail.triangles.push_back({0, 1, count});  // 963 indices: the last one in the scalar tail
    CHECK_EQ(render_frame(ctx, *c, tail, p).stats.rasterized, std::size_t{0});
    tail.triangles.back() = {0, 1, count - 1};
    CHECK(render_frame(ctx, *c, tail, p).stats.rasterized > 0);
}
