// texture.cpp — grey textures: from a canvas (PGM files: texture_pgm.cpp); nearest, bilinear,
// trilinear and anisotropic sampling with repeat or clamp addressing (mipmaps:
// texture_mipmap.cpp).
#include <algorithm>
#include <cmath>

#include "raster.h"
#include "texture_lod.h"
#include "texture_walk.h"
#include "../../kernels.h"
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

// Texel index along one axis for i ∈ [−1, n] (coordinates reduced first): one wrap by n
// suffices, with no division per texel.
int address(int i, int n, texture_wrap wrap) {
    if (wrap == texture_wrap::clamp) return i < 0 ? 0 : (i >= n ? n - 1 : i);
    return i < 0 ? i + n : (i >= n ? i - n : i);
}

// ⌊t⌋ for finite t without a libm call (the x86-64 baseline has no rounding instruction);
// from 2^23 on every float is an integer.
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

// ⌊t⌋ for |t| < 2^31; a branch, not a select: t < 0 is rare and predicted, so the texel
// address need not wait for the compare.
int floor_index(float t) {
    int i = static_cast<int>(t);
    if (t < static_cast<float>(i)) [[unlikely]]
        --i;
    return i;
}

// One level of the mip chain (0: the base texture).
struct level_view {
    const float *texels;
    int width, height;
};

// One level sampled bilinearly between the four texel centres around the texel-space point
// (fx, fy) = (u·width − ½, v·height − ½) (centres at i + ½), |fx|, |fy| < 2 × the level's size.
[[gnu::always_inline]] inline float bilinear_at(const level_view &l, float fx, float fy, texture_wrap wrap) {
    const int i0 = floor_index(fx), j0 = floor_index(fy);
    const float tx = fx - static_cast<float>(i0), ty = fy - static_cast<float>(j0);
    const int left = address(i0, l.width, wrap), right = address(i0 + 1, l.width, wrap);
    const float *row0 = l.texels + static_cast<std::size_t>(address(j0, l.height, wrap)) * l.width;
    const float *row1 = l.texels + static_cast<std::size_t>(address(j0 + 1, l.height, wrap)) * l.width;
    const float top = row0[left] + (row0[right] - row0[left]) * tx;
    const float bottom = row1[left] + (row1[right] - row1[left]) * tx;
    return top + (bottom - top) * ty;
}

// Bilinear at (u, v) given as ru = reduce(u), rv = reduce(v) (the same for every level, so
// trilinear reduces once).
[[gnu::always_inline]] inline float bilinear_reduced(const level_view &l, float ru, float rv, texture_wrap wrap) {
    return bilinear_at(l, ru * static_cast<float>(l.width) - 0.5f, rv * static_cast<float>(l.height) - 0.5f, wrap);
}

bool usable(const texture &tex) {
    return tex.width > 0 && tex.height > 0 && tex.texels.size() >= static_cast<std::size_t>(tex.width) * tex.height;
}

bool usable(const texture &tex, float u, float v) { return usable(tex) && std::isfinite(u) && std::isfinite(v); }

level_view level_at(const texture &tex, int l) {
    if (l == 0) return {tex.texels.data(), tex.width, tex.height};
    const texture_level &m = tex.mipmaps[static_cast<std::size_t>(l - 1)];
    return {m.texels.data(), m.width, m.height};
}

// The two levels a trilinear lookup at λ blends, found once so that the anisotropic taps,
// which all share λ, do not search for them again.
struct level_pair {
    level_view fine, coarse;
    float t;     // λ − ⌊λ⌋
    bool blend;  // false: `fine` alone (t = 0, or λ at the last level)
};

[[gnu::always_inline]] inline level_pair levels_for(const texture &tex, float lod) {
    const int last = static_cast<int>(tex.mipmaps.size());
    if (!(lod > 0.0f)) lod = 0.0f;  // also NaN
    if (lod >= static_cast<float>(last)) lod = static_cast<float>(last);
    // k = ⌊λ⌋ by predicted branches, not a conversion (λ varies slowly from pixel to pixel),
    // so the texel loads start before λ is known.
    int k = 0;
    float floor_lod = 0.0f;
    while (lod >= floor_lod + 1.0f) ++k, floor_lod += 1.0f;
    const float t = lod - floor_lod;
    const bool blend = !(t == 0.0f || k == last);
    return {level_at(tex, k), blend ? level_at(tex, k + 1) : level_view{}, t, blend};
}

// Trilinear: both levels sampled bilinearly at the same reduced (u, v), then blended.
[[gnu::always_inline]] inline float sample_levels(const level_pair &levels, float u, float v, texture_wrap wrap) {
    const float ru = reduce(u, wrap), rv = reduce(v, wrap);
    const float a = bilinear_reduced(levels.fine, ru, rv, wrap);
    if (!levels.blend) return a;
    return a + (bilinear_reduced(levels.coarse, ru, rv, wrap) - a) * levels.t;
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
    return bilinear_reduced(level_at(tex, 0), reduce(u, wrap), reduce(v, wrap), wrap);
}

float texture_lod(const texture &tex, float du_dx, float dv_dx, float du_dy, float dv_dy) {
    const float w = static_cast<float>(tex.width), h = static_cast<float>(tex.height);
    return 0.5f * std::log2(detail::texel_footprint2(du_dx * w, dv_dx * h, du_dy * w, dv_dy * h));  // log2 √ρ²
}

float texture_sample_trilinear(const texture &tex, float u, float v, float lod, texture_wrap wrap) {
    if (!usable(tex, u, v)) return 0.0f;
    return sample_levels(levels_for(tex, lod), u, v, wrap);
}

float texture_sample_anisotropic(const texture &tex, float u, float v, float du_dx, float dv_dx, float du_dy,
                                 float dv_dy, int max_taps, texture_wrap wrap) {
    if (!usable(tex, u, v)) return 0.0f;
    const float w = static_cast<float>(tex.width), h = static_cast<float>(tex.height);
    // The footprint's two axes in texels (the parallelogram spanned by the screen steps), as
    // in EXT_texture_filter_anisotropic: P_x = |∂(u, v)/∂x|, P_y = |∂(u, v)/∂y|.
    const float px2 = du_dx * w * (du_dx * w) + dv_dx * h * (dv_dx * h);
    const float py2 = du_dy * w * (du_dy * w) + dv_dy * h * (dv_dy * h);
    if (!std::isfinite(px2 + py2)) return texture_sample_trilinear(tex, u, v, 0.0f, wrap);
    const bool x_major = px2 >= py2;
    const float major2 = x_major ? px2 : py2, minor2 = x_major ? py2 : px2;
    const int limit = std::clamp(max_taps, 1, 64);
    // Magnified (the whole footprint under 1/√2 texel along its longer axis, so within a
    // bilinear cell or two): one bilinear lookup at the centre, as a magnification filter.
    // The taps would change little there, and such pixels are most of a near, textured
    // surface (mipmaps.md has the cost and the error of this choice). A GPU's rule is looser:
    // magnified whenever log2(major / N) ≤ 0.
    if (major2 <= 0.5f) return sample_levels(levels_for(tex, 0.0f), u, v, wrap);
    // N = ⌈major / minor⌉ taps, at most `limit`; each filters major / N texels across, so the
    // level is log2(major / N) — the minor axis's when N is not clamped.
    const float ratio = minor2 > 0.0f ? std::sqrt(major2 / minor2) : static_cast<float>(limit);
    // ⌈r⌉ for r = min(ratio, limit) ∈ [1, 64] (NaN: 1 tap): truncation, then one up.
    const float r = std::min(ratio, static_cast<float>(limit));
    const int whole = r >= 1.0f ? static_cast<int>(r) : 1;
    const int taps = std::min(whole + (static_cast<float>(whole) < r ? 1 : 0), limit);
    const float n = static_cast<float>(taps), inv_n = 1.0f / n;
    const float lod = 0.5f * detail::fast_log2(major2 * inv_n * inv_n);  // −∞ for a zero footprint: level 0
    const level_pair levels = levels_for(tex, lod);
    if (taps == 1) return sample_levels(levels, u, v, wrap);
    // Taps evenly spread over the major axis, centred on (u, v): tap i at (i + ½)/N − ½ of it.
    const float step_u = (x_major ? du_dx : du_dy) * inv_n, step_v = (x_major ? dv_dx : dv_dy) * inv_n;
    const float first = 0.5f - 0.5f * n;  // tap 0's offset, in steps
    if (wrap == texture_wrap::repeat && std::fabs(step_u) * n <= 0.5f && std::fabs(step_v) * n <= 0.5f) {
        // The usual case: the footprint spans at most half the texture, so each level's taps
        // stay within the one wrap tap_walk allows.
        const float ru = reduce(u, wrap), rv = reduce(v, wrap);
        float (*const walk_taps)(const detail::tap_walk &) = detail::default_kernels().walk_taps;
        const auto walk = [&](const level_view &l) {
            const float w_l = static_cast<float>(l.width), h_l = static_cast<float>(l.height);
            const detail::tap_walk taps_here{l.texels, l.width, l.height, (ru + step_u * first) * w_l - 0.5f,
                                             (rv + step_v * first) * h_l - 0.5f, step_u * w_l, step_v * h_l, taps};
            return walk_taps ? walk_taps(taps_here) : detail::walk_taps_portable(taps_here);
        };
        const float fine_sum = walk(levels.fine);
        if (!levels.blend) return fine_sum * inv_n;
        const float coarse_sum = walk(levels.coarse);
        // The mean of the taps' trilinear blends a + (b − a)·t is the blend of their means.
        return (fine_sum + (coarse_sum - fine_sum) * levels.t) * inv_n;
    }
    float tap_u = u + step_u * first, tap_v = v + step_v * first, sum = 0.0f;
    for (int i = 0; i < taps; ++i, tap_u += step_u, tap_v += step_v)
        if (std::isfinite(tap_u) && std::isfinite(tap_v)) [[likely]]
            sum += sample_levels(levels, tap_u, tap_v, wrap);
    return sum * inv_n;
}

namespace detail {

float walk_taps_portable(const tap_walk &w) {
    const level_view level{w.texels, w.width, w.height};
    float lanes[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < w.taps; ++i) {
        const float k = static_cast<float>(i);
        lanes[i % 8] += bilinear_at(level, w.fx0 + k * w.sx, w.fy0 + k * w.sy, texture_wrap::repeat);
    }
    return ((lanes[0] + lanes[4]) + (lanes[2] + lanes[6])) + ((lanes[1] + lanes[5]) + (lanes[3] + lanes[7]));
}

}  // namespace detail

}  // namespace tiny3d
