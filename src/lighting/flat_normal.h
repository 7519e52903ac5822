// flat_normal.h — the geometric normal flat shading lights (shared by lighting.cpp and
// src/material/material.cpp; not installed).
#ifndef TINY3D_FLAT_NORMAL_H
#define TINY3D_FLAT_NORMAL_H

#include "math3d.h"

namespace tiny3d {

// unit((b − a) × (c − a)), computed in double; (0, 0, 0) for a degenerate triangle.
vec3_t flat_unit_normal(vec3_t a, vec3_t b, vec3_t c);

}  // namespace tiny3d

#endif
