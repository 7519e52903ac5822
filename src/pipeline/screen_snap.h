// screen_snap.h — the vertex stage's last step (internal): a projected point (clip_to_screen,
// pipeline.h) snapped to the fixed-point screen grid of 1/2^bits px that the rasterizer's
// edge equations work on. The one definition: the vertex transform (vertex_transform.h, and
// its SSE2 kernel lane by lane) and the raster set-up (raster/setup/setup.h) both snap
// through it. Not installed.
#ifndef TINY3D_SCREEN_SNAP_H
#define TINY3D_SCREEN_SNAP_H

#include <cmath>
#include <cstdint>

#include "../simd_config.h"

#ifdef TINY3D_SSE2
#include <emmintrin.h>
#endif

namespace tiny3d::detail {

// |x|, |y| beyond this (px) are not snapped: with bits ≤ 8, x·2^bits then fits in 32 bits.
// raster.h publishes it as RASTER_MAX_COORD (raster/setup/setup.h checks that the two agree).
inline constexpr float SNAP_MAX_COORD = 1 << 22;

// Rounds a screen coordinate to the nearest 1/2^bits pixel (ties to even), in sub-pixel
// units. std::lrint, which GCC -O2 compiles to a library call; cvtss2si is one instruction.
// Needs |x| ≤ SNAP_MAX_COORD and bits ≤ 8.
inline std::int32_t snap_coord(float x, int bits) {
    const float one = static_cast<float>(1 << bits);
#ifdef TINY3D_SSE2
    return _mm_cvtss_si32(_mm_set_ss(x * one));
#else
    return static_cast<std::int32_t>(std::lrint(x * one));
#endif
}

// Whether a screen point can be snapped: finite, |x|, |y| ≤ SNAP_MAX_COORD.
inline bool snappable(float x, float y) {
    return std::isfinite(x) && std::isfinite(y) && std::fabs(x) <= SNAP_MAX_COORD && std::fabs(y) <= SNAP_MAX_COORD;
}

// Snaps the screen point (x, y) to 1/2^bits px into (sx, sy). False, with sx, sy untouched,
// when it cannot be snapped (non-finite or beyond SNAP_MAX_COORD): the set-up skips such a
// triangle.
inline bool snap_screen_point(float x, float y, int bits, std::int32_t &sx, std::int32_t &sy) {
    if (!snappable(x, y)) return false;
    sx = snap_coord(x, bits);
    sy = snap_coord(y, bits);
    return true;
}

}  // namespace tiny3d::detail

#endif
