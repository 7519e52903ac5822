// renderer.h — meshes, loaders, projection, clipping, wireframes and filled triangles.
#ifndef TINY3D_RENDERER_H
#define TINY3D_RENDERER_H

#include "canvas.h"
#include "math3d.h"
#include "mesh.h"

// ---- meshes, generators, loaders, projection, clipping, wireframes (see below) ----

// ---- filled triangles ----
#include "raster.h"

#endif
