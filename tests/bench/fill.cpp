// fill.cpp — filled-triangle costs against accuracy:
//  * fill rate: 16 full-screen opaque quads (32 triangles) at 1024², each nearer than the
//    last, depth LESS — half-space (SSE2) fast path, the faithful scan-line fill, and the
//    exact 64-bit visitor; ns per pixel (Gpixel/s printed);
//  * triangle fill: 2,000 seeded random triangles on 512², scan-line vs half-space vs the
//    double-precision per-pixel ray cast (reference: centre inside the unsnapped triangle);
//    error = fraction of covered pixels whose coverage differs from the reference;
//  * texture mapping: a slanted textured quad, affine vs perspective-correct, error =
//    mean / max |u − analytic u| at pixel centres;
//  * ply_render: the lab's per-pixel ray cast vs the fast path on the 3,696-triangle torus
//    knot, file read included; error = fraction of differing pixels.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "../raster_test_util.h"
#include "common/bench.h"
#include "canvas.h"
#include "lab.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"

using namespace tiny3d;

namespace {

constexpr int FILL_SIDE = 1024, FILL_LAYERS = 16;
constexpr int TRI_SIDE = 512, TRI_COUNT = 2000;

screen_vertex sv(float x, float y, float z) { return {x, y, z, 1.0f}; }

// Fraction of pixels where (a > 0) differs from (b > 0), over pixels covered in b.
std::pair<double, double> coverage_error(const canvas_t &a, const canvas_t &b) {
    long diff = 0, covered = 0;
    for (long i = 0; i < static_cast<long>(a.width) * a.height; ++i) {
        covered += b.data[i] > 0;
        diff += (a.data[i] > 0) != (b.data[i] > 0);
    }
    const double f = covered ? static_cast<double>(diff) / covered : 0.0;
    return {f, f};
}

// Reference coverage: pixel centre inside the unsnapped triangle, in double, ties counted in.
void raycast_fill(canvas_t &c, const screen_vertex v[3]) {
    const double x0 = v[0].x, y0 = v[0].y, x1 = v[1].x, y1 = v[1].y, x2 = v[2].x, y2 = v[2].y;
    const double area = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0);
    if (area == 0) return;
    const int bx0 = std::max(0, static_cast<int>(std::floor(std::min({x0, x1, x2}))));
    const int bx1 = std::min(c.width - 1, static_cast<int>(std::ceil(std::max({x0, x1, x2}))));
    const int by0 = std::max(0, static_cast<int>(std::floor(std::min({y0, y1, y2}))));
    const int by1 = std::min(c.height - 1, static_cast<int>(std::ceil(std::max({y0, y1, y2}))));
    for (int y = by0; y <= by1; ++y)
        for (int x = bx0; x <= bx1; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            const double e0 = ((x2 - x1) * (py - y1) - (y2 - y1) * (px - x1)) * area;
            const double e1 = ((x0 - x2) * (py - y2) - (y0 - y2) * (px - x2)) * area;
            const double e2 = ((x1 - x0) * (py - y0) - (y1 - y0) * (px - x0)) * area;
            if (e0 >= 0 && e1 >= 0 && e2 >= 0) c.pixels[y][x] = 1.0f;
        }
}

}  // namespace

int main(int argc, char **argv) {
    const bench::options o = bench::parse_options(argc, argv);
    const int repeats = o.quick ? 3 : 15;
    std::vector<bench::row> rows;
    const float ones[3] = {1, 1, 1};

    // ---- fill rate -------------------------------------------------------------------
    {
        canvas_ptr c = make_canvas(FILL_SIDE, FILL_SIDE).value();
        zbuffer z;
        if (!z.resize(FILL_SIDE, FILL_SIDE).ok()) return 1;
        const double pixels = static_cast<double>(FILL_LAYERS) * FILL_SIDE * FILL_SIDE;
        const float s = FILL_SIDE;
        auto layers = [&](auto fill_one) {
            z.clear(1.0f);
            for (int k = 0; k < FILL_LAYERS; ++k) {
                const float depth = 0.9f - 0.05f * k, shade = 0.05f + 0.05f * k;
                const float in[3] = {shade, shade, shade};
                const screen_vertex a[3] = {sv(0, 0, depth), sv(s, 0, depth), sv(s, s, depth)};
                const screen_vertex b[3] = {sv(0, 0, depth), sv(s, s, depth), sv(0, s, depth)};
                fill_one(a, in);
                fill_one(b, in);
            }
        };
        auto fast = [&](const screen_vertex *v, const float *in) {
            fill_triangle(*c, &z, v, in, depth_func::less, true, {0, 0, FILL_SIDE, FILL_SIDE});
        };
        auto scan = [&](const screen_vertex *v, const float *in) { fill_triangle_scanline(*c, &z, v, in, depth_func::less); };
        auto exact = [&](const screen_vertex *v, const float *in) {
            rasterize_triangle(v[0], v[1], v[2], {0, 0, FILL_SIDE, FILL_SIDE}, [&](int x, int y, float, float, float) {
                float &d = z.row(y)[x];
                if (v[0].z < d) d = v[0].z, c->pixels[y][x] = in[0];
            });
        };
        canvas_ptr ref = make_canvas(FILL_SIDE, FILL_SIDE).value();
        const bench::timing te = bench::measure_ns(repeats, pixels, [&] { layers(exact); });
        std::copy(c->data, c->data + FILL_SIDE * FILL_SIDE, ref->data);
        auto image_error = [&] {
            double worst = 0, sum = 0;
            for (int i = 0; i < FILL_SIDE * FILL_SIDE; ++i) {
                const double d = std::fabs(c->data[i] - ref->data[i]);
                worst = std::max(worst, d), sum += d;
            }
            return std::pair<double, double>{sum / (FILL_SIDE * FILL_SIDE), worst};
        };
        const bench::timing ts = bench::measure_ns(repeats, pixels, [&] { layers(scan); });
        const auto es = image_error();
        const bench::timing tf = bench::measure_ns(repeats, pixels, [&] { layers(fast); });
        const auto ef = image_error();
        rows.push_back({"fill", "16 layers scan-line (edge walking)", "faithful", "ns/px", ts, es.first, es.second,
                        "abs intensity", ""});
        rows.push_back({"fill", "16 layers exact 64-bit visitor", "reference", "ns/px", te, 0, 0, "abs intensity", ""});
        rows.push_back({"fill", "16 layers half-space SSE2", "fast", "ns/px", tf, ef.first, ef.second, "abs intensity",
                        std::to_string(1.0 / tf.median) + " Gpixel/s (median)"});
        std::printf("fill rate, 16 full-screen layers with depth LESS, fill_triangle: %.2f Gpixel/s (median), %.2f (best)\n",
                    1.0 / tf.median, 1.0 / tf.min);
        // The same 16 layers through the render context: 32-row bands stay in cache while
        // every layer is drawn into them. Quads given in clip space (identity transform),
        // slightly larger than the screen, each nearer than the last.
        raster_mesh layers_mesh;
        for (int k = 0; k < FILL_LAYERS; ++k) {
            const float z = 0.8f - 0.1f * k;
            const std::uint32_t i = static_cast<std::uint32_t>(layers_mesh.positions.size());
            layers_mesh.positions.insert(layers_mesh.positions.end(), {{-1.1f, -1.1f, z}, {1.1f, -1.1f, z}, {1.1f, 1.1f, z}, {-1.1f, 1.1f, z}});
            layers_mesh.triangles.push_back({i, i + 1, i + 2});
            layers_mesh.triangles.push_back({i, i + 2, i + 3});
        }
        layers_mesh.normals.assign(layers_mesh.positions.size(), {0, 0, 1});
        layers_mesh.uvs.assign(layers_mesh.positions.size(), {0, 0});
        layers_mesh.bound_radius = 2.0f;
        for (int threads : {1, 2}) {
            render_context ctx(threads);
            draw_params p;
            p.model = mat4_identity();
            p.view_projection = mat4_identity();
            p.lights = make_light_rig(std::span<const light_t>(), 0.5f).value();
            p.shade = shading::flat;
            const bench::timing tc = bench::measure_ns(repeats, pixels, [&] {
                if (!ctx.begin_frame(*c).ok()) return;
                ctx.draw(layers_mesh, p);
                ctx.end_frame();
            });
            rows.push_back({"fill", "16 layers render_context banded, " + std::to_string(threads) + " thread(s)", "fast",
                            "ns/px", tc, NAN, NAN, "abs intensity",
                            std::to_string(1.0 / tc.median) + " Gpixel/s (median), incl. clear"});
            std::printf("fill rate, 16 layers through render_context, %d thread(s): %.2f Gpixel/s (median), %.2f (best)\n",
                        threads, 1.0 / tc.median, 1.0 / tc.min);
        }
    }

    // ---- random triangles: time vs coverage error ------------------------------------------
    {
        std::mt19937 rng(2024);
        std::uniform_real_distribution<float> centre(0.0f, TRI_SIDE), size(-40.0f, 40.0f);
        std::vector<std::array<screen_vertex, 3>> tris;
        for (int k = 0; k < TRI_COUNT; ++k) {
            const float cx = centre(rng), cy = centre(rng);
            tris.push_back({sv(cx + size(rng), cy + size(rng), 0.5f), sv(cx + size(rng), cy + size(rng), 0.5f),
                            sv(cx + size(rng), cy + size(rng), 0.5f)});
        }
        canvas_ptr ref = make_canvas(TRI_SIDE, TRI_SIDE).value(), c = make_canvas(TRI_SIDE, TRI_SIDE).value();
        // Per-triangle error: each drawn alone on a cleared canvas would cost a clear per
        // triangle; instead draw all and compare the union plus per-triangle counts below.
        const bench::timing tr = bench::measure_ns(repeats, TRI_COUNT, [&] {
            canvas_clear(ref.get(), 0);
            for (const auto &t : tris) raycast_fill(*ref, t.data());
        });
        const bench::timing ts = bench::measure_ns(repeats, TRI_COUNT, [&] {
            canvas_clear(c.get(), 0);
            for (const auto &t : tris) fill_triangle_scanline(*c, nullptr, t.data(), ones, depth_func::always);
        });
        const auto es = coverage_error(*c, *ref);
        const bench::timing tf = bench::measure_ns(repeats, TRI_COUNT, [&] {
            canvas_clear(c.get(), 0);
            for (const auto &t : tris) fill_triangle(*c, nullptr, t.data(), ones, depth_func::always, false, {0, 0, TRI_SIDE, TRI_SIDE});
        });
        const auto ef = coverage_error(*c, *ref);
        rows.push_back({"fill", "triangles scan-line (edge walking)", "faithful", "ns/tri", ts, es.first, es.second,
                        "coverage fraction", "incl. canvas clear"});
        rows.push_back({"fill", "triangles raycast double", "reference", "ns/tri", tr, 0, 0, "coverage fraction",
                        "incl. canvas clear"});
        rows.push_back({"fill", "triangles half-space SSE2", "fast", "ns/tri", tf, ef.first, ef.second, "coverage fraction",
                        "1/16 px snapping + top-left ties"});
    }

    // ---- texture mapping: affine vs perspective-correct -------------------------------------
    {
        constexpr int S = 512;
        const raster_test::slanted_quad quad;
        canvas_ptr c = make_canvas(S, S).value();
        render_context ctx(1);
        for (bool perspective : {false, true}) {
            const draw_params p = quad.params(perspective);
            long covered = 0;
            const bench::timing t =
                bench::measure_ns(repeats, 1.0, [&] { (void)raster_test::draw_frame(ctx, *c, quad.mesh, p); });
            double sum = 0, worst = 0;
            for (int y = 0; y < S; ++y)
                for (int x = 0; x < S; ++x) {
                    double u;
                    if (!raster_test::slanted_quad::exact_u(x, y, S, 0.98, u)) continue;
                    const double e = std::fabs(c->pixels[y][x] - u);
                    sum += e, worst = std::max(worst, e), ++covered;
                }
            bench::timing per_px = t;
            const double n = static_cast<double>(covered);
            per_px.median /= n, per_px.min /= n, per_px.max /= n;
            rows.push_back({"fill", perspective ? "texture perspective-correct" : "texture affine (screen-space u, v)",
                            perspective ? "fast" : "faithful", "ns/textured px", per_px, sum / n, worst, "abs u", ""});
        }
    }

    // ---- ply_render: raycast vs fast, file read included ----------------------------------------
    {
        const mesh knot = make_torus_knot(2, 3, 154, 12);
        std::string bytes = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(knot.positions.size()) +
                            "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                            std::to_string(knot.face_count()) + "\nproperty list uchar int vertex_indices\nend_header\n";
        for (const vec3_t &p : knot.positions) bytes.append(reinterpret_cast<const char *>(&p), sizeof p);
        for (std::size_t f = 0; f < knot.face_count(); ++f) {
            bytes += static_cast<char>(knot.face_size(f));
            for (std::uint32_t k = knot.face_start[f]; k < knot.face_start[f + 1]; ++k) {
                const std::int32_t i = static_cast<std::int32_t>(knot.indices[k]);
                bytes.append(reinterpret_cast<const char *>(&i), 4);
            }
        }
        const std::string path = o.out_dir + "/fill_torus_knot.ply";
        if (!write_file_atomic(path, bytes.data(), bytes.size()).ok()) return 1;
        lab_image slow, fast;
        auto run = [&](bool use_fast, lab_image &out) {
            result<mesh> m = load_ply(path);
            if (!m) return;
            const lab_camera cam = ply_lab_camera(*m, M_PI / 2, M_PI / 4, -3 * M_PI / 4).value();
            out = use_fast ? render_lab_fast(*m, cam) : raycast_lab(*m, cam);
        };
        const bench::timing tslow = bench::measure_ns(1, 1e6, [&] { run(false, slow); });
        const bench::timing tfast = bench::measure_ns(repeats, 1e6, [&] { run(true, fast); });
        long diff = 0;
        for (std::size_t i = 0; i < slow.pixels.size(); ++i) diff += slow.pixels[i] != fast.pixels[i];
        const double frac = slow.pixels.empty() ? NAN : static_cast<double>(diff) / slow.pixels.size();
        rows.push_back({"fill", "ply_render raycast (lab)", "faithful", "ms/image", tslow, 0, 0, "px fraction",
                        "3,696 tris, 256^2, incl. file read"});
        rows.push_back({"fill", "ply_render fast (projected boxes)", "fast", "ms/image", tfast, frac, frac, "px fraction",
                        "3,696 tris, 256^2, incl. file read"});
        std::remove(path.c_str());
    }
    const int result = bench::report(o, "fill", rows, "Filled triangles: time vs error");
    if (result != 0) return result;
    // One chart per workload (each has its own unit): fill.pgm is the 16 layers.
    return bench::write_workload_charts(o, rows, {
        {"16 layers ", "fill", "Fill, 16 layers: ns per px vs error"},
        {"triangles ", "fill_triangles", "Fill, single triangles: ns per triangle vs coverage error"},
        {"texture ", "fill_texture", "Fill, textured: ns per textured px vs (u, v) error"},
        {"ply_render ", "fill_ply_render", "Fill, ply_render lab: ms per image vs pixel error"},
    });
}
