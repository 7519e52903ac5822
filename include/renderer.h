// renderer.h — meshes, loaders, projection, clipping, wireframes and filled triangles.
#ifndef TINY3D_RENDERER_H
#define TINY3D_RENDERER_H

#include "canvas.h"
#include "math3d.h"
#include "mesh.h"

// ---- meshes, generators, loaders, projection, clipping, wireframes ----
// mesh.h: the mesh type, mesh utilities (edges, normals, adjacency, bounds), generators.
// loaders.h: OBJ and PLY. pipeline.h: project_vertex, clipping, circular viewport,
// frustum culling, render_wireframe.
#include "loaders.h"
#include "pipeline.h"

// ---- filled triangles ----
#include "raster.h"

#include "compat/renderer_alias.h"  // pins the forms other libtiny3d programs call

#endif
