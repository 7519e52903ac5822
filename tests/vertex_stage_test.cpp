// vertex_stage_test.cpp — the vertex stage's SIMD kernels against their portable references,
// bit for bit, on ordinary, extreme and non-finite points: the 4-wide projection both
// pipelines use (src/pipeline/project4.h) against clip_outcode and clip_to_screen, and the
// render context's vertex kernels (src/pipeline/vertex_kernels_sse2.h) against
// vertex_transform.h's; and the stage's snap (src/pipeline/screen_snap.h) against set-up's.
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "../src/pipeline/project4.h"
#include "../src/pipeline/vertex_kernels_sse2.h"
#include "../src/pipeline/vertex_transform.h"
#include "../src/raster/msaa/msaa.h"
#include "harness.h"
#include "../src/simd_config.h"

namespace {

using tiny3d::detail::xvertex;

// The SIMD kernels' checks (built with TINY3D_PORTABLE there is no SIMD kernel to compare
// with the references, so only the references' own checks below run).
#ifdef TINY3D_SSE2
bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_vertex(const xvertex &a, const xvertex &b) {
    if (a.outcode != b.outcode || a.snapped != b.snapped) return false;
    return !a.snapped || (same_bits(a.depth, b.depth) && a.snapped_x == b.snapped_x && a.snapped_y == b.snapped_y);
}
bool same_clip(const vec4_t &a, const vec4_t &b) {
    return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z) && same_bits(a.w, b.w);
}

// Positions around a camera: most in view, some behind it, far off, huge or non-finite.
std::vector<vec3_t> test_positions(std::size_t n) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    std::vector<vec3_t> p(n);
    for (vec3_t &v : p) v = {u(rng), u(rng), u(rng)};
    p[1] = {0.0f, 0.0f, 3.0f};  // at the eye: w = 0
    p[2] = {1e30f, -1e30f, 0.0f};
    p[3] = {NAN, 0.0f, 0.0f};
    p[5] = {INFINITY, 1.0f, 1.0f};
    p[6] = {0.0f, 0.0f, 1e-38f};
    return p;
}

#endif

mat4_t camera() {
    return mat4_multiply(tiny3d::mat4_perspective(0.8f, 1.0f, 0.1f, 100.0f), mat4_translate(0.2f, -0.1f, -3.0f));
}

}  // namespace

#ifdef TINY3D_SSE2
TEST(project4_matches_clip_outcode_and_clip_to_screen_bit_for_bit) {
    std::vector<vec4_t> c;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f);
    for (int k = 0; k < 400; ++k) c.push_back({u(rng), u(rng), u(rng), u(rng)});
    const float specials[] = {0.0f, -0.0f, 1e-40f, 1e30f, -1e30f, 3e38f, INFINITY, -INFINITY, NAN};
    for (float a : specials)
        for (float b : specials) c.push_back({a, 0.5f, b, 1.0f}), c.push_back({0.25f, a, 0.5f, b}), c.push_back({b, b, a, a});
    while (c.size() % 4) c.push_back({0, 0, 0, 1});
    int mismatches = 0;
    for (float guard : {1.0f, 1.953125f, 4.0f})
        for (std::size_t i = 0; i < c.size(); i += 4) {
            __m128 x = _mm_loadu_ps(&c[i].x), y = _mm_loadu_ps(&c[i + 1].x), z = _mm_loadu_ps(&c[i + 2].x),
                   w = _mm_loadu_ps(&c[i + 3].x);
            _MM_TRANSPOSE4_PS(x, y, z, w);
            const tiny3d::detail::projected4 p = tiny3d::detail::project4(x, y, z, w, guard, 640.0f, 480.0f, true);
            alignas(16) float px[4], py[4], pd[4], front[4];
            alignas(16) std::uint32_t code[4];
            _mm_store_ps(px, p.x), _mm_store_ps(py, p.y), _mm_store_ps(pd, p.depth), _mm_store_ps(front, p.in_front);
            _mm_store_si128(reinterpret_cast<__m128i *>(code), p.outcode);
            for (int l = 0; l < 4; ++l) {
                const tiny3d::screen_point ref = tiny3d::clip_to_screen(c[i + l], 640, 480);
                const bool in_front = std::isnan(front[l]);  // all ones = a NaN pattern
                mismatches += code[l] != tiny3d::clip_outcode(c[i + l], guard) || in_front == ref.behind;
                if (!ref.behind) mismatches += !same_bits(px[l], ref.x) || !same_bits(py[l], ref.y) || !same_bits(pd[l], ref.depth);
            }
        }
    CHECK_EQ(mismatches, 0);
    // clip_outcode itself, hand-checked: inside, each plane, the guard band, non-finite.
    CHECK_EQ(tiny3d::clip_outcode({0.5f, -0.5f, 0.0f, 1.0f}), 0u);
    CHECK_EQ(tiny3d::clip_outcode({0.0f, 0.0f, -2.0f, 1.0f}), unsigned(tiny3d::clip_near));
    CHECK_EQ(tiny3d::clip_outcode({1.5f, 0.0f, 0.0f, 1.0f}), unsigned(tiny3d::clip_right));
    CHECK_EQ(tiny3d::clip_outcode({1.5f, 0.0f, 0.0f, 1.0f}, 2.0f), 0u);
    CHECK_EQ(tiny3d::clip_outcode({-3.0f, 3.0f, 0.0f, 1.0f}, 2.0f), unsigned(tiny3d::clip_left | tiny3d::clip_top));
    CHECK_EQ(tiny3d::clip_outcode({NAN, 0.0f, 0.0f, 1.0f}), unsigned(tiny3d::clip_all));
    CHECK_EQ(tiny3d::clip_outcode({0.0f, INFINITY, 0.0f, 1.0f}, 4.0f), unsigned(tiny3d::clip_all));
}

TEST(project_x4_matches_project_one_bit_for_bit) {
    const std::vector<vec3_t> p = test_positions(400);
    const mat4_t m = camera();
    for (int bits : {tiny3d::RASTER_SUBPIXEL_BITS, tiny3d::detail::MSAA_16_SUBPIXEL_BITS})
    for (float guard : {1.0f, 1.953125f, 4.0f}) {
        std::vector<xvertex> fast(p.size()), ref(p.size());
        std::vector<vec4_t> fast_clip(p.size()), ref_clip(p.size());
        int mismatches = 0;
        for (std::uint32_t i = 0; i + 4 <= p.size(); i += 4) {
            const std::uint32_t index[4] = {i + 3, i + 1, i, i + 2};  // gathered out of order
            tiny3d::detail::project_x4(m, p.data(), index, guard, 1024, 768, bits, fast.data(), fast_clip.data());
        }
        for (std::size_t i = 0; i < p.size(); ++i) {
            tiny3d::detail::project_one(m, p[i], guard, 1024, 768, bits, ref[i], ref_clip[i]);
            mismatches += !same_vertex(fast[i], ref[i]) || !same_clip(fast_clip[i], ref_clip[i]);
        }
        CHECK_EQ(mismatches, 0);
        CHECK(ref[3].outcode != 0);  // the NaN position is outside
        CHECK(!ref[3].snapped);
    }
}

TEST(shade_gouraud_x4_matches_shade_directional_one_bit_for_bit) {
    std::vector<vec3_t> n = test_positions(200);
    n[7] = {0.0f, 0.0f, 0.0f};
    n[8] = {1e-20f, 0.0f, 0.0f};
    const light_t lights[2] = {{{1, 1, 1}, 0.8f}, {{-1, 0.5f, 0.2f}, 0.4f}};
    const tiny3d::light_rig rig = tiny3d::make_light_rig(std::span<const light_t>(lights, 2), 0.1f).value();
    const tiny3d::normal_transform nt = tiny3d::make_normal_transform(mat4_rotate_xyz(0.3f, -1.1f, 0.7f));
    int mismatches = 0;
    for (std::uint32_t i = 0; i + 4 <= n.size(); i += 4) {
        const std::uint32_t index[4] = {i, i + 2, i + 1, i + 3};
        alignas(16) float shade[4];
        tiny3d::detail::shade_gouraud_x4(rig, nt, n.data(), index, shade);
        for (int l = 0; l < 4; ++l)
            mismatches += !same_bits(shade[l], tiny3d::detail::shade_directional_one(rig, nt, n[index[l]]));
    }
    CHECK_EQ(mismatches, 0);
    // The reference itself against a hand computation: ambient + Σ max(0, n·l)·I, clamped.
    const tiny3d::normal_transform identity = tiny3d::make_normal_transform(mat4_identity());
    const float up = tiny3d::detail::shade_directional_one(rig, identity, {0.0f, 0.0f, 2.0f});
    const float expected = 0.1f + 0.8f * (1.0f / std::sqrt(3.0f)) + 0.4f * (0.2f / std::sqrt(1.0f + 0.25f + 0.04f));
    CHECK_NEAR(up, expected, 1e-6);
}
#endif

TEST(project_one_outcodes_and_screen_position) {
    const mat4_t m = camera();
    xvertex v;
    vec4_t clip;
    // The point the camera looks at (0.2 right of the origin's image, 0.1 down): hand-computed.
    tiny3d::detail::project_one(m, {-0.2f, 0.1f, 0.0f}, 1.0f, 1024, 768, tiny3d::RASTER_SUBPIXEL_BITS, v, clip);
    CHECK_EQ(unsigned(v.outcode), 0u);
    CHECK(v.snapped);
    CHECK_EQ(v.snapped_x, 512 * 16);
    CHECK_EQ(v.snapped_y, 384 * 16);
    CHECK_NEAR(clip.w, 3.0, 1e-6);
    // On the 16-sample frames' grid (1/256 px).
    tiny3d::detail::project_one(m, {-0.2f, 0.1f, 0.0f}, 1.0f, 1024, 768, tiny3d::detail::MSAA_16_SUBPIXEL_BITS, v, clip);
    CHECK_EQ(v.snapped_x, 512 * 256);
    CHECK_EQ(v.snapped_y, 384 * 256);
    // Behind the eye: outside the near plane, never snapped.
    tiny3d::detail::project_one(m, {0.0f, 0.0f, 5.0f}, 1.0f, 1024, 768, tiny3d::RASTER_SUBPIXEL_BITS, v, clip);
    CHECK(v.outcode & tiny3d::clip_near);
    CHECK(!v.snapped);
}


// The snap the vertex stage and the set-up use rounds to nearest, ties to even (std::lrint),
// whichever instruction the build uses.
TEST(snap_screen_point_matches_lrint) {
    std::vector<float> xs = {0.0f, -0.0f, 0.03125f, 0.09375f, -0.09375f, 0.15625f, 511.96875f, -3.5f, 1e-30f,
                             tiny3d::RASTER_MAX_COORD, -tiny3d::RASTER_MAX_COORD,
                             std::nextafter(tiny3d::RASTER_MAX_COORD, INFINITY), -1e30f, INFINITY, -INFINITY, NAN};
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-5000.0f, 5000.0f);
    for (int k = 0; k < 300; ++k) xs.push_back(u(rng));
    int mismatches = 0;
    for (int bits : {tiny3d::RASTER_SUBPIXEL_BITS, tiny3d::detail::MSAA_16_SUBPIXEL_BITS})
        for (float x : xs)
            for (float y : {0.5f, -1234.40625f, x}) {
                std::int32_t sx = -7, sy = -7;
                const bool snapped = tiny3d::detail::snap_screen_point(x, y, bits, sx, sy);
                const bool in_range = std::isfinite(x) && std::isfinite(y) && std::fabs(x) <= tiny3d::RASTER_MAX_COORD &&
                                      std::fabs(y) <= tiny3d::RASTER_MAX_COORD;
                mismatches += snapped != in_range;
                if (snapped) mismatches += sx != std::lrint(std::ldexp(x, bits)) || sy != std::lrint(std::ldexp(y, bits));
                else mismatches += sx != -7 || sy != -7;  // untouched
            }
    CHECK_EQ(mismatches, 0);
    std::int32_t sx = 0, sy = 0;  // ties to even on the 1/16 px grid: 1.5 → 2, 2.5 → 2, −1.5 → −2
    CHECK(tiny3d::detail::snap_screen_point(1.5f / 16, 2.5f / 16, 4, sx, sy));
    CHECK_EQ(sx, 2);
    CHECK_EQ(sy, 2);
    CHECK(tiny3d::detail::snap_screen_point(-1.5f / 16, 0.0f, 4, sx, sy));
    CHECK_EQ(sx, -2);
}
