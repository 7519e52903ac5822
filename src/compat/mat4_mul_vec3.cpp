// mat4_mul_vec3.cpp — other libtiny3d programs' name, C linkage (declared in compat/math_alias.h (C)).
// Alone in its object file of libtiny3d.a: a program that defines its own mat4_mul_vec3 never
// pulls this one in (the linker takes an archive member only for a symbol still undefined).

#include "math3d.h"

extern "C" vec3_t mat4_mul_vec3(mat4_t m, vec3_t v) { return apply_transform(m, v); }
