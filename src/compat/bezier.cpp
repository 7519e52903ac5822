// bezier.cpp — other libtiny3d programs' name, C linkage (declared in compat/animation_alias.h (C)).
// Alone in its object file of libtiny3d.a: a program that defines its own bezier never
// pulls this one in (the linker takes an archive member only for a symbol still undefined).

#include "animation.h"

extern "C" vec3_t bezier(vec3_t p0, vec3_t p1, vec3_t p2, vec3_t p3, float t) { return vec3_bezier(p0, p1, p2, p3, t); }
