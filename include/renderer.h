// renderer.h — the libtiny3d report's renderer header: meshes and their loaders,
// projection, clipping, wireframes and filled triangles, as one include. Each is a module
// header of its own; this one only gathers them (and math3d.h, canvas.h and lines.h
// through them), so programs written for the report, which include renderer.h for
// project_vertex, render_wireframe and generate_soccer_ball, keep compiling.
#ifndef TINY3D_RENDERER_H
#define TINY3D_RENDERER_H

#include "canvas.h"
#include "lines.h"
#include "math3d.h"
#include "mesh.h"       // the mesh type, utilities, generators (generate_soccer_ball), OBJ/PLY loaders
#include "pipeline.h"   // the vertex stage: project_vertex, clipping, circular viewport, frustum culling
#include "wireframe.h"  // render_wireframe (the report's and tiny3d::'s)
// From C (C11): the C parts of the headers above — project_vertex,
// clip_to_circular_viewport, render_wireframe, generate_soccer_ball, draw_line_f and the
// canvas and math API — with C linkage; filled triangles and the pins are C++ only.
#ifdef __cplusplus
#include "raster.h"     // filled triangles: the render context, textures, the reference image

#include "compat/renderer_alias.h"  // pins the forms other libtiny3d programs call
#endif

#endif
