/* shapes.h — the program's own declarations of names the library also provides, with the
 * library's parameter types exactly (two of them with C linkage, as C headers that are
 * also compiled as C++ declare them). Defined in shapes.c; called from main.c. */
#ifndef OWN_SPLIT_SHAPES_H
#define OWN_SPLIT_SHAPES_H

#include "tiny3d.h"

#ifdef __cplusplus
extern "C" {
#endif
int save_canvas_pgm(const canvas_t *canvas, const char *path);
vec3_t vec3_normalize(vec3_t v);
#ifdef __cplusplus
}
#endif

void create_cube(vec3_t **verts, int **edges, int *vcount, int *ecount);
mat4_t mat4_perspective(float fov_degrees, float aspect, float near_plane, float far_plane);
void draw_line_f(canvas_t *canvas, float x0, float y0, float x1, float y1, float thickness, float intensity);

#endif
