// raster_rules_test.cpp — the fill rule and the depth compare on every raster path, against
// hand-computed pixel sets.
//
// Paths: the render context's fast setup (setup_fast_triangle) drawn by the SSE2 narrow
// loop (≤ 16 px wide), the SSE2 span loop and its lane-by-lane tail at the canvas' right
// edge; the context's clipped triangles (triangle_setup after Sutherland–Hodgman against the
// guard band); the context's per-pixel path (Phong); the public fill_triangle (fast, and
// the 64-bit scalar loop for triangles spanning ≥ 2040 px), rasterize_triangle and the
// scan-line fill (depth only: it has its own centre rule). The context runs with 1, 2 and 3
// threads on a 64 × 128 canvas (four 32-row bands, so shapes straddle band boundaries).
// In a build without SSE2 the same tests check the portable loops.
//
// Geometry is given in pixels and mapped by an exact matrix (powers of two), so every edge
// lies exactly where written: all edges below pass through pixel centres (x + 0.5, y + 0.5).
// The top-left rule: a centre on a top edge (horizontal, inside below it) or a left edge is
// inside, on a right or bottom edge outside. So the square [2.5, 5.5]² covers columns and
// rows 2..4 (the mutation that flips the rule gives 3..5).
//
// Depth: the same triangle drawn twice gives bit-identical depths; so do coplanar meshes at
// constant depth triangulated differently. `less` keeps the first colour, `less_equal` (and
// equal, greater_equal) takes the second.
#include <array>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "harness.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "pipeline.h"
#include "raster.h"
#include "raster_test_util.h"

using namespace tiny3d;
using raster_test::constant_light;

namespace {

constexpr int W = 64, H = 128;

using pixel = std::pair<int, int>;  // (x, y)
using pixel_set = std::set<pixel>;
struct tri {
    float x[3], y[3];
};
using shape = std::vector<tri>;

// Axis-aligned rectangle [x0, x1] × [y0, y1] as two triangles (split along either diagonal).
shape rect(float x0, float y0, float x1, float y1, bool other_diagonal = false) {
    if (other_diagonal) return {{{x0, x1, x1}, {y0, y0, y1}}, {{x0, x1, x0}, {y0, y1, y1}}};
    return {{{x0, x1, x0}, {y0, y0, y1}}, {{x1, x1, x0}, {y0, y1, y1}}};
}

// Columns [c0, c1] × rows [r0, r1], clamped to the canvas.
pixel_set block(int c0, int r0, int c1, int r1) {
    pixel_set s;
    for (int y = std::max(r0, 0); y <= std::min(r1, H - 1); ++y)
        for (int x = std::max(c0, 0); x <= std::min(c1, W - 1); ++x) s.insert({x, y});
    return s;
}

pixel_set where(int c0, int r0, int c1, int r1, bool (*keep)(int, int)) {
    pixel_set s;
    for (const pixel &p : block(c0, r0, c1, r1))
        if (keep(p.first, p.second)) s.insert(p);
    return s;
}

struct rule_case {
    const char *name;
    shape geometry;
    pixel_set expected;
};

// The cases, each hand-computed from the rule above.
std::vector<rule_case> fill_cases() {
    return {
        // Narrow: horizontal and vertical edges through centres.
        {"square", rect(2.5f, 2.5f, 5.5f, 5.5f), block(2, 2, 4, 4)},
        // The triangle below-left of the diagonal x + y = 9 (a right edge: centres on it out)
        // and the one above-right (a left edge: centres on it in); together the 4 × 4 square.
        {"lower triangle", {{{2.5f, 6.5f, 2.5f}, {2.5f, 2.5f, 6.5f}}},
         where(2, 2, 5, 5, [](int x, int y) { return x + y <= 7; })},
        {"upper triangle", {{{6.5f, 6.5f, 2.5f}, {2.5f, 6.5f, 6.5f}}},
         where(2, 2, 5, 5, [](int x, int y) { return x + y >= 8; })},
        // Span loop, across the band boundary between rows 31 and 32.
        {"wide rectangle over a band boundary", rect(1.5f, 29.5f, 41.5f, 34.5f), block(1, 29, 40, 33)},
        // Span loop ending at the canvas' right edge: the last group lane by lane.
        {"rectangle through the right edge", rect(53.5f, 60.5f, 70.0f, 66.5f), block(53, 60, 63, 65)},
        // A tall thin one over three bands: a vertical edge through centres on each side.
        {"tall column", rect(10.5f, 20.5f, 12.5f, 100.5f), block(10, 20, 11, 99)},
    };
}

// Shapes reaching far beyond the guard band on the left (x = −1000 px is −32 in NDC, the
// band is ±4): the context clips them, then sets up with triangle_setup.
std::vector<rule_case> clipped_cases() {
    return {
        {"clipped rectangle", rect(-1000.0f, 2.5f, 5.5f, 5.5f), block(0, 2, 4, 4)},
        {"clipped rectangle over a band boundary", rect(-1000.0f, 29.5f, 20.5f, 64.5f), block(0, 29, 19, 63)},
        // Right edge on the diagonal x + y = 11 through centres (out), top edge y = 2.5 (in).
        {"clipped triangle", {{{-1000.0f, 8.5f, -1000.0f}, {2.5f, 2.5f, 1010.5f}}},
         where(0, 2, W - 1, H - 1, [](int x, int y) { return x + y <= 9; })},
    };
}

// Pixel units → NDC, exactly (W and H are powers of two); z passes through.
mat4_t pixels_to_ndc() {
    mat4_t m = mat4_identity();
    m.m[0] = 2.0f / W;
    m.m[12] = -1.0f;
    m.m[5] = -2.0f / H;
    m.m[13] = 1.0f;
    return m;
}

raster_mesh to_mesh(const shape &s, float z) {
    raster_mesh m;
    for (const tri &t : s) {
        const std::uint32_t base = static_cast<std::uint32_t>(m.positions.size());
        for (int k = 0; k < 3; ++k) {
            m.positions.push_back({t.x[k], t.y[k], z});
            m.normals.push_back({0, 0, 1});
            m.uvs.push_back({0, 0});
        }
        m.triangles.push_back({base, base + 1, base + 2});
    }
    const bounding_sphere b = bounding_sphere_of(m.positions);
    m.bound_center = b.center;
    m.bound_radius = b.radius;
    return m;
}

enum class context_path { fast, phong };

// Draws each (shape, depth, intensity) in order with the render context.
struct layer {
    const shape *geometry;
    float z, intensity;
    depth_func test = depth_func::less;
};
canvas_ptr draw_context(const std::vector<layer> &layers, int threads, context_path path) {
    canvas_ptr c = make_canvas(W, H).value();
    render_context ctx(threads);
    CHECK(ctx.begin_frame(*c, 0.0f).ok());
    std::vector<light_rig> rigs;
    rigs.reserve(layers.size());
    for (const layer &l : layers) {
        const raster_mesh m = to_mesh(*l.geometry, l.z);
        rigs.push_back(constant_light(l.intensity));
        draw_params p;
        p.model = mat4_identity();
        p.view_projection = pixels_to_ndc();
        p.lights = rigs.back();
        p.shade = path == context_path::phong ? shading::phong : shading::flat;
        p.cull = cull_mode::none;
        p.depth = l.test;
        ctx.draw(m, p);
    }
    ctx.end_frame();
    return c;
}

pixel_set pixels_equal_to(const canvas_t &c, float value) {
    pixel_set s;
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x)
            if (c.pixels[y][x] == value) s.insert({x, y});
    return s;
}

// The first pixel where the sets differ, for the message.
std::string first_difference(const pixel_set &got, const pixel_set &want) {
    for (const pixel &p : got)
        if (!want.count(p)) return "extra pixel (" + std::to_string(p.first) + ", " + std::to_string(p.second) + ")";
    for (const pixel &p : want)
        if (!got.count(p)) return "missing pixel (" + std::to_string(p.first) + ", " + std::to_string(p.second) + ")";
    return "same";
}

void check_set(const pixel_set &got, const pixel_set &want, const std::string &what) {
    CHECK_MSG(got == want, what + ": " + first_difference(got, want) + " (" + std::to_string(got.size()) + " vs " +
                               std::to_string(want.size()) + " pixels)");
}

const char *path_name(context_path p) { return p == context_path::fast ? "fast" : "phong"; }

// The public fill_triangle with depth, each layer in order.
canvas_ptr draw_fill_triangle(const std::vector<layer> &layers, bool scanline = false) {
    canvas_ptr c = make_canvas(W, H).value();
    zbuffer depth;
    CHECK(depth.resize(W, H).ok());
    depth.clear(1.0f);
    for (const layer &l : layers)
        for (const tri &t : *l.geometry) {
            const screen_vertex v[3] = {{t.x[0], t.y[0], l.z, 1.0f}, {t.x[1], t.y[1], l.z, 1.0f}, {t.x[2], t.y[2], l.z, 1.0f}};
            const float in[3] = {l.intensity, l.intensity, l.intensity};
            if (scanline) fill_triangle_scanline(*c, &depth, v, in, l.test);
            else fill_triangle(*c, &depth, v, in, l.test, true, {0, 0, W, H});
        }
    return c;
}

// A rectangle reaching 3000 px off the canvas: its snapped box spans ≥ 2040 px, so
// fill_triangle takes the 64-bit scalar loop.
rule_case wide_case() { return {"wide (scalar 64-bit) rectangle", rect(-3000.0f, 30.5f, 20.5f, 33.5f), block(0, 30, 19, 32)}; }

// What the second of two equal-depth draws leaves: the first (0.25) with `less` against
// the cleared depth 1, the second (0.75) with the function tested.
struct depth_case {
    depth_func test;
    const char *name;
    float expected;
};
const depth_case kDepthCases[] = {
    {depth_func::less, "less", 0.25f},     {depth_func::less_equal, "less_equal", 0.75f},
    {depth_func::equal, "equal", 0.75f},   {depth_func::greater_equal, "greater_equal", 0.75f},
    {depth_func::greater, "greater", 0.25f}, {depth_func::not_equal, "not_equal", 0.25f},
    {depth_func::always, "always", 0.75f}, {depth_func::never, "never", 0.25f},
};

}  // namespace

namespace {

// Each case drawn by the render context (fast and per-pixel paths, 1, 2 and 3 threads)
// covers exactly its expected pixels; with `rest_blank`, every other pixel keeps the clear 0.
void check_cases_on_the_context(const std::vector<rule_case> &cases, bool rest_blank) {
    for (int threads : {1, 2, 3})
        for (context_path path : {context_path::fast, context_path::phong})
            for (const rule_case &c : cases) {
                const canvas_ptr img = draw_context({{&c.geometry, 0.0f, 0.5f}}, threads, path);
                check_set(pixels_equal_to(*img, 0.5f), c.expected,
                          std::string(c.name) + ", " + path_name(path) + ", " + std::to_string(threads) + " threads");
                if (rest_blank) CHECK_EQ(pixels_equal_to(*img, 0.0f).size() + c.expected.size(), std::size_t(W * H));
            }
}

}  // namespace

TEST(top_left_rule_on_the_contexts_fast_and_per_pixel_paths_with_1_2_3_threads) {
    check_cases_on_the_context(fill_cases(), true);
}

TEST(top_left_rule_on_the_contexts_clipped_path_with_1_2_3_threads) {
    check_cases_on_the_context(clipped_cases(), false);
}

TEST(top_left_rule_of_fill_triangle_and_rasterize_triangle) {
    std::vector<rule_case> cases = fill_cases();
    cases.push_back(wide_case());
    for (const rule_case &c : cases) {
        const canvas_ptr img = draw_fill_triangle({{&c.geometry, 0.5f, 0.5f}});
        check_set(pixels_equal_to(*img, 0.5f), c.expected, std::string("fill_triangle: ") + c.name);
        pixel_set hits;
        std::size_t calls = 0;
        for (const tri &t : c.geometry)
            rasterize_triangle({t.x[0], t.y[0], 0.5f, 1.0f}, {t.x[1], t.y[1], 0.5f, 1.0f}, {t.x[2], t.y[2], 0.5f, 1.0f},
                               {0, 0, W, H}, [&](int x, int y, float, float, float) {
                                   hits.insert({x, y});
                                   ++calls;
                               });
        check_set(hits, c.expected, std::string("rasterize_triangle: ") + c.name);
        CHECK_EQ(calls, c.expected.size());  // shared edges: no pixel twice
    }
}

TEST(equal_depths_same_triangle_twice_on_every_path) {
    std::vector<rule_case> cases = fill_cases();
    for (const rule_case &c : clipped_cases()) cases.push_back(c);
    for (const depth_case &d : kDepthCases)
        for (const rule_case &c : cases) {
            const std::vector<layer> twice = {{&c.geometry, 0.25f, 0.25f}, {&c.geometry, 0.25f, 0.75f, d.test}};
            for (int threads : {1, 2, 3})
                for (context_path path : {context_path::fast, context_path::phong}) {
                    const canvas_ptr img = draw_context(twice, threads, path);
                    check_set(pixels_equal_to(*img, d.expected), c.expected,
                              std::string(d.name) + ", " + c.name + ", " + path_name(path) + ", " +
                                  std::to_string(threads) + " threads");
                    CHECK_EQ(pixels_equal_to(*img, 0.0f).size(), std::size_t(W * H) - c.expected.size());
                }
        }
}

TEST(equal_depths_in_fill_triangle_its_wide_loop_and_the_scanline_fill) {
    std::vector<rule_case> cases = fill_cases();
    cases.push_back(wide_case());
    for (const depth_case &d : kDepthCases)
        for (const rule_case &c : cases) {
            const std::vector<layer> twice = {{&c.geometry, 0.25f, 0.25f}, {&c.geometry, 0.25f, 0.75f, d.test}};
            const canvas_ptr img = draw_fill_triangle(twice);
            check_set(pixels_equal_to(*img, d.expected), c.expected, std::string("fill_triangle ") + d.name + ", " + c.name);
            // The scan-line fill has its own centre rule (both ends of a span in) and draws
            // shared edges twice, so only its depth compare is checked, on single triangles:
            // every pixel the first draw wrote follows the depth function.
            if (c.geometry.size() != 1) continue;
            const pixel_set drawn = pixels_equal_to(*draw_fill_triangle({twice[0]}, true), 0.25f);
            CHECK(drawn.size() >= c.expected.size());
            check_set(pixels_equal_to(*draw_fill_triangle(twice, true), d.expected), drawn,
                      std::string("scanline ") + d.name + ", " + c.name);
        }
}

TEST(coplanar_meshes_at_equal_depth_with_1_2_3_threads) {
    // The same square triangulated along either diagonal, at constant depth: every pixel
    // centre gets exactly the same depth from both (a constant plane), whatever the split.
    const shape first = rect(2.5f, 20.5f, 50.5f, 70.5f), second = rect(2.5f, 20.5f, 50.5f, 70.5f, true);
    const pixel_set covered = block(2, 20, 49, 69);
    for (int threads : {1, 2, 3})
        for (context_path path : {context_path::fast, context_path::phong})
            for (const depth_case &d : kDepthCases) {
                const canvas_ptr img =
                    draw_context({{&first, -0.5f, 0.25f}, {&second, -0.5f, 0.75f, d.test}}, threads, path);
                check_set(pixels_equal_to(*img, d.expected), covered,
                          std::string("coplanar ") + d.name + ", " + path_name(path) + ", " + std::to_string(threads) +
                              " threads");
            }
}

TEST(a_nearer_layer_wins_and_a_farther_one_loses_under_less) {
    // Not only ties: the depth compare must still order distinct depths on every path.
    const shape near_square = rect(2.5f, 28.5f, 30.5f, 40.5f), far_square = rect(10.5f, 30.5f, 40.5f, 36.5f);
    for (int threads : {1, 2, 3})
        for (context_path path : {context_path::fast, context_path::phong}) {
            const canvas_ptr img =
                draw_context({{&near_square, -0.5f, 0.25f}, {&far_square, 0.5f, 0.75f}}, threads, path);
            check_set(pixels_equal_to(*img, 0.25f), block(2, 28, 29, 39), "near first");
            check_set(pixels_equal_to(*img, 0.75f), block(30, 30, 39, 35), "far part outside the near square");
        }
}

TEST(segment_clipping_against_each_side_plane_cuts_where_that_coordinate_reaches_w) {
    // From the centre (0, 0, 0, 1) to a point beyond one side plane only; the cut is where
    // that coordinate alone reaches ±w: t = 1/3 for 3, t = 1/4 for −4 (the others stay 0.5,
    // so a plane testing the wrong coordinate would not cut at all).
    struct side {
        vec4_t end;
        double t1;
    } sides[] = {{{3.0f, 0.5f, 0.0f, 1.0f}, 1.0 / 3}, {{-4.0f, 0.5f, 0.0f, 1.0f}, 0.25},
                 {{0.5f, 3.0f, 0.0f, 1.0f}, 1.0 / 3}, {{0.5f, -4.0f, 0.0f, 1.0f}, 0.25},
                 {{0.5f, 0.5f, 3.0f, 1.0f}, 1.0 / 3}, {{0.5f, 0.5f, -4.0f, 1.0f}, 0.25}};
    for (const side &s : sides) {
        const segment_clip c = clip_segment({0.0f, 0.0f, 0.0f, 1.0f}, s.end);
        CHECK(c.visible);
        CHECK_NEAR(c.t0, 0.0, 1e-12);
        CHECK_NEAR(c.t1, s.t1, 1e-9);
    }
}
