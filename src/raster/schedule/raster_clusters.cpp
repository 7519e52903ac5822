// raster_clusters.cpp — cluster culling: per chunk of consecutive triangles a bounding
// sphere and a normal cone (built once per mesh), and the per-draw test that decides, before
// any per-triangle work, whether a whole chunk is back-facing.
// The derivation and its error budget are in documentation/raster.md ("Cluster culling").
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "../../math3d/dvec3.h"
#include "../setup/setup.h"
#include "cluster_view.h"

namespace tiny3d {

namespace {

using detail::dvec3;
using detail::widen;

dvec3 load(const double p[3]) { return {p[0], p[1], p[2]}; }
void store(dvec3 v, double p[3]) { p[0] = v.x, p[1] = v.y, p[2] = v.z; }

// Slack for double rounding in the precomputed bounds (relative to the quantities' scale):
// their errors are ~1e-16 relative, so 1e-12 makes every stored bound hold for the exact
// values too.
constexpr double BOUND_SLACK = 1e-12;
// The narrowest usable cone: cos α must exceed this (α < 90°), or no apex exists.
constexpr double MIN_CONE_COS = 1e-6;
// A bound on the error of one float clip coordinate (4 operations) or one screen coordinate
// computed from it, relative to the sum of the magnitudes involved: 2^-20 = 16 float ulps,
// several times the γ_4 = 4·2^-24 of the worst case.
constexpr double FLOAT_ERROR = 1.0 / (1 << 20);
// Snapping to 1/16 px moves a coordinate by at most half a sub-pixel step.
constexpr double SNAP_ERROR = 0.5 / RASTER_SUBPIXEL_ONE;
// Perturbations at least this large (px) make the row range and area argument pointless.
constexpr double MAX_PERTURBATION = 0.25;

raster_cluster build_cluster(const raster_mesh &m, std::uint32_t first, std::uint32_t count) {
    raster_cluster c;
    c.first = first;
    c.count = count;
    dvec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (std::uint32_t i = first; i < first + count; ++i)
        for (std::uint32_t v : m.triangles[i]) {
            const vec3_t p = m.positions[v];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                c.radius = INFINITY;  // never inside anything, no cone
                return c;
            }
            lo = {std::min(lo.x, double(p.x)), std::min(lo.y, double(p.y)), std::min(lo.z, double(p.z))};
            hi = {std::max(hi.x, double(p.x)), std::max(hi.y, double(p.y)), std::max(hi.z, double(p.z))};
        }
    if (count == 0) return c;
    const dvec3 center = (lo + hi) * 0.5;
    double radius = 0;
    for (std::uint32_t i = first; i < first + count; ++i)
        for (std::uint32_t v : m.triangles[i]) radius = std::max(radius, length(widen(m.positions[v]) - center));
    store(center, c.center);
    c.radius = radius * (1 + BOUND_SLACK) + BOUND_SLACK;
    // Normal cone: axis = the normalised mean of the unit face normals.
    dvec3 sum{0, 0, 0};
    double min_area = INFINITY, edge_ratio = 0;
    // Calls f(n, p0, p1, p2) for each face: n its unnormalised normal (p1 − p0) × (p2 − p0).
    auto each_face = [&](auto &&f) {
        for (std::uint32_t i = first; i < first + count; ++i) {
            const dvec3 p0 = widen(m.positions[m.triangles[i][0]]), p1 = widen(m.positions[m.triangles[i][1]]),
                        p2 = widen(m.positions[m.triangles[i][2]]);
            f(cross(p1 - p0, p2 - p0), p0, p1, p2);
        }
    };
    each_face([&](const dvec3 &n, const dvec3 &p0, const dvec3 &p1, const dvec3 &p2) {
        const double len = length(n);
        min_area = std::min(min_area, len);
        if (len > 0) sum = sum + n * (1 / len);
        edge_ratio = std::max(edge_ratio, (length(p1 - p0) + length(p2 - p0)) / len);
    });
    c.min_double_area = min_area * (1 - BOUND_SLACK);
    c.edge_ratio = edge_ratio * (1 + BOUND_SLACK);
    const double sum_len = length(sum);
    if (!(min_area > 0) || !(sum_len > 0)) return c;
    const dvec3 axis = sum * (1 / sum_len);
    double cone_cos = 1;
    each_face([&](const dvec3 &n, const dvec3 &, const dvec3 &, const dvec3 &) {
        cone_cos = std::min(cone_cos, dot(n, axis) / length(n));
    });
    cone_cos -= BOUND_SLACK;
    if (!(cone_cos > MIN_CONE_COS)) return c;
    // Apex = center − t·axis with the smallest t that puts it on or behind every plane:
    // n·(p0 − center + t·axis) ≥ 0  ⇔  t ≥ n·(center − p0) / (n·axis).
    double t = -INFINITY;
    each_face([&](const dvec3 &n, const dvec3 &p0, const dvec3 &, const dvec3 &) {
        t = std::max(t, dot(n, center - p0) / dot(n, axis));
    });
    const dvec3 apex = center - axis * t;
    double margin = INFINITY;  // the smallest n·(p0 − apex), ≈ 0 (rounding either way)
    each_face([&](const dvec3 &n, const dvec3 &p0, const dvec3 &, const dvec3 &) {
        margin = std::min(margin, dot(n, p0 - apex) / length(n));
    });
    store(axis, c.axis);
    store(apex, c.apex);
    c.cone_cos = cone_cos;
    c.cone_sin = std::min(1.0, std::sqrt(1 - cone_cos * cone_cos) + BOUND_SLACK);
    // The slack also covers the per-draw rounding of apex − eye (the eye's part is in eye_slack).
    c.apex_margin = margin - BOUND_SLACK * (1 + 2 * length(apex) + length(center) + c.radius);
    c.cone_valid = std::isfinite(c.apex_margin) && std::isfinite(c.edge_ratio);
    return c;
}

double det3(const double a[3], const double b[3], const double c[3]) {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

}  // namespace

result<raster_clusters> make_raster_clusters(const raster_mesh &m, int triangles_per_cluster) {
    if (triangles_per_cluster < 1)
        return error{"", 0, -1, "raster clusters: triangles_per_cluster " + std::to_string(triangles_per_cluster) + " < 1"};
    for (std::size_t i = 0; i < m.triangles.size(); ++i)
        for (std::uint32_t v : m.triangles[i])
            if (v >= m.positions.size())
                return error{"", 0, -1, "raster clusters: triangle " + std::to_string(i) + " refers to position " +
                                            std::to_string(v) + " of " + std::to_string(m.positions.size())};
    raster_clusters out;
    out.vertex_count_ = m.positions.size();
    out.triangle_count_ = m.triangles.size();
    const std::size_t per = static_cast<std::size_t>(triangles_per_cluster);
    out.clusters_.reserve((m.triangles.size() + per - 1) / per);
    std::vector<std::uint32_t> last_chunk(m.positions.size(), std::numeric_limits<std::uint32_t>::max());
    for (std::size_t first = 0; first < m.triangles.size(); first += per) {
        const std::uint32_t chunk = static_cast<std::uint32_t>(out.clusters_.size());
        raster_cluster c = build_cluster(m, static_cast<std::uint32_t>(first),
                                         static_cast<std::uint32_t>(std::min(per, m.triangles.size() - first)));
        c.vertex_first = static_cast<std::uint32_t>(out.vertices_.size());
        for (std::uint32_t i = c.first; i < c.first + c.count; ++i)
            for (std::uint32_t v : m.triangles[i])
                if (last_chunk[v] != chunk) {
                    last_chunk[v] = chunk;
                    out.vertices_.push_back(v);
                }
        std::sort(out.vertices_.begin() + c.vertex_first, out.vertices_.end());
        c.vertex_count = static_cast<std::uint32_t>(out.vertices_.size() - c.vertex_first);
        out.clusters_.push_back(c);
    }
    return out;
}

namespace detail {

// The eye is the kernel of the x, y, w rows B (3×4) of the MVP: E_j = (−1)^j · M_j with M_j
// the 3×3 minor without column j, so B·E = 0, and eye = E.xyz / E_w. For triangle points
// P_k = (p_k, 1), det[x_k y_k w_k] = det(B·[P0 P1 P2]) = κ · N·(p0 − eye), N = (p1 − p0) × (p2 − p0),
// κ = det([B; E'ᵀ]) / |E'|² with E' = E / E_w, which simplifies to κ = M_w (the minor of the
// xyz columns). The screen double area (y down) is −hw·hh·det / (w0·w1·w2), so with κ < 0 a
// triangle is back-facing (culled) exactly when N·(p0 − eye) > 0.
cluster_view make_cluster_view(const mat4_t &mvp, int width, int height, float guard, cull_mode cull) {
    cluster_view v{};
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            v.row[r][c] = mvp.m[c * 4 + r];
            v.abs_row[r][c] = std::fabs(v.row[r][c]);
        }
        v.row_length[r] = length(load(v.row[r]));
    }
    // Outcode planes, in clip_outcode's form: s·coordinate + g·w ≥ 0.
    const double g = guard;
    const struct {
        int row;
        double sign, guard;
    } planes[6] = {{2, 1, 1}, {2, -1, 1}, {0, 1, g}, {0, -1, g}, {1, 1, g}, {1, -1, g}};
    for (int k = 0; k < 6; ++k) {
        for (int c = 0; c < 4; ++c) v.plane[k][c] = planes[k].sign * v.row[planes[k].row][c] + planes[k].guard * v.row[3][c];
        v.plane_length[k] = length(load(v.plane[k]));
        v.plane_guard[k] = planes[k].guard;
        v.plane_row[k] = planes[k].row;
    }
    v.half_w = 0.5 * width;
    v.half_h = 0.5 * height;
    double minor[4];
    for (int skip = 0; skip < 4; ++skip) {
        double a[3], b[3], c[3];
        for (int col = 0, k = 0; col < 4; ++col) {
            if (col == skip) continue;
            a[k] = v.row[0][col], b[k] = v.row[1][col], c[k] = v.row[3][col];
            ++k;
        }
        minor[skip] = det3(a, b, c);
    }
    const double e[4] = {minor[0], -minor[1], minor[2], -minor[3]};
    const double largest = std::max({std::fabs(e[0]), std::fabs(e[1]), std::fabs(e[2]), std::fabs(e[3])});
    const double kappa = minor[3];
    constexpr double MIN_RELATIVE_EYE_W = 1e-9;  // smaller: (nearly) orthographic, no finite eye
    v.cone_usable = cull == cull_mode::back && std::isfinite(largest) && std::fabs(e[3]) > MIN_RELATIVE_EYE_W * largest &&
                    kappa < 0;
    if (!v.cone_usable) return v;
    for (int k = 0; k < 3; ++k) v.eye[k] = e[k] / e[3];
    v.eye_slack = BOUND_SLACK * 2 * length(load(v.eye));
    v.area_scale = v.half_w * v.half_h * -kappa;
    return v;
}

bool cluster_back_facing(const cluster_view &v, const raster_cluster &c) {
    const double r = c.radius;
    if (!(r < INFINITY)) return false;  // also NaN
    const dvec3 center = load(c.center);
    const dvec3 abs_reach{std::fabs(center.x) + r, std::fabs(center.y) + r, std::fabs(center.z) + r};
    double at_center[4], magnitude[4];  // clip coordinate at the centre, and the sum of the
                                        // |terms| of its float evaluation over the sphere
    for (int k = 0; k < 4; ++k) {
        at_center[k] = dot(load(v.row[k]), center) + v.row[k][3];
        magnitude[k] = dot(load(v.abs_row[k]), abs_reach) + v.abs_row[k][3];
    }
    // Inside every outcode plane, with a margin for the float distance's error.
    for (int k = 0; k < 6; ++k) {
        const int a = v.plane_row[k];
        const double distance = dot(load(v.plane[k]), center) + v.plane[k][3] - v.plane_length[k] * r;
        if (!(distance >= FLOAT_ERROR * (magnitude[a] + v.plane_guard[k] * magnitude[3]))) return false;
    }
    const double w_min = at_center[3] - v.row_length[3] * r, w_max = at_center[3] + v.row_length[3] * r;
    if (!(w_min > 0)) return false;
    // Range of x/w (k = 0) or y/w (k = 1) over the sphere, x and w ranges taken independently.
    double lo[2], hi[2], largest[2];
    for (int k = 0; k < 2; ++k) {
        const double a = at_center[k] - v.row_length[k] * r, b = at_center[k] + v.row_length[k] * r;
        lo[k] = a <= 0 ? a / w_min : a / w_max;
        hi[k] = b >= 0 ? b / w_min : b / w_max;
        largest[k] = std::max(std::fabs(lo[k]), std::fabs(hi[k]));
    }
    // Float error of a screen coordinate h·(x/w + 1): from x and w, then the division, add
    // and scale.
    auto screen_error = [&](int k, double half) {
        return half * FLOAT_ERROR * ((magnitude[k] + largest[k] * magnitude[3]) / w_min + largest[k] + 1);
    };
    const double delta = SNAP_ERROR + std::max(screen_error(0, v.half_w), screen_error(1, v.half_h));
    if (!(delta < MAX_PERTURBATION)) return false;
    if (!v.cone_usable || !c.cone_valid) return false;
    // Every triangle's n·(p − eye) ≥ |u|·cos(α + θ) + apex_margin, u = apex − eye (raster.h).
    const dvec3 axis = load(c.axis), u = load(c.apex) - load(v.eye);
    const double along = dot(u, axis), across = length(u - axis * along);
    const double h = c.cone_cos * along - c.cone_sin * across + c.apex_margin - v.eye_slack;
    if (!(h > 0)) return false;
    // Triangle i's exact screen double area is ≥ area_scale·|N_i|·h / w_max³. Moving each
    // vertex by ≤ delta per axis (float transform and snapping) changes (b − a) × (c − a) by
    // ≤ 2·delta·(|b − a|₁ + |c − a|₁) + 8·delta², and a screen edge's |·|₁ is at most
    // (Lx + Ly)·|object edge|, L = the largest screen gradient over the sphere,
    // h·(|x row| + |w row|·max|x/w|) / w_min. So the sign survives when, for every triangle,
    // area_scale·h / w_max³ > 2·delta·(Lx + Ly)·edge_ratio + 8·delta² / min_double_area.
    const double lipschitz = (v.half_w * (v.row_length[0] + v.row_length[3] * largest[0]) +
                              v.half_h * (v.row_length[1] + v.row_length[3] * largest[1])) / w_min;
    const double area_per_normal = v.area_scale * h / (w_max * w_max * w_max);
    const double change = 2 * delta * lipschitz * c.edge_ratio + 8 * delta * delta / c.min_double_area;
    constexpr double ROUNDING_FACTOR = 1 + 1e-9;  // the double evaluation of the two sides
    return area_per_normal > change * ROUNDING_FACTOR;
}

}  // namespace detail

}  // namespace tiny3d
