// compat/animation_alias.h — other libtiny3d implementations' name for the Bezier curve.
//
// Included at the end of animation.h (and self-contained). documentation/compat.md has the
// full table.
#ifndef TINY3D_COMPAT_ANIMATION_ALIAS_H
#define TINY3D_COMPAT_ANIMATION_ALIAS_H

#include "../animation.h"

// vec3_bezier: the cubic B(t) = (1−t)³p0 + 3(1−t)²t p1 + 3(1−t)t² p2 + t³p3, t in [0, 1].
// C++: a template, so a program's own bezier (of any signature) wins. C: declared with C
// linkage, alone in its object file of the archive (src/compat/), so a program that
// defines its own (same form) links its own.
#ifdef __cplusplus
template <class = void>
vec3_t bezier(vec3_t p0, vec3_t p1, vec3_t p2, vec3_t p3, float t) {
    return vec3_bezier(p0, p1, p2, p3, t);
}
#else
vec3_t bezier(vec3_t p0, vec3_t p1, vec3_t p2, vec3_t p3, float t);
#endif

#endif
