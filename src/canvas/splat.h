// splat.h — (internal) the report's bilinear splat, inline so the faithful line's inner
// loop (a disc of splats every 0.5 px) does not pay a call and libm floorf per splat.
// set_pixel_f (canvas.cpp) is this function; the pixels are bit-identical either way.
// Also floor_to_int, which the line drawers (src/lines/) use too.
#ifndef TINY3D_SPLAT_H
#define TINY3D_SPLAT_H

#include <cmath>

#include "canvas.h"
#include "math3d.h"

namespace tiny3d::detail {

using tiny3d::clamp01;  // math3d.h

// floor(v) as an int for |v| < 2^31: truncate, then step down for negative non-integers
// (exact, unlike adding an offset first, which can round; and no libm call, which
// std::floor is on baseline x86-64).
template <class T>
inline int floor_to_int(T v) {
    const int t = static_cast<int>(v);
    return t - (v < static_cast<T>(t) ? 1 : 0);
}

// The report's set_pixel_f in the report's convention (integer coordinates are pixel
// centres): x0 = floor(x), dx = x − x0, and pixel (x0 + i, y0 + j), i, j ∈ {0, 1}, gains
// intensity·(1 − |i − dx|)(1 − |j − dy|), clamped to 0..1; off-canvas parts and
// non-finite input are ignored.
inline void splat(canvas_t *c, float x, float y, float intensity) {
    if (!c || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(intensity)) return;
    // Far off the canvas: nothing to do (also keeps the int conversion in range).
    if (x <= -2.0f || y <= -2.0f || x >= float(c->width) + 1.0f || y >= float(c->height) + 1.0f) return;
    const int x0 = floor_to_int(x);
    const int y0 = floor_to_int(y);
    const float dx = x - float(x0);
    const float dy = y - float(y0);
    for (int j = 0; j <= 1; ++j)
        for (int i = 0; i <= 1; ++i) {
            const int xi = x0 + i, yj = y0 + j;
            if (xi < 0 || xi >= c->width || yj < 0 || yj >= c->height) continue;
            const float w = (1.0f - std::fabs(float(i) - dx)) * (1.0f - std::fabs(float(j) - dy));
            const float v = c->pixels[yj][xi] + intensity * w;
            c->pixels[yj][xi] = clamp01(v);
        }
}

}  // namespace tiny3d::detail

#endif
