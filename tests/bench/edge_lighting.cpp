// edge_lighting.cpp — per-edge lighting of the soccer-ball wireframe: the report's
// lambert_intensity (edge direction · light), the corrected model (mean of the adjacent
// faces' normals, with ambient) and the reference (the mean Lambert brightness of the two
// faces the edge borders, in double). Time per edge, error against the reference, and the
// fraction of black edges, over 100 seeded random light directions.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "common/bench.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"

namespace {

constexpr float AMBIENT = 0.1f;
constexpr float LIGHT_INTENSITY = 0.9f;
constexpr int LIGHTS = 100;

struct measured {
    bench::timing time;
    double error_mean, error_max, black_fraction;
};

}  // namespace

int main(int argc, char **argv) {
    const bench::options o = bench::parse_options(argc, argv);
    const int repeats = o.quick ? 3 : 15;
    const tiny3d::mesh ball = tiny3d::make_soccer_ball(1.0f);
    const std::vector<vec3_t> edge_normal = tiny3d::mesh_edge_normals(ball);
    const std::vector<vec3_t> face_normal = tiny3d::mesh_face_normals(ball);
    const tiny3d::edge_adjacency adjacency = tiny3d::mesh_edge_faces(ball);
    const std::size_t edges = ball.edges.size();

    std::mt19937 rng(2026);
    std::normal_distribution<float> gauss;
    std::vector<tiny3d::light_rig> rigs;
    for (int i = 0; i < LIGHTS; ++i) {
        const light_t l = {{gauss(rng), gauss(rng), gauss(rng)}, LIGHT_INTENSITY};
        auto rig = tiny3d::make_light_rig(std::span(&l, 1), AMBIENT);
        if (!rig) {
            std::fprintf(stderr, "edge_lighting: %s\n", rig.message().c_str());
            return 1;
        }
        rigs.push_back(rig.value());
    }

    // Reference per (light, edge): ambient + I · mean over adjacent faces of max(0, n·L), double.
    auto reference = [&](const tiny3d::light_rig &rig, std::size_t e) {
        const vec3_t L = rig.lights[0].direction;
        double sum = 0;
        for (const std::uint32_t *f = adjacency.begin(e); f != adjacency.end(e); ++f) {
            const vec3_t n = face_normal[*f];
            sum += std::max(0.0, double(n.x) * L.x + double(n.y) * L.y + double(n.z) * L.z);
        }
        const double mean = adjacency.count(e) ? sum / adjacency.count(e) : 0.0;
        return std::min(1.0, double(rig.ambient) + double(rig.lights[0].intensity) * mean);
    };
    std::vector<float> out(edges * LIGHTS);
    auto run = [&](auto &&shade_one) {
        measured m{};
        m.time = bench::measure_ns(repeats, double(edges) * LIGHTS, [&] {
            for (int l = 0; l < LIGHTS; ++l)
                for (std::size_t e = 0; e < edges; ++e) out[l * edges + e] = float(shade_one(rigs[l], e));
            bench::keep(out);
        });
        double sum = 0;
        std::size_t black = 0;
        for (int l = 0; l < LIGHTS; ++l)
            for (std::size_t e = 0; e < edges; ++e) {
                const double err = std::fabs(out[l * edges + e] - reference(rigs[l], e));
                sum += err;
                m.error_max = std::max(m.error_max, err);
                black += out[l * edges + e] == 0.0f;
            }
        m.error_mean = sum / double(out.size());
        m.black_fraction = double(black) / double(out.size());
        return m;
    };
    auto point = [&](std::size_t e, bool first) { return ball.positions[first ? ball.edges[e].a : ball.edges[e].b]; };

    const measured faithful = run([&](const tiny3d::light_rig &rig, std::size_t e) {
        return tiny3d::shade_edge_faithful(rig, point(e, true), point(e, false));
    });
    const measured exact = run(reference);
    const measured corrected = run([&](const tiny3d::light_rig &rig, std::size_t e) {
        return tiny3d::shade_edge(rig, point(e, true), point(e, false), edge_normal[e]);
    });

    auto note = [](const measured &m) {
        char text[64];
        std::snprintf(text, sizeof text, "black edges %.1f %%", 100.0 * m.black_fraction);
        return std::string(text);
    };
    const std::string unit = "ns/edge", err_unit = "abs intensity";
    std::vector<bench::row> rows = {
        {"edge_lighting", "lambert_intensity per edge (report)", "faithful", unit, faithful.time, faithful.error_mean,
         faithful.error_max, err_unit, note(faithful)},
        {"edge_lighting", "mean of adjacent faces' Lambert (double)", "reference", unit, exact.time, exact.error_mean,
         exact.error_max, err_unit, note(exact)},
        {"edge_lighting", "edge normal = mean face normal + ambient", "fast", unit, corrected.time, corrected.error_mean,
         corrected.error_max, err_unit, note(corrected)},
    };
    return bench::report(o, "edge_lighting", rows, "Soccer-ball edge lighting: time per edge vs intensity error");
}
