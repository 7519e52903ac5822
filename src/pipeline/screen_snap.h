// screen_snap.h — the vertex stage's last step (internal): a projected point (clip_to_screen,
// pipeline.h) snapped to the fixed-point screen grid of 1/2^bits px that the rasterizer's
// edge equations work on. Used by the vertex transform (vertex_transform.h; its SSE2 kernel
// does the same lane by lane); the raster set-up's snap_vertex (raster/setup/setup.h) computes
// the same. Not installed.
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
// raster.h publishes it as RASTER_MAX_COORD (setup.h checks that the two agree).
inline constexpr float SNAP_MAX_COORD = 1 << 22;

// Snaps the screen point (x, y) to the nearest 1/2^bits px (ties to even) into (sx, sy), in
// sub-pixel units. False, with sx, sy untouched, when it cannot be snapped (non-finite or
// beyond SNAP_MAX_COORD): the set-up skips such a triangle. Needs bits ≤ 8. std::lrint,
// which GCC -O2 compiles to a library call; cvtss2si is one instruction.
inline bool snap_screen_point(float x, float y, int bits, std::int32_t &sx, std::int32_t &sy) {
    if (!(std::isfinite(x) && std::isfinite(y) && std::fabs(x) <= SNAP_MAX_COORD && std::fabs(y) <= SNAP_MAX_COORD))
        return false;
    const float one = static_cast<float>(1 << bits);
#ifdef TINY3D_SSE2
    sx = _mm_cvtss_si32(_mm_set_ss(x * one));
    sy = _mm_cvtss_si32(_mm_set_ss(y * one));
#else
    sx = static_cast<std::int32_t>(std::lrint(x * one));
    sy = static_cast<std::int32_t>(std::lrint(y * one));
#endif
    return true;
}

}  // namespace tiny3d::detail

#endif
