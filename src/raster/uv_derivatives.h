// uv_derivatives.h — screen-space derivatives of a triangle's interpolated (u, v), for the
// trilinear level of detail (texture_lod). Not installed.
#ifndef TINY3D_UV_DERIVATIVES_H
#define TINY3D_UV_DERIVATIVES_H

#include "raster.h"

namespace tiny3d::detail {

// With barycentrics l_k (affine in screen x, y) and weights q_k (1/w_k perspective-correct,
// 1 affine): u = A/B, A = Σ l_k q_k u_k, B = Σ l_k q_k, both affine in screen space, so
// ∂u/∂x = (∂A/∂x − u·∂B/∂x) / B exactly (the quotient rule); likewise v and y.
struct uv_derivatives {
    float au_x = 0, au_y = 0, av_x = 0, av_y = 0, b_x = 0, b_y = 0;

    // v: the screen vertices; u, v: their texture coordinates.
    static uv_derivatives of(const screen_vertex s[3], const float u[3], const float v[3], bool perspective) {
        uv_derivatives d;
        const double x1 = double(s[1].x) - s[0].x, y1 = double(s[1].y) - s[0].y;
        const double x2 = double(s[2].x) - s[0].x, y2 = double(s[2].y) - s[0].y;
        const double det = x1 * y2 - x2 * y1;
        if (!(det != 0)) return d;
        // ∂l_k/∂x, ∂l_k/∂y (l_0 = 1 − l_1 − l_2).
        const double lx[3] = {-(y2 - y1) / det, y2 / det, -y1 / det};
        const double ly[3] = {(x2 - x1) / det, -x2 / det, x1 / det};
        double au_x = 0, au_y = 0, av_x = 0, av_y = 0, b_x = 0, b_y = 0;
        for (int k = 0; k < 3; ++k) {
            const double q = perspective ? s[k].inv_w : 1.0;
            au_x += lx[k] * q * u[k], au_y += ly[k] * q * u[k];
            av_x += lx[k] * q * v[k], av_y += ly[k] * q * v[k];
            b_x += lx[k] * q, b_y += ly[k] * q;
        }
        d.au_x = float(au_x), d.au_y = float(au_y), d.av_x = float(av_x), d.av_y = float(av_y);
        d.b_x = float(b_x), d.b_y = float(b_y);
        return d;
    }

    // The level of detail at a pixel with interpolated (u, v) and 1/B (1 when affine).
    float lod(const texture &tex, float u, float v, float inv_b) const {
        return texture_lod(tex, (au_x - u * b_x) * inv_b, (av_x - v * b_x) * inv_b, (au_y - u * b_y) * inv_b,
                           (av_y - v * b_y) * inv_b);
    }
};

}  // namespace tiny3d::detail

#endif
