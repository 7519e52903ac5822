// uv_derivatives.h — screen-space derivatives of a triangle's interpolated (u, v), for the
// trilinear level of detail (texture_lod). Not installed.
#ifndef TINY3D_UV_DERIVATIVES_H
#define TINY3D_UV_DERIVATIVES_H

#include "raster.h"
#include "texture_lod.h"

namespace tiny3d::detail {

// With barycentrics l_k (affine in screen x, y) and weights q_k (1/w_k perspective-correct,
// 1 affine): u = A/B, A = Σ l_k q_k u_k, B = Σ l_k q_k, both affine in screen space, so
// ∂u/∂x = (∂A/∂x − u·∂B/∂x) / B exactly (the quotient rule); likewise v and y.
struct uv_derivatives {
    float au_x = 0, au_y = 0, av_x = 0, av_y = 0, b_x = 0, b_y = 0;

    // s: the screen vertices; u, v: their texture coordinates in texels (u·width, v·height),
    // so that the derivatives come out in texels per pixel.
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

    // The level of detail at a pixel from the sums A_u = Σ l_k q_k u_k, A_v (in texels, as
    // `of` was given), B = Σ l_k q_k before the division and inv_b = 1/B (B = 1 and
    // inv_b = 1 when affine); within 1e-5 of texture_lod (half fast_log2's error).
    // ∂u/∂x = (∂A_u/∂x·B − A_u·∂B/∂x)/B², the quotient rule with u = A_u/B: the numerators
    // need not wait for the division, which shortens the chain of latencies from a pixel's
    // barycentrics to its texel loads; 1/B² scales ρ² once, as ρ²/B⁴.
    float lod(float a_u, float a_v, float b, float inv_b) const {
        const float rho2_b4 = texel_footprint2(au_x * b - a_u * b_x, av_x * b - a_v * b_x, au_y * b - a_u * b_y,
                                               av_y * b - a_v * b_y);
        const float s = inv_b * inv_b;
        return 0.5f * fast_log2(rho2_b4 * s * s);
    }
};

}  // namespace tiny3d::detail

#endif
