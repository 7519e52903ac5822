// texture_mipmap.cpp — the mipmap chain of a texture: exact box averages, level by level,
// separable (rows, then columns), for any size (odd sizes weight the straddled texels).
#include <algorithm>
#include <string>

#include "raster.h"

namespace tiny3d {

namespace {

// out[i] = the mean of in[] over [i·r, (i + 1)·r), r = n / m, each input sample weighted by
// its overlap (in[] is read with stride `stride`, out[] written with `out_stride`).
void box_reduce(const float *in, int n, std::size_t stride, float *out, int m, std::size_t out_stride) {
    const double r = static_cast<double>(n) / m;
    for (int i = 0; i < m; ++i) {
        const double lo = i * r, hi = (i + 1) * r;
        double sum = 0;
        for (int k = static_cast<int>(lo); k < n && k < hi; ++k) {
            const double overlap = std::min<double>(k + 1, hi) - std::max<double>(k, lo);
            if (overlap > 0) sum += overlap * in[static_cast<std::size_t>(k) * stride];
        }
        out[static_cast<std::size_t>(i) * out_stride] = static_cast<float>(sum / r);
    }
}

}  // namespace

status build_mipmaps(texture &tex) {
    if (tex.width <= 0 || tex.height <= 0 ||
        tex.texels.size() != static_cast<std::size_t>(tex.width) * static_cast<std::size_t>(tex.height))
        return error{"", 0, -1, "build_mipmaps: texture is " + std::to_string(tex.width) + " x " +
                                    std::to_string(tex.height) + " with " + std::to_string(tex.texels.size()) +
                                    " texels"};
    std::vector<texture_level> levels;
    std::vector<float> rows;  // the level reduced along x only
    const float *src = tex.texels.data();
    int w = tex.width, h = tex.height;
    while (w > 1 || h > 1) {
        texture_level next;
        next.width = std::max(1, w / 2);
        next.height = std::max(1, h / 2);
        rows.assign(static_cast<std::size_t>(next.width) * h, 0.0f);
        for (int y = 0; y < h; ++y)
            box_reduce(src + static_cast<std::size_t>(y) * w, w, 1, rows.data() + static_cast<std::size_t>(y) * next.width,
                       next.width, 1);
        next.texels.assign(static_cast<std::size_t>(next.width) * next.height, 0.0f);
        for (int x = 0; x < next.width; ++x)
            box_reduce(rows.data() + x, h, static_cast<std::size_t>(next.width), next.texels.data() + x, next.height,
                       static_cast<std::size_t>(next.width));
        levels.push_back(std::move(next));
        src = levels.back().texels.data();
        w = levels.back().width;
        h = levels.back().height;
    }
    tex.mipmaps = std::move(levels);
    return {};
}

}  // namespace tiny3d
