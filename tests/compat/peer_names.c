/* peer_names.c — a user program written for another libtiny3d that calls, through the
 * normal headers only (no tiny3d_compat.h), the names such programs use for the cube, the
 * perspective matrix, the normalisation, the 7-argument line and the PGM saves:
 * create_cube (malloc'd arrays the program frees), mat4_perspective and draw_line_f with
 * int and double literals, vec3_normalize with compound literals, save_canvas_pgm,
 * save_canvas_as_pgm, canvas_save_to_pgm and save_canvas_to_pgm (0 on success).
 * usage: peer_names OUTDIR   (writes OUTDIR/peer_<name>.pgm for each save name) */
#include <stdio.h>
#include <stdlib.h>

#include "canvas.h"
#include "math3d.h"
#include "renderer.h"

#define WIDTH 96
#define HEIGHT 64

static void print_mat(const char *label, mat4_t m) {
    printf("%s", label);
    for (int i = 0; i < 16; i++) printf(" %.9g", m.m[i]);
    printf("\n");
}

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";

    vec3_t *verts = NULL;
    int *edges = NULL;
    int vcount = 0, ecount = 0;
    int made = create_cube(&verts, &edges, &vcount, &ecount);
    printf("cube %d %d %d\n", made, vcount, ecount);
    if (!made) return 1;
    for (int i = 0; i < vcount; i++) printf("cube_vertex %d %.9g %.9g %.9g\n", i, verts[i].x, verts[i].y, verts[i].z);
    for (int i = 0; i < ecount; i++) printf("cube_edge %d %d\n", edges[2 * i], edges[2 * i + 1]);
    vec3_t *no_verts = verts;
    int no_count = -1;
    printf("cube_null_output %d\n", create_cube(&no_verts, NULL, &no_count, &no_count) == 0 && no_verts == NULL && no_count == 0);

    mat4_t proj = mat4_perspective(M_PI / 3, (double)WIDTH / HEIGHT, 0.5, 50); /* double and int literals */
    print_mat("perspective", proj);
    print_mat("perspective_ints", mat4_perspective(1, 2, 1, 10));

    vec3_t n = vec3_normalize((vec3_t){3, 4, 12});
    printf("normalize 3 4 12 -> %.9g %.9g %.9g\n", n.x, n.y, n.z);
    vec3_t zero = vec3_normalize((vec3_t){0, 0, 0});
    printf("normalize 0 0 0 -> %.9g %.9g %.9g\n", zero.x, zero.y, zero.z);
    vec3_t axis = vec3_normalize((vec3_t){.x = 0, .y = -2, .z = 0});
    printf("normalize 0 -2 0 -> %.9g %.9g %.9g\n", axis.x, axis.y, axis.z);

    canvas_t *canvas = create_canvas(WIDTH, HEIGHT);
    if (!canvas) return 1;
    /* the cube turned and pushed 4 units away, its edges drawn at intensity 0.75 */
    mat4_t model = mat4_multiply(mat4_translate(0, 0, -4), mat4_rotate_xyz(0.4, 0.6, 0));
    mat4_t mvp = mat4_multiply(proj, model);
    for (int i = 0; i < ecount; i++) {
        vec3_t a = apply_transform(mvp, verts[edges[2 * i]]);
        vec3_t b = apply_transform(mvp, verts[edges[2 * i + 1]]);
        draw_line_f(canvas, (a.x + 1) * 0.5f * WIDTH, (1 - a.y) * 0.5f * HEIGHT, (b.x + 1) * 0.5f * WIDTH,
                    (1 - b.y) * 0.5f * HEIGHT, 1.5f, 0.75f);
    }
    /* a horizontal bar, int and double literals; integer coordinates are pixel centres (as
     * for the six-argument draw_line_f), so y = 59.5 is the boundary of rows 59 and 60 */
    draw_line_f(canvas, 10, 59.5, 80, 59.5, 2, 0.5);
    free(verts);
    free(edges);

    const char *names[4] = {"save_canvas_pgm", "save_canvas_as_pgm", "canvas_save_to_pgm", "save_canvas_to_pgm"};
    char path[1024];
    for (int i = 0; i < 4; i++) {
        snprintf(path, sizeof path, "%s/peer_%s.pgm", dir, names[i]);
        int status = i == 0 ? save_canvas_pgm(canvas, path)
                   : i == 1 ? save_canvas_as_pgm(canvas, path)
                   : i == 2 ? canvas_save_to_pgm(canvas, path)
                            : save_canvas_to_pgm(canvas, path);
        printf("save %s %d\n", names[i], status);
    }
    snprintf(path, sizeof path, "%s/no_such_folder/x.pgm", dir);
    printf("failed_save %d\n", save_canvas_pgm(canvas, path));
    destroy_canvas(canvas);
    return 0;
}
