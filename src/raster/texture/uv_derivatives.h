// uv_derivatives.h — screen-space derivatives of a triangle's interpolated (u, v), for the
// trilinear level of detail (texture_lod). Not installed.
#ifndef TINY3D_UV_DERIVATIVES_H
#define TINY3D_UV_DERIVATIVES_H

#include "raster.h"
#include "texture_lod.h"

namespace tiny3d::detail {

// u = A/B with A = Σ l_k q_k u_k, B = Σ l_k q_k affine in screen space (q_k = 1/w_k, or 1),
// so ∂u/∂x = (∂A/∂x·B − A·∂B/∂x) / B², whose numerator Σ w_k (∂A/∂x − u_k ∂B/∂x) is a dot
// product of the unnormalised weights w_k = l_k q_k with per-triangle constants: it need not
// wait for the division 1/B.
struct uv_derivatives {
    // numerator[d][k]: the constant of w_k in the numerator of derivative d =
    // ∂u/∂x, ∂v/∂x, ∂u/∂y, ∂v/∂y (in the units of the (u, v) given to `of`).
    float numerator[4][3] = {};

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
        for (int k = 0; k < 3; ++k) {
            d.numerator[0][k] = float(au_x - u[k] * b_x), d.numerator[1][k] = float(av_x - v[k] * b_x);
            d.numerator[2][k] = float(au_y - u[k] * b_y), d.numerator[3][k] = float(av_y - v[k] * b_y);
        }
        return d;
    }

    // ∂u/∂x, ∂v/∂x, ∂u/∂y, ∂v/∂y at a pixel (weights as `lod`), in the units given to `of`.
    void at(float w0, float w1, float w2, float inv_b, float out[4]) const {
        const float s = inv_b * inv_b;
        for (int d = 0; d < 4; ++d) out[d] = (w0 * numerator[d][0] + w1 * numerator[d][1] + w2 * numerator[d][2]) * s;
    }

    // The level of detail at a pixel with weights w_k = l_k q_k before the normalisation and
    // inv_b = 1/Σ w_k (w_k = l_k and inv_b = 1 when affine); within 1e-5 of texture_lod of
    // the same derivatives (half fast_log2's error). 1/B² scales ρ² once, as ρ²·(1/B)⁴.
    float lod(float w0, float w1, float w2, float inv_b) const {
        auto at = [&](const float (&c)[3]) { return w0 * c[0] + w1 * c[1] + w2 * c[2]; };
        const float rho2_b4 = texel_footprint2(at(numerator[0]), at(numerator[1]), at(numerator[2]), at(numerator[3]));
        const float s = inv_b * inv_b;
        return 0.5f * fast_log2(rho2_b4 * s * s);
    }
};

}  // namespace tiny3d::detail

#endif
