/* own.h — the program's OWN functions under names the library also has (other libtiny3d
 * implementations' forms). Each prints "own <name>" when called. The first group is the
 * same in C and C++; the second is C++ only, because C has one function per name and
 * these names there are the library's forms (documentation/compat.md). */
#ifndef OWN_H
#define OWN_H

#include "renderer.h"

/* the library's forms exactly (C declares these too: they must match in C) */
vec3_t mat4_mul_vec3(mat4_t m, vec3_t v);  /* own: no division by w */
mat4_t mat4_mul(mat4_t a, mat4_t b);       /* own: b . a (the other order) */
void canvas_clear(canvas_t *canvas, float value); /* own: value / 2 */
vec3_t bezier(vec3_t p0, vec3_t p1, vec3_t p2, vec3_t p3, float t); /* own: the chord p0 -> p3 */
/* forms the library has only in C++ (C does not declare these names) */
void vec3_normalize(vec3_t *v);            /* own: the zero vector becomes +z */
float vec3_length(vec3_t v);               /* own: the 1-norm */
vec3_t vec3_sub(vec3_t a, vec3_t b);       /* own: b - a */
mat4_t mat4_frustum(double l, double r, double b, double t, double n, double f); /* own: 2 * identity */
void clear_canvas(canvas_t *canvas, double value); /* own: 1 - value */

#ifdef __cplusplus
/* the report's printed form (generate_soccer.c): a tetrahedron. C declares the name
 * without a prototype (renderer.h), which takes this definition and the call as written
 * below; C++ calls it with the argument cast to the printed type. */
void generate_soccer_ball(vec3_t **vertices, int *vertex_count, int *edges[][2], int *edge_count);
/* C++ only: other forms of names C declares */
void mat4_identity(mat4_t *m);             /* own: 3 * identity */
void canvas_clear(canvas_t *canvas);       /* own: 0.75 */
mat4_t mat4_mul(const mat4_t *a, const mat4_t *b); /* own: the sum */
vec3_t mat4_mul_vec3(const mat4_t *m, vec3_t v);   /* own: v + translation */
int generate_soccer_ball(vec3_t **vertices, int *vertex_count, int (**edges)[2], int *edge_count); /* own: 7 */
#endif

#endif
