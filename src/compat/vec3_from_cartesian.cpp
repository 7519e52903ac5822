// vec3_from_cartesian.cpp — other libtiny3d programs' name, C linkage (declared in compat/math_alias.h (C)).
// Alone in its object file of libtiny3d.a: a program that defines its own vec3_from_cartesian never
// pulls this one in (the linker takes an archive member only for a symbol still undefined).

#include "math3d.h"

extern "C" vec3_t vec3_from_cartesian(float x, float y, float z) { return vec3_t{x, y, z}; }
