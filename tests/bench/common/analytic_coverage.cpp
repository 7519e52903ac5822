// analytic_coverage.cpp — the analytic-coverage prototype (analytic_coverage.h).
#include "analytic_coverage.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "lighting.h"

namespace bench {

using namespace tiny3d;

void coverage_box::compute(const float x[3], const float y[3]) {
    const float min_x = std::min({x[0], x[1], x[2]}), max_x = std::max({x[0], x[1], x[2]});
    const float min_y = std::min({y[0], y[1], y[2]}), max_y = std::max({y[0], y[1], y[2]});
    x0 = static_cast<int>(std::floor(min_x));
    y0 = static_cast<int>(std::floor(min_y));
    w = static_cast<int>(std::floor(max_x)) - x0 + 1;
    h = std::max(1, static_cast<int>(std::ceil(max_y)) - y0);
    stride_ = w + 2;  // an edge's carry reaches column w (ceil of the right end)
    const std::size_t cells = static_cast<std::size_t>(stride_) * h;
    if (acc_.size() < cells) acc_.resize(cells, 0.0f);  // kept all zero between calls
    if (areas_.size() < static_cast<std::size_t>(w) * h) areas_.resize(static_cast<std::size_t>(w) * h);
    for (int k = 0; k < 3; ++k) edge(x[k], y[k], x[(k + 1) % 3], y[(k + 1) % 3]);
    // Prefix sums along each row: the signed area inside each cell; the sign is the
    // orientation's, so |·| (clamped for rounding) is the area. Zeroes acc_ behind it.
    for (int j = 0; j < h; ++j) {
        float *a = acc_.data() + static_cast<std::size_t>(j) * stride_, *out = areas_.data() + static_cast<std::size_t>(j) * w;
        float sum = 0.0f;
        for (int i = 0; i < w; ++i) {
            sum += a[i];
            a[i] = 0.0f;
            out[i] = std::min(std::fabs(sum), 1.0f);
        }
        a[w] = a[w + 1] = 0.0f;
    }
}

// One edge's contribution (after font-rs's accumulation rasterizer, R. Levien 2016): for
// each row band [y, y + 1] the edge crosses with height dy (signed by its direction), cell
// i gains d · (the fraction of the band's height-weighted area right of the edge that
// starts in cell i), so that the prefix sum at cell i is the area of the band right of the
// edge inside cell i.
void coverage_box::edge(float ax, float ay, float bx, float by) {
    if (ay == by) return;
    float dir = 1.0f;
    if (ay > by) std::swap(ax, bx), std::swap(ay, by), dir = -1.0f;
    const float dxdy = (bx - ax) / (by - ay);
    float x = ax - static_cast<float>(x0);
    const float top = ay - static_cast<float>(y0), bottom = by - static_cast<float>(y0);
    const int j_end = std::min(h, static_cast<int>(std::ceil(bottom)));
    for (int j = static_cast<int>(std::floor(top)); j < j_end; ++j) {
        float *a = acc_.data() + static_cast<std::size_t>(j) * stride_;
        const float dy = std::min(static_cast<float>(j + 1), bottom) - std::max(static_cast<float>(j), top);
        const float x_next = x + dxdy * dy, d = dy * dir;
        const float lo = std::min(x, x_next), hi = std::max(x, x_next);
        const float lo_floor = std::floor(lo), hi_ceil = std::ceil(hi);
        const int i0 = std::max(0, static_cast<int>(lo_floor)), i1 = std::min(w, static_cast<int>(hi_ceil));
        if (i1 <= i0 + 1) {  // within one cell: split by the mean x
            const float m = 0.5f * (x + x_next) - static_cast<float>(i0);
            a[i0] += d - d * m;
            a[i0 + 1] += d * m;
        } else {
            const float s = 1.0f / (hi - lo), f0 = lo - lo_floor, f1 = hi - hi_ceil + 1.0f;
            const float a0 = 0.5f * s * (1.0f - f0) * (1.0f - f0), am = 0.5f * s * f1 * f1;
            a[i0] += d * a0;
            if (i1 == i0 + 2) {
                a[i0 + 1] += d * (1.0f - a0 - am);
            } else {
                const float a1 = s * (1.5f - f0);
                a[i0 + 1] += d * (a1 - a0);
                for (int i = i0 + 2; i < i1 - 1; ++i) a[i] += d * s;
                const float a2 = a1 + static_cast<float>(i1 - i0 - 3) * s;
                a[i1 - 1] += d * (1.0f - a2 - am);
            }
            a[i1] += d * am;
        }
        x = x_next;
    }
}

namespace {

// LSD radix sort of `order` by 32-bit keys (three passes of 11 bits).
void radix_sort(std::vector<std::uint32_t> &keys, std::vector<std::uint32_t> &order, std::vector<std::uint32_t> &tmp_keys,
                std::vector<std::uint32_t> &tmp_order) {
    const std::size_t n = keys.size();
    tmp_keys.resize(n);
    tmp_order.resize(n);
    for (int shift = 0; shift < 32; shift += 11) {
        std::uint32_t count[2049] = {};
        for (std::uint32_t k : keys) ++count[((k >> shift) & 2047) + 1];
        for (int b = 0; b < 2048; ++b) count[b + 1] += count[b];
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t at = count[(keys[i] >> shift) & 2047]++;
            tmp_keys[at] = keys[i];
            tmp_order[at] = order[i];
        }
        keys.swap(tmp_keys);
        order.swap(tmp_order);
    }
}

}  // namespace

bool analytic_renderer::render(canvas_t &canvas, const raster_mesh &mesh, const draw_params &p, float clear_intensity) {
    if (p.tex || (p.shade != shading::flat && p.shade != shading::gouraud)) return false;
    const int width = canvas.width, height = canvas.height;
    const mat4_t mvp = mat4_multiply(p.view_projection, p.model);
    const normal_transform nt = make_normal_transform(p.model);
    const float *m = mvp.m, *mm = p.model.m;
    vertices_.resize(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const vec3_t v = mesh.positions[i];
        const float cx = m[0] * v.x + m[4] * v.y + m[8] * v.z + m[12], cy = m[1] * v.x + m[5] * v.y + m[9] * v.z + m[13];
        const float cz = m[2] * v.x + m[6] * v.y + m[10] * v.z + m[14], cw = m[3] * v.x + m[7] * v.y + m[11] * v.z + m[15];
        vertex &o = vertices_[i];
        o.usable = cw > 0 && cz >= -cw && cz <= cw;
        const float inv = 1.0f / cw;
        o.x = (cx * inv + 1.0f) * 0.5f * static_cast<float>(width);
        o.y = (1.0f - cy * inv) * 0.5f * static_cast<float>(height);
        o.z = 0.5f * cz * inv + 0.5f;
        o.shade = 0.0f;
        if (p.shade == shading::gouraud) {
            const vec3_t world = {mm[0] * v.x + mm[4] * v.y + mm[8] * v.z + mm[12], mm[1] * v.x + mm[5] * v.y + mm[9] * v.z + mm[13],
                                  mm[2] * v.x + mm[6] * v.y + mm[10] * v.z + mm[14]};
            o.shade = shade_gouraud_vertex(p.lights, world, apply_normal_transform(nt, mesh.normals[i]));
        }
    }
    // Cull, then sort the survivors nearest first (window depth in [0, 1]: its float bits
    // order as integers).
    keys_.clear();
    order_.clear();
    skipped_ = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const vertex &a = vertices_[mesh.triangles[t][0]], &b = vertices_[mesh.triangles[t][1]], &c = vertices_[mesh.triangles[t][2]];
        if (!a.usable || !b.usable || !c.usable) {
            ++skipped_;
            continue;
        }
        const float area2 = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (!(area2 != 0.0f)) continue;
        const bool front = area2 < 0;  // counter-clockwise in NDC = clockwise on the y-down screen
        if ((p.cull == cull_mode::back && !front) || (p.cull == cull_mode::front && front)) continue;
        if (std::min({a.x, b.x, c.x}) < 0 || std::min({a.y, b.y, c.y}) < 0 || std::max({a.x, b.x, c.x}) >= width ||
            std::max({a.y, b.y, c.y}) >= height) {
            ++skipped_;
            continue;
        }
        std::uint32_t key;
        const float z = std::max(0.0f, std::min({a.z, b.z, c.z}));
        std::memcpy(&key, &z, sizeof key);
        keys_.push_back(key);
        order_.push_back(static_cast<std::uint32_t>(t));
    }
    radix_sort(keys_, order_, tmp_keys_, tmp_order_);
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    alpha_.assign(pixels, 0.0f);
    std::fill(canvas.data, canvas.data + pixels, 0.0f);
    for (std::uint32_t t : order_) {
        const vertex *v[3] = {&vertices_[mesh.triangles[t][0]], &vertices_[mesh.triangles[t][1]], &vertices_[mesh.triangles[t][2]]};
        const float x[3] = {v[0]->x, v[1]->x, v[2]->x}, y[3] = {v[0]->y, v[1]->y, v[2]->y};
        // The intensity plane i(X, Y) = i0 + gx (X − x0) + gy (Y − y0) through the vertices.
        float i0 = v[0]->shade, gx = 0, gy = 0;
        if (p.shade == shading::flat) {
            const auto world = [&](int k) {
                const vec3_t q = mesh.positions[mesh.triangles[t][k]];
                return vec3_t{mm[0] * q.x + mm[4] * q.y + mm[8] * q.z + mm[12], mm[1] * q.x + mm[5] * q.y + mm[9] * q.z + mm[13],
                              mm[2] * q.x + mm[6] * q.y + mm[10] * q.z + mm[14]};
            };
            i0 = shade_flat(p.lights, world(0), world(1), world(2));
        } else {
            const float ux = x[1] - x[0], uy = y[1] - y[0], wx = x[2] - x[0], wy = y[2] - y[0];
            const float di1 = v[1]->shade - i0, di2 = v[2]->shade - i0, inv = 1.0f / (ux * wy - uy * wx);
            gx = (di1 * wy - di2 * uy) * inv;
            gy = (di2 * ux - di1 * wx) * inv;
        }
        box_.compute(x, y);
        for (int j = 0; j < box_.h; ++j) {
            const int py = box_.y0 + j;
            const float *cov = box_.row(j);
            float *colour = canvas.pixels[py] + box_.x0, *alpha = alpha_.data() + static_cast<std::size_t>(py) * width + box_.x0;
            const float row_shade = i0 + gy * (static_cast<float>(py) + 0.5f - y[0]);
            for (int i = 0; i < box_.w; ++i) {
                const float c = cov[i], room = 1.0f - alpha[i];
                if (c <= 0.0f || room <= 0.0f) continue;
                const float take = std::min(c, room);
                const float shade = clamp01(row_shade + gx * (static_cast<float>(box_.x0 + i) + 0.5f - x[0]));
                colour[i] += take * shade;
                alpha[i] += take;
            }
        }
    }
    const float clear = clamp01(clear_intensity);
    for (std::size_t k = 0; k < pixels; ++k) canvas.data[k] += std::max(0.0f, 1.0f - alpha_[k]) * clear;
    return true;
}

}  // namespace bench
