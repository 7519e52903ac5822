// texture_lod.h — the texture stage's level of detail (texture/: textures, mip chains,
// lookups; in: uv and its screen derivatives, out: a filtered texel; called by the
// per-pixel path, schedule/raster_pixel_path.cpp): the footprint shared by texture_lod
// (exact, libm's log2) and the per-pixel path (uv_derivatives::lod, with fast_log2). Not
// installed.
#ifndef TINY3D_TEXTURE_LOD_H
#define TINY3D_TEXTURE_LOD_H

#include <bit>
#include <cmath>
#include <cstdint>

#include "raster.h"

namespace tiny3d::detail {

// ρ² = max(|(a_x, b_x)|², |(a_y, b_y)|²) for the texel-space derivatives a = ∂u/∂·w,
// b = ∂v/∂·h along screen x and y (texture_lod's formula, squared); NaN when one is not
// finite.
inline float texel_footprint2(float a_x, float b_x, float a_y, float b_y) {
    if (!std::isfinite(a_x + b_x + a_y + b_y)) return NAN;
    const float along_x = a_x * a_x + b_x * b_x, along_y = a_y * a_y + b_y * b_y;
    return along_x > along_y ? along_x : along_y;
}

// log2 x within 2e-5 for normal x, exact at powers of two: x = 2^e · m, m ∈ [√½, √2), then
// log2 m = t·p(t), t = m − 1, p a minimax quartic. Below FLT_MIN −∞; +∞ and NaN pass
// through. Inline, where libm's log2f is a call on every trilinear lookup.
inline float fast_log2(float x) {
    const std::int32_t bits = std::bit_cast<std::int32_t>(x);
    // One unsigned compare for "positive, normal and finite": exponent field 1..254.
    if (static_cast<std::uint32_t>(bits - 0x00800000) >= 0x7f000000u) [[unlikely]]
        return x != x || x > 1.0f ? x : -INFINITY;  // NaN, +∞; 0, denormals, negatives
    const std::int32_t e = (bits - 0x3f3504f3) >> 23;  // 0x3f3504f3 = √½: m lands in [√½, √2)
    const float t = std::bit_cast<float>(bits - (e << 23)) - 1.0f;
    // Estrin's form: a chain of 3 multiply-adds instead of Horner's 4 (the pixel waits on it).
    const float t2 = t * t;
    const float p = (1.4425780085046165f - 0.7202417919512255f * t) +
                    t2 * (0.4866862123526085f - 0.3945753983578955f * t) + (t2 * t2) * 0.25265972067842235f;
    return static_cast<float>(e) + t * p;
}

}  // namespace tiny3d::detail

#endif
