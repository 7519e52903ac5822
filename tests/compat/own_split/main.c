/* main.c — a user program split over files: shapes.h declares its own save_canvas_pgm,
 * vec3_normalize, create_cube, mat4_perspective and 7-argument draw_line_f (the library's
 * parameter types exactly), shapes.c defines them. Both files include tiny3d.h; the
 * program must link and call its own functions.
 * usage: own_split OUTDIR   (writes OUTDIR/own_split.pgm) */
#include <stdio.h>
#include <stdlib.h>

#include "shapes.h"

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";
    vec3_t *verts;
    int *edges, vcount, ecount;
    create_cube(&verts, &edges, &vcount, &ecount);
    printf("cube %d %d\n", vcount, ecount);
    for (int i = 0; i < vcount; i++) printf("cube_vertex %d %.9g %.9g %.9g\n", i, verts[i].x, verts[i].y, verts[i].z);
    free(verts);
    free(edges);

    vec3_t z = vec3_normalize((vec3_t){0, 0, 0});
    printf("normalize 0 0 0 -> %.9g %.9g %.9g\n", z.x, z.y, z.z);
    vec3_t n = vec3_normalize((vec3_t){0, 0, -5});
    printf("normalize 0 0 -5 -> %.9g %.9g %.9g\n", n.x, n.y, n.z);

    mat4_t p = mat4_perspective(90, 1, 1, 3); /* int literals */
    printf("perspective");
    for (int i = 0; i < 16; i++) printf(" %.9g", p.m[i]);
    printf("\n");

    canvas_t *canvas = create_canvas(8, 4);
    if (!canvas) return 1;
    draw_line_f(canvas, 1, 1, 6, 2, 2, 0.25); /* int and double literals */
    char path[1024];
    snprintf(path, sizeof path, "%s/own_split.pgm", dir);
    printf("save %d\n", save_canvas_pgm(canvas, path));
    destroy_canvas(canvas);
    return 0;
}
