// raster_pixel_path.cpp — the render context's per-pixel path: triangles with Phong
// shading, a texture or translucency, drawn with rasterize_triangle one pixel at a time.
#include <algorithm>

#include "render_context_impl.h"
#include "../texture/uv_derivatives.h"

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

namespace {

// A per-pixel-path triangle's shading: the shade at barycentrics l0..l2 (screen-affine, of
// the pixel centre) — perspective-correct weights, Phong or Gouraud, texture.
struct pixel_shader {
    const draw_params &p;
    const generic_triangle &g;
    bool trilinear, anisotropic;  // filters that need the derivatives of (u, v)
    // How the shade is found, chosen once per triangle: interpolated (flat, Gouraud), Phong
    // diffuse-only (the default material), or Phong with the material's Blinn-Phong model.
    enum class source { interpolated, phong, phong_material } from;
    viewer eye;
    uv_derivatives uv_d;

    pixel_shader(const draw_params &params, const generic_triangle &tri)
        : p(params), g(tri), trilinear(params.tex && params.filter == texture_filter::trilinear),
          anisotropic(params.tex && params.filter == texture_filter::anisotropic),
          from(params.shade != shading::phong          ? source::interpolated
               : material_is_lambert(params.surface) ? source::phong
                                                       : source::phong_material),
          eye(from == source::phong_material ? viewer_of(params.view_projection) : viewer{}) {
        if (trilinear || anisotropic) {
            float texel_u[3], texel_v[3];  // the vertices' (u, v) in texels
            for (int k = 0; k < 3; ++k) {
                texel_u[k] = g.attr[k][ATTR_U] * static_cast<float>(p.tex->width);
                texel_v[k] = g.attr[k][ATTR_V] * static_cast<float>(p.tex->height);
            }
            uv_d = uv_derivatives::of(g.v, texel_u, texel_v, p.perspective_correct);
        }
    }

    float operator()(float l0, float l1, float l2) const {
        // Perspective-correct weights: l_k/w_k normalised (attr/w and 1/w interpolated).
        float w0 = l0, w1 = l1, w2 = l2, inv_b = 1.0f;
        if (p.perspective_correct) {
            w0 = l0 * g.v[0].inv_w, w1 = l1 * g.v[1].inv_w, w2 = l2 * g.v[2].inv_w;
            inv_b = 1.0f / (w0 + w1 + w2);
        }
        const float lod = trilinear ? uv_d.lod(w0, w1, w2, inv_b) : 0.0f;  // before the normalisation
        float d[4] = {0, 0, 0, 0};  // texels per pixel (anisotropic)
        if (anisotropic) uv_d.at(w0, w1, w2, inv_b, d);
        if (p.perspective_correct) w0 *= inv_b, w1 *= inv_b, w2 *= inv_b;
        auto lerp = [&](int slot) { return w0 * g.attr[0][slot] + w1 * g.attr[1][slot] + w2 * g.attr[2][slot]; };
        float shade;
        if (from == source::phong)
            shade = shade_phong_pixel(p.lights, {lerp(ATTR_PX), lerp(ATTR_PY), lerp(ATTR_PZ)},
                                      {lerp(ATTR_NX), lerp(ATTR_NY), lerp(ATTR_NZ)});
        else if (from == source::phong_material)
            shade = shade_point_material(p.lights, p.surface, eye, {lerp(ATTR_PX), lerp(ATTR_PY), lerp(ATTR_PZ)},
                                         unit_or_zero({lerp(ATTR_NX), lerp(ATTR_NY), lerp(ATTR_NZ)}));
        else shade = lerp(ATTR_SHADE);
        if (trilinear) shade *= texture_sample_trilinear(*p.tex, lerp(ATTR_U), lerp(ATTR_V), lod, p.wrap);
        else if (anisotropic) {  // (d in texels per pixel; the filter takes uv units)
            const float w = static_cast<float>(p.tex->width), h = static_cast<float>(p.tex->height);
            shade *= texture_sample_anisotropic(*p.tex, lerp(ATTR_U), lerp(ATTR_V), d[0] / w, d[1] / h, d[2] / w,
                                                d[3] / h, p.anisotropy, p.wrap);
        } else if (p.tex) shade *= texture_sample(*p.tex, lerp(ATTR_U), lerp(ATTR_V), p.filter, p.wrap);
        return shade;
    }
};

// A pixel or sample passing the depth test: "over" blend with alpha (colour only), or an
// opaque write of colour and depth.
inline void write_fragment(const draw_params &p, float &dst, float &stored_z, float z, float shade) {
    if (p.alpha < 1.0f) {
        const float alpha = std::clamp(p.alpha, 0.0f, 1.0f);
        dst = clamp01(alpha * shade + (1.0f - alpha) * dst);
    } else {
        dst = clamp01(shade);
        stored_z = z;
    }
}

// Depth at barycentrics (·, l1, l2): from vertex 0 plus the barycentric steps, exact for a
// constant depth (l0 + l1 + l2 is not exactly 1 in float), so coplanar meshes at one depth
// tie exactly, as on the fast path, and `less_equal` passes can redraw them.
inline float depth_at(const generic_triangle &g, float l1, float l2) {
    return g.v[0].z + l1 * (g.v[1].z - g.v[0].z) + l2 * (g.v[2].z - g.v[0].z);
}

}  // namespace

void draw_generic_rows(canvas_t &target, zbuffer &depth, const draw_params &p, const generic_triangle &g, int y0,
                       int y1) {
    const pixel_rect band{0, y0, target.width, y1};
    const pixel_shader shade(p, g);
    rasterize_triangle(g.v[0], g.v[1], g.v[2], band, [&](int x, int y, float l0, float l1, float l2) {
        const float z = depth_at(g, l1, l2);
        float *zp = depth.row(y) + x;
        if (!depth_passes(p.depth, z, *zp)) return;
        write_fragment(p, target.pixels[y][x], *zp, z, shade(l0, l1, l2));
    });
}

void draw_generic_samples(sample_store &tile, const sample_pattern &pat, const draw_params &p,
                          const generic_triangle &g, int y0, int y1) {
    const pixel_rect band{0, y0, tile.width(), y1};
    std::int32_t X[3], Y[3];  // on the pattern's grid, as emit() binned it
    for (int k = 0; k < 3; ++k)
        if (!snap_screen_point(g.v[k].x, g.v[k].y, pat.bits, X[k], Y[k])) return;
    const triangle_edges t = triangle_setup_snapped(X, Y, band, cull_mode::none, pat.bits);
    if (t.area2 == 0) return;
    const pixel_shader shade_at(p, g);
    const int S = pat.count;
    const float zv[3] = {g.v[0].z, g.v[1].z, g.v[2].z};
    const double vx[3] = {g.v[0].x, g.v[1].x, g.v[2].x}, vy[3] = {g.v[0].y, g.v[1].y, g.v[2].y};
    fast_triangle planes;  // the depth plane's steps (zdx, zdy)
    planes.min_x = planes.min_y = 0;
    set_planes(vx, vy, zv, zv, planes);
    float dz[MSAA_MAX_SAMPLES];
    for (int k = 0; k < S; ++k) dz[k] = planes.zdx * pat.fdx[k] + planes.zdy * pat.fdy[k];
    const double inv_area = 1.0 / static_cast<double>(t.area2);
    for_each_covered_pixel(t, X, Y, pat, band, [&](int x, int y, unsigned mask) {
        // Barycentrics of the centre (unbiased edge values, as rasterize_triangle).
        const float l0 = static_cast<float>(static_cast<double>(t.c[0] + t.a[0] * x + t.b[0] * y) * inv_area);
        const float l1 = static_cast<float>(static_cast<double>(t.c[1] + t.a[1] * x + t.b[1] * y) * inv_area);
        const float l2 = 1.0f - l0 - l1;
        const float zc = depth_at(g, l1, l2);
        float *px = tile.touch(x, y);
        bool shaded = false;
        float shade = 0.0f;
        for (int k = 0; k < S; ++k) {
            const float z = zc + dz[k];
            if (!((mask >> k) & 1) || !depth_passes(p.depth, z, px[k])) continue;
            if (!shaded) shade = shade_at(l0, l1, l2), shaded = true;  // once per pixel
            write_fragment(p, px[tile.colour_offset() + k], px[k], z, shade);
        }
    });
}

}  // namespace tiny3d::detail
