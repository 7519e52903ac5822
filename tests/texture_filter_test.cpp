// texture_filter_test.cpp — mipmaps, the trilinear level of detail, anisotropic filtering,
// every filter on a grazing plane against the supersampled reference, and the converged
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
#include "grazing_plane.h"
#include "../src/raster/texture/uv_derivatives.h"

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

// The per-pixel path's log2 (a polynomial on the mantissa) against libm's in double, over
// every binade of the normal floats, at the special values and exactly at powers of two
// (so that integer levels of detail select one level, as texture_lod does).
TEST(fast_log2_is_within_its_bound_of_log2) {
    using detail::fast_log2;
    double worst = 0;
    for (int e = -126; e <= 127; ++e)
        for (int k = 0; k < 512; ++k) {
            const float x = std::ldexp(1.0f + static_cast<float>(k) / 512.0f + 1.0f / 4096.0f, e);
            if (!std::isfinite(x)) continue;
            worst = std::max(worst, std::fabs(fast_log2(x) - std::log2(static_cast<double>(x))));
        }
    CHECK(worst > 0);  // a polynomial, not libm ...
    CHECK_NEAR(worst, 0.0, 2e-5);  // ... within its stated bound
    for (int e = -126; e <= 127; ++e) CHECK_EQ(fast_log2(std::ldexp(1.0f, e)), static_cast<float>(e));
    CHECK_EQ(fast_log2(0.0f), -INFINITY);
    CHECK_EQ(fast_log2(1e-40f), -INFINITY);  // a denormal
    CHECK_EQ(fast_log2(-2.0f), -INFINITY);
    CHECK_EQ(fast_log2(INFINITY), INFINITY);
    CHECK(std::isnan(fast_log2(NAN)));
}

// The render context's level of detail (uv_derivatives: the quotient rule's numerators
// from the weights before the division, fast_log2) against texture_lod given the derivatives of u = A/B
// computed in double from the same perspective triangle, at pixels across it.
TEST(per_pixel_lod_matches_texture_lod_of_the_exact_derivatives) {
    texture t;
    t.width = 128;
    t.height = 64;
    screen_vertex s[3] = {};
    s[0].x = 3.0f, s[0].y = 2.0f, s[0].inv_w = 1.0f;
    s[1].x = 60.0f, s[1].y = 9.0f, s[1].inv_w = 0.125f;
    s[2].x = 17.0f, s[2].y = 51.0f, s[2].inv_w = 0.4f;
    const double u[3] = {0.1, 3.7, -1.2}, v[3] = {0.0, 0.6, 2.9};
    float tu[3], tv[3];
    for (int k = 0; k < 3; ++k) tu[k] = static_cast<float>(u[k] * t.width), tv[k] = static_cast<float>(v[k] * t.height);
    for (bool perspective : {true, false}) {
        const detail::uv_derivatives d = detail::uv_derivatives::of(s, tu, tv, perspective);
        double worst = 0;
        for (double py = 4.5; py < 40; py += 5)
            for (double px = 8.5; px < 40; px += 5) {
                // Barycentrics l_k affine in (x, y); A_u = Σ l q u, B = Σ l q, u = A_u/B.
                const double x1 = s[1].x - s[0].x, y1 = s[1].y - s[0].y, x2 = s[2].x - s[0].x, y2 = s[2].y - s[0].y;
                const double det = x1 * y2 - x2 * y1;
                auto bary = [&](double x, double y, double l[3]) {
                    l[1] = ((x - s[0].x) * y2 - x2 * (y - s[0].y)) / det;
                    l[2] = (x1 * (y - s[0].y) - (x - s[0].x) * y1) / det;
                    l[0] = 1 - l[1] - l[2];
                };
                auto uv_at = [&](double x, double y, double &uu, double &vv) {
                    double l[3], a_u = 0, a_v = 0, b = 0;
                    bary(x, y, l);
                    for (int k = 0; k < 3; ++k) {
                        const double q = perspective ? s[k].inv_w : 1.0;
                        a_u += l[k] * q * u[k], a_v += l[k] * q * v[k], b += l[k] * q;
                    }
                    uu = a_u / b, vv = a_v / b;
                };
                // The exact derivatives by central differences of the rational function
                // (step 1e-4 px: truncation ~1e-9, far below the tolerance).
                constexpr double H = 1e-4;
                double ux0, vx0, ux1, vx1, uy0, vy0, uy1, vy1;
                uv_at(px - H, py, ux0, vx0), uv_at(px + H, py, ux1, vx1);
                uv_at(px, py - H, uy0, vy0), uv_at(px, py + H, uy1, vy1);
                const float expected = texture_lod(t, static_cast<float>((ux1 - ux0) / (2 * H)), static_cast<float>((vx1 - vx0) / (2 * H)),
                                                   static_cast<float>((uy1 - uy0) / (2 * H)), static_cast<float>((vy1 - vy0) / (2 * H)));
                double l[3];
                bary(px, py, l);
                float w[3], b = 0;
                for (int k = 0; k < 3; ++k) b += (w[k] = static_cast<float>(l[k]) * (perspective ? s[k].inv_w : 1.0f));
                worst = std::max(worst, std::fabs(static_cast<double>(d.lod(w[0], w[1], w[2], 1.0f / b)) - expected));
            }
        CHECK_NEAR(worst, 0.0, 2e-4);  // float set-up and barycentrics; fast_log2 adds ≤ 1e-5
    }
    // A derivative that is not finite gives NaN (the lookup then uses level 0), as texture_lod.
    detail::uv_derivatives broken;
    broken.numerator[0][1] = INFINITY;
    CHECK(std::isnan(broken.lod(0.25f, 0.5f, 0.25f, 1.0f)));
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
    // Integer levels and the edges of the level search (k = ⌊λ⌋ found by compares).
    CHECK_NEAR(texture_sample_trilinear(t, 0.3f, 0.7f, 2.0f, texture_wrap::repeat), 0.2, 1e-6);
    CHECK_NEAR(texture_sample_trilinear(t, 0.3f, 0.7f, std::nextafter(2.0f, 0.0f), texture_wrap::repeat), 0.2, 1e-6);
    CHECK_NEAR(texture_sample_trilinear(t, 0.3f, 0.7f, 4.0f, texture_wrap::repeat), 0.4, 1e-6);
    CHECK_NEAR(texture_sample_trilinear(t, 0.3f, 0.7f, 3.5f, texture_wrap::clamp), 0.35, 1e-6);
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
// ---- anisotropic filtering --------------------------------------------------------------

namespace {

// 64 × 64 texels of horizontal stripes 2 texels high (0.1, 0.9: constant along u), mipmapped.
texture stripes() {
    texture t;
    t.width = t.height = 64;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) t.texels.push_back((j / 2) % 2 ? 0.9f : 0.1f);
    CHECK(build_mipmaps(t).ok());
    return t;
}

}  // namespace

TEST(anisotropic_is_trilinear_for_a_round_footprint) {
    const texture t = stripes();
    for (float texels : {0.5f, 1.0f, 3.0f, 6.5f}) {
        const float d = texels / 64.0f;  // per pixel, along x and along y: isotropic
        for (float u : {0.13f, 0.5f, 0.77f}) {
            const float want = texture_sample_trilinear(t, u, 0.31f, std::log2(texels), texture_wrap::repeat);
            CHECK_NEAR(texture_sample_anisotropic(t, u, 0.31f, d, 0, 0, d, 8, texture_wrap::repeat), want, 1e-6);
        }
    }
    CHECK_EQ(texture_sample_anisotropic(t, NAN, 0.5f, 0.1f, 0, 0, 0.1f, 8, texture_wrap::repeat), 0.0f);
}

TEST(anisotropic_keeps_detail_across_a_long_footprint) {
    // A footprint 16 texels along u (where the stripes do not change) and 2 across them
    // (along v). Trilinear filters 16 texels both ways (λ = 4): the stripes blur to their
    // mean, 0.5. Eight anisotropic taps each cover 2 × 2 (λ = 1, where a stripe is one texel
    // and its centre keeps its value): the stripe under the pixel.
    const texture t = stripes();
    const float du = 16.0f / 64.0f, dv = 2.0f / 64.0f;
    for (int stripe = 0; stripe < 8; ++stripe) {
        const float v = (2.0f * stripe + 1.0f) / 64.0f;  // the centre of the stripe (level 1's texel row `stripe`)
        const float want = (stripe % 2) ? 0.9f : 0.1f;
        CHECK_NEAR(texture_sample_anisotropic(t, 0.4f, v, du, 0, 0, dv, 8, texture_wrap::repeat), want, 1e-5);
        CHECK_NEAR(texture_sample_trilinear(t, 0.4f, v, 4.0f, texture_wrap::repeat), 0.5, 1e-5);
        // With 2 taps at most, each covers 8 × 8 (λ = 3): blurred as trilinear.
        CHECK_NEAR(texture_sample_anisotropic(t, 0.4f, v, du, 0, 0, dv, 2, texture_wrap::repeat), 0.5, 1e-5);
    }
}

TEST(anisotropic_taps_are_the_mean_of_trilinear_lookups) {
    // The definition, evaluated tap by tap with the public trilinear lookup: N = ⌈min(P_major /
    // P_minor, limit)⌉ taps at u + (i − (N − 1)/2)·∂u/N along the major axis, all at
    // λ = log2(P_major / N); a magnified footprint (P_major² ≤ ½ texel²) one bilinear lookup. The filter walks the taps in each level's texel space instead;
    // this holds it to the definition on a texture of odd size (levels 37×23 … 1×1), for
    // footprints of every direction, length and level, centres by the edges where taps wrap,
    // and both wrap modes. Tolerance: its log2 is within 2e-5 of libm's, and float sums.
    texture t;
    t.width = 37;
    t.height = 23;
    for (int j = 0; j < t.height; ++j)
        for (int i = 0; i < t.width; ++i) t.texels.push_back(static_cast<float>((i * 7 + j * 13) % 11) / 10.0f);
    CHECK(build_mipmaps(t).ok());
    std::uint32_t seed = 12345;
    auto next = [&] {  // uniform in [0, 1)
        seed = seed * 1664525u + 1013904223u;
        return static_cast<float>(seed >> 8) / 16777216.0f;
    };
    double worst = 0.0;
    int magnified = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const texture_wrap wrap = trial % 5 == 4 ? texture_wrap::clamp : texture_wrap::repeat;
        const float u = trial % 3 == 0 ? next() * 0.04f - 0.02f : 3.0f * next() - 1.0f;  // some centres by u = 0
        const float v = 2.0f * next() - 0.5f;
        const float angle = 6.2831853f * next(), length = std::exp2(10.0f * next() - 7.0f);  // 1/128 … 8 textures
        const float aspect = 1.0f + 15.0f * next(), across = length / aspect;
        const float du_dx = length * std::cos(angle), dv_dx = length * std::sin(angle);
        const float du_dy = -across * std::sin(angle), dv_dy = across * std::cos(angle);
        const int limit = 1 + trial % 16;
        const double w = t.width, h = t.height;
        const double px = std::hypot(du_dx * w, dv_dx * h), py = std::hypot(du_dy * w, dv_dy * h);
        const bool x_major = px >= py;
        const double major = x_major ? px : py, minor = x_major ? py : px;
        if (major * major <= 0.5) {  // magnified: one bilinear lookup in the base level
            ++magnified;
            const double got = texture_sample_anisotropic(t, u, v, du_dx, dv_dx, du_dy, dv_dy, limit, wrap);
            worst = std::max(worst, std::fabs(got - texture_sample(t, u, v, texture_filter::bilinear, wrap)));
            continue;
        }
        const int taps = std::clamp(static_cast<int>(std::ceil(std::min(major / minor, static_cast<double>(limit)) - 1e-6)), 1, limit);
        const float lod = static_cast<float>(std::log2(major / taps));
        const double su = (x_major ? du_dx : du_dy) / static_cast<double>(taps), sv = (x_major ? dv_dx : dv_dy) / static_cast<double>(taps);
        double want = 0.0;
        for (int i = 0; i < taps; ++i) {
            const double k = i - 0.5 * (taps - 1);
            want += texture_sample_trilinear(t, static_cast<float>(u + k * su), static_cast<float>(v + k * sv), lod, wrap);
        }
        want /= taps;
        const double got = texture_sample_anisotropic(t, u, v, du_dx, dv_dx, du_dy, dv_dy, limit, wrap);
        worst = std::max(worst, std::fabs(got - want));
    }
    CHECK_MSG(worst <= 1e-4, "largest difference " + std::to_string(worst));
    CHECK(magnified > 100 && magnified < 2000);  // both regimes were exercised
}

TEST(filters_on_a_grazing_plane_against_the_supersampled_reference) {
    // Mean error over all pixels (grey levels) against 256 samples per pixel. Mipmaps
    // remove bilinear's aliasing far away; anisotropic taps remove trilinear's blur at
    // grazing angles. Targets: trilinear ≤ 0.5 × bilinear, anisotropic ≤ 0.75 × trilinear.
    constexpr int SIDE = 128;
    grazing_plane::scene plane;
    grazing_plane::make(plane);
    canvas_ptr reference = make_canvas(SIDE, SIDE).value();
    const reference_draw d{&plane.mesh, plane.params};
    CHECK(render_reference(*reference, std::span<const reference_draw>(&d, 1), 0.0f, 16).ok());
    double error[4] = {};
    const texture_filter filters[4] = {texture_filter::nearest, texture_filter::bilinear, texture_filter::trilinear,
                                       texture_filter::anisotropic};
    for (int f = 0; f < 4; ++f) {
        plane.params.filter = filters[f];
        canvas_ptr image = make_canvas(SIDE, SIDE).value();
        render_context ctx(1);
        CHECK(draw_frame(ctx, *image, plane.mesh, plane.params).ok());
        for (int y = 0; y < SIDE; ++y)
            for (int x = 0; x < SIDE; ++x) error[f] += 255.0 * std::fabs(image->pixels[y][x] - reference->pixels[y][x]);
        error[f] /= SIDE * SIDE;
    }
    const std::string figures = "nearest " + std::to_string(error[0]) + ", bilinear " + std::to_string(error[1]) +
                                ", trilinear " + std::to_string(error[2]) + ", anisotropic " + std::to_string(error[3]);
    CHECK_MSG(error[2] <= 0.5 * error[1], figures);
    CHECK_MSG(error[3] <= 0.75 * error[2], figures);
    CHECK_MSG(error[1] <= error[0], figures);
    CHECK(error[3] > 0.0);
}

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

