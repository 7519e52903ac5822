// mat4_mul.cpp — other libtiny3d programs' name, C linkage (declared in compat/math_alias.h (C)).
// Alone in its object file of libtiny3d.a: a program that defines its own mat4_mul never
// pulls this one in (the linker takes an archive member only for a symbol still undefined).

#include "math3d.h"

extern "C" mat4_t mat4_mul(mat4_t a, mat4_t b) { return mat4_multiply(a, b); }
