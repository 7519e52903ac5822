// tests/fuzz/fuzz_checks.h — what "no crash, no garbage" means for a loaded file.
//
// Shared by the libFuzzer targets (tests/fuzz/fuzz_*.cpp, clang) and by
// tests/fuzz_regression_test.cpp (g++, part of `make test`), so a crash input kept under
// tests/fuzz/regressions/ is judged by exactly the checks the fuzzer applied.
//
// Every check returns an empty string when the outcome is acceptable, otherwise a sentence
// saying what was wrong. Acceptable means:
//  * an error that names the file it was given (error::file) and a non-empty reason, or
//  * a value that satisfies every invariant the headers promise: a mesh that passes
//    mesh_validate with finite positions and attributes, sorted unique edges, face and
//    vertex normals that are unit or zero, an adjacency that accounts for every face edge,
//    a bounding sphere that holds every position; an image of legal size with every
//    intensity in 0..1. A loaded mesh is then also rasterised (small meshes only) onto a
//    small canvas, and every pixel must stay in 0..1: loader output must be safe to draw.
#ifndef TINY3D_FUZZ_CHECKS_H
#define TINY3D_FUZZ_CHECKS_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <string_view>

#include "canvas.h"
#include "lighting.h"
#include "math3d.h"
#include "mesh.h"
#include "raster.h"
#include "wireframe.h"

namespace fuzz_checks {

// Meshes bigger than this are only checked, not rendered (keeps each fuzz run fast).
inline constexpr std::size_t RENDER_MAX_TRIANGLES = 4096;
inline constexpr int RENDER_SIDE = 24;  // px, the check canvas
// |n| of a normal reported as unit (float normalisation of any finite vector).
inline constexpr double UNIT_TOLERANCE = 1e-4;
// Slack of the bounding sphere test, relative to the radius (float rounding of centre and
// radius).
inline constexpr double SPHERE_SLACK = 1e-5;

inline bool finite3(vec3_t v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

inline double length_d(vec3_t v) {
    return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
}

// A normal must be (0, 0, 0) or unit length.
inline bool unit_or_zero(vec3_t n) {
    if (!finite3(n)) return false;
    if (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f) return true;
    return std::fabs(length_d(n) - 1.0) <= UNIT_TOLERANCE;
}

inline std::string check_error(const tiny3d::error &e, const std::string &name) {
    if (e.file != name) return "the error names '" + e.file + "' instead of '" + name + "': " + e.message();
    if (e.reason.empty()) return "the error has no reason";
    return {};
}

inline std::string check_canvas_values(const canvas_t &c) {
    if (c.width <= 0 || c.height <= 0 || !c.data || !c.pixels) return "invalid canvas returned";
    const std::size_t n = std::size_t(c.width) * std::size_t(c.height);
    for (std::size_t i = 0; i < n; ++i)
        if (!(c.data[i] >= 0.0f && c.data[i] <= 1.0f))
            return "pixel " + std::to_string(i) + " holds " + std::to_string(c.data[i]) + ", outside 0..1";
    for (int y = 0; y < c.height; ++y)
        if (c.pixels[y] != c.data + std::size_t(y) * std::size_t(c.width)) return "row pointer mismatch";
    return {};
}

// Draws the mesh as wireframes (both line methods) and filled (flat, Gouraud: framed by its
// bounding sphere; Phong: in the file's raw coordinates, so huge ones get clipped), no
// culling, and checks each image. Only called for meshes that passed the structural checks.
inline std::string check_renders(const tiny3d::mesh &m) {
    const tiny3d::bounding_sphere bounds = tiny3d::mesh_bounding_sphere(m);
    // Framed: the mesh mapped onto the unit sphere in double (any finite extent), 3 units in
    // front of the camera. The mapping refuses only a mesh with no finite position or with
    // every position the same point.
    tiny3d::mesh framed_mesh = m;
    const tiny3d::result<tiny3d::unit_sphere_map> fit = tiny3d::mesh_fit_unit_sphere(framed_mesh);
    if (!fit) {
        if (!(bounds.radius > 0.0f)) return {};
        return "mesh_fit_unit_sphere refused a sphere of radius " + std::to_string(bounds.radius) + ": " +
               fit.message();
    }
    tiny3d::result<tiny3d::raster_mesh> rm = tiny3d::make_raster_mesh(m, tiny3d::mesh_vertex_normals(m));
    tiny3d::result<tiny3d::raster_mesh> framed_rm =
        tiny3d::make_raster_mesh(framed_mesh, tiny3d::mesh_vertex_normals(framed_mesh));
    if (!rm || !framed_rm) return "make_raster_mesh rejected a valid mesh: " + (rm ? framed_rm : rm).message();
    tiny3d::result<tiny3d::canvas_ptr> canvas = tiny3d::make_canvas(RENDER_SIDE, RENDER_SIDE);
    if (!canvas) return "make_canvas failed";
    const light_t light = {{0.3f, 0.5f, 1.0f}, 0.8f};
    tiny3d::result<tiny3d::light_rig> rig = tiny3d::make_light_rig({&light, 1}, 0.1f);
    if (!rig) return "make_light_rig failed";
    const mat4_t model = mat4_translate(0.0f, 0.0f, -3.0f);
    const mat4_t projection = tiny3d::mat4_perspective(1.0f, 1.0f, 0.5f, 10.0f);
    // Wireframes: framed, and raw (the file's own coordinates, however far or huge: clipped).
    tiny3d::wireframe_workspace ws;
    // An edge that must show when framed: at least 1/1000 of the bounding radius long (in
    // double), so float rounding of the framed ends cannot collapse it to a point.
    bool has_long_edge = false;
    for (const tiny3d::edge &e : m.edges) {
        const vec3_t a = m.positions[e.a], b = m.positions[e.b];
        const double dx = double(a.x) - b.x, dy = double(a.y) - b.y, dz = double(a.z) - b.z;
        has_long_edge = has_long_edge || std::sqrt(dx * dx + dy * dy + dz * dz) >= 1e-3 * double(bounds.radius);
    }
    for (const bool framed : {true, false})
        for (tiny3d::line_method method : {tiny3d::line_method::faithful, tiny3d::line_method::coverage}) {
            const mat4_t m_model = framed ? model : mat4_identity();
            canvas_clear(canvas->get(), 0.0f);
            tiny3d::wireframe_options o;
            o.method = method;
            o.thickness = 1.5f;
            o.depth_cue = true;
            tiny3d::wireframe_stats stats;
            if (tiny3d::status s = tiny3d::render_wireframe(**canvas, framed ? framed_mesh : m,
                                                            mat4_multiply(projection, m_model), o, ws, &stats);
                !s)
                return "render_wireframe rejected a valid mesh: " + s.message();
            if (std::string e = check_canvas_values(**canvas); !e.empty()) return "wireframe image: " + e;
            // Framed, the whole mesh is in view: an edge must show (no silent blank frame).
            if (framed && has_long_edge &&
                (stats.edges_drawn == 0 || canvas_count_differing(canvas->get(), 0.0f) == 0))
                return "the framed wireframe came out blank (" + std::to_string(stats.edges_drawn) + " of " +
                       std::to_string(m.edges.size()) + " edges drawn)";
        }
    tiny3d::render_context ctx(1);
    for (tiny3d::shading shade : {tiny3d::shading::flat, tiny3d::shading::gouraud, tiny3d::shading::phong}) {
        if (!ctx.begin_frame(**canvas)) return "begin_frame failed";
        tiny3d::draw_params p{};
        const bool raw = shade == tiny3d::shading::phong;  // phong: the file's raw coordinates
        p.model = raw ? mat4_identity() : model;
        p.view_projection = projection;
        p.lights = *rig;
        p.shade = shade;
        p.cull = tiny3d::cull_mode::none;
        ctx.draw(raw ? *rm : *framed_rm, p);
        ctx.end_frame();
        if (std::string e = check_canvas_values(**canvas); !e.empty()) return "rendered image: " + e;
    }
    return {};
}

inline std::string check_mesh(const tiny3d::result<tiny3d::mesh> &r, const std::string &name) {
    if (!r) return check_error(r.err(), name);
    const tiny3d::mesh &m = *r;
    if (tiny3d::status s = tiny3d::mesh_validate(m); !s) return "invalid mesh returned: " + s.message();
    for (std::size_t i = 0; i < m.positions.size(); ++i)
        if (!finite3(m.positions[i])) return "position " + std::to_string(i) + " is not finite";
    for (const tiny3d::vec2 &uv : m.corner_uvs)
        if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return "a corner uv is not finite";
    for (const vec3_t &n : m.corner_normals)
        if (!finite3(n)) return "a corner normal is not finite";
    for (std::size_t e = 0; e < m.edges.size(); ++e) {
        if (!(m.edges[e].a < m.edges[e].b)) return "edge " + std::to_string(e) + " is not stored with a < b";
        if (e > 0 && !(m.edges[e - 1].a < m.edges[e].a ||
                       (m.edges[e - 1].a == m.edges[e].a && m.edges[e - 1].b < m.edges[e].b)))
            return "edges not sorted and unique at " + std::to_string(e);
    }
    for (const vec3_t &n : tiny3d::mesh_face_normals(m))
        if (!unit_or_zero(n)) return "a face normal is neither unit nor zero";
    for (const vec3_t &n : tiny3d::mesh_vertex_normals(m))
        if (!unit_or_zero(n)) return "a vertex normal is neither unit nor zero";
    const tiny3d::edge_adjacency adj = tiny3d::mesh_edge_faces(m);
    if (adj.start.size() != m.edges.size() + 1 || adj.faces.size() != adj.start.back())
        return "edge adjacency has the wrong shape";
    for (std::uint32_t f : adj.faces)
        if (f >= m.face_count()) return "edge adjacency names a face out of range";
    const tiny3d::bounding_sphere bs = tiny3d::mesh_bounding_sphere(m);
    if (m.positions.empty() != (bs.radius < 0.0f)) return "bounding sphere radius sign is wrong";
    for (const vec3_t &p : m.positions) {
        // In double: p − centre may overflow float for coordinates near FLT_MAX.
        const double dx = double(p.x) - bs.center.x, dy = double(p.y) - bs.center.y, dz = double(p.z) - bs.center.z;
        const double dist = std::sqrt(dx * dx + dy * dy + dz * dz);
        if (dist > double(bs.radius) * (1.0 + SPHERE_SLACK)) return "a position lies outside the bounding sphere";
    }
    const std::vector<tiny3d::corner_triangle> tris = tiny3d::mesh_triangles(m);
    if (tris.size() <= RENDER_MAX_TRIANGLES) return check_renders(m);
    return {};
}

inline std::string check_obj(std::string_view bytes, const std::string &name) {
    return check_mesh(tiny3d::parse_obj(bytes, name), name);
}

inline std::string check_ply(std::string_view bytes, const std::string &name) {
    return check_mesh(tiny3d::parse_ply(bytes, name), name);
}

// The PNM reader is path based: `path` names a file holding the bytes.
inline std::string check_pnm_file(const std::string &path) {
    tiny3d::result<tiny3d::canvas_ptr> r = tiny3d::load_pgm(path);
    if (!r) return check_error(r.err(), path);
    const canvas_t &c = **r;
    if (tiny3d::status s = tiny3d::check_canvas_size(c.width, c.height); !s) return "canvas beyond limits returned";
    return check_canvas_values(c);
}

// The texture path: the file loaded as a texture (load_texture_pgm: the PNM reader, then
// build_mipmaps), its mipmap chain checked against what raster.h promises, and the texture
// sampled by every filter and wrap mode. An exact box average of values in [lo, hi] lies in
// [lo, hi] and keeps the mean, so each level's texels stay in the base level's range and each
// level's mean (in double) equals the base level's mean, within float rounding per level.
inline constexpr double TEXTURE_MEAN_TOLERANCE = 1e-4;
inline constexpr double TEXTURE_RANGE_SLACK = 1e-6;

inline std::string check_texture_file(const std::string &path) {
    tiny3d::result<tiny3d::texture> r = tiny3d::load_texture_pgm(path);
    if (!r) return check_error(r.err(), path);
    const tiny3d::texture &t = *r;
    if (tiny3d::status s = tiny3d::check_canvas_size(t.width, t.height); !s) return "texture beyond limits returned";
    if (t.texels.size() != std::size_t(t.width) * std::size_t(t.height)) return "texel count differs from width x height";
    double lo = 1.0, hi = 0.0, sum = 0.0;
    for (float v : t.texels) {
        if (!(v >= 0.0f && v <= 1.0f)) return "texel " + std::to_string(v) + " outside 0..1";
        lo = std::min(lo, double(v));
        hi = std::max(hi, double(v));
        sum += v;
    }
    const double mean = sum / double(t.texels.size());
    int w = t.width, h = t.height;
    for (std::size_t k = 0; k < t.mipmaps.size(); ++k) {
        const tiny3d::texture_level &l = t.mipmaps[k];
        const std::string level = "mipmap level " + std::to_string(k + 1);
        if (l.width != std::max(1, w / 2) || l.height != std::max(1, h / 2))
            return level + " is " + std::to_string(l.width) + " x " + std::to_string(l.height) + " below " +
                   std::to_string(w) + " x " + std::to_string(h);
        if (l.texels.size() != std::size_t(l.width) * std::size_t(l.height)) return level + ": texel count";
        double level_sum = 0.0;
        for (float v : l.texels) {
            if (!(v >= lo - TEXTURE_RANGE_SLACK && v <= hi + TEXTURE_RANGE_SLACK))
                return level + " holds " + std::to_string(v) + " outside the base range";
            level_sum += v;
        }
        const double level_mean = level_sum / double(l.texels.size());
        if (std::fabs(level_mean - mean) > TEXTURE_MEAN_TOLERANCE)
            return level + " mean " + std::to_string(level_mean) + " differs from the base mean " + std::to_string(mean);
        w = l.width;
        h = l.height;
    }
    if (w != 1 || h != 1) return "the mipmap chain stops at " + std::to_string(w) + " x " + std::to_string(h);
    // Lookups: in range wherever they land (far outside, on edges, at NaN / inf: 0).
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const float coords[] = {0.0f, 0.5f, 1.0f, -0.25f, 0.999999f, 1.75f, -1e30f, 1e30f, 3e9f};
    const float lods[] = {-inf, -1.0f, 0.0f, 0.5f, 1.3f, float(t.mipmaps.size()) + 2.0f, inf, nan};
    const tiny3d::texture_filter filters[] = {tiny3d::texture_filter::nearest, tiny3d::texture_filter::bilinear,
                                              tiny3d::texture_filter::trilinear};
    const auto in_range = [&](float v) {
        return v >= lo - TEXTURE_RANGE_SLACK && v <= hi + TEXTURE_RANGE_SLACK;
    };
    for (const tiny3d::texture_wrap wrap : {tiny3d::texture_wrap::repeat, tiny3d::texture_wrap::clamp}) {
        for (float u : coords)
            for (float v : coords) {
                for (const tiny3d::texture_filter f : filters) {
                    const float s = tiny3d::texture_sample(t, u, v, f, wrap);
                    if (!in_range(s))
                        return "texture_sample(" + std::to_string(u) + ", " + std::to_string(v) + ") = " +
                               std::to_string(s) + " outside the texel range";
                }
                for (float lod : lods) {
                    const float s = tiny3d::texture_sample_trilinear(t, u, v, lod, wrap);
                    if (!in_range(s))
                        return "texture_sample_trilinear(" + std::to_string(u) + ", " + std::to_string(v) + ", " +
                               std::to_string(lod) + ") = " + std::to_string(s) + " outside the texel range";
                }
            }
        for (const tiny3d::texture_filter f : filters)
            if (tiny3d::texture_sample(t, nan, 0.5f, f, wrap) != 0.0f || tiny3d::texture_sample(t, 0.5f, inf, f, wrap) != 0.0f)
                return "a lookup at a non-finite coordinate is not 0";
        if (tiny3d::texture_sample_trilinear(t, nan, 0.5f, 0.0f, wrap) != 0.0f) return "trilinear lookup at NaN is not 0";
    }
    const float lod = tiny3d::texture_lod(t, 1.0f / 3.0f, 0.0f, 0.0f, 0.25f);
    if (!std::isfinite(lod)) return "texture_lod of finite derivatives is not finite";
    return {};
}

}  // namespace fuzz_checks

#endif
