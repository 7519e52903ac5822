// raster_test.cpp — filled triangles: coverage (watertight, top-left), fast fill vs the
// 64-bit reference, depth, the scan-line fill, degenerate / NaN input, the z-buffer. The
// render context's drawing (perspective-correct uv, culling, near-plane clipping, threads,
// textures, transparency): raster_context_test.cpp; cluster culling: raster_cluster_test.cpp.
#include <cmath>
#include <random>
#include <vector>

#include "harness.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "pipeline.h"
#include "raster.h"

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
