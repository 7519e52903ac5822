// chart_test.cpp — the benchmarks' library: font, axis mapping, chart layout, CSV.
// Linked with tests/bench/common (build/bench/libtiny3d_bench.a). The library's PNG bytes:
// png_test.cpp.
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "bench/common/bench.h"
#include "bench/common/chart.h"
#include "harness.h"

namespace {

using tiny3d::axis_range;
using tiny3d::axis_scale;

tiny3d::canvas_ptr canvas_or_die(int w, int h) {
    auto c = tiny3d::make_canvas(w, h);
    if (!c) {
        std::fprintf(stderr, "cannot create canvas: %s\n", c.message().c_str());
        std::exit(1);
    }
    return std::move(*c);
}

// Counts CSV fields of one record, honouring quotes; records empty fields.
std::vector<std::string> naive_fields(const std::string &line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (const char c : line) {
        if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) out.emplace_back();
        else out.back() += c;
    }
    return out;
}

bool inside(const tiny3d::pixel_box &b, int w, int h) {
    return b.x >= 0 && b.y >= 0 && b.width > 0 && b.height > 0 && b.x + b.width <= w && b.y + b.height <= h;
}

bool overlap(const tiny3d::pixel_box &a, const tiny3d::pixel_box &b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

float darkest_near(const canvas_t &c, double x, double y, int r) {
    float m = 1.0f;
    for (int yy = int(y) - r; yy <= int(y) + r; ++yy)
        for (int xx = int(x) - r; xx <= int(x) + r; ++xx)
            if (xx >= 0 && yy >= 0 && xx < c.width && yy < c.height) m = std::min(m, c.pixels[yy][xx]);
    return m;
}

}  // namespace

// ---- font ---------------------------------------------------------------------------

TEST(font_glyph_A_matches_hand_drawn_bitmap) {
    const char *A[7] = {".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"};
    for (int row = 0; row < 7; ++row)
        for (int col = 0; col < 5; ++col)
            CHECK_MSG(tiny3d::font_glyph_pixel('A', col, row) == (A[row][col] == '#'),
                      "A at column " + std::to_string(col) + " row " + std::to_string(row));
    CHECK(!tiny3d::font_glyph_pixel('A', -1, 0));
    CHECK(!tiny3d::font_glyph_pixel('A', 5, 0));
    CHECK(!tiny3d::font_glyph_pixel('A', 0, 7));
}

TEST(font_space_is_blank_and_unknown_characters_are_boxes) {
    int space_ink = 0, box_ink = 0;
    for (int row = 0; row < 7; ++row)
        for (int col = 0; col < 5; ++col) {
            space_ink += tiny3d::font_glyph_pixel(' ', col, row);
            box_ink += tiny3d::font_glyph_pixel(U'\u00B0', col, row);
        }
    CHECK_EQ(space_ink, 0);
    CHECK_EQ(box_ink, 2 * 5 + 2 * 5);  // outline of a 5 × 7 box
    // Every printable ASCII character except space has some ink.
    for (char32_t c = 33; c <= 126; ++c) {
        bool any = false;
        for (int row = 0; row < 7 && !any; ++row)
            for (int col = 0; col < 5 && !any; ++col) any = tiny3d::font_glyph_pixel(c, col, row);
        CHECK_MSG(any, "glyph " + std::to_string(int(c)) + " is empty");
    }
}

TEST(text_width_counts_code_points) {
    CHECK_EQ(tiny3d::text_width(""), 0);
    CHECK_EQ(tiny3d::text_width("T"), 5);
    CHECK_EQ(tiny3d::text_width("abc"), 17);             // 3 · 6 − 1
    CHECK_EQ(tiny3d::text_width("abc", 2), 34);
    CHECK_EQ(tiny3d::text_width("\xC2\xB0" "C"), 11);    // "°C": two code points
    CHECK_EQ(tiny3d::text_width("abc", 0), 0);
    CHECK_EQ(tiny3d::text_height(3), 21);
}

TEST(draw_text_sets_exactly_the_glyph_pixels_at_scale_2) {
    auto c = canvas_or_die(20, 20);
    tiny3d::draw_text(*c, 3, 4, "T", 0.75f, 2);
    // Hand-computed: T = top row (5 cells) + centre column below it (6 cells), each cell 2×2.
    int ink = 0;
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x) {
            const int cx = (x - 3) / 2, cy = (y - 4) / 2;
            const bool in_cell = x >= 3 && y >= 4 && cx < 5 && cy < 7;
            const bool expected = in_cell && (cy == 0 || cx == 2);
            CHECK_MSG((c->pixels[y][x] == 0.75f) == expected, "pixel " + std::to_string(x) + "," + std::to_string(y));
            ink += c->pixels[y][x] > 0;
        }
    CHECK_EQ(ink, (5 + 6) * 4);
}

TEST(draw_text_clips_at_the_canvas_edges) {
    auto c = canvas_or_die(8, 8);
    tiny3d::draw_text(*c, -3, -3, "WWWW", 1.0f, 3);  // mostly off canvas: must not crash
    tiny3d::draw_text(*c, 6, 6, "W", 1.0f, 1);
    CHECK_EQ(c->pixels[6][6], 1.0f);  // W's top-left cell has ink
}

TEST(vertical_text_reads_bottom_to_top) {
    auto c = canvas_or_die(10, 10);
    tiny3d::draw_text_vertical(*c, 1, 1, "L", 1.0f);
    // "L" turned counter-clockwise: its stem (column 0, rows 0..6) becomes the top row of
    // the box, running right to left from bottom... here: box 7 wide, 5 tall at (1, 1).
    // Stem pixel (col 0, row r) lands at (1 + r, 1 + 5 − 1 − 0) = (1 + r, 5).
    for (int r = 0; r < 7; ++r) CHECK_EQ(c->pixels[5][1 + r], 1.0f);
    // The foot (row 6, columns 0..4) lands at x = 7, y = 5 − col.
    for (int col = 0; col < 5; ++col) CHECK_EQ(c->pixels[5 - col][7], 1.0f);
    CHECK_EQ(c->pixels[1][1], 0.0f);
}

// ---- axes ---------------------------------------------------------------------------

TEST(axis_mapping_is_exact_at_the_ends) {
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> exponent(-12, 12), pixel(-500, 2000);
    for (int i = 0; i < 1000; ++i) {
        double a = std::pow(10.0, exponent(rng)), b = std::pow(10.0, exponent(rng));
        if (a == b) continue;
        if (a > b) std::swap(a, b);
        const double p0 = pixel(rng), p1 = pixel(rng);
        for (const axis_scale s : {axis_scale::linear, axis_scale::log10}) {
            const axis_range r{a, b, s};
            CHECK_EQ(tiny3d::axis_to_pixel(r, a, p0, p1), p0);
            CHECK_EQ(tiny3d::axis_to_pixel(r, b, p0, p1), p1);
        }
        const axis_range lin{-a, b, axis_scale::linear};
        CHECK_EQ(tiny3d::axis_to_pixel(lin, -a, p0, p1), p0);
        CHECK_EQ(tiny3d::axis_to_pixel(lin, b, p0, p1), p1);
    }
}

TEST(linear_axis_is_affine) {
    const axis_range r{-2.0, 6.0, axis_scale::linear};
    CHECK_NEAR(tiny3d::axis_to_pixel(r, 2.0, 100.5, 500.5), 300.5, 1e-12);
    CHECK_NEAR(tiny3d::axis_to_pixel(r, 0.0, 100.5, 500.5), 200.5, 1e-12);
    CHECK_NEAR(tiny3d::axis_to_pixel(r, 10.0, 100.5, 500.5), 700.5, 1e-12);  // extrapolates
    // Reversed pixel direction (a y axis: lo at the bottom).
    CHECK_NEAR(tiny3d::axis_to_pixel(r, 4.0, 400.5, 0.5), 100.5, 1e-12);
}

TEST(log_axis_spaces_decades_equally) {
    const axis_range r{1e-4, 1e2, axis_scale::log10};
    const double p0 = 40.5, p1 = 640.5;  // 6 decades over 600 px: 100 px per decade
    for (int e = -4; e <= 2; ++e)
        CHECK_NEAR(tiny3d::axis_to_pixel(r, std::pow(10.0, e), p0, p1), p0 + 100.0 * (e + 4), 1e-9);
    // √10 is half a decade; 2 is log10(2) ≈ 0.30103 of one.
    CHECK_NEAR(tiny3d::axis_to_pixel(r, std::sqrt(10.0), p0, p1), p0 + 450.0, 1e-9);
    CHECK_NEAR(tiny3d::axis_to_pixel(r, 2.0, p0, p1), p0 + 400.0 + 30.10299956639812, 1e-9);
}

TEST(axis_mapping_rejects_what_it_cannot_place) {
    const axis_range log_r{1e-3, 1.0, axis_scale::log10};
    CHECK(std::isnan(tiny3d::axis_to_pixel(log_r, 0.0, 0, 100)));
    CHECK(std::isnan(tiny3d::axis_to_pixel(log_r, -1.0, 0, 100)));
    CHECK(std::isnan(tiny3d::axis_to_pixel(log_r, NAN, 0, 100)));
    CHECK(std::isnan(tiny3d::axis_to_pixel(log_r, INFINITY, 0, 100)));
    CHECK(std::isnan(tiny3d::axis_to_pixel({0.0, 1.0, axis_scale::log10}, 0.5, 0, 100)));
    CHECK(std::isnan(tiny3d::axis_to_pixel({1.0, 1.0, axis_scale::linear}, 1.0, 0, 100)));
    CHECK(std::isnan(tiny3d::axis_to_pixel({2.0, 1.0, axis_scale::linear}, 1.5, 0, 100)));
    CHECK(std::isnan(tiny3d::axis_to_pixel({0.0, INFINITY, axis_scale::linear}, 1.0, 0, 100)));
}

TEST(choose_axis_uses_log_only_across_decades) {
    const std::vector<double> decades = {3e-5, 0.2, 7.0, NAN, INFINITY};
    const axis_range a = tiny3d::choose_axis(decades);
    CHECK(a.scale == axis_scale::log10);
    CHECK_NEAR(a.lo, 1e-5, 1e-20);
    CHECK_NEAR(a.hi, 10.0, 1e-12);
    const std::vector<double> narrow = {2.0, 3.5, 7.9};
    const axis_range b = tiny3d::choose_axis(narrow);
    CHECK(b.scale == axis_scale::linear);
    CHECK_EQ(b.lo, 0.0);  // smallest is below half the largest: start at zero
    CHECK(b.hi >= 7.9 * 1.05 - 1e-12);
    CHECK(b.hi <= 10.0);
    const std::vector<double> with_zero = {0.0, 1e-6, 1.0};
    CHECK(tiny3d::choose_axis(with_zero).scale == axis_scale::linear);
    const std::vector<double> negative = {-3.0, -2.5};
    const axis_range n = tiny3d::choose_axis(negative);
    CHECK(n.lo <= -3.0 && n.hi >= -2.5 && n.lo < n.hi);
    const axis_range none = tiny3d::choose_axis(std::span<const double>());
    CHECK_EQ(none.lo, 0.0);
    CHECK_EQ(none.hi, 1.0);
    const std::vector<double> zeros = {0.0, 0.0};
    CHECK_EQ(tiny3d::choose_axis(zeros).lo, 0.0);
    CHECK_EQ(tiny3d::choose_axis(zeros).hi, 1.0);
    const std::vector<double> single = {5.0};
    const axis_range s = tiny3d::choose_axis(single);
    CHECK(s.lo < 5.0 && s.hi > 5.0);
}

TEST(ticks_are_decades_or_125_steps_inside_the_range) {
    const std::vector<double> log_ticks = tiny3d::axis_ticks({1e-3, 1e2, axis_scale::log10});
    CHECK_EQ(log_ticks.size(), std::size_t(6));
    for (std::size_t i = 0; i < log_ticks.size(); ++i)
        CHECK_NEAR(log_ticks[i], std::pow(10.0, int(i) - 3), 1e-15 * std::pow(10.0, int(i)));
    const std::vector<double> inner = tiny3d::axis_ticks({2e-3, 50.0, axis_scale::log10});
    CHECK_EQ(inner.size(), std::size_t(4));  // 0.01, 0.1, 1, 10
    std::mt19937 rng(81);
    std::uniform_real_distribution<double> u(-1e4, 1e4);
    for (int i = 0; i < 500; ++i) {
        double a = u(rng), b = u(rng);
        if (a == b) continue;
        if (a > b) std::swap(a, b);
        const std::vector<double> t = tiny3d::axis_ticks({a, b, axis_scale::linear});
        CHECK(t.size() >= 3 && t.size() <= 10);
        for (const double v : t) CHECK(v >= a - 1e-9 * (b - a) && v <= b + 1e-9 * (b - a));
    }
    const std::vector<double> unit = tiny3d::axis_ticks({0.0, 1.0, axis_scale::linear});
    CHECK_EQ(unit.size(), std::size_t(6));  // span / 8 = 0.125 rounds up to the step 0.2
}

TEST(tick_labels_are_short) {
    CHECK_EQ(tiny3d::tick_label(0.01, axis_scale::log10), std::string("0.01"));
    CHECK_EQ(tiny3d::tick_label(1000, axis_scale::log10), std::string("1000"));
    CHECK_EQ(tiny3d::tick_label(1e-5, axis_scale::log10), std::string("1e-5"));
    CHECK_EQ(tiny3d::tick_label(1e6, axis_scale::log10), std::string("1e6"));
    CHECK_EQ(tiny3d::tick_label(2.5, axis_scale::linear), std::string("2.5"));
    CHECK_EQ(tiny3d::tick_label(0.0, axis_scale::linear), std::string("0"));
}

// ---- whole charts -------------------------------------------------------------------

TEST(chart_puts_markers_where_the_axes_say_and_text_inside) {
    auto c = canvas_or_die(640, 400);
    tiny3d::chart_spec spec;
    spec.title = "time against error";
    spec.x_title = "ns per call";
    spec.y_title = "relative error";
    spec.points = {{2.0, 1e-3, "faithful"}, {20.0, 1e-6, "fast"}, {200.0, 0.0, "reference"},
                   {NAN, 1.0, "broken"}};
    const auto layout = tiny3d::draw_chart(*c, spec);
    CHECK(layout.ok());
    if (!layout) return;
    CHECK(layout->x_axis.scale == axis_scale::log10);
    CHECK(layout->y_axis.scale == axis_scale::log10);
    for (std::size_t i = 0; i < 2; ++i) {
        const double mx = tiny3d::axis_to_pixel(layout->x_axis, spec.points[i].x, layout->plot_left, layout->plot_right);
        const double my = tiny3d::axis_to_pixel(layout->y_axis, spec.points[i].y, layout->plot_bottom, layout->plot_top);
        CHECK_EQ(layout->marker_x[i], mx);
        CHECK_EQ(layout->marker_y[i], my);
        CHECK(darkest_near(*c, mx, my, 4) < 0.25f);  // there is ink at the marker
    }
    CHECK_EQ(layout->marker_y[2], layout->plot_bottom);  // zero error on the floor
    CHECK(std::isnan(layout->marker_x[3]));
    // Paper is white; the plot area has ink only where drawn.
    CHECK_EQ(c->pixels[c->height - 1][c->width - 1], 1.0f);
    for (const tiny3d::pixel_box &b : layout->text_boxes) CHECK(inside(b, c->width, c->height));
    CHECK(layout->text_boxes.size() >= 4 + 3 + 2);  // title, axis titles, ≥3 tick labels per axis, legend
    for (std::size_t i = 0; i < layout->text_boxes.size(); ++i)
        for (std::size_t j = i + 1; j < layout->text_boxes.size(); ++j)
            CHECK_MSG(!overlap(layout->text_boxes[i], layout->text_boxes[j]),
                      "text boxes " + std::to_string(i) + " and " + std::to_string(j) + " overlap");
}

TEST(chart_keeps_long_labels_inside_a_small_canvas) {
    std::mt19937 rng(88);
    std::uniform_real_distribution<double> e(-15, 15);
    for (const int w : {tiny3d::chart_min_width, 333, 1000}) {
        const int h = w == 1000 ? 240 : tiny3d::chart_min_height;
        auto c = canvas_or_die(w, h);
        tiny3d::chart_spec spec;
        spec.title = std::string(200, 'W') + " a very long title";
        spec.x_title = std::string(300, 'x');
        spec.y_title = std::string(300, 'y');
        for (int i = 0; i < 30; ++i)
            spec.points.push_back({std::pow(10.0, e(rng)), std::pow(10.0, e(rng)),
                                   "variant " + std::to_string(i) + std::string(std::size_t(i) * 7, '#')});
        spec.points.push_back({-1e300, 1e300, "huge"});
        const auto layout = tiny3d::draw_chart(*c, spec);
        CHECK(layout.ok());
        if (!layout) continue;
        for (const tiny3d::pixel_box &b : layout->text_boxes) CHECK(inside(b, w, h));
        for (std::size_t i = 0; i < layout->text_boxes.size(); ++i)
            for (std::size_t j = i + 1; j < layout->text_boxes.size(); ++j)
                CHECK(!overlap(layout->text_boxes[i], layout->text_boxes[j]));
        for (std::size_t i = 0; i < spec.points.size(); ++i)
            if (!std::isnan(layout->marker_x[i])) {
                CHECK(layout->marker_x[i] >= layout->plot_left && layout->marker_x[i] <= layout->plot_right);
                CHECK(layout->marker_y[i] >= layout->plot_top && layout->marker_y[i] <= layout->plot_bottom);
            }
    }
}

// A series is one legend entry, one marker shape and a line through its points; a long
// label wraps in the legend instead of being cut.
TEST(chart_series_share_one_entry_and_a_line_and_long_labels_wrap) {
    auto c = canvas_or_die(800, 500);
    tiny3d::chart_spec spec;
    spec.title = "series";
    const std::string long_label = "a variant with a long descriptive name (the robust one, in double precision)";
    for (int k = 0; k < 4; ++k) {
        tiny3d::chart_point p{std::pow(10.0, k), std::pow(10.0, -k), "ignored"};
        p.series = "method A";
        p.tag = "T=" + std::to_string(k);
        spec.points.push_back(p);
        tiny3d::chart_point q{2 * std::pow(10.0, k), 3 * std::pow(10.0, -k), "ignored"};
        q.series = "method B";
        spec.points.push_back(q);
    }
    spec.points.push_back({5.0, 0.5, long_label});
    const auto layout = tiny3d::draw_chart(*c, spec);
    CHECK(layout.ok());
    if (!layout) return;
    CHECK_EQ(layout->legend_entries, std::size_t(3));  // not 9
    for (std::size_t i = 0; i < 8; ++i) CHECK_EQ(layout->legend_entry[i], i % 2);
    CHECK_EQ(layout->legend_entry[8], std::size_t(2));
    // Ink on the line half-way between two points of series A (no marker there).
    const double mx = 0.5 * (layout->marker_x[0] + layout->marker_x[2]), my = 0.5 * (layout->marker_y[0] + layout->marker_y[2]);
    CHECK(darkest_near(*c, mx, my, 1) < 0.5f);
    // The long label is all there, over several legend rows: the text boxes right of the
    // plot add up to at least its width.
    int legend_text = 0, legend_rows = 0;
    for (const tiny3d::pixel_box &b : layout->text_boxes)
        if (b.x > layout->plot_right) legend_text += b.width, ++legend_rows;
    CHECK(legend_rows >= 3 + 1);
    CHECK(legend_text >= tiny3d::text_width(long_label) + tiny3d::text_width("method A") - 2 * tiny3d::font_advance);
    for (const tiny3d::pixel_box &b : layout->text_boxes) CHECK(inside(b, c->width, c->height));
    for (std::size_t i = 0; i < layout->text_boxes.size(); ++i)
        for (std::size_t j = i + 1; j < layout->text_boxes.size(); ++j)
            CHECK(!overlap(layout->text_boxes[i], layout->text_boxes[j]));
}

TEST(chart_refuses_small_canvases_and_bad_axes) {
    auto c = canvas_or_die(tiny3d::chart_min_width - 1, 300);
    tiny3d::chart_spec spec;
    spec.points = {{1.0, 1.0, "a"}};
    const auto small = tiny3d::draw_chart(*c, spec);
    CHECK(!small.ok());
    if (!small.ok()) CHECK(small.message().find("smaller than") != std::string::npos);
    CHECK_EQ(c->pixels[0][0], 0.0f);  // untouched
    auto big = canvas_or_die(400, 300);
    spec.y_axis = axis_range{0.0, 1.0, axis_scale::log10};
    const auto bad = tiny3d::draw_chart(*big, spec);
    CHECK(!bad.ok());
    if (!bad.ok()) CHECK(bad.message().find("y axis") != std::string::npos);
}

TEST(markers_are_distinct) {
    // Each marker drawn alone on a small canvas gives a different image.
    std::vector<std::vector<float>> images;
    for (int i = 0; i < tiny3d::marker_count; ++i) {
        auto c = canvas_or_die(16, 16);
        tiny3d::draw_marker(*c, 8.0, 8.0, i, 5.0);
        images.emplace_back(c->data, c->data + 256);
        float ink = 0;
        for (const float v : images.back()) ink += v;
        CHECK(ink > 4.0f);
    }
    for (std::size_t i = 0; i < images.size(); ++i)
        for (std::size_t j = i + 1; j < images.size(); ++j) CHECK(images[i] != images[j]);
}

// ---- benchmark CSV --------------------------------------------------------------------

namespace {
std::vector<bench::row> sample_rows() {
    return {
        {"lines", "faithful DDA splat T=1.5", "faithful", "ns/px", {10, 9, 14}, 0.02, 0.5, "abs intensity", ""},
        {"lines", "Wu, \"classic\"", "fast", "ns/px", {2.5, 2, 3}, 0.01, 0.2, "abs intensity", "note, with comma"},
        {"lines", "supersampled 16x16", "reference", "ns/px", {400, 390, 450}, NAN, NAN, "abs intensity", ""},
        {"lines", "frame", "other", "ms/frame", {5, 4, 6}, 0.0, 0.0, "", "multi\nline"},
    };
}
}  // namespace

TEST(csv_has_one_complete_row_per_variant) {
    const std::vector<bench::row> rows = sample_rows();
    const std::string csv = bench::csv_text(rows);
    std::vector<std::string> lines;
    for (std::size_t p = 0, e; p < csv.size(); p = e + 1) {
        e = csv.find('\n', p);
        lines.push_back(csv.substr(p, e - p));
    }
    CHECK_EQ(lines.size(), rows.size() + 1);
    const std::size_t n = bench::csv_columns().size();
    CHECK_EQ(n, std::size_t(12));
    for (const std::string &line : lines) {
        const std::vector<std::string> f = naive_fields(line);
        CHECK_EQ(f.size(), n);
        for (const std::string &field : f) CHECK_MSG(!field.empty(), "empty field in: " + line);
    }
    CHECK_EQ(naive_fields(lines[2])[10], std::string("0.25"));  // ratio to faithful
    CHECK_EQ(naive_fields(lines[3])[7], std::string("nan"));    // missing error is spelled out
    CHECK_EQ(naive_fields(lines[4])[10], std::string("nan"));   // other unit: no faithful row
    const auto back = bench::parse_csv(csv, "sample.csv");
    CHECK(back.ok());
    if (!back) return;
    CHECK_EQ(back->size(), rows.size());
    for (std::size_t i = 0; i < rows.size() && i < back->size(); ++i) {
        CHECK_EQ((*back)[i].variant, rows[i].variant);
        CHECK_EQ((*back)[i].note, i == 3 ? std::string("multi line") : rows[i].note);
        CHECK_EQ((*back)[i].time.median, rows[i].time.median);
        CHECK_EQ(std::isnan((*back)[i].error_mean), std::isnan(rows[i].error_mean));
    }
}

TEST(csv_parser_names_the_line_of_a_broken_row) {
    std::string csv = bench::csv_text(sample_rows());
    csv += "lines,x,fast,ns/px,1,2\n";
    const auto r = bench::parse_csv(csv, "broken.csv");
    CHECK(!r.ok());
    if (!r.ok()) CHECK_EQ(r.message(), std::string("broken.csv:6: expected 12 fields, found 6"));
    const auto header = bench::parse_csv("a,b\n", "h.csv");
    CHECK(!header.ok());
    std::string bad_number = bench::csv_text({sample_rows()[0]});
    bad_number.replace(bad_number.find(",10,"), 4, ",ten,");
    const auto n = bench::parse_csv(bad_number, "n.csv");
    CHECK(!n.ok());
    if (!n.ok()) CHECK(n.message().find("n.csv:2:") == 0);
}

TEST(ratios_and_measurements) {
    const std::vector<double> r = bench::ratios_to_faithful(sample_rows());
    CHECK_EQ(r[0], 1.0);
    CHECK_EQ(r[1], 0.25);
    CHECK_EQ(r[2], 40.0);
    CHECK(std::isnan(r[3]));
    // Two workloads in one family and unit: each row compares with the faithful row
    // listed before it; a row before any faithful row uses the first one after it.
    std::vector<bench::row> two = sample_rows();
    two.insert(two.begin(), {"lines", "early fast", "fast", "ns/px", {5, 5, 5}, 0, 0, "abs intensity", ""});
    two.push_back({"lines", "second faithful", "faithful", "ns/px", {100, 90, 110}, 0, 0, "abs intensity", ""});
    two.push_back({"lines", "second fast", "fast", "ns/px", {20, 19, 21}, 0, 0, "abs intensity", ""});
    const std::vector<double> r2 = bench::ratios_to_faithful(two);
    CHECK_EQ(r2[0], 0.5);   // 5 / 10 (the first faithful row comes after it)
    CHECK_EQ(r2[2], 0.25);  // 2.5 / 10
    CHECK_EQ(r2[5], 1.0);
    CHECK_EQ(r2[6], 0.2);   // 20 / 100
    int calls = 0;
    const bench::timing t = bench::measure_ns(5, 10.0, [&] { ++calls; bench::keep(calls); });
    CHECK_EQ(calls, 6);  // one warm-up + 5 timed runs
    CHECK(t.min <= t.median && t.median <= t.max && t.min >= 0);
}
