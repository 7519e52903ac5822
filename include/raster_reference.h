// raster_reference.h — the converged image of a filled scene: the yardstick every
// anti-aliasing mode and texture filter of the render context is measured against
// (tests/antialias_test.cpp, tests/bench/antialias.cpp). Part of the raster module.
//
// An independent, deliberately simple implementation in double precision: no snapping, no
// fixed point, no bands or threads. Each pixel gets N = n² samples on a rank-1 lattice:
// sample k of pixel (px, py) at (px + frac(½ + k/φ), py + (k + ½)/N), φ the golden ratio —
// one sample in each of the N rows of height 1/N, and well spread along x for every edge
// direction (a plain or sheared n × n grid counts edges near its own directions in steps
// of 1/n; this lattice has no such direction) — and every
// sample is depth-tested and shaded on its own (depth, barycentrics and attributes at the
// sample); the pixel is the box-filtered mean of its samples. Shading follows draw_params
// (raster.h): flat per triangle, Gouraud intensities interpolated screen-affine, Phong
// position and normal interpolated per sample; a texture is looked up bilinearly in its
// BASE level at every sample (the supersampled texture, whatever the draw's filter);
// perspective_correct as in the draw. Clipping: near and far planes in clip space (double),
// attributes interpolated linearly in clip space; x and y are cut by the canvas.
// Cull mode and depth function as in each draw.
#ifndef TINY3D_RASTER_REFERENCE_H
#define TINY3D_RASTER_REFERENCE_H

#include <span>

#include "raster.h"

namespace tiny3d {

struct reference_draw {
    const raster_mesh *mesh = nullptr;
    draw_params params;
};

inline constexpr int REFERENCE_SAMPLES_PER_AXIS = 16;  // 256 samples per pixel

// Clears `target` to clear_intensity (depth to 1) and draws `draws` in order. Slow by design
// (every sample shaded in double) and allocating (a band of sample buffers); for tests and benchmarks.
// Errors: canvas without pixels, samples_per_axis outside 1..64, a null mesh, a mesh whose
// normals or uvs count differs from its positions, a triangle index out of range, a
// translucent draw (alpha < 1: not supported).
status render_reference(canvas_t &target, std::span<const reference_draw> draws, float clear_intensity = 0.0f,
                        int samples_per_axis = REFERENCE_SAMPLES_PER_AXIS);

}  // namespace tiny3d

#endif
