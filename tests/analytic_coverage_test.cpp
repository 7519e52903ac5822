// analytic_coverage_test.cpp — the antialias bench's analytic-coverage prototype
// (tests/bench/common/analytic_coverage.h): the per-pixel areas against hand-computed
// fractions and against an independent clip-and-shoelace computation, and a small frame
// against render_reference. Linked with tests/bench/common (build/bench/libtiny3d_bench.a).
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "bench/common/analytic_coverage.h"
#include "harness.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"

namespace {

using bench::coverage_box;

// Area of triangle ∩ [px, px+1] × [py, py+1]: Sutherland–Hodgman against the four sides,
// then the shoelace formula, in double.
double clipped_area(const double x[3], const double y[3], int px, int py) {
    std::vector<std::array<double, 2>> poly = {{x[0], y[0]}, {x[1], y[1]}, {x[2], y[2]}};
    const double bound[4] = {double(px), double(px + 1), double(py), double(py + 1)};
    for (int side = 0; side < 4; ++side) {
        const int axis = side / 2;
        const double s = side % 2 ? -1.0 : 1.0, b = bound[side];
        std::vector<std::array<double, 2>> out;
        for (std::size_t k = 0; k < poly.size(); ++k) {
            const auto &p = poly[k], &q = poly[(k + 1) % poly.size()];
            const double dp = s * (p[axis] - b), dq = s * (q[axis] - b);
            if (dp >= 0) out.push_back(p);
            if ((dp >= 0) != (dq >= 0)) {
                const double t = dp / (dp - dq);
                out.push_back({p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t});
            }
        }
        poly = out;
        if (poly.empty()) return 0;
    }
    double a = 0;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        const auto &p = poly[k], &q = poly[(k + 1) % poly.size()];
        a += p[0] * q[1] - q[0] * p[1];
    }
    return std::fabs(a) / 2;
}

double area_at(const coverage_box &b, int px, int py) {
    if (px < b.x0 || px >= b.x0 + b.w || py < b.y0 || py >= b.y0 + b.h) return 0;
    return b.area(px - b.x0, py - b.y0);
}

}  // namespace

TEST(analytic_area_of_known_fractions) {
    coverage_box b;
    // Half of pixel (2, 3) cut by its diagonal, both orientations.
    const float x1[3] = {2, 3, 2}, y1[3] = {3, 3, 4};
    b.compute(x1, y1);
    CHECK_NEAR(area_at(b, 2, 3), 0.5, 1e-6);
    const float x2[3] = {2, 2, 3}, y2[3] = {3, 4, 3};
    b.compute(x2, y2);
    CHECK_NEAR(area_at(b, 2, 3), 0.5, 1e-6);
    // A right triangle with legs 2 over pixels (0..1, 0..1) from (10, 20): the corner pixel
    // is full, the two beside it half, the far one empty.
    const float x3[3] = {10, 12, 10}, y3[3] = {20, 20, 22};
    b.compute(x3, y3);
    CHECK_NEAR(area_at(b, 10, 20), 1.0, 1e-6);
    CHECK_NEAR(area_at(b, 11, 20), 0.5, 1e-6);
    CHECK_NEAR(area_at(b, 10, 21), 0.5, 1e-6);
    CHECK_NEAR(area_at(b, 11, 21), 0.0, 1e-6);
    // A sliver inside one pixel: base 0.5 at y = 5.25, apex at y = 5.75 → area 0.125.
    const float x4[3] = {7.25f, 7.75f, 7.5f}, y4[3] = {5.25f, 5.25f, 5.75f};
    b.compute(x4, y4);
    CHECK_NEAR(area_at(b, 7, 5), 0.125, 1e-6);
    CHECK_EQ(b.w, 1);
    CHECK_EQ(b.h, 1);
}

TEST(analytic_area_matches_clipping_and_shoelace) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> pos(100.0f, 108.0f);
    coverage_box b;
    double worst = 0, total = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const float x[3] = {pos(rng), pos(rng), pos(rng)}, y[3] = {pos(rng), pos(rng), pos(rng)};
        const double dx[3] = {x[0], x[1], x[2]}, dy[3] = {y[0], y[1], y[2]};
        b.compute(x, y);
        double sum = 0;
        for (int py = 99; py <= 109; ++py)
            for (int px = 99; px <= 109; ++px) {
                worst = std::max(worst, std::fabs(area_at(b, px, py) - clipped_area(dx, dy, px, py)));
                sum += area_at(b, px, py);
            }
        const double whole = std::fabs((dx[1] - dx[0]) * (dy[2] - dy[0]) - (dy[1] - dy[0]) * (dx[2] - dx[0])) / 2;
        total = std::max(total, std::fabs(sum - whole));
    }
    CHECK(worst < 2e-5);  // float accumulation at coordinates ~100
    CHECK(total < 1e-4);
}

// A small icosphere frame against the 256-sample reference: the silhouette pixels (partial
// reference coverage) within 3 grey levels on average (measured 1.1).
TEST(analytic_frame_near_the_reference) {
    using namespace tiny3d;
    constexpr int SIDE = 96;
    const mesh m = make_icosphere(3);
    raster_mesh rm = make_raster_mesh(m, mesh_vertex_normals(m)).value();
    draw_params p;
    const light_t light = {{1, 1, 1}, 1.0f};
    p.lights = make_light_rig(std::span<const light_t>(&light, 1), 0.1f).value();
    p.view_projection = mat4_multiply(mat4_perspective(static_cast<float>(45 * M_PI / 180), 1.0f, 0.1f, 100.0f),
                                      mat4_look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}));
    p.model = mat4_identity();
    draw_params white = p;
    white.lights = make_light_rig(std::span<const light_t>(), 1.0f).value();
    white.shade = shading::flat;
    canvas_ptr ref = make_canvas(SIDE, SIDE).value(), cov = make_canvas(SIDE, SIDE).value(), img = make_canvas(SIDE, SIDE).value();
    const reference_draw shaded{&rm, p}, flat{&rm, white};
    CHECK(render_reference(*ref, std::span<const reference_draw>(&shaded, 1)).ok());
    CHECK(render_reference(*cov, std::span<const reference_draw>(&flat, 1)).ok());
    bench::analytic_renderer r;
    CHECK(r.render(*img, rm, p, 0.0f));
    CHECK_EQ(r.skipped(), 0L);
    // The flat white frame: the analytic coverage itself, against the reference's sampled one.
    canvas_ptr img_white = make_canvas(SIDE, SIDE).value();
    CHECK(r.render(*img_white, rm, white, 0.0f));
    double edge = 0, edge_cov = 0;
    long n = 0;
    for (int k = 0; k < SIDE * SIDE; ++k)
        if (cov->data[k] > 1e-3f && cov->data[k] < 1 - 1e-3f) {
            edge += 255 * std::fabs(img->data[k] - ref->data[k]);
            edge_cov = std::max(edge_cov, static_cast<double>(std::fabs(img_white->data[k] - cov->data[k])));
            ++n;
        }
    std::printf("  analytic: silhouette %.2f (%ld px), coverage max diff %.4f\n", edge / static_cast<double>(n), n, edge_cov);
    CHECK(n > 100);
    CHECK(edge / static_cast<double>(n) < 3.0);
    CHECK(edge_cov < 0.03);  // measured 0.017: the reference's 256-sample lattice errs too
}
