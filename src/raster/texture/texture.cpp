// texture.cpp — grey textures: from a canvas (PGM files: texture_pgm.cpp); nearest, bilinear
// and trilinear sampling with repeat or clamp addressing (mipmaps: texture_mipmap.cpp).
#include <cmath>

#include "raster.h"
#include "texture_lod.h"
#include "../../canvas/splat.h"  // floor_to_int

namespace tiny3d {

result<texture> texture_from_canvas(const canvas_t &canvas) {
    if (canvas.width <= 0 || canvas.height <= 0 || !canvas.data)
        return error{"", 0, -1, "texture: the canvas is empty"};
    texture t;
    t.width = canvas.width;
    t.height = canvas.height;
    t.texels.assign(canvas.data, canvas.data + static_cast<std::size_t>(canvas.width) * canvas.height);
    const status built = build_mipmaps(t);
    if (!built) return built.err();
    return t;
}

namespace {

// Texel index along one axis for integer coordinate i (may be outside 0..n−1). Callers
// pass coordinates reduced first (reduce): with repeat, x ∈ [0, 1]·n, so i ∈ [−1, n] and one
// wrap by n suffices (no division per texel: it was most of a bilinear lookup's time).
int address(int i, int n, texture_wrap wrap) {
    if (wrap == texture_wrap::clamp) return i < 0 ? 0 : (i >= n ? n - 1 : i);
    return i < 0 ? i + n : (i >= n ? i - n : i);
}

// ⌊t⌋ for finite t, without a libm call (x86-64's baseline has no rounding instruction):
// from 2^23 on every float is an integer; below, truncation then one step down. (Not
// float(floor_to_int(t)): the extra int → float conversion sits on the lookup's critical path.)
float floor_of(float t) {
    if (!(std::fabs(t) < 8388608.0f)) return t;
    const float f = static_cast<float>(static_cast<int>(t));
    return f > t ? f - 1.0f : f;
}

// Reduces a coordinate for repeat addressing to [0, 1] so that huge values keep their
// fraction's precision relative to the texture and the integer conversion cannot overflow.
float reduce(float t, texture_wrap wrap) {
    if (wrap == texture_wrap::repeat) return t - floor_of(t);
    return t < -1.0f ? -1.0f : (t > 2.0f ? 2.0f : t);  // clamp: beyond ±1 texture all edge texels
}

// ⌊t⌋ for |t| < 2^31: truncation, then one step down in a branch rather than a select, as
// t < 0 only in the first half texel (or beyond the edge with clamp): the branch is
// predicted and the texel address need not wait for the compare.
int floor_index(float t) {
    int i = static_cast<int>(t);
    if (t < static_cast<float>(i)) [[unlikely]]
        --i;
    return i;
}

// One level's texels (the base level or a mipmap), sampled bilinearly between the four
// texel centres around (u, v), given as ru = reduce(u), rv = reduce(v) (the same for every
// level, so trilinear reduces once).
float bilinear_reduced(const float *texels, int width, int height, float ru, float rv, texture_wrap wrap) {
    const float fx = ru * static_cast<float>(width) - 0.5f;  // centres at i + 0.5
    const float fy = rv * static_cast<float>(height) - 0.5f;
    const int i0 = floor_index(fx), j0 = floor_index(fy);  // |fx|, |fy| ≤ 2n
    const float tx = fx - static_cast<float>(i0), ty = fy - static_cast<float>(j0);
    const int left = address(i0, width, wrap), right = address(i0 + 1, width, wrap);
    const float *row0 = texels + static_cast<std::size_t>(address(j0, height, wrap)) * width;
    const float *row1 = texels + static_cast<std::size_t>(address(j0 + 1, height, wrap)) * width;
    const float top = row0[left] + (row0[right] - row0[left]) * tx;
    const float bottom = row1[left] + (row1[right] - row1[left]) * tx;
    return top + (bottom - top) * ty;
}

bool usable(const texture &tex, float u, float v) {
    return tex.width > 0 && tex.height > 0 && tex.texels.size() >= static_cast<std::size_t>(tex.width) * tex.height &&
           std::isfinite(u) && std::isfinite(v);
}

}  // namespace

float texture_sample(const texture &tex, float u, float v, texture_filter filter, texture_wrap wrap) {
    if (!usable(tex, u, v)) return 0.0f;
    if (filter == texture_filter::nearest) {
        const float x = reduce(u, wrap) * static_cast<float>(tex.width);
        const float y = reduce(v, wrap) * static_cast<float>(tex.height);
        const int i = address(detail::floor_to_int(x), tex.width, wrap);
        const int j = address(detail::floor_to_int(y), tex.height, wrap);
        return tex.texels[static_cast<std::size_t>(j) * tex.width + i];
    }
    return bilinear_reduced(tex.texels.data(), tex.width, tex.height, reduce(u, wrap), reduce(v, wrap), wrap);
}

float texture_lod(const texture &tex, float du_dx, float dv_dx, float du_dy, float dv_dy) {
    const float w = static_cast<float>(tex.width), h = static_cast<float>(tex.height);
    return 0.5f * std::log2(detail::texel_footprint2(du_dx * w, dv_dx * h, du_dy * w, dv_dy * h));  // log2 √ρ²
}

float texture_sample_trilinear(const texture &tex, float u, float v, float lod, texture_wrap wrap) {
    if (!usable(tex, u, v)) return 0.0f;
    const int last = static_cast<int>(tex.mipmaps.size());
    if (!(lod > 0.0f)) lod = 0.0f;  // also NaN
    if (lod >= static_cast<float>(last)) lod = static_cast<float>(last);
    // k = ⌊λ⌋ by compares and branches, not a conversion: λ varies slowly from pixel to
    // pixel, so the processor predicts k and starts the texel loads before λ is known.
    // (λ ≤ last, so the search stops at the last level by itself.)
    int k = 0;
    float floor_lod = 0.0f;
    while (lod >= floor_lod + 1.0f) ++k, floor_lod += 1.0f;
    const float t = lod - floor_lod;
    const float ru = reduce(u, wrap), rv = reduce(v, wrap);
    auto level = [&](int l) {
        if (l == 0) return bilinear_reduced(tex.texels.data(), tex.width, tex.height, ru, rv, wrap);
        const texture_level &m = tex.mipmaps[static_cast<std::size_t>(l - 1)];
        return bilinear_reduced(m.texels.data(), m.width, m.height, ru, rv, wrap);
    };
    const float a = level(k);
    if (t == 0.0f || k == last) return a;
    return a + (level(k + 1) - a) * t;
}

}  // namespace tiny3d
