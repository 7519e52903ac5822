// tiny3d.h — all of libtiny3d: every module header, lowest first (a module includes only
// modules above it in this list: tests/check_header_layers.sh; documentation/README.md has
// the map).
#ifndef TINY3D_H
#define TINY3D_H

#include "tiny3d_result.h"  // the error type every module returns
#include "math3d.h"
#include "animation.h"
#include "canvas.h"
#include "lines.h"
#include "lighting.h"
#include "mesh.h"
#include "pipeline.h"
#ifdef __cplusplus  // C: the C parts of the headers above and renderer.h's
#include "material.h"
#include "raster.h"
#endif
#include "wireframe.h"
#ifdef __cplusplus
#include "lab.h"
#include "scene.h"
#endif
#include "renderer.h"  // the report's gathering header (its compat pins)

#endif
