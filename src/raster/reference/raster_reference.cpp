// raster_reference.cpp — the converged reference image (raster.h): double
// precision, n² golden-ratio lattice samples per pixel, per-sample depth and shading, box filter.
#include "raster.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../setup/setup.h"

namespace tiny3d {

namespace {

enum slot { WX, WY, WZ, NX, NY, NZ, U, V, SHADE, SLOTS };

struct dvertex {
    double clip[4];
    double attr[SLOTS];
};

// A screen triangle ready for sampling.
struct ref_triangle {
    double x[3], y[3], z[3], q[3];  // screen px, window depth, perspective weight (1/w or 1)
    double attr[3][SLOTS];
    std::size_t draw;
    double y_min, y_max, area2;  // area2: twice the signed screen area
};

constexpr int BAND_ROWS = 8;

error reference_error(const std::string &what) { return error{"", 0, -1, "render_reference: " + what}; }

// Sutherland–Hodgman against one plane d(v) ≥ 0 (d linear in clip space).
template <class Distance>
std::vector<dvertex> clip_against(const std::vector<dvertex> &in, Distance d) {
    std::vector<dvertex> out;
    for (std::size_t k = 0; k < in.size(); ++k) {
        const dvertex &a = in[k], &b = in[(k + 1) % in.size()];
        const double da = d(a), db = d(b);
        if (da >= 0) out.push_back(a);
        if ((da >= 0) != (db >= 0)) {
            const double t = da / (da - db);
            dvertex c;
            for (int i = 0; i < 4; ++i) c.clip[i] = a.clip[i] + (b.clip[i] - a.clip[i]) * t;
            for (int i = 0; i < SLOTS; ++i) c.attr[i] = a.attr[i] + (b.attr[i] - a.attr[i]) * t;
            out.push_back(c);
        }
    }
    return out;
}

vec3_t narrow(const double *p) { return {float(p[0]), float(p[1]), float(p[2])}; }

// The draw's triangles, transformed, clipped, culled and projected, appended to `out`.
status prepare(const reference_draw &d, std::size_t index, int width, int height, std::vector<ref_triangle> &out) {
    const raster_mesh &m = *d.mesh;
    const draw_params &p = d.params;
    if (m.normals.size() != m.positions.size() || m.uvs.size() != m.positions.size())
        return reference_error("draw " + std::to_string(index) + ": normals or uvs count differs from positions");
    if (p.alpha < 1.0f) return reference_error("draw " + std::to_string(index) + ": translucent draws are not supported");
    if (const status bad = check_material(p.surface); !bad)
        return reference_error("draw " + std::to_string(index) + ": " + bad.message());
    double model[16], vp[16];
    for (int i = 0; i < 16; ++i) model[i] = p.model.m[i], vp[i] = p.view_projection.m[i];
    auto apply = [](const double *mat, const double v[4], double r[4]) {
        for (int row = 0; row < 4; ++row)
            r[row] = mat[row] * v[0] + mat[4 + row] * v[1] + mat[8 + row] * v[2] + mat[12 + row] * v[3];
    };
    const normal_transform nt = make_normal_transform(p.model);
    const bool material_lit = !material_is_lambert(p.surface);  // Blinn-Phong (material.h)
    const viewer eye = viewer_of(p.view_projection);
    const double hw = 0.5 * width, hh = 0.5 * height;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        std::vector<dvertex> poly(3);
        double world[3][3];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t i = m.triangles[t][k];
            if (i >= m.positions.size())
                return reference_error("draw " + std::to_string(index) + ": triangle " + std::to_string(t) +
                                       " refers to position " + std::to_string(i));
            const double obj[4] = {m.positions[i].x, m.positions[i].y, m.positions[i].z, 1.0};
            double w4[4];
            apply(model, obj, w4);
            apply(vp, w4, poly[k].clip);
            for (int c = 0; c < 3; ++c) world[k][c] = w4[c];
            const vec3_t n = apply_normal_transform(nt, m.normals[i]);
            double *a = poly[k].attr;
            a[WX] = w4[0], a[WY] = w4[1], a[WZ] = w4[2];
            a[NX] = n.x, a[NY] = n.y, a[NZ] = n.z;
            a[U] = m.uvs[i].x, a[V] = m.uvs[i].y;
            a[SHADE] = p.shade != shading::gouraud ? 0.0
                       : material_lit  ? shade_point_material(p.lights, p.surface, eye, narrow(world[k]), unit_or_zero(n))
                                       : shade_gouraud_vertex(p.lights, narrow(world[k]), n);
        }
        if (p.shade == shading::flat) {
            const double s = material_lit
                                 ? shade_flat_material(p.lights, p.surface, eye, narrow(world[0]), narrow(world[1]), narrow(world[2]))
                                 : shade_flat(p.lights, narrow(world[0]), narrow(world[1]), narrow(world[2]));
            for (dvertex &v : poly) v.attr[SHADE] = s;
        }
        bool finite = true;
        for (const dvertex &v : poly)
            for (double c : v.clip) finite = finite && std::isfinite(c);
        if (!finite) continue;
        poly = clip_against(poly, [](const dvertex &v) { return v.clip[2] + v.clip[3]; });  // near
        if (!poly.empty()) poly = clip_against(poly, [](const dvertex &v) { return v.clip[3] - v.clip[2]; });  // far
        for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
            const dvertex *v[3] = {&poly[0], &poly[k], &poly[k + 1]};
            ref_triangle r;
            r.draw = index;
            bool ok = true;
            for (int j = 0; j < 3; ++j) {
                const double w = v[j]->clip[3];
                if (!(w > 0)) ok = false;
                r.x[j] = (v[j]->clip[0] / w + 1) * hw;
                r.y[j] = (1 - v[j]->clip[1] / w) * hh;
                r.z[j] = 0.5 * v[j]->clip[2] / w + 0.5;
                r.q[j] = 1 / w;
                std::copy(v[j]->attr, v[j]->attr + SLOTS, r.attr[j]);
            }
            if (!ok) continue;
            r.area2 = (r.x[1] - r.x[0]) * (r.y[2] - r.y[0]) - (r.y[1] - r.y[0]) * (r.x[2] - r.x[0]);
            if (!(r.area2 != 0) || !std::isfinite(r.area2) || detail::facing_culled(r.area2, p.cull)) continue;
            r.y_min = std::min({r.y[0], r.y[1], r.y[2]});
            r.y_max = std::max({r.y[0], r.y[1], r.y[2]});
            out.push_back(r);
        }
    }
    return {};
}

}  // namespace

status render_reference(canvas_t &target, std::span<const reference_draw> draws, float clear_intensity,
                        int samples_per_axis) {
    if (!target.pixels || target.width <= 0 || target.height <= 0) return reference_error("canvas has no pixels");
    if (samples_per_axis < 1 || samples_per_axis > 64)
        return reference_error("samples_per_axis " + std::to_string(samples_per_axis) + " outside 1..64");
    const int width = target.width, height = target.height, n = samples_per_axis;
    std::vector<ref_triangle> tris;
    for (std::size_t i = 0; i < draws.size(); ++i) {
        if (!draws[i].mesh) return reference_error("draw " + std::to_string(i) + " has no mesh");
        const status s = prepare(draws[i], i, width, height, tris);
        if (!s) return s;
    }
    std::vector<viewer> eyes;  // per draw, for Blinn-Phong materials
    for (const reference_draw &d : draws) eyes.push_back(viewer_of(d.params.view_projection));
    const double clear = detail::clamp01(clear_intensity);
    // Sample rows of one band: band row r, sample row j at y = y0 + r + (j + ½)/n.
    const std::size_t per_pixel = static_cast<std::size_t>(n) * n;
    struct point {
        double x, y;
    };
    std::vector<point> offset(per_pixel);
    const double golden = (std::sqrt(5.0) - 1) / 2;  // 1/φ
    for (std::size_t k = 0; k < per_pixel; ++k) {
        const double x = 0.5 + static_cast<double>(k) * golden;
        offset[k] = {x - std::floor(x), (static_cast<double>(k) + 0.5) / static_cast<double>(per_pixel)};
    }
    std::vector<double> depth, colour;
    for (int y0 = 0; y0 < height; y0 += BAND_ROWS) {
        const int rows = std::min(BAND_ROWS, height - y0);
        depth.assign(per_pixel * width * rows, 1.0);
        colour.assign(per_pixel * width * rows, clear);
        // Sample k of pixel (px, py) is stored at ((py − y0)·width + px)·n² + k.
        for (const ref_triangle &r : tris) {
            if (r.y_max < y0 || r.y_min > y0 + rows) continue;
            const draw_params &p = draws[r.draw].params;
            const bool material_lit = !material_is_lambert(p.surface);
            const viewer &eye = eyes[r.draw];
            const double sign = r.area2 > 0 ? 1 : -1;
            // Edge k opposite vertex k, positive inside after orientation: l_k = e_k / |area2|.
            auto edge = [&](int k, double sx, double sy) {
                const int a = (k + 1) % 3, b = (k + 2) % 3;
                return sign * ((r.x[b] - r.x[a]) * (sy - r.y[a]) - (r.y[b] - r.y[a]) * (sx - r.x[a]));
            };
            const double inv_area = 1 / std::fabs(r.area2);
            const double x_min = std::min({r.x[0], r.x[1], r.x[2]}), x_max = std::max({r.x[0], r.x[1], r.x[2]});
            const int px0 = std::max(0, static_cast<int>(std::floor(x_min)));
            const int px1 = std::min(width - 1, static_cast<int>(std::floor(x_max)));
            const int py0 = std::max(y0, static_cast<int>(std::floor(r.y_min)));
            const int py1 = std::min(y0 + rows - 1, static_cast<int>(std::floor(r.y_max)));
            for (int py = py0; py <= py1; ++py)
                for (std::size_t k = 0; k < per_pixel; ++k) {
                    const double sy = py + offset[k].y;
                    if (sy < r.y_min || sy > r.y_max) continue;
                    for (int px = px0; px <= px1; ++px) {
                            const double sx = px + offset[k].x;
                            const double e0 = edge(0, sx, sy), e1 = edge(1, sx, sy), e2 = edge(2, sx, sy);
                            if (e0 < 0 || e1 < 0 || e2 < 0) continue;
                            const double l[3] = {e0 * inv_area, e1 * inv_area, e2 * inv_area};
                            const double z = l[0] * r.z[0] + l[1] * r.z[1] + l[2] * r.z[2];
                            const std::size_t at = (static_cast<std::size_t>(py - y0) * width + px) * per_pixel + k;
                            if (!detail::depth_passes(p.depth, z, depth[at])) continue;
                            double w[3] = {l[0], l[1], l[2]};
                            if (p.perspective_correct) {
                                const double b = l[0] * r.q[0] + l[1] * r.q[1] + l[2] * r.q[2];
                                for (int k = 0; k < 3; ++k) w[k] = l[k] * r.q[k] / b;
                            }
                            auto lerp = [&](int s, const double *weights) {
                                return weights[0] * r.attr[0][s] + weights[1] * r.attr[1][s] + weights[2] * r.attr[2][s];
                            };
                            double shade;
                            if (p.shade == shading::phong) {
                                const double pos[3] = {lerp(WX, w), lerp(WY, w), lerp(WZ, w)};
                                const double nor[3] = {lerp(NX, w), lerp(NY, w), lerp(NZ, w)};
                                shade = material_lit ? shade_point_material(p.lights, p.surface, eye, narrow(pos),
                                                                            unit_or_zero(narrow(nor)))
                                                     : shade_phong_pixel(p.lights, narrow(pos), narrow(nor));
                            } else {
                                // Screen-affine (the fast path), perspective weights with a texture (the
                                // per-pixel path), as the render context.
                                shade = lerp(SHADE, p.tex ? w : l);
                            }
                            if (p.tex)
                                shade *= texture_sample(*p.tex, static_cast<float>(lerp(U, w)), static_cast<float>(lerp(V, w)),
                                                        texture_filter::bilinear, p.wrap);
                            depth[at] = z;
                            colour[at] = std::clamp(shade, 0.0, 1.0);
                        }
                }
        }
        for (int r = 0; r < rows; ++r)
            for (int px = 0; px < width; ++px) {
                const double *c = &colour[(static_cast<std::size_t>(r) * width + px) * per_pixel];
                double sum = 0;
                for (std::size_t s = 0; s < per_pixel; ++s) sum += c[s];
                target.pixels[y0 + r][px] = static_cast<float>(sum / static_cast<double>(per_pixel));
            }
    }
    return {};
}

}  // namespace tiny3d
