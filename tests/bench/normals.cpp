// normals.cpp — vertex normals of a 1 M-triangle torus: per position (mesh_vertex_normals,
// what render used before crease normals), and per corner with creases
// (mesh_crease_normals), on the torus as generated and on a copy cut into patches that
// repeat their seam vertices (as the Utah teapot ships). Time per triangle; error = the
// angle between a corner's normal and the analytic torus normal there (double), degrees.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "common/bench.h"
#include "mesh.h"
#include "../seam_split.h"

namespace {

constexpr float kMajor = 1.0f, kMinor = 0.4f;

// The torus as triangles (1 M of them at 1000 × 500 segments).
tiny3d::mesh triangulated_torus(int major_segments, int minor_segments) {
    const tiny3d::mesh quads = tiny3d::make_torus(kMajor, kMinor, major_segments, minor_segments);
    tiny3d::mesh m;
    m.positions = quads.positions;
    for (const tiny3d::corner_triangle &t : tiny3d::mesh_triangles(quads))
        m.add_face({quads.indices[t[0]], quads.indices[t[1]], quads.indices[t[2]]});
    return m;
}

// Angle in degrees between n and the torus's outward normal at p (in double).
double angle_to_exact(vec3_t p, vec3_t n) {
    const double ring = std::hypot(double(p.x), double(p.y));
    const double cx = kMajor * p.x / ring, cy = kMajor * p.y / ring;
    const double ex = p.x - cx, ey = p.y - cy, ez = p.z, el = std::sqrt(ex * ex + ey * ey + ez * ez);
    const double nl = std::sqrt(double(n.x) * n.x + double(n.y) * n.y + double(n.z) * n.z);
    const double c = (ex * n.x + ey * n.y + ez * n.z) / (el * nl);
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
}

struct errors {
    double mean = 0, max = 0;
};

// The error of every corner's normal (normal_of(k) for corner k).
template <class NormalOf>
errors measure(const tiny3d::mesh &m, NormalOf normal_of) {
    errors e;
    for (std::size_t k = 0; k < m.indices.size(); ++k) {
        const double a = angle_to_exact(m.positions[m.indices[k]], normal_of(k));
        e.mean += a;
        e.max = std::max(e.max, a);
    }
    e.mean /= double(m.indices.size());
    return e;
}

}  // namespace

int main(int argc, char **argv) {
    const bench::options o = bench::parse_options(argc, argv);
    const int repeats = o.quick ? 1 : 7;
    const tiny3d::mesh whole = o.quick ? triangulated_torus(100, 50) : triangulated_torus(1000, 500);
    const tiny3d::mesh patched = seam_split::split_into_patches(whole, 512);
    const double triangles = double(whole.face_count());
    std::vector<bench::row> rows;
    for (const auto &[shape, m] : {std::pair<const char *, const tiny3d::mesh &>{"", whole}, {", seams split", patched}}) {
        std::vector<vec3_t> per_position;
        const bench::timing t = bench::measure_ns(repeats, triangles, [&] {
            per_position = tiny3d::mesh_vertex_normals(m);
            bench::keep(per_position);
        });
        const errors e = measure(m, [&](std::size_t k) { return per_position[m.indices[k]]; });
        rows.push_back({"normals", std::string("per position (mesh_vertex_normals)") + shape, "faithful", "ns/triangle", t,
                        e.mean, e.max, "deg from the analytic normal", "what render used before"});
        for (float crease : {60.0f, 180.0f}) {
            std::vector<vec3_t> per_corner;
            const bench::timing tc = bench::measure_ns(repeats, triangles, [&] {
                per_corner = tiny3d::mesh_crease_normals(m, crease);
                bench::keep(per_corner);
            });
            const errors ec = measure(m, [&](std::size_t k) { return per_corner[k]; });
            rows.push_back({"normals", "crease " + std::to_string(int(crease)) + " (mesh_crease_normals)" + shape,
                            crease == 60.0f ? "fast" : "other", "ns/triangle", tc, ec.mean, ec.max,
                            "deg from the analytic normal", crease == 60.0f ? "render's default" : "smooth everywhere"});
        }
    }
    return bench::report(o, "normals", rows,
                         "Vertex normals of a " + std::to_string(whole.face_count()) + "-triangle torus: time vs angle error");
}
