// report_pixels_test.cpp — the report's functions give the report's pixels: set_pixel_f,
// draw_line_f, project_vertex and the 7-argument render_wireframe against an independent
// transcription of the libtiny3d report's C code (below, float arithmetic and libm calls
// exactly as printed in the report), on the report's clock, thousands of random splats
// and lines, random projections and the soccer ball.
#include <cmath>
#include <random>
#include <vector>

#include "harness.h"
#include "program_runner.h"
#include "renderer.h"

namespace {

// ---- the report's C code, transcribed (its canvas_t, set_pixel_f, draw_line_f,
// project_vertex, render_wireframe, clock) --------------------------------------------------
namespace report {

struct canvas {
    int width, height;
    std::vector<float> data;
    std::vector<float *> rows;
    canvas(int w, int h) : width(w), height(h), data(std::size_t(w) * std::size_t(h), 0.0f), rows(std::size_t(h)) {
        for (int y = 0; y < h; ++y) rows[std::size_t(y)] = data.data() + std::size_t(y) * std::size_t(w);
    }
    float **pixels() { return rows.data(); }
};

void set_pixel_f(canvas *c, float x, float y, float intensity) {
    int x0 = (int)floorf(x);
    int y0 = (int)floorf(y);
    float dx = x - x0;
    float dy = y - y0;
    for (int j = 0; j <= 1; ++j)
        for (int i = 0; i <= 1; ++i) {
            int xi = x0 + i, yj = y0 + j;
            if (xi < 0 || xi >= c->width || yj < 0 || yj >= c->height) continue;
            float w = (1.0f - fabsf(i - dx)) * (1.0f - fabsf(j - dy));
            float v = c->pixels()[yj][xi] + intensity * w;
            if (v > 1.0f) v = 1.0f;
            c->pixels()[yj][xi] = v;
        }
}

void draw_line_f(canvas *c, float x0, float y0, float x1, float y1, float thickness) {
    float dx = x1 - x0;
    float dy = y1 - y0;
    float len = hypotf(dx, dy);
    if (len == 0.0f) {
        set_pixel_f(c, x0, y0, 1.0f);
        return;
    }
    const float step = 0.5f;
    int steps = (int)ceilf(len / step);
    for (int n = 0; n <= steps; ++n) {
        float t = (float)n / steps;
        float px = x0 + t * dx;
        float py = y0 + t * dy;
        for (float ky = -thickness / 2; ky < thickness / 2; ky += 0.5f)
            for (float kx = -thickness / 2; kx < thickness / 2; kx += 0.5f)
                if ((kx * kx + ky * ky) <= (thickness * thickness) / 4.0f) set_pixel_f(c, px + kx, py + ky, 1.0f);
    }
}

struct vec4 {
    float x, y, z, w;
};
// Column-major m[column*4 + row], as the report stores matrices.
vec4 mat4_mul_vec4(const mat4_t &m, vec4 v) {
    vec4 r;
    r.x = m.m[0] * v.x + m.m[4] * v.y + m.m[8] * v.z + m.m[12] * v.w;
    r.y = m.m[1] * v.x + m.m[5] * v.y + m.m[9] * v.z + m.m[13] * v.w;
    r.z = m.m[2] * v.x + m.m[6] * v.y + m.m[10] * v.z + m.m[14] * v.w;
    r.w = m.m[3] * v.x + m.m[7] * v.y + m.m[11] * v.z + m.m[15] * v.w;
    return r;
}

int project_vertex(vec3_t v, mat4_t model, mat4_t proj, int w, int h, float *x_out, float *y_out) {
    vec4 vm = {v.x, v.y, v.z, 1.0f};
    vm = mat4_mul_vec4(model, vm);
    vm = mat4_mul_vec4(proj, vm);
    if (vm.w == 0.0f) return 0;
    float nx = vm.x / vm.w;
    float ny = vm.y / vm.w;
    *x_out = (nx * 0.5f + 0.5f) * (float)(w - 1);
    *y_out = (1.0f - (ny * 0.5f + 0.5f)) * (float)(h - 1);
    return 1;
}

void render_wireframe(canvas *c, vec3_t *vertices, int vertex_count, int edges[][2], int edge_count, mat4_t model,
                      mat4_t proj) {
    for (int i = 0; i < edge_count; ++i) {
        int i0 = edges[i][0];
        int i1 = edges[i][1];
        if (i0 < 0 || i0 >= vertex_count || i1 < 0 || i1 >= vertex_count) continue;
        float x0, y0, x1, y1;
        if (!report::project_vertex(vertices[i0], model, proj, c->width, c->height, &x0, &y0)) continue;
        if (!report::project_vertex(vertices[i1], model, proj, c->width, c->height, &x1, &y1)) continue;
        draw_line_f(c, x0, y0, x1, y1, 1.0f);
    }
}

// The report's main.c, part 1: lines every 15° from the centre, radius 200, thickness 1.5.
template <class Canvas, class DrawLine>
void clock_lines(Canvas *canvas, int width, int height, DrawLine draw_line) {
    const float c_x = width / 2.0f;
    const float c_y = height / 2.0f;
    for (int angle = 0; angle < 360; angle += 15) {
        float rad = angle * M_PI / 180.0f;
        float x = c_x + 200.0f * cosf(rad);
        float y = c_y + 200.0f * sinf(rad);
        draw_line(canvas, c_x, c_y, x, y, 1.5f);
    }
}

}  // namespace report

// Largest |ours − report| over the canvas, and how many pixels differ at all.
struct difference {
    double max = 0;
    long differing = 0;
};
difference compare(const canvas_t &ours, const report::canvas &theirs) {
    difference d;
    for (std::size_t i = 0; i < theirs.data.size(); ++i) {
        const double e = std::fabs(double(ours.data[i]) - double(theirs.data[i]));
        d.max = std::max(d.max, e);
        d.differing += e != 0.0;
    }
    return d;
}

double ink(const report::canvas &c) {
    double s = 0;
    for (float v : c.data) s += v;
    return s;
}

}  // namespace

TEST(a_splat_at_an_integer_point_lands_wholly_on_that_pixel) {
    tiny3d::canvas_ptr c(create_canvas(8, 8));
    report::canvas r(8, 8);
    set_pixel_f(c.get(), 3, 3, 1);
    report::set_pixel_f(&r, 3, 3, 1);
    CHECK_EQ(c->pixels[3][3], 1.0f);
    CHECK_EQ(r.pixels()[3][3], 1.0f);
    double sum = 0;
    for (int i = 0; i < 64; ++i) sum += c->data[i];
    CHECK_EQ(sum, 1.0);
    // Half-way between two centres: split evenly.
    set_pixel_f(c.get(), 5.5f, 1, 0.5f);
    CHECK_EQ(c->pixels[1][5], 0.25f);
    CHECK_EQ(c->pixels[1][6], 0.25f);
}

TEST(random_splats_equal_the_reports_bit_for_bit) {
    constexpr int W = 37, H = 23;
    std::mt19937 rng(18);
    std::uniform_real_distribution<float> ux(-3.0f, W + 3.0f), uy(-3.0f, H + 3.0f), ui(0.0f, 0.6f);
    for (int round = 0; round < 40; ++round) {
        tiny3d::canvas_ptr c(create_canvas(W, H));
        report::canvas r(W, H);
        for (int i = 0; i < 200; ++i) {  // 8,000 splats in all, overlapping, some clamped
            float x = ux(rng), y = uy(rng);
            if (i % 7 == 0) x = std::round(x);  // integers and exact halves too
            if (i % 11 == 0) y = std::round(y) + 0.5f;
            const float v = ui(rng);
            set_pixel_f(c.get(), x, y, v);
            report::set_pixel_f(&r, x, y, v);
        }
        const difference d = compare(*c, r);
        CHECK_EQ(d.differing, 0L);
        CHECK(ink(r) > 10.0);
    }
}

TEST(the_reports_clock_equals_the_reports_bit_for_bit) {
    constexpr int SIZE = 512;  // the report's canvas
    tiny3d::canvas_ptr c(create_canvas(SIZE, SIZE));
    report::canvas r(SIZE, SIZE);
    report::clock_lines(c.get(), SIZE, SIZE, [](canvas_t *k, float a, float b, float p, float q, float t) {
        draw_line_f(k, a, b, p, q, t);
    });
    report::clock_lines(&r, SIZE, SIZE, report::draw_line_f);
    const difference d = compare(*c, r);
    CHECK_EQ(d.differing, 0L);
    CHECK_EQ(d.max, 0.0);
    CHECK(ink(r) > 24 * 200 * 2.0);  // 24 spokes of 200 px, ≥ 2 px of ink per px of length
    // The centre pixel (256, 256) is where every spoke starts: full.
    CHECK_EQ(c->pixels[256][256], 1.0f);
}

// The clock demo's clock_lines.pgm is the report's clock_lines.pgm: the transcription's
// image, written as 8-bit round(v · 255), byte for byte (build/demo/clock, as make test
// builds the demos first).
TEST(the_clock_demo_writes_the_reports_image) {
    using namespace program_runner;
    const std::string program = demo_path("clock");
    CHECK_MSG(fs::exists(program), program + " is not built (make test builds the demos first)");
    if (!fs::exists(program)) return;
    temp_dir out, logs;
    const run_result r = run(program, {"--out", out.path.string()}, logs.path);
    CHECK_MSG(r.exit_code == 0, "clock failed: " + r.err);
    const pgm_image img = parse_pgm(file_bytes(out.path / "clock_lines.pgm"));
    CHECK_EQ(img.width, 512);
    CHECK_EQ(img.height, 512);
    if (img.width != 512 || img.height != 512) return;
    report::canvas expected(512, 512);
    report::clock_lines(&expected, 512, 512, report::draw_line_f);
    long differing = 0;
    for (std::size_t i = 0; i < expected.data.size(); ++i) {
        const float v = expected.data[i];  // 0..1: the report clamps at 1, nothing is negative
        differing += img.pixels[i] != (unsigned char)std::lround(v * 255.0f);
    }
    CHECK_EQ(differing, 0L);
    // The exact-coverage image shows the same spokes on the same pixels: its ink centroid
    // is the canvas centre (256.5, 256.5 in the library's coordinates = pixel 256's centre).
    const pgm_image fast = parse_pgm(file_bytes(out.path / "clock_lines_fast.pgm"));
    CHECK_EQ(fast.width, 512);
    if (fast.width != 512) return;
    double sum = 0, sx = 0, sy = 0;
    for (int y = 0; y < 512; ++y)
        for (int x = 0; x < 512; ++x) sum += fast.at(x, y), sx += fast.at(x, y) * (x + 0.5), sy += fast.at(x, y) * (y + 0.5);
    CHECK_NEAR(sx / sum, 256.5, 0.02);
    CHECK_NEAR(sy / sum, 256.5, 0.02);
}

TEST(random_lines_inside_the_canvas_equal_the_reports_bit_for_bit) {
    constexpr int W = 64, H = 48;
    std::mt19937 rng(180);
    std::uniform_real_distribution<float> ux(0.0f, W - 1.0f), uy(0.0f, H - 1.0f), ut(0.3f, 3.5f);
    long lines = 0;
    for (int round = 0; round < 500; ++round) {
        tiny3d::canvas_ptr c(create_canvas(W, H));
        report::canvas r(W, H);
        for (int i = 0; i < 6; ++i, ++lines) {  // 3,000 lines: thin, thick, short, degenerate
            const float x0 = ux(rng), y0 = uy(rng);
            float x1 = ux(rng), y1 = uy(rng);
            if (i == 5) x1 = x0, y1 = y0;                          // a point
            if (i == 4) x1 = x0 + (x1 - x0) * 0.05f, y1 = y0 + 0.3f;  // a very short one
            const float t = i == 3 ? 1.0f + 0.25f * float(round % 4) : ut(rng);
            draw_line_f(c.get(), x0, y0, x1, y1, t);
            report::draw_line_f(&r, x0, y0, x1, y1, t);
        }
        const difference d = compare(*c, r);
        CHECK_EQ(d.differing, 0L);
    }
    CHECK_EQ(lines, 3000L);
}

// A line that leaves the canvas is clipped first and its samples on the report's lattice
// computed in double; each sample may move by an ulp of its coordinate (~4e-6 px at 60),
// moving a splat weight by about as much (measured: at most 1.6e-5 over these 1,000 lines).
TEST(random_lines_across_the_border_equal_the_reports_to_float_rounding) {
    constexpr int W = 40, H = 30;
    std::mt19937 rng(1800);
    std::uniform_real_distribution<float> ux(-25.0f, W + 25.0f), uy(-25.0f, H + 25.0f), ut(0.6f, 3.0f);
    double worst = 0;
    for (int round = 0; round < 1000; ++round) {
        tiny3d::canvas_ptr c(create_canvas(W, H));
        report::canvas r(W, H);
        const float x0 = ux(rng), y0 = uy(rng), x1 = ux(rng), y1 = uy(rng), t = ut(rng);
        draw_line_f(c.get(), x0, y0, x1, y1, t);
        report::draw_line_f(&r, x0, y0, x1, y1, t);
        worst = std::max(worst, compare(*c, r).max);
    }
    CHECK_NEAR(worst, 0.0, 1e-4);
}

TEST(project_vertex_equals_the_reports) {
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f), angle(-3.0f, 3.0f), depth(-9.0f, -1.5f);
    const mat4_t proj = mat4_frustum_asymmetric(-1.2f, 0.8f, -0.7f, 1.1f, 1.0f, 20.0f);
    double worst = 0;
    int behind = 0;
    for (int i = 0; i < 2000; ++i) {
        const mat4_t model = mat4_multiply(mat4_translate(u(rng), u(rng), depth(rng)),
                                           mat4_rotate_xyz(angle(rng), angle(rng), angle(rng)));
        const vec3_t v{u(rng), u(rng), u(rng)};
        const int w = 64 + i % 300, h = 48 + i % 170;
        float x = 0, y = 0, rx = 0, ry = 0;
        const int ours = project_vertex(v, model, proj, w, h, &x, &y);
        const int theirs = report::project_vertex(v, model, proj, w, h, &rx, &ry);
        // The one deliberate difference: a point behind the camera (w < 0), which the
        // report mirrors onto the screen, is refused.
        const float clip_w = report::mat4_mul_vec4(proj, report::mat4_mul_vec4(model, {v.x, v.y, v.z, 1.0f})).w;
        CHECK_EQ(ours, clip_w > 0.0f ? theirs : 0);
        behind += clip_w < 0.0f;
        if (ours) worst = std::max({worst, double(std::fabs(x - rx)), double(std::fabs(y - ry))});
    }
    CHECK_EQ(worst, 0.0);  // the same float operations in the same order
    CHECK(behind > 0 && behind < 200);
    // NDC ±1 → the first and last pixel centres.
    float x, y;
    const mat4_t id = mat4_identity(), square = mat4_frustum_asymmetric(-1, 1, -1, 1, 1, 10);
    CHECK_EQ(project_vertex({-1, 1, -1}, id, square, 100, 50, &x, &y), 1);
    CHECK_EQ(x, 0.0f);
    CHECK_EQ(y, 0.0f);
    CHECK_EQ(project_vertex({1, -1, -1}, id, square, 100, 50, &x, &y), 1);
    CHECK_EQ(x, 99.0f);
    CHECK_EQ(y, 49.0f);
}

TEST(the_seven_argument_render_wireframe_draws_the_reports_soccer_ball) {
    vec3_t *vertices = nullptr;
    int (*edges)[2] = nullptr;
    int vertex_count = 0, edge_count = 0;
    CHECK_EQ(generate_soccer_ball(&vertices, &vertex_count, &edges, &edge_count), 1);
    CHECK_EQ(vertex_count, 60);
    CHECK_EQ(edge_count, 90);
    const mat4_t proj = mat4_frustum_asymmetric(-1, 1, -1, 1, 1, 10);
    for (int frame = 0; frame < 6; ++frame) {
        const mat4_t model = mat4_multiply(mat4_translate(0, 0, -3.5f), mat4_rotate_xyz(0.35f, 0.4f * float(frame), 0));
        tiny3d::canvas_ptr c(create_canvas(160, 120));
        report::canvas r(160, 120);
        render_wireframe(c.get(), vertices, vertex_count, edges, edge_count, model, proj);
        report::render_wireframe(&r, vertices, vertex_count, edges, edge_count, model, proj);
        CHECK_EQ(compare(*c, r).differing, 0L);
        CHECK(ink(r) > 500.0);
    }
    free_soccer_ball(vertices, edges);
}
