// lines_test.cpp — the exact-coverage line against its double-precision reference, the
// reference against geometry and supersampling, the faithful line's pinned flaws, Wu,
// Bresenham (all octants vs the classic plotLine), the gradient line, clipping.
#include "harness.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "canvas.h"
#include "lines.h"
#include "line_test_util.h"

namespace {

using namespace line_test;  // blank, ink, error_stats, compare, kPi

#if defined(__SANITIZE_ADDRESS__)
constexpr int kSegmentsPerThickness = 250;  // sanitizers: a subset (plain run does 1,000)
#else
constexpr int kSegmentsPerThickness = 1000;
#endif

using canvas_ptr = tiny3d::canvas_ptr;

struct segment {
    float x0, y0, x1, y1;
};

// A random segment of length 5..300 px at any angle with sub-pixel ends, placed in a
// canvas just big enough to hold its stroke (so the whole stroke is on the canvas).
struct placed_segment {
    segment s;
    int width, height;
};

placed_segment random_segment(std::mt19937 &rng, double thickness, double min_length = 5.0,
                              double max_length = 300.0) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double length = min_length + (max_length - min_length) * unit(rng), angle = 2.0 * kPi * unit(rng);
    const double margin = thickness / 2 + 3.0;
    const double dx = length * std::cos(angle), dy = length * std::sin(angle);
    const double x0 = margin + std::max(0.0, -dx) + unit(rng), y0 = margin + std::max(0.0, -dy) + unit(rng);
    placed_segment p;
    p.s = {float(x0), float(y0), float(x0 + dx), float(y0 + dy)};
    p.width = int(std::ceil(std::max(p.s.x0, p.s.x1) + margin));
    p.height = int(std::ceil(std::max(p.s.y0, p.s.y1) + margin));
    return p;
}

double true_ink(const segment &s, double thickness, tiny3d::line_cap cap) {
    const double length = std::hypot(double(s.x1) - s.x0, double(s.y1) - s.y0);
    return length * thickness + (cap == tiny3d::line_cap::round ? kPi * thickness * thickness / 4 : 0.0);
}

void check_against_reference(double thickness, tiny3d::line_cap cap, int count, unsigned seed,
                             double min_length = 5.0, double max_length = 300.0) {
    std::mt19937 rng(seed);
    error_stats e;
    double worst_ink = 0;
    std::vector<double> ref;
    for (int k = 0; k < count; ++k) {
        const placed_segment p = random_segment(rng, thickness, min_length, max_length);
        canvas_ptr c = blank(p.width, p.height);
        tiny3d::draw_line_coverage(c.get(), p.s.x0, p.s.y0, p.s.x1, p.s.y1, float(thickness), {cap, 1.0f});
        tiny3d::line_coverage_reference(ref, p.width, p.height, p.s.x0, p.s.y0, p.s.x1, p.s.y1, thickness, cap);
        compare(*c, ref, e);
        const double expect = true_ink(p.s, thickness, cap);
        worst_ink = std::max(worst_ink, std::fabs(ink(*c) - expect) / expect);
    }
    const double mean = e.sum / double(std::max(e.pixels, 1L));
    // The required bounds: mean ≤ 0.05 % of full scale, max ≤ 0.07, ink within 0.1 %.
    CHECK_MSG(mean <= 5e-4, "T=" + std::to_string(thickness) + " mean " + std::to_string(mean));
    CHECK_MSG(e.max <= 0.07, "T=" + std::to_string(thickness) + " max " + std::to_string(e.max));
    CHECK_MSG(worst_ink <= 1e-3, "T=" + std::to_string(thickness) + " ink " + std::to_string(worst_ink));
    // What the implementation actually achieves (float closed form, double end pixels).
    CHECK_MSG(e.max <= 1e-4, "T=" + std::to_string(thickness) + " max " + std::to_string(e.max));
    CHECK(e.pixels > count * (min_length > 1.0 ? 5 : 1));
}

}  // namespace

// ---- the fast coverage line -----------------------------------------------------------

TEST(coverage_matches_reference_round_caps) {
    const double thicknesses[] = {0.5, 1.0, 1.5, 3.0, 8.0};
    for (int i = 0; i < 5; ++i)
        check_against_reference(thicknesses[i], tiny3d::line_cap::round, kSegmentsPerThickness, 1000u + unsigned(i));
}

TEST(coverage_matches_reference_butt_caps) {
    const double thicknesses[] = {0.5, 1.5, 8.0};
    for (int i = 0; i < 3; ++i)
        check_against_reference(thicknesses[i], tiny3d::line_cap::butt, kSegmentsPerThickness / 5, 2000u + unsigned(i));
}

// Segments shorter than the stroke is wide: both ends' cap columns meet or overlap.
TEST(coverage_short_segments_match_reference) {
    const double thicknesses[] = {0.5, 1.5, 3.0, 8.0};
    for (int i = 0; i < 4; ++i) {
        check_against_reference(thicknesses[i], tiny3d::line_cap::round, kSegmentsPerThickness / 4, 3000u + unsigned(i),
                                0.0, 4.0);
        check_against_reference(thicknesses[i], tiny3d::line_cap::butt, kSegmentsPerThickness / 4, 3100u + unsigned(i),
                                0.01, 4.0);
    }
}

TEST(coverage_axis_aligned_hand_values) {
    // Horizontal, centre line y = 2.5, T = 1.5: row 2 fully covered, rows 1 and 3 a quarter.
    canvas_ptr c = blank(12, 6);
    tiny3d::draw_line_coverage(c.get(), 1.0f, 2.5f, 11.0f, 2.5f, 1.5f, {tiny3d::line_cap::butt, 1.0f});
    for (int x = 1; x < 11; ++x) {
        CHECK_NEAR(c->pixels[2][x], 1.0, 1e-6);
        CHECK_NEAR(c->pixels[1][x], 0.25, 1e-6);
        CHECK_NEAR(c->pixels[3][x], 0.25, 1e-6);
        CHECK_EQ(c->pixels[0][x], 0.0f);
    }
    CHECK_EQ(c->pixels[2][0], 0.0f);  // butt: nothing before x = 1
    CHECK_EQ(c->pixels[2][11], 0.0f);
    // Vertical: the same by symmetry.
    canvas_ptr v = blank(6, 12);
    tiny3d::draw_line_coverage(v.get(), 2.5f, 1.0f, 2.5f, 11.0f, 1.5f, {tiny3d::line_cap::butt, 1.0f});
    for (int y = 1; y < 11; ++y) {
        CHECK_NEAR(v->pixels[y][2], 1.0, 1e-6);
        CHECK_NEAR(v->pixels[y][1], 0.25, 1e-6);
    }
}

TEST(coverage_diagonal_hand_value) {
    // 45° line through pixel centres, T = √2/2: the pixel it crosses has coverage
    // = square ∩ band of half-width √2/4 about its diagonal = 1 − 2·(½·(½)²) = 0.75.
    canvas_ptr c = blank(16, 16);
    tiny3d::draw_line_coverage(c.get(), 2.5f, 2.5f, 12.5f, 12.5f, float(std::sqrt(2.0) / 2), {tiny3d::line_cap::butt, 1.0f});
    for (int k = 4; k < 11; ++k) {
        CHECK_NEAR(c->pixels[k][k], 0.75, 1e-5);
        CHECK_NEAR(c->pixels[k][k + 1], 0.125, 1e-5);  // two corner triangles of ⅛ each side
        CHECK_NEAR(c->pixels[k + 1][k], 0.125, 1e-5);
    }
}

TEST(coverage_over_combine) {
    // Pixel fully covered with intensity 0.5, twice: 0.5, then 0.5 + 0.5·(1 − 0.5) = 0.75.
    canvas_ptr c = blank(8, 4);
    const tiny3d::line_style half{tiny3d::line_cap::butt, 0.5f};
    tiny3d::draw_line_coverage(c.get(), 0.0f, 1.5f, 8.0f, 1.5f, 1.0f, half);
    CHECK_NEAR(c->pixels[1][3], 0.5, 1e-6);
    tiny3d::draw_line_coverage(c.get(), 0.0f, 1.5f, 8.0f, 1.5f, 1.0f, half);
    CHECK_NEAR(c->pixels[1][3], 0.75, 1e-6);
    // Half coverage (band y ∈ [2, 2.5]) over 0.75 elsewhere: 0.5 on an empty row.
    tiny3d::draw_line_coverage(c.get(), 0.0f, 2.25f, 8.0f, 2.25f, 0.5f, {tiny3d::line_cap::butt, 1.0f});
    CHECK_NEAR(c->pixels[2][3], 0.5, 1e-6);
    tiny3d::draw_line_coverage(c.get(), 0.0f, 2.25f, 8.0f, 2.25f, 0.5f, {tiny3d::line_cap::butt, 1.0f});
    CHECK_NEAR(c->pixels[2][3], 0.75, 1e-6);
    // Full coverage saturates at exactly 1.
    tiny3d::draw_line_coverage(c.get(), 0.0f, 1.5f, 8.0f, 1.5f, 1.0f);
    CHECK_EQ(c->pixels[1][3], 1.0f);
    // Many overlapping strokes never push a pixel above 1.
    std::mt19937 rng(5);
    canvas_ptr d = blank(64, 64);
    for (int k = 0; k < 300; ++k) {
        const placed_segment p = random_segment(rng, 3.0);
        tiny3d::draw_line_coverage(d.get(), p.s.x0 * 0.2f, p.s.y0 * 0.2f, p.s.x1 * 0.2f, p.s.y1 * 0.2f, 3.0f);
    }
    float top = 0.0f;
    for (int i = 0; i < 64 * 64; ++i) top = std::max(top, d->data[i]);
    CHECK(top <= 1.0f);
}

TEST(coverage_reversed_is_bit_identical) {
    std::mt19937 rng(7);
    for (double t : {0.5, 1.5, 3.0, 8.0})
        for (int k = 0; k < 60; ++k) {
            const placed_segment p = random_segment(rng, t);
            canvas_ptr a = blank(p.width, p.height), b = blank(p.width, p.height);
            tiny3d::draw_line_coverage(a.get(), p.s.x0, p.s.y0, p.s.x1, p.s.y1, float(t));
            tiny3d::draw_line_coverage(b.get(), p.s.x1, p.s.y1, p.s.x0, p.s.y0, float(t));
            CHECK(std::memcmp(a->data, b->data, sizeof(float) * std::size_t(p.width * p.height)) == 0);
        }
}

TEST(coverage_far_off_segments_are_clipped) {
    // (−1e9, 5.5) → (1e9, 5.5), T = 1: row 5 exactly covered, nothing else.
    canvas_ptr c = blank(40, 12);
    tiny3d::draw_line_coverage(c.get(), -1e9f, 5.5f, 1e9f, 5.5f, 1.0f);
    for (int x = 0; x < 40; ++x) {
        CHECK_NEAR(c->pixels[5][x], 1.0, 1e-6);
        CHECK_EQ(c->pixels[4][x], 0.0f);
        CHECK_EQ(c->pixels[6][x], 0.0f);
    }
    // A far-off diagonal equals the reference of the same (unclipped) segment.
    canvas_ptr d = blank(48, 48);
    const float far0 = -1e7f, far1 = -1e7f + 3.3f, far2 = 1e7f, far3 = 1e7f + 3.3f;  // float-rounded ends
    tiny3d::draw_line_coverage(d.get(), far0, far1, far2, far3, 2.0f);
    std::vector<double> ref;
    tiny3d::line_coverage_reference(ref, 48, 48, far0, far1, far2, far3, 2.0);
    error_stats e;
    compare(*d, ref, e);
    CHECK(e.pixels > 48 * 2);
    CHECK_NEAR(e.max, 0.0, 1e-4);
    // Ends at ±3e38 (near FLT_MAX): the clipped ends come from the line's implicit
    // equation, so the diagonal still runs through the pixel centres (k + ½, k + ½) and
    // gives the hand values of coverage_diagonal_hand_value.
    canvas_ptr m = blank(16, 16);
    tiny3d::draw_line_coverage(m.get(), -3e38f, -3e38f, 3e38f, 3e38f, float(std::sqrt(2.0) / 2));
    for (int k = 1; k < 14; ++k) {
        CHECK_NEAR(m->pixels[k][k], 0.75, 1e-5);
        CHECK_NEAR(m->pixels[k][k + 1], 0.125, 1e-5);
    }
    canvas_ptr n = blank(16, 8);
    tiny3d::draw_line_coverage(n.get(), -3e38f, 3.0f, 3e38f, 4.0f, 1.0f);  // crosses at y = 3.5
    for (int x = 0; x < 16; ++x) CHECK_NEAR(n->pixels[3][x], 1.0, 1e-5);
    CHECK_NEAR(tiny3d::line_coverage_reference_at(5, 3, -3e38, 3.0, 3e38, 4.0, 1.0), 1.0, 1e-9);
    // Entirely off the canvas: nothing.
    canvas_ptr o = blank(16, 16);
    tiny3d::draw_line_coverage(o.get(), -100.0f, -50.0f, 300.0f, -40.0f, 3.0f);
    CHECK_EQ(ink(*o), 0.0);
}

TEST(coverage_degenerate_and_bad_input) {
    canvas_ptr c = blank(16, 16);
    tiny3d::draw_line_coverage(c.get(), NAN, 1.0f, 5.0f, 5.0f, 1.0f);
    tiny3d::draw_line_coverage(c.get(), 1.0f, 1.0f, 5.0f, INFINITY, 1.0f);
    tiny3d::draw_line_coverage(c.get(), 1.0f, 1.0f, 5.0f, 5.0f, NAN);
    tiny3d::draw_line_coverage(c.get(), 1.0f, 1.0f, 5.0f, 5.0f, 0.0f);
    tiny3d::draw_line_coverage(c.get(), 1.0f, 1.0f, 5.0f, 5.0f, -2.0f);
    tiny3d::draw_line_coverage(c.get(), 1.0f, 1.0f, 5.0f, 5.0f, 1.0f, {tiny3d::line_cap::round, NAN});
    tiny3d::draw_line_coverage(nullptr, 1.0f, 1.0f, 5.0f, 5.0f, 1.0f);
    CHECK_EQ(ink(*c), 0.0);
    // Zero length, round caps: a disc of radius 2 (area 4π); butt caps: nothing.
    tiny3d::draw_line_coverage(c.get(), 8.3f, 7.9f, 8.3f, 7.9f, 4.0f);
    CHECK_NEAR(ink(*c), 4.0 * kPi, 1e-4);
    canvas_ptr b = blank(16, 16);
    tiny3d::draw_line_coverage(b.get(), 8.3f, 7.9f, 8.3f, 7.9f, 4.0f, {tiny3d::line_cap::butt, 1.0f});
    CHECK_EQ(ink(*b), 0.0);
    // Denormal-length segment: still the disc, no NaN.
    canvas_ptr d = blank(16, 16);
    tiny3d::draw_line_coverage(d.get(), 8.0f, 8.0f, 8.0f + 1e-40f, 8.0f, 4.0f);
    CHECK_NEAR(ink(*d), 4.0 * kPi, 1e-4);
    // Huge thickness covers the canvas without trouble.
    canvas_ptr h = blank(16, 16);
    tiny3d::draw_line_coverage(h.get(), 8.0f, 8.0f, 9.0f, 8.0f, 1e6f);
    CHECK_NEAR(ink(*h), 256.0, 1e-3);
}

// ---- the reference itself, checked independently ----------------------------------------

TEST(reference_geometry) {
    // A disc of radius ½ centred on a pixel centre covers π/4 of that pixel, nothing else.
    CHECK_NEAR(tiny3d::line_coverage_reference_at(3, 4, 3.5, 4.5, 3.5, 4.5, 1.0), kPi / 4, 1e-12);
    CHECK_NEAR(tiny3d::line_coverage_reference_at(4, 4, 3.5, 4.5, 3.5, 4.5, 1.0), 0.0, 1e-12);
    // Total ink = L·T + πT²/4 (round) and L·T (butt) for an arbitrary segment.
    std::vector<double> ref;
    const double x0 = 10.3, y0 = 20.7, x1 = 51.9, y1 = 37.2, t = 3.3;
    const double len = std::hypot(x1 - x0, y1 - y0);
    tiny3d::line_coverage_reference(ref, 64, 64, x0, y0, x1, y1, t);
    double sum = 0;
    for (double v : ref) sum += v;
    CHECK_NEAR(sum, len * t + kPi * t * t / 4, 1e-9);
    tiny3d::line_coverage_reference(ref, 64, 64, x0, y0, x1, y1, t, tiny3d::line_cap::butt);
    sum = 0;
    for (double v : ref) sum += v;
    CHECK_NEAR(sum, len * t, 1e-9);
}

TEST(reference_matches_supersampling) {
    // 64×64 stratified samples per pixel: a straight or circular boundary crossing a pixel
    // is off by at most about one sample row, 2/64 ≈ 0.03; on average far less.
    std::mt19937 rng(11);
    for (double t : {1.0, 3.0}) {
        const placed_segment p = random_segment(rng, t);
        canvas_ptr c = blank(p.width, p.height);
        tiny3d::draw_line_supersampled(c.get(), p.s.x0, p.s.y0, p.s.x1, p.s.y1, float(t), 64);
        std::vector<double> ref;
        tiny3d::line_coverage_reference(ref, p.width, p.height, p.s.x0, p.s.y0, p.s.x1, p.s.y1, t);
        error_stats e;
        compare(*c, ref, e);
        CHECK(e.max <= 0.035);
        CHECK(e.sum / double(e.pixels) <= 0.004);
    }
}

// ---- the faithful line's known failures, pinned ------------------------------------------

TEST(faithful_line_known_failures) {
    canvas_ptr c = blank(64, 64);
    // T < 2 − √2 ≈ 0.586: no sample (kx, ky) of the 0.5 grid from −T/2 satisfies
    // kx² + ky² ≤ T²/4 (the nearest, (½ − T/2)·(1, 1), needs √2·(½ − T/2) ≤ T/2).
    draw_line_f(c.get(), 5.3f, 7.1f, 55.8f, 40.2f, 0.5f);
    draw_line_f(c.get(), 5.3f, 7.1f, 55.8f, 40.2f, 0.58f);
    CHECK_EQ(ink(*c), 0.0);
    draw_line_f(c.get(), 5.3f, 7.1f, 55.8f, 40.2f, 0.6f);
    CHECK(ink(*c) > 0.0);
    // From 0.586 to 1 every sample is one whole splat, 2 per px of length: well over the
    // true ink L·T + πT²/4 (about 2–2.5 times at 0.59–0.70, not nothing).
    const segment thin{5.3f, 7.1f, 55.8f, 40.2f};
    for (float t : {0.59f, 0.65f, 0.7f}) {
        canvas_clear(c.get(), 0.0f);
        draw_line_f(c.get(), thin.x0, thin.y0, thin.x1, thin.y1, t);
        const double ratio = ink(*c) / true_ink(thin, t, tiny3d::line_cap::round);
        CHECK_MSG(ratio > 1.8 && ratio < 3.0, "T = " + std::to_string(t) + ": ink / true ink " + std::to_string(ratio));
    }
    canvas_clear(c.get(), 0.0f);
    // T = 1: about twice the true ink L·T + π/4 (each of the 0.5 px steps splats a whole
    // unit; only the clamp at 1 keeps it from being far more).
    const segment s{5.3f, 7.1f, 55.8f, 40.2f};
    draw_line_f(c.get(), s.x0, s.y0, s.x1, s.y1, 1.0f);
    const double ratio = ink(*c) / true_ink(s, 1.0, tiny3d::line_cap::round);
    CHECK(ratio > 1.6 && ratio < 2.4);
    // The fast line at the same T has the true ink.
    canvas_ptr f = blank(64, 64);
    tiny3d::draw_line_coverage(f.get(), s.x0, s.y0, s.x1, s.y1, 1.0f);
    CHECK_NEAR(ink(*f) / true_ink(s, 1.0, tiny3d::line_cap::round), 1.0, 1e-5);
    // …and at T = 0.5 draws half a pixel's worth per unit length.
    canvas_ptr g = blank(64, 64);
    tiny3d::draw_line_coverage(g.get(), s.x0, s.y0, s.x1, s.y1, 0.5f);
    CHECK_NEAR(ink(*g) / true_ink(s, 0.5, tiny3d::line_cap::round), 1.0, 1e-5);
}

TEST(coverage_line_intensity_above_one_is_clamped_to_one) {
    // lines.h: c = intensity · coverage with intensity clamped to ≤ 1. An intensity of 4
    // must give exactly the image of intensity 1, i.e. the double-precision coverage
    // reference, not a partial edge pixel multiplied up to full ink.
    std::mt19937 rng(71);
    std::vector<double> ref;
    for (int k = 0; k < 20; ++k) {
        const placed_segment p = random_segment(rng, 2.5, 10.0, 60.0);
        canvas_ptr bright = blank(p.width, p.height), unit = blank(p.width, p.height);
        tiny3d::draw_line_coverage(bright.get(), p.s.x0, p.s.y0, p.s.x1, p.s.y1, 2.5f, {tiny3d::line_cap::round, 4.0f});
        tiny3d::draw_line_coverage(unit.get(), p.s.x0, p.s.y0, p.s.x1, p.s.y1, 2.5f, {tiny3d::line_cap::round, 1.0f});
        CHECK(std::memcmp(bright->data, unit->data, sizeof(float) * std::size_t(p.width) * p.height) == 0);
        tiny3d::line_coverage_reference(ref, p.width, p.height, p.s.x0, p.s.y0, p.s.x1, p.s.y1, 2.5,
                                        tiny3d::line_cap::round);
        error_stats e;
        compare(*bright, ref, e);
        CHECK_MSG(e.max <= 0.07, "max error " + std::to_string(e.max));
        CHECK_NEAR(ink(*bright) / true_ink(p.s, 2.5, tiny3d::line_cap::round), 1.0, 1e-3);
    }
}

// ---- Xiaolin Wu -------------------------------------------------------------------------

TEST(wu_weights) {
    canvas_ptr c = blank(20, 8);
    tiny3d::draw_line_wu(c.get(), 1.0f, 2.75f, 19.0f, 2.75f);  // a quarter below row 2's centre
    for (int x = 2; x < 18; ++x) {
        CHECK_NEAR(c->pixels[2][x], 0.75, 1e-6);
        CHECK_NEAR(c->pixels[3][x], 0.25, 1e-6);
    }
    // Any shallow slope: every interior column's two weights sum to the intensity.
    canvas_ptr d = blank(40, 40);
    tiny3d::draw_line_wu(d.get(), 2.2f, 3.9f, 37.6f, 21.3f, 0.8f);
    for (int x = 4; x < 36; ++x) {
        double col = 0;
        for (int y = 0; y < 40; ++y) col += d->pixels[y][x];
        CHECK_NEAR(col, 0.8, 1e-5);
    }
    // Far-off ends are clipped: the same as the canvas-wide line.
    canvas_ptr e = blank(20, 8), f = blank(20, 8);
    tiny3d::draw_line_wu(e.get(), -1e9f, 2.75f, 1e9f, 2.75f);
    tiny3d::draw_line_wu(f.get(), -10.0f, 2.75f, 30.0f, 2.75f);
    CHECK(std::memcmp(e->data, f->data, sizeof(float) * 160) == 0);
    canvas_ptr g = blank(12, 12);
    tiny3d::draw_line_wu(g.get(), -3e38f, -3e38f, 3e38f, 3e38f);  // y = x: on the centres
    for (int k = 1; k < 11; ++k) CHECK_NEAR(g->pixels[k][k], 1.0, 1e-6);
}

TEST(wu_end_columns_carry_the_covered_length) {
    // Wu's weights along the major axis: column i (pixels i .. i + 1 in canvas units) gets
    // the length of [x0, x1] inside it, split over two rows. So each column's ink is
    // intensity · |[x0, x1] ∩ [i, i + 1]| (in double), the end columns included, and the
    // column past each end gets none. Both orientations (steep: rows instead of columns)
    // and both directions.
    std::mt19937 rng(83);
    std::uniform_real_distribution<double> start(3.0, 12.0), length(2.0, 30.0), slope(-0.9, 0.9), level(0.2, 1.0);
    for (int k = 0; k < 200; ++k) {
        const double a0 = start(rng), a1 = a0 + length(rng), b0 = 32.0 + start(rng) * 0.2;
        const double b1 = b0 + slope(rng) * (a1 - a0);
        const float value = float(level(rng));
        const bool steep = k % 2 == 1, reversed = k % 4 >= 2;
        const float fa0 = float(a0), fa1 = float(a1), fb0 = float(b0), fb1 = float(b1);
        canvas_ptr c = blank(64, 64);
        float x0 = steep ? fb0 : fa0, y0 = steep ? fa0 : fb0, x1 = steep ? fb1 : fa1, y1 = steep ? fa1 : fb1;
        if (reversed) {
            std::swap(x0, x1);
            std::swap(y0, y1);
        }
        tiny3d::draw_line_wu(c.get(), x0, y0, x1, y1, value);
        for (int i = 0; i < 64; ++i) {
            double column = 0;
            for (int j = 0; j < 64; ++j) column += steep ? c->pixels[i][j] : c->pixels[j][i];
            const double covered = std::max(0.0, std::min<double>(fa1, i + 1.0) - std::max<double>(fa0, i));
            CHECK_NEAR(column, double(value) * covered, 2e-6);
        }
    }
}

// ---- Bresenham and the gradient line -----------------------------------------------------

namespace {

// The classic integer plotLine (all octants), transcribed as written (steep swap, end swap, yi sign), unclipped.
std::set<std::pair<int, int>> seed_bresenham(int x0, int y0, int x1, int y1) {
    std::set<std::pair<int, int>> out;
    bool steep = false;
    if (std::abs(y1 - y0) > std::abs(x1 - x0)) {
        std::swap(x0, y0);
        std::swap(x1, y1);
        steep = true;
    }
    if (x0 > x1) {
        std::swap(x0, x1);
        std::swap(y0, y1);
    }
    const int dx = x1 - x0;
    int dy = y1 - y0, yi = 1;
    if (dy < 0) {
        yi = -1;
        dy = -dy;
    }
    int d = 2 * dy - dx, y = y0;
    for (int x = x0; x <= x1; ++x) {
        out.insert(steep ? std::make_pair(y, x) : std::make_pair(x, y));
        if (d > 0) {
            y += yi;
            d -= 2 * dx;
        }
        d += 2 * dy;
    }
    return out;
}

std::set<std::pair<int, int>> lit_pixels(const canvas_t &c) {
    std::set<std::pair<int, int>> out;
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x)
            if (c.pixels[y][x] != 0.0f) out.insert({x, y});
    return out;
}

}  // namespace

TEST(bresenham_all_octants_both_orders) {
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> coord(-20, 83);  // ends on and off a 64×64 canvas
    int octants_seen = 0;
    for (int k = 0; k < 800; ++k) {
        const int x0 = coord(rng), y0 = coord(rng), x1 = coord(rng), y1 = coord(rng);
        const int dx = x1 - x0, dy = y1 - y0;
        octants_seen |= 1 << ((dx < 0) * 4 + (dy < 0) * 2 + (std::abs(dy) > std::abs(dx)));
        std::set<std::pair<int, int>> expect;
        for (auto p : seed_bresenham(x0, y0, x1, y1))
            if (p.first >= 0 && p.first < 64 && p.second >= 0 && p.second < 64) expect.insert(p);
        canvas_ptr a = blank(64, 64), b = blank(64, 64);
        tiny3d::draw_line_bresenham(a.get(), x0, y0, x1, y1);
        tiny3d::draw_line_bresenham(b.get(), x1, y1, x0, y0);
        CHECK(lit_pixels(*a) == expect);
        CHECK(lit_pixels(*b) == expect);
    }
    CHECK_EQ(octants_seen, 255);
}

TEST(bresenham_huge_coordinates) {
    canvas_ptr c = blank(32, 16);
    tiny3d::draw_line_bresenham(c.get(), -2000000000, 5, 2000000000, 5, 0.5f);
    std::set<std::pair<int, int>> row;
    for (int x = 0; x < 32; ++x) row.insert({x, 5});
    CHECK(lit_pixels(*c) == row);
    CHECK_EQ(c->pixels[5][7], 0.5f);
    // A long diagonal with slope 1/3 through the canvas: pixel (x, y) lit iff y is the
    // seed's rounding of the exact line, checked against the closed form in 128-bit math.
    canvas_ptr d = blank(64, 64);
    const int x0 = -1500000000, y0 = -500000000 + 20, x1 = 1500000001, y1 = 500000000 + 20;
    tiny3d::draw_line_bresenham(d.get(), x0, y0, x1, y1);
    std::set<std::pair<int, int>> expect;
    const long long dx = (long long)x1 - x0, dy = (long long)y1 - y0;
    for (int x = 0; x < 64; ++x) {
        const long long k = (long long)x - x0;
        __extension__ const __int128 num = (__int128)2 * k * dy - dx;
        const long long c = (long long)((num + 2 * dx - 1) / (2 * dx));  // ceil, num > 0 here
        const long long y = y0 + c;
        if (y >= 0 && y < 64) expect.insert({x, int(y)});
    }
    CHECK(!expect.empty());
    CHECK(lit_pixels(*d) == expect);
}

TEST(gradient_line_interpolates) {
    canvas_ptr c = blank(16, 4);
    tiny3d::draw_line_gradient(c.get(), 2, 1, 12, 1, 0.0f, 1.0f);
    for (int k = 0; k <= 10; ++k) CHECK_NEAR(c->pixels[1][2 + k], k / 10.0, 1e-6);
    canvas_ptr r = blank(16, 4);
    tiny3d::draw_line_gradient(r.get(), 12, 1, 2, 1, 1.0f, 0.0f);  // reversed: same image
    for (int x = 0; x < 16; ++x) CHECK_NEAR(r->pixels[1][x], c->pixels[1][x], 1e-6);
    CHECK_NEAR(tiny3d::mix_intensity(0.2f, 0.6f, 0.25f), 0.3, 1e-6);
    CHECK_NEAR(tiny3d::mix_intensity(0.2f, 0.6f, 7.0f), 0.6, 1e-6);  // t clamped
    CHECK_NEAR(tiny3d::mix_intensity(0.2f, 0.6f, -1.0f), 0.2, 1e-6);
    canvas_ptr p = blank(4, 4);
    tiny3d::draw_line_gradient(p.get(), 1, 1, 1, 1, 0.3f, 0.9f);  // one pixel: intensity0
    CHECK_NEAR(p->pixels[1][1], 0.3, 1e-6);
}

TEST(coverage_on_tiny_canvases) {
    // Columns shorter than one SSE2 group of four, and runs that fill the whole column.
    for (int size = 1; size <= 9; ++size) {
        canvas_ptr c = blank(size, size);
        tiny3d::draw_line_coverage(c.get(), -3.0f, 0.3f, float(size) + 3.0f, float(size) - 0.2f, 6.0f);
        tiny3d::draw_line_coverage(c.get(), 0.4f, -2.0f, float(size) - 0.3f, float(size) + 2.0f, 6.0f);
        std::vector<double> ref;
        tiny3d::line_coverage_reference(ref, size, size, -3.0, 0.3, size + 3.0, size - 0.2, 6.0);
        canvas_ptr one = blank(size, size);
        tiny3d::draw_line_coverage(one.get(), -3.0f, 0.3f, float(size) + 3.0f, float(size) - 0.2f, 6.0f);
        error_stats e;
        compare(*one, ref, e);
        CHECK_NEAR(e.max, 0.0, 1e-5);
        for (int i = 0; i < size * size; ++i) CHECK(c->data[i] >= 0.0f && c->data[i] <= 1.0f);
    }
}

TEST(coverage_of_very_thick_strokes) {
    // Strokes wider than any per-column window (and than the canvas): the general column
    // path. Every pixel of a 24×20 canvas lies deep inside, so each gets exactly 1; a stroke
    // of 1e30 px neither overflows nor leaves a pixel untouched.
    const float widths[] = {200.0f, 1e6f, 1e30f};
    const float ends[][4] = {{2.0f, 3.0f, 21.0f, 9.0f}, {4.0f, 1.0f, 9.0f, 18.0f}, {12.0f, 10.0f, 12.5f, 10.2f}};
    for (float w : widths)
        for (const auto &e : ends) {
            canvas_ptr c = blank(24, 20);
            tiny3d::draw_line_coverage(c.get(), e[0], e[1], e[2], e[3], w);
            double low = 1.0, high = 0.0;
            for (int i = 0; i < 24 * 20; ++i) {
                low = std::min(low, double(c->data[i]));
                high = std::max(high, double(c->data[i]));
            }
            CHECK_NEAR(low, 1.0, 1e-6);
            CHECK_NEAR(high, 1.0, 1e-6);
        }
    // A 40 px wide stroke on a larger canvas against the reference (window of 11 groups).
    canvas_ptr c = blank(120, 90);
    tiny3d::draw_line_coverage(c.get(), 10.3f, 12.7f, 101.9f, 71.2f, 40.0f);
    std::vector<double> ref;
    tiny3d::line_coverage_reference(ref, 120, 90, 10.3, 12.7, 101.9, 71.2, 40.0);
    error_stats e;
    compare(*c, ref, e);
    CHECK_NEAR(e.max, 0.0, 1e-4);
}

TEST(coverage_of_segments_crossing_the_canvas_edges) {
    // Ends anywhere in and around a small odd-sized canvas: clipped ends, end columns and
    // body rows cut by the canvas border, windows that do not fit, every angle.
    std::mt19937 rng(4242u);
    std::uniform_real_distribution<double> x_of(-20.0, 57.0), y_of(-20.0, 49.0);
    const double thicknesses[] = {0.5, 1.5, 3.0, 8.0, 25.0};
    std::vector<double> ref;
    for (double thickness : thicknesses)
        for (auto cap : {tiny3d::line_cap::round, tiny3d::line_cap::butt}) {
            error_stats e;
            for (int k = 0; k < kSegmentsPerThickness / 5; ++k) {
                const segment s{float(x_of(rng)), float(y_of(rng)), float(x_of(rng)), float(y_of(rng))};
                canvas_ptr c = blank(37, 29);
                tiny3d::draw_line_coverage(c.get(), s.x0, s.y0, s.x1, s.y1, float(thickness), {cap, 1.0f});
                tiny3d::line_coverage_reference(ref, 37, 29, s.x0, s.y0, s.x1, s.y1, thickness, cap);
                compare(*c, ref, e);
            }
            CHECK_MSG(e.max <= 1e-4, "T=" + std::to_string(thickness) + " max " + std::to_string(e.max));
            CHECK(e.pixels > 100);
        }
}

TEST(coverage_of_axis_aligned_and_diagonal_segments) {
    // Exact ties of the major-axis choice (|dx| = |dy|) and of the end regions (dy = 0: the
    // end line is vertical, zero-width butt pieces), every direction, against the reference.
    const double thicknesses[] = {0.5, 1.0, 1.5, 3.0};
    const double dirs[][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {-1, 1}, {1, -1}, {-1, -1}};
    std::vector<double> ref;
    error_stats e;
    for (double thickness : thicknesses)
        for (const auto &d : dirs)
            for (double length : {0.0, 0.3, 2.0, 9.25})
                for (auto cap : {tiny3d::line_cap::round, tiny3d::line_cap::butt}) {
                    const double x0 = 12.37, y0 = 11.61;
                    const double x1 = x0 + d[0] * length, y1 = y0 + d[1] * length;
                    canvas_ptr c = blank(26, 25);
                    tiny3d::draw_line_coverage(c.get(), float(x0), float(y0), float(x1), float(y1), float(thickness),
                                               {cap, 1.0f});
                    tiny3d::line_coverage_reference(ref, 26, 25, float(x0), float(y0), float(x1), float(y1), thickness,
                                                    cap);
                    compare(*c, ref, e);
                }
    CHECK_NEAR(e.max, 0.0, 1e-5);
    CHECK(e.pixels > 1000);
}
