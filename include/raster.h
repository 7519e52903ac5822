// raster.h — filled triangles: z-buffer, half-space and scan-line rasterizers, culling,
// triangle clipping, shading levels, textures, transparency, tiled two-thread rendering.
// Part of the renderer module (renderer.h includes it).
#ifndef TINY3D_RASTER_H
#define TINY3D_RASTER_H

#include "canvas.h"
#include "math3d.h"
#include "mesh.h"

#endif
