// texture_anisotropic.cpp — anisotropic filtering: several trilinear taps along the major
// axis of a pixel's footprint in texture space. See include/raster.h.
#include <algorithm>
#include <cmath>

#include "raster.h"
#include "texture_lod.h"

namespace tiny3d {

float texture_sample_anisotropic(const texture &tex, float u, float v, float du_dx, float dv_dx, float du_dy,
                                 float dv_dy, int max_taps, texture_wrap wrap) {
    if (!std::isfinite(u) || !std::isfinite(v)) return 0.0f;
    const float w = static_cast<float>(tex.width), h = static_cast<float>(tex.height);
    // The footprint's two axes in texels (the parallelogram spanned by the screen steps), as
    // in EXT_texture_filter_anisotropic: P_x = |∂(u, v)/∂x|, P_y = |∂(u, v)/∂y|.
    const float px2 = du_dx * w * (du_dx * w) + dv_dx * h * (dv_dx * h);
    const float py2 = du_dy * w * (du_dy * w) + dv_dy * h * (dv_dy * h);
    if (!std::isfinite(px2 + py2)) return texture_sample_trilinear(tex, u, v, 0.0f, wrap);
    const bool x_major = px2 >= py2;
    const float major2 = x_major ? px2 : py2, minor2 = x_major ? py2 : px2;
    const int limit = std::clamp(max_taps, 1, 64);
    // N = ⌈major / minor⌉ taps, at most `limit`; each filters major / N texels across, so the
    // level is log2(major / N) — the minor axis's when N is not clamped.
    const float ratio = minor2 > 0.0f ? std::sqrt(major2 / minor2) : static_cast<float>(limit);
    const int taps = std::clamp(static_cast<int>(std::ceil(std::min(ratio, static_cast<float>(limit)))), 1, limit);
    const float n = static_cast<float>(taps);
    const float lod = 0.5f * detail::fast_log2(major2 / (n * n));  // −∞ for a zero footprint: level 0
    if (taps == 1) return texture_sample_trilinear(tex, u, v, lod, wrap);
    // Taps evenly spread over the major axis, centred on (u, v): tap i at (i + ½)/N − ½ of it.
    const float step_u = (x_major ? du_dx : du_dy) / n, step_v = (x_major ? dv_dx : dv_dy) / n;
    float tap_u = u - step_u * (0.5f * n - 0.5f), tap_v = v - step_v * (0.5f * n - 0.5f);
    float sum = 0.0f;
    for (int i = 0; i < taps; ++i, tap_u += step_u, tap_v += step_v)
        sum += texture_sample_trilinear(tex, tap_u, tap_v, lod, wrap);
    return sum / n;
}

}  // namespace tiny3d
