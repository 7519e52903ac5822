// line_tabulated_test.cpp — the tabulated line (draw_line_tabulated + line_table) against
// the exact double-precision reference (line_coverage_reference): random segments of every
// angle and width, short segments, axis-aligned and diagonal ones, segments crossing the
// canvas edges or running far off it, bad input, and the wireframe that uses it.
#include "harness.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "canvas.h"
#include "lines.h"
#include "raster.h"
#include "math3d.h"
#include "mesh.h"
#include "wireframe.h"
#include "line_test_util.h"

namespace {

using namespace line_test;  // blank, ink, error_stats, compare, kPi

#if defined(__SANITIZE_ADDRESS__)
constexpr int kSegments = 120;  // sanitizers: a subset (the plain run does 600)
#else
constexpr int kSegments = 600;
#endif

using canvas_ptr = tiny3d::canvas_ptr;
tiny3d::line_table table_for(double thickness, tiny3d::line_cap cap = tiny3d::line_cap::round) {
    return std::move(tiny3d::line_table::make(float(thickness), cap).value());
}

// Every drawing path this CPU runs (the best one is also what every other test uses).
std::vector<tiny3d::line_simd> paths() {
    std::vector<tiny3d::line_simd> out{tiny3d::line_simd::portable};
    if (int(tiny3d::best_line_simd()) >= int(tiny3d::line_simd::sse2)) out.push_back(tiny3d::line_simd::sse2);
    if (tiny3d::best_line_simd() == tiny3d::line_simd::avx512) out.push_back(tiny3d::line_simd::avx512);
    return out;
}
const char *path_name(tiny3d::line_simd simd) {
    return simd == tiny3d::line_simd::avx512 ? "avx512" : simd == tiny3d::line_simd::sse2 ? "sse2" : "portable";
}

// Random segments of length min..max px at any angle inside a 64 × 64 canvas (whole stroke
// on it), drawn alone: their error against the reference.
error_stats random_segments(const tiny3d::line_table &table, int count, unsigned seed, double min_length,
                            double max_length) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double thickness = table.thickness();
    const int side = int(std::ceil(max_length + thickness)) + 8;
    error_stats e;
    std::vector<double> ref;
    for (int k = 0; k < count; ++k) {
        const double length = min_length + (max_length - min_length) * unit(rng), angle = 2 * kPi * unit(rng);
        const double cx = side / 2.0 + unit(rng), cy = side / 2.0 + unit(rng);
        const float x0 = float(cx - 0.5 * length * std::cos(angle)), y0 = float(cy - 0.5 * length * std::sin(angle));
        const float x1 = float(cx + 0.5 * length * std::cos(angle)), y1 = float(cy + 0.5 * length * std::sin(angle));
        canvas_ptr c = blank(side, side);
        tiny3d::draw_line_tabulated(c.get(), x0, y0, x1, y1, table);
        tiny3d::line_coverage_reference(ref, side, side, x0, y0, x1, y1, thickness, table.cap());
        compare(*c, ref, e);
    }
    return e;
}

std::string describe(const char *what, double thickness, const error_stats &e) {
    return std::string(what) + " T=" + std::to_string(thickness) + " mean " + std::to_string(e.mean()) + " max " +
           std::to_string(e.max);
}

}  // namespace

TEST(table_rejects_bad_thickness) {
    for (float t : {0.0f, -1.0f, NAN, INFINITY, 16.5f}) {
        const auto table = tiny3d::line_table::make(t);
        CHECK(!table.ok());
        if (!table.ok()) CHECK(table.message().find("thickness") != std::string::npos);
    }
    const auto good = tiny3d::line_table::make(1.5f, tiny3d::line_cap::butt);
    CHECK(good.ok());
    if (good.ok()) {
        CHECK_EQ(good->thickness(), 1.5f);
        CHECK(good->cap() == tiny3d::line_cap::butt);
    }
}

// Table blocks are the reference's end corrections D = E − band at their samples: for the
// first direction (+x) and the end at a pixel corner, recomputed here from the documented
// layout; every D lies in [−1, 0] (the half-infinite stroke lies inside the band).
TEST(table_holds_reference_corrections) {
    const tiny3d::line_table t = table_for(1.5);
    CHECK_EQ(t.stamp_size, 4);
    const std::size_t area = 16, phases = tiny3d::line_table::kStampPhases;
    CHECK_EQ(t.stamps.size(), std::size_t(tiny3d::line_table::kStampIntervals) * 2 * phases * phases * area);
    CHECK_EQ(reinterpret_cast<std::uintptr_t>(t.stamps.data()) % 64, 0u);  // a block per cache line
    const int origin_x = t.stamp_axes[0], origin_y = t.stamp_axes[2];
    const double px = 20.0, py = 20.0;  // end at a pixel corner (phase 0), stroke towards +x
    int checked = 0;
    for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a) {
            const int ix = 20 + origin_x + a, iy = 20 + origin_y + b;
            const double e = tiny3d::line_coverage_reference_at(ix, iy, px, py, px + 64, py, 1.5);
            const double band = tiny3d::line_coverage_reference_at(ix, iy, px - 64, py, px + 64, py, 1.5);
            CHECK_NEAR(t.stamps[std::size_t(b * 4 + a)], e - band, 1e-6);
            checked += std::fabs(e - band) > 0.01;
        }
    CHECK(checked >= 4);  // the block is not all zeros
    for (float d : t.stamps) {
        CHECK(d <= 1e-6f && d >= -1.0f - 1e-6f);
        if (!(d <= 1e-6f && d >= -1.0f - 1e-6f)) break;
    }
    // From ~5.35 px on no table: the exact line draws, bit for bit.
    const tiny3d::line_table wide = table_for(6.0);
    CHECK_EQ(wide.stamp_size, 0);
    canvas_ptr a = blank(40, 40), b = blank(40, 40);
    tiny3d::draw_line_tabulated(a.get(), 5.2f, 7.7f, 31.9f, 22.4f, wide, 0.7f);
    tiny3d::draw_line_coverage(b.get(), 5.2f, 7.7f, 31.9f, 22.4f, 6.0f, {tiny3d::line_cap::round, 0.7f});
    CHECK(std::memcmp(a->data, b->data, sizeof(float) * 40 * 40) == 0);
}

TEST(table_simd_choice) {
    tiny3d::line_table t = table_for(1.5);
    CHECK(t.simd() == tiny3d::best_line_simd());
    for (tiny3d::line_simd simd : paths()) {
        CHECK(t.use_simd(simd));
        CHECK(t.simd() == simd);
    }
    // An instruction set this CPU lacks (unless TINY3D_KERNELS chose a lesser one).
    if (tiny3d::best_line_simd() != tiny3d::line_simd::avx512 && tiny3d::default_raster_simd().requested.empty()) {
        CHECK(!t.use_simd(tiny3d::line_simd::avx512));
        CHECK(t.simd() != tiny3d::line_simd::avx512);
    }
}

// The widths of the wireframes and charts; the bounds hold what was measured with margin
// (measured: mean 4e-5–9e-5, max 0.003–0.013 for T = 0.5–3, 1–40 px, round and butt —
// the largest at T = 1 round, where a cap of radius ½ entering a pixel makes the coverage
// a (depth)^1.5 function of the end's position, which the position steps follow least
// well: 0.021 with 1/16-px steps, hence 1/24; T = 8 is drawn by the exact line).
TEST(tabulated_matches_reference_at_every_angle) {
    const double thicknesses[] = {0.5, 1.0, 1.5, 3.0, 8.0};
    auto check = [](const tiny3d::line_table &built, const char *cap, int seed, double min_length) {
        for (tiny3d::line_simd simd : paths()) {
            tiny3d::line_table t = built;  // one build per thickness and cap, each path on a copy
            t.use_simd(simd);
            const int count = simd == tiny3d::best_line_simd() ? kSegments : kSegments / 4;
            const bool round = built.cap() == tiny3d::line_cap::round;
            const error_stats e = random_segments(t, round ? count : count / 3, unsigned(seed), min_length, 40.0);
            CHECK_MSG(e.mean() <= 2e-4, path_name(simd) + (" " + describe(cap, t.thickness(), e)));
            CHECK_MSG(e.max <= 0.015, path_name(simd) + (" " + describe(cap, t.thickness(), e)));
            if (round) CHECK(e.pixels > count * 10);
        }
    };
    for (int i = 0; i < 5; ++i)
        check(table_for(thicknesses[i]), "round", 500 + i, std::max(thicknesses[i] / 2, 1.0));
    for (double t : {1.0, 1.5, 3.0}) check(table_for(t, tiny3d::line_cap::butt), "butt", 600, 1.0);
}

// The drawing paths compute the same coverage: u and v are rounded to float from different
// pixels (last bits), and the AVX-512 path visits only pixels within reach of the segment's
// bounding box, where the others also visit the corners of the stroke's rectangle beyond
// the round caps, whose reference coverage is 0 and whose table value is off by at most
// the interpolation error there (measured ≤ 0.0024): the largest difference.
TEST(tabulated_paths_agree) {
    std::mt19937 rng(77);
    std::uniform_real_distribution<float> at(-6.0f, 50.0f);
    const std::vector<tiny3d::line_simd> simds = paths();
    for (double thickness : {1.0, 1.5, 2.5}) {
        const tiny3d::line_table built = table_for(thickness);
        std::vector<tiny3d::line_table> tables(simds.size(), built);
        for (std::size_t p = 0; p < simds.size(); ++p) tables[p].use_simd(simds[p]);
        std::vector<double> worst(simds.size(), 0.0);  // against the portable path
        for (int k = 0; k < kSegments / 4; ++k) {
            const float x0 = at(rng), y0 = at(rng), x1 = x0 + at(rng) / 3, y1 = y0 + at(rng) / 3;
            canvas_ptr first = blank(45, 47);
            tiny3d::draw_line_tabulated(first.get(), x0, y0, x1, y1, tables[0], 0.9f);
            for (std::size_t p = 1; p < tables.size(); ++p) {
                canvas_ptr other = blank(45, 47);
                tiny3d::draw_line_tabulated(other.get(), x0, y0, x1, y1, tables[p], 0.9f);
                for (int i = 0; i < 45 * 47; ++i)
                    worst[p] = std::max(worst[p], std::fabs(double(first->data[i]) - other->data[i]));
            }
        }
        for (std::size_t p = 1; p < simds.size(); ++p)
            CHECK_MSG(worst[p] <= (simds[p] == tiny3d::line_simd::avx512 ? 0.004 : 1e-6),
                      std::string(path_name(simds[p])) + " T=" + std::to_string(thickness) + " differs by " +
                          std::to_string(worst[p]));
    }
}

// draw_lines_tabulated is draw_line_tabulated on each segment in order, bit for bit:
// batches mixing tabulated, exact (short, long), clipped, invisible and invalid segments.
TEST(tabulated_batch_equals_single_calls) {
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> at(-10.0f, 70.0f), ink_of(-0.2f, 1.3f);
    const tiny3d::line_table built = table_for(1.5);
    for (tiny3d::line_simd simd : paths()) {
        tiny3d::line_table t = built;
        t.use_simd(simd);
        std::vector<tiny3d::line_segment> segments;
        for (int k = 0; k < 300; ++k) {
            const float x0 = at(rng), y0 = at(rng);
            const float scale = k % 7 == 0 ? 1.5f : k % 11 == 0 ? 0.01f : 0.15f;  // long, tiny, usual
            segments.push_back({x0, y0, x0 + scale * at(rng), y0 + scale * at(rng), ink_of(rng)});
        }
        segments[5].x0 = NAN;
        segments[6].intensity = INFINITY;
        canvas_ptr batch = blank(61, 58), single = blank(61, 58);
        tiny3d::draw_lines_tabulated(batch.get(), segments.data(), segments.size(), t);
        for (const tiny3d::line_segment &g : segments)
            tiny3d::draw_line_tabulated(single.get(), g.x0, g.y0, g.x1, g.y1, t, g.intensity);
        CHECK_MSG(std::memcmp(batch->data, single->data, sizeof(float) * 61 * 58) == 0, path_name(simd));
        CHECK(ink(*batch) > 100.0);
        tiny3d::draw_lines_tabulated(batch.get(), nullptr, 5, t);  // nothing
        tiny3d::draw_lines_tabulated(nullptr, segments.data(), segments.size(), t);
        CHECK(std::memcmp(batch->data, single->data, sizeof(float) * 61 * 58) == 0);
    }
}

// Shorter than half the width: drawn by the exact line (identity (1) needs L ≥ T/2).
TEST(tabulated_short_segments) {
    for (double t : {1.5, 3.0}) {
        const error_stats e = random_segments(table_for(t), kSegments / 3, 700u, 0.0, t / 2);
        CHECK_MSG(e.max <= 1e-4, describe("short", t, e));
        const error_stats f = random_segments(table_for(t), kSegments / 3, 701u, t / 2, 2.0);
        CHECK_MSG(f.max <= 0.015, describe("short", t, f));
    }
}

// Pixels away from the ends get the exact band area: a long horizontal stroke centred on
// y = 2.5 with T = 1.5 covers row 2 fully and rows 1 and 3 by a quarter (hand values).
TEST(tabulated_body_hand_values) {
    const tiny3d::line_table t = table_for(1.5);
    canvas_ptr c = blank(40, 6);
    tiny3d::draw_line_tabulated(c.get(), 3.0f, 2.5f, 37.0f, 2.5f, t);
    for (int x = 6; x < 34; ++x) {
        CHECK_NEAR(c->pixels[2][x], 1.0, 1e-6);
        CHECK_NEAR(c->pixels[1][x], 0.25, 1e-6);
        CHECK_NEAR(c->pixels[3][x], 0.25, 1e-6);
        CHECK_EQ(c->pixels[0][x], 0.0f);
    }
    // Total ink of a long stroke: L·T + πT²/4 within the table's error on the ~20 end pixels.
    canvas_ptr d = blank(64, 64);
    tiny3d::draw_line_tabulated(d.get(), 5.3f, 7.1f, 55.2f, 49.9f, t);
    const double length = std::hypot(55.2 - 5.3, 49.9 - 7.1);
    CHECK_NEAR(ink(*d), length * 1.5 + kPi * 1.5 * 1.5 / 4, 0.02);
}

// Beyond 64 px the exact line is the faster one and draws instead: the same bits.
TEST(tabulated_long_segments_are_exact) {
    const tiny3d::line_table t = table_for(1.5);
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < 20; ++k) {
        const double length = 65.0 + 60.0 * unit(rng), angle = 2 * kPi * unit(rng);
        const float x0 = float(70 + unit(rng)), y0 = float(70 + unit(rng));
        const float x1 = float(x0 + length * std::cos(angle)), y1 = float(y0 + length * std::sin(angle));
        canvas_ptr a = blank(140, 140), b = blank(140, 140);
        tiny3d::draw_line_tabulated(a.get(), x0, y0, x1, y1, t, 0.8f);
        tiny3d::draw_line_coverage(b.get(), x0, y0, x1, y1, 1.5f, {tiny3d::line_cap::round, 0.8f});
        CHECK(std::memcmp(a->data, b->data, sizeof(float) * 140 * 140) == 0);
    }
}

TEST(tabulated_reversed_is_bit_identical) {
    const tiny3d::line_table t = table_for(1.5);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> at(2.0f, 30.0f);
    for (int k = 0; k < 100; ++k) {
        const float x0 = at(rng), y0 = at(rng), x1 = at(rng), y1 = at(rng);
        canvas_ptr a = blank(32, 32), b = blank(32, 32);
        tiny3d::draw_line_tabulated(a.get(), x0, y0, x1, y1, t);
        tiny3d::draw_line_tabulated(b.get(), x1, y1, x0, y0, t);
        CHECK(std::memcmp(a->data, b->data, sizeof(float) * 32 * 32) == 0);
    }
}

TEST(tabulated_axis_aligned_and_diagonal) {
    const double dirs[][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {-1, 1}, {1, -1}, {-1, -1}};
    std::vector<double> ref;
    for (double thickness : {1.0, 1.5, 3.0}) {
        const tiny3d::line_table t = table_for(thickness);
        error_stats e;
        for (const auto &d : dirs)
            for (double length : {0.3, 2.0, 9.25}) {
                const double x0 = 12.37, y0 = 11.61, x1 = x0 + d[0] * length, y1 = y0 + d[1] * length;
                canvas_ptr c = blank(26, 25);
                tiny3d::draw_line_tabulated(c.get(), float(x0), float(y0), float(x1), float(y1), t);
                tiny3d::line_coverage_reference(ref, 26, 25, float(x0), float(y0), float(x1), float(y1), thickness);
                compare(*c, ref, e);
            }
        CHECK_MSG(e.max <= 0.005, describe("axis", thickness, e));
        CHECK(e.pixels > 100);
    }
}

// Ends anywhere in and around a small odd-sized canvas (clipped ends, rows cut by the
// border, canvases narrower than an SSE group), and ends far off it.
TEST(tabulated_crossing_and_far_off_segments) {
    std::mt19937 rng(4243u);
    std::uniform_real_distribution<double> x_of(-20.0, 57.0), y_of(-20.0, 49.0);
    std::vector<double> ref;
    for (double thickness : {0.5, 1.5, 3.0}) {
        const tiny3d::line_table t = table_for(thickness);
        error_stats e;
        for (int k = 0; k < kSegments / 3; ++k) {
            const float x0 = float(x_of(rng)), y0 = float(y_of(rng)), x1 = float(x_of(rng)), y1 = float(y_of(rng));
            canvas_ptr c = blank(37, 29);
            tiny3d::draw_line_tabulated(c.get(), x0, y0, x1, y1, t);
            tiny3d::line_coverage_reference(ref, 37, 29, x0, y0, x1, y1, thickness);
            compare(*c, ref, e);
        }
        CHECK_MSG(e.max <= 0.015, describe("crossing", thickness, e));
        CHECK(e.pixels > 100);
        for (int w : {1, 2, 3, 5}) {  // tiny canvases: the scalar path and shifted groups
            error_stats s;
            for (int k = 0; k < 20; ++k) {
                const float x0 = float(x_of(rng)) / 8, y0 = float(y_of(rng)) / 8;
                const float x1 = float(x_of(rng)) / 8, y1 = float(y_of(rng)) / 8;
                canvas_ptr c = blank(w, 4);
                tiny3d::draw_line_tabulated(c.get(), x0, y0, x1, y1, t);
                tiny3d::line_coverage_reference(ref, w, 4, x0, y0, x1, y1, thickness);
                compare(*c, ref, s);
            }
            CHECK_MSG(s.max <= 0.01, describe("tiny canvas", thickness, s));
        }
    }
    // A far-off horizontal through row 5 (T = 1): exactly that row, nothing else.
    const tiny3d::line_table one = table_for(1.0);
    canvas_ptr c = blank(40, 12);
    tiny3d::draw_line_tabulated(c.get(), -1e9f, 5.5f, 1e9f, 5.5f, one);
    for (int x = 0; x < 40; ++x) {
        CHECK_NEAR(c->pixels[5][x], 1.0, 1e-6);
        CHECK_EQ(c->pixels[4][x], 0.0f);
    }
    // Ends at ±3e38 on the diagonal (T = 1): the line runs through the pixel centres;
    // hand values: the centre pixel loses two corner triangles with legs 1 − 1/√2, the
    // side neighbours get a triangle with legs 1/√2 (area ¼).
    canvas_ptr d = blank(48, 48);
    tiny3d::draw_line_tabulated(d.get(), -3e38f, -3e38f, 3e38f, 3e38f, one);
    const double leg = 1.0 - 1.0 / std::sqrt(2.0);
    for (int k = 1; k < 46; ++k) {
        CHECK_NEAR(d->pixels[k][k], 1.0 - leg * leg, 1e-5);
        CHECK_NEAR(d->pixels[k][k + 1], 0.25, 1e-5);
        CHECK_NEAR(d->pixels[k + 1][k], 0.25, 1e-5);
        CHECK_EQ(d->pixels[k][k + 2], 0.0f);
    }
    canvas_ptr o = blank(16, 16);
    tiny3d::draw_line_tabulated(o.get(), -100.0f, -50.0f, 300.0f, -40.0f, one);
    CHECK_EQ(ink(*o), 0.0);
}

TEST(tabulated_bad_input_draws_nothing) {
    const tiny3d::line_table t = table_for(1.5);
    canvas_ptr c = blank(16, 16);
    tiny3d::draw_line_tabulated(c.get(), NAN, 1.0f, 5.0f, 5.0f, t);
    tiny3d::draw_line_tabulated(c.get(), 1.0f, 1.0f, 5.0f, INFINITY, t);
    tiny3d::draw_line_tabulated(c.get(), 1.0f, 1.0f, 5.0f, 5.0f, t, NAN);
    tiny3d::draw_line_tabulated(c.get(), 1.0f, 1.0f, 5.0f, 5.0f, t, 0.0f);
    tiny3d::draw_line_tabulated(c.get(), 1.0f, 1.0f, 5.0f, 5.0f, t, -1.0f);
    tiny3d::draw_line_tabulated(nullptr, 1.0f, 1.0f, 5.0f, 5.0f, t);
    CHECK_EQ(ink(*c), 0.0);
    // Intensity above 1 is clamped: the same image as 1.
    canvas_ptr a = blank(16, 16), b = blank(16, 16);
    tiny3d::draw_line_tabulated(a.get(), 2.2f, 3.1f, 12.7f, 9.4f, t, 7.0f);
    tiny3d::draw_line_tabulated(b.get(), 2.2f, 3.1f, 12.7f, 9.4f, t, 1.0f);
    CHECK(std::memcmp(a->data, b->data, sizeof(float) * 256) == 0);
    // A zero-length segment is the exact disc (drawn by draw_line_coverage).
    canvas_ptr d = blank(16, 16);
    tiny3d::draw_line_tabulated(d.get(), 8.3f, 7.9f, 8.3f, 7.9f, t);
    CHECK_NEAR(ink(*d), kPi * 0.75 * 0.75, 1e-4);
}

// render_wireframe with line_method::tabulated: the soccer ball's image against the
// exact coverage line's (both "over"-combined in the same order).
TEST(wireframe_tabulated_matches_coverage) {
    const tiny3d::mesh ball = tiny3d::make_soccer_ball();
    const mat4_t mvp = mat4_multiply(tiny3d::mat4_perspective(0.8f, 1.0f, 0.1f, 100.0f),
                                     mat4_multiply(mat4_translate(0, 0, -3), tiny3d::mat4_rotate_y(0.3f)));
    canvas_ptr exact = blank(256, 256), tab = blank(256, 256);
    tiny3d::wireframe_options o;
    o.thickness = 1.5f;
    o.method = tiny3d::line_method::coverage;
    tiny3d::wireframe_workspace ws;
    CHECK(tiny3d::render_wireframe(*exact, ball, mvp, o, ws).ok());
    o.method = tiny3d::line_method::tabulated;
    CHECK(tiny3d::render_wireframe(*tab, ball, mvp, o, ws).ok());
    CHECK_EQ(ws.line_tables.size(), std::size_t(1));
    double sum = 0, worst = 0;
    long n = 0;
    for (int i = 0; i < 256 * 256; ++i) {
        if (exact->data[i] == 0.0f && tab->data[i] == 0.0f) continue;
        const double d = std::fabs(double(exact->data[i]) - tab->data[i]);
        sum += d;
        worst = std::max(worst, d);
        ++n;
    }
    CHECK(n > 2000);
    CHECK_MSG(sum / double(n) <= 5e-4, "mean " + std::to_string(sum / double(n)));
    CHECK_MSG(worst <= 0.015, "max " + std::to_string(worst));
    // A thickness the table cannot hold is an error, and nothing is drawn.
    o.thickness = 40.0f;
    canvas_ptr none = blank(64, 64);
    const tiny3d::status st = tiny3d::render_wireframe(*none, ball, mvp, o, ws);
    CHECK(!st.ok());
    CHECK(st.message().find("thickness") != std::string::npos);
    CHECK_EQ(ink(*none), 0.0);
}
