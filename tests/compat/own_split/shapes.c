/* shapes.c — the definitions of shapes.h: each prints "own <name>" when called. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "shapes.h"

/* An ASCII P2 file with a comment line naming its writer. */
int save_canvas_pgm(const canvas_t *canvas, const char *path) {
    printf("own save_canvas_pgm\n");
    FILE *f = fopen(path, "w");
    if (!f) return 5;
    fprintf(f, "P2\n# own_split\n%d %d\n255\n", canvas->width, canvas->height);
    for (int y = 0; y < canvas->height; y++)
        for (int x = 0; x < canvas->width; x++) fprintf(f, "%d\n", canvas->pixels[y][x] > 0 ? 255 : 0);
    return fclose(f) == 0 ? 0 : 5;
}

/* Normalises; the zero vector becomes +z (the library's gives 0, 0, 0). */
vec3_t vec3_normalize(vec3_t v) {
    printf("own vec3_normalize\n");
    float len = sqrtf(v.x * v.x + v.y * v.y + v.z * v.z);
    if (len == 0) return (vec3_t){0, 0, 1};
    return (vec3_t){v.x / len, v.y / len, v.z / len};
}

/* A cube of side 1 centred on the origin, edges as pairs. */
void create_cube(vec3_t **verts, int **edges, int *vcount, int *ecount) {
    printf("own create_cube\n");
    *verts = (vec3_t *)malloc(8 * sizeof(vec3_t));
    *edges = (int *)malloc(24 * sizeof(int));
    int k = 0;
    for (int i = 0; i < 8; i++) {
        (*verts)[i] = (vec3_t){(i & 1) - 0.5f, ((i >> 1) & 1) - 0.5f, (i >> 2) - 0.5f};
        for (int bit = 1; bit < 8; bit <<= 1)
            if (!(i & bit)) {
                (*edges)[k++] = i;
                (*edges)[k++] = i | bit;
            }
    }
    *vcount = 8;
    *ecount = k / 2;
}

/* Field of view in degrees. */
mat4_t mat4_perspective(float fov_degrees, float aspect, float near_plane, float far_plane) {
    printf("own mat4_perspective\n");
    float f = 1 / tanf(fov_degrees * (float)M_PI / 360);
    mat4_t m = {0};
    m.m[0] = f / aspect;
    m.m[5] = f;
    m.m[10] = (far_plane + near_plane) / (near_plane - far_plane);
    m.m[11] = -1;
    m.m[14] = 2 * far_plane * near_plane / (near_plane - far_plane);
    return m;
}

/* Sets the pixel under each end to the intensity. */
void draw_line_f(canvas_t *canvas, float x0, float y0, float x1, float y1, float thickness, float intensity) {
    printf("own draw_line_f %.9g\n", thickness);
    canvas->pixels[(int)y0][(int)x0] = intensity;
    canvas->pixels[(int)y1][(int)x1] = intensity;
}
