// raster_pixel_path.cpp — the render context's per-pixel path: triangles with Phong
// shading, a texture or translucency, drawn with rasterize_triangle one pixel at a time.
#include <algorithm>

#include "render_context_impl.h"
#include "uv_derivatives.h"

namespace tiny3d::detail {

generic_triangle make_generic_triangle(const screen_vertex v[3], const clip_vertex *const c[3], std::uint32_t state) {
    generic_triangle g;
    for (int j = 0; j < 3; ++j) {
        g.v[j] = v[j];
        for (int a = 0; a < ATTR_COUNT; ++a) g.attr[j][a] = c[j]->attr[a];
    }
    g.mean_depth = (v[0].z + v[1].z + v[2].z) / 3.0f;
    g.state = state;
    g.sequence = 0;
    return g;
}

void draw_generic_rows(canvas_t &target, zbuffer &depth, const draw_params &p, const generic_triangle &g, int y0,
                       int y1) {
    const bool translucent = p.alpha < 1.0f;
    const float alpha = std::clamp(p.alpha, 0.0f, 1.0f);
    const pixel_rect band{0, y0, target.width, y1};
    const bool trilinear = p.tex && p.filter == texture_filter::trilinear;
    uv_derivatives uv_d;
    if (trilinear) {
        const float u[3] = {g.attr[0][ATTR_U], g.attr[1][ATTR_U], g.attr[2][ATTR_U]};
        const float v[3] = {g.attr[0][ATTR_V], g.attr[1][ATTR_V], g.attr[2][ATTR_V]};
        uv_d = uv_derivatives::of(g.v, u, v, p.perspective_correct);
    }
    rasterize_triangle(g.v[0], g.v[1], g.v[2], band, [&](int x, int y, float l0, float l1, float l2) {
        const float z = l0 * g.v[0].z + l1 * g.v[1].z + l2 * g.v[2].z;
        float *zp = depth.row(y) + x;
        if (!depth_passes(p.depth, z, *zp)) return;
        // Perspective-correct weights: l_k/w_k normalised (attr/w and 1/w interpolated).
        float w0 = l0, w1 = l1, w2 = l2, inv_b = 1.0f;
        if (p.perspective_correct) {
            w0 = l0 * g.v[0].inv_w, w1 = l1 * g.v[1].inv_w, w2 = l2 * g.v[2].inv_w;
            inv_b = 1.0f / (w0 + w1 + w2);
            w0 *= inv_b, w1 *= inv_b, w2 *= inv_b;
        }
        auto lerp = [&](int slot) { return w0 * g.attr[0][slot] + w1 * g.attr[1][slot] + w2 * g.attr[2][slot]; };
        float shade;
        if (p.shade == shading::phong)
            shade = shade_phong_pixel(p.lights, {lerp(ATTR_PX), lerp(ATTR_PY), lerp(ATTR_PZ)},
                                      {lerp(ATTR_NX), lerp(ATTR_NY), lerp(ATTR_NZ)});
        else shade = lerp(ATTR_SHADE);
        if (trilinear) {
            const float u = lerp(ATTR_U), v = lerp(ATTR_V);
            shade *= texture_sample_trilinear(*p.tex, u, v, uv_d.lod(*p.tex, u, v, inv_b), p.wrap);
        } else if (p.tex) {
            shade *= texture_sample(*p.tex, lerp(ATTR_U), lerp(ATTR_V), p.filter, p.wrap);
        }
        float &dst = target.pixels[y][x];
        if (translucent) {
            dst = clamp01(alpha * shade + (1.0f - alpha) * dst);
        } else {
            dst = clamp01(shade);
            *zp = z;
        }
    });
}

}  // namespace tiny3d::detail
