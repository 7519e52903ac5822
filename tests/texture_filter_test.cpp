// texture_filter_test.cpp — mipmaps, the trilinear level of detail and the converged
// reference image that the anti-aliasing modes are measured against (antialias_test.cpp).
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "harness.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"
#include "raster_test_util.h"

using namespace tiny3d;
using raster_test::clip_quad;
using raster_test::draw_frame;
using raster_test::flat_params;

// ---- mipmaps ----------------------------------------------------------------------------

TEST(mipmap_levels_are_the_hand_computed_box_averages) {
    texture t;
    t.width = 4;
    t.height = 2;
    t.texels = {0, 1, 2, 3,  //
                4, 5, 6, 7};
    CHECK(build_mipmaps(t).ok());
    CHECK_EQ(t.mipmaps.size(), std::size_t{2});  // 2 × 1, 1 × 1
    CHECK_EQ(t.mipmaps[0].width, 2);
    CHECK_EQ(t.mipmaps[0].height, 1);
    CHECK_NEAR(t.mipmaps[0].texels[0], (0 + 1 + 4 + 5) / 4.0, 1e-6);
    CHECK_NEAR(t.mipmaps[0].texels[1], (2 + 3 + 6 + 7) / 4.0, 1e-6);
    CHECK_EQ(t.mipmaps[1].width, 1);
    CHECK_NEAR(t.mipmaps[1].texels[0], 3.5, 1e-6);
    // Odd size: 3 × 3 → 1 × 1 is the mean of all nine texels; 5 × 1 → 2 × 1 splits the
    // middle texel between the two outputs (footprints [0, 2.5) and [2.5, 5)).
    texture odd;
    odd.width = 3;
    odd.height = 3;
    odd.texels = {1, 2, 3, 4, 5, 6, 7, 8, 10};
    CHECK(build_mipmaps(odd).ok());
    CHECK_EQ(odd.mipmaps.size(), std::size_t{1});
    CHECK_NEAR(odd.mipmaps[0].texels[0], 46.0 / 9, 1e-6);
    texture row;
    row.width = 5;
    row.height = 1;
    row.texels = {1, 2, 3, 4, 6};
    CHECK(build_mipmaps(row).ok());
    CHECK_EQ(row.mipmaps[0].width, 2);
    CHECK_NEAR(row.mipmaps[0].texels[0], (1 + 2 + 0.5 * 3) / 2.5, 1e-6);
    CHECK_NEAR(row.mipmaps[0].texels[1], (0.5 * 3 + 4 + 6) / 2.5, 1e-6);
    CHECK_NEAR(row.mipmaps[1].texels[0], 16.0 / 5, 1e-6);  // the mean is kept level to level
    // A wrong texel count is an error and leaves the levels alone.
    texture bad = t;
    bad.texels.pop_back();
    CHECK(!build_mipmaps(bad).ok());
    CHECK_EQ(bad.mipmaps.size(), std::size_t{2});
}

TEST(texture_lod_is_log2_of_the_larger_texel_footprint) {
    texture t;
    t.width = 64;
    t.height = 32;
    CHECK_NEAR(texture_lod(t, 4.0f / 64, 0, 0, 2.0f / 32), 2.0, 1e-6);  // 4 texels per px along x
    CHECK_NEAR(texture_lod(t, 0, 3.0f / 32, 0, 4.0f / 32), 2.0, 1e-6);  // |(0, 3)| < |(0, 4)|
    CHECK_NEAR(texture_lod(t, 3.0f / 64, 4.0f / 32, 0, 0), std::log2(5.0), 1e-6);  // |(3, 4)| = 5
    CHECK(texture_lod(t, 0.5f / 64, 0, 0, 0.5f / 32) < 0);  // magnification
    CHECK(std::isnan(texture_lod(t, NAN, 0, 0, 0)));
}

TEST(trilinear_blends_the_two_levels_around_the_lod) {
    texture t;
    t.width = 16;
    t.height = 16;
    t.texels.assign(256, 0.0f);
    CHECK(build_mipmaps(t).ok());
    CHECK_EQ(t.mipmaps.size(), std::size_t{4});
    for (std::size_t k = 0; k < t.mipmaps.size(); ++k)
        std::fill(t.mipmaps[k].texels.begin(), t.mipmaps[k].texels.end(), 0.1f * (k + 1));  // level k+1 = 0.1(k+1)
    CHECK_NEAR(texture_sample_trilinear(t, 0.3f, 0.7f, 0.0f, texture_wrap::repeat), 0.0, 1e-6);
    CHECK_NEAR(texture_sample_trilinear(t, 0.3f, 0.7f, 2.25f, texture_wrap::repeat), 0.225, 1e-6);
    CHECK_NEAR(texture_sample_trilinear(t, 0.3f, 0.7f, -3.0f, texture_wrap::repeat), 0.0, 1e-6);
    CHECK_NEAR(texture_sample_trilinear(t, 0.3f, 0.7f, 99.0f, texture_wrap::repeat), 0.4, 1e-6);
    CHECK_NEAR(texture_sample_trilinear(t, 0.3f, 0.7f, NAN, texture_wrap::repeat), 0.0, 1e-6);
    CHECK_EQ(texture_sample_trilinear(t, NAN, 0.7f, 1.0f, texture_wrap::repeat), 0.0f);
}

// A plane with known derivatives: a screen-filling quad whose u advances 2^λu / 64 per pixel
// along x and v 2^λv / 64 along y; with the levels painted constant, each pixel shows the
// blend at λ = max(λu, λv), affine and perspective-correct alike (w = 1).
TEST(trilinear_lod_on_a_plane_with_known_derivatives) {
    constexpr int S = 32;
    texture t;
    t.width = 64;
    t.height = 64;
    t.texels.assign(64 * 64, 0.0f);
    CHECK(build_mipmaps(t).ok());
    for (std::size_t k = 0; k < t.mipmaps.size(); ++k)
        std::fill(t.mipmaps[k].texels.begin(), t.mipmaps[k].texels.end(), 0.1f * (k + 1));
    const struct {
        double lod_u, lod_v;
    } cases[] = {{2.5, 1.0}, {0.75, 1.5}, {-1.0, -2.0}, {3.0, 3.0}};
    for (const auto &c : cases) {
        for (bool perspective : {true, false}) {
            // Over the S-pixel canvas the quad's uv spans S · 2^λ / 64.
            const float du = static_cast<float>(S * std::exp2(c.lod_u) / 64), dv = static_cast<float>(S * std::exp2(c.lod_v) / 64);
            const raster_mesh quad = clip_quad(-1, -1, 1, 1, 0, 0.25f, 0.5f, du, -dv);
            canvas_ptr canvas = make_canvas(S, S).value();
            render_context ctx(1);
            draw_params p = flat_params(1.0f);
            p.tex = &t;
            p.filter = texture_filter::trilinear;
            p.perspective_correct = perspective;
            CHECK(draw_frame(ctx, *canvas, quad, p).ok());
            const double lod = std::max(0.0, std::max(c.lod_u, c.lod_v));
            const double expected = 0.1 * std::min(lod, 6.0);  // level k shows 0.1·k
            double worst = 0;
            for (int y = 0; y < S; ++y)
                for (int x = 0; x < S; ++x) worst = std::max(worst, std::fabs(canvas->pixels[y][x] - expected));
            CHECK_NEAR(worst, 0.0, 1e-4);
        }
    }
}

// ---- the converged reference ----------------------------------------------------------

// A half-plane edge through a pixel: the reference's coverage against the exact area.
TEST(reference_coverage_matches_the_exact_area) {
    constexpr int S = 8;
    canvas_ptr canvas = make_canvas(S, S).value();
    // A big triangle whose left edge runs from screen (2.3, −8) to (4.1, 16), interior to its
    // right; in clip space x = 2·sx/S − 1, y = 1 − 2·sy/S.
    auto clip_x = [](double sx) { return static_cast<float>(2 * sx / S - 1); };
    auto clip_y = [](double sy) { return static_cast<float>(1 - 2 * sy / S); };
    raster_mesh m;
    m.positions = {{clip_x(2.3), clip_y(-8), 0}, {clip_x(4.1), clip_y(16), 0}, {clip_x(40), clip_y(4), 0}};
    m.normals.assign(3, vec3_t{0, 0, 1});
    m.uvs.assign(3, vec2{0, 0});
    m.triangles = {{0, 1, 2}};
    m.bound_radius = 100;
    draw_params p = flat_params(1.0f);
    p.cull = cull_mode::none;
    const reference_draw d{&m, p};
    CHECK(render_reference(*canvas, std::span<const reference_draw>(&d, 1), 0.0f, 16).ok());
    double worst = 0;
    for (int py = 0; py < S; ++py)
        for (int px = 0; px < S; ++px) {
            // Edge x(y) = 2.3 + 0.075·(y + 8); covered area of the pixel right of it.
            const double slope = 1.8 / 24;
            auto xe = [&](double y) { return 2.3 + slope * (y + 8); };
            // ∫ over y in [py, py + 1] of clamp(px + 1 − xe(y), 0, 1) dy, numerically fine-grained.
            double area = 0;
            constexpr int STEPS = 4000;
            for (int k = 0; k < STEPS; ++k) area += std::clamp(px + 1 - xe(py + (k + 0.5) / STEPS), 0.0, 1.0) / STEPS;
            worst = std::max(worst, std::fabs(canvas->pixels[py][px] - area));
        }
    CHECK(worst > 0);         // the samples are not the exact integral ...
    CHECK_NEAR(worst, 0.0, 1.5 / 256);  // ... but within ~1 sample of it (sheared grid)
}

TEST(reference_rejects_bad_input) {
    canvas_ptr canvas = make_canvas(4, 4).value();
    raster_mesh m = clip_quad(-1, -1, 1, 1, 0, 0, 0, 1, 1);
    draw_params p = flat_params(1.0f);
    reference_draw d{&m, p};
    CHECK(!render_reference(*canvas, std::span<const reference_draw>(&d, 1), 0.0f, 0).ok());
    d.params.alpha = 0.5f;
    CHECK(!render_reference(*canvas, std::span<const reference_draw>(&d, 1)).ok());
    d.params.alpha = 1.0f;
    m.triangles[0][1] = 7;
    CHECK(!render_reference(*canvas, std::span<const reference_draw>(&d, 1)).ok());
    d.mesh = nullptr;
    CHECK(!render_reference(*canvas, std::span<const reference_draw>(&d, 1)).ok());
}

