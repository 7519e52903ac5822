// texture.cpp — grey textures: from a canvas (PGM files: texture_pgm.cpp); nearest and bilinear sampling
// with repeat or clamp addressing.
#include <cmath>

#include "raster.h"

namespace tiny3d {

result<texture> texture_from_canvas(const canvas_t &canvas) {
    if (canvas.width <= 0 || canvas.height <= 0 || !canvas.data)
        return error{"", 0, -1, "texture: the canvas is empty"};
    texture t;
    t.width = canvas.width;
    t.height = canvas.height;
    t.texels.assign(canvas.data, canvas.data + static_cast<std::size_t>(canvas.width) * canvas.height);
    return t;
}

namespace {

// Texel index along one axis for integer coordinate i (may be outside 0..n−1).
int address(int i, int n, texture_wrap wrap) {
    if (wrap == texture_wrap::clamp) return i < 0 ? 0 : (i >= n ? n - 1 : i);
    const int r = i % n;
    return r < 0 ? r + n : r;
}

// Reduces a coordinate for repeat addressing to [0, 1) so that huge values keep their
// fraction's precision relative to the texture and the integer conversion cannot overflow.
float reduce(float t, texture_wrap wrap) {
    if (wrap == texture_wrap::repeat) return t - std::floor(t);
    return t < -1.0f ? -1.0f : (t > 2.0f ? 2.0f : t);  // clamp: beyond ±1 texture all edge texels
}

}  // namespace

float texture_sample(const texture &tex, float u, float v, texture_filter filter, texture_wrap wrap) {
    if (tex.width <= 0 || tex.height <= 0 || tex.texels.size() < static_cast<std::size_t>(tex.width) * tex.height ||
        !std::isfinite(u) || !std::isfinite(v))
        return 0.0f;
    const float x = reduce(u, wrap) * static_cast<float>(tex.width);
    const float y = reduce(v, wrap) * static_cast<float>(tex.height);
    auto texel = [&](int i, int j) {
        return tex.texels[static_cast<std::size_t>(address(j, tex.height, wrap)) * tex.width +
                          address(i, tex.width, wrap)];
    };
    if (filter == texture_filter::nearest) return texel(static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
    // Bilinear between the four texel centres around (x, y) (centres at i + 0.5).
    const float fx = x - 0.5f, fy = y - 0.5f;
    const float x0 = std::floor(fx), y0 = std::floor(fy);
    const float tx = fx - x0, ty = fy - y0;
    const int i0 = static_cast<int>(x0), j0 = static_cast<int>(y0);
    const float top = texel(i0, j0) + (texel(i0 + 1, j0) - texel(i0, j0)) * tx;
    const float bottom = texel(i0, j0 + 1) + (texel(i0 + 1, j0 + 1) - texel(i0, j0 + 1)) * tx;
    return top + (bottom - top) * ty;
}

}  // namespace tiny3d
