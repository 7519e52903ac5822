/* c_names.c — a C program written against other libtiny3d implementations' names that a
 * C program gets from the normal headers (documentation/compat.md): canvas_create,
 * canvas_clear(c, value), canvas_save_pgm, the four PPM save names, canvas_free,
 * free_canvas, canvas_destroy, the global mat4_rotate_x/y/z, mat4_mul, mat4_mul_vec3,
 * mat4_transform_vec3, vec3_from_cartesian and bezier; with malloc without a cast, M_PI
 * from math3d.h (also under strict -std=c11), compound literals and designated
 * initialisers. Built as strict C11, as gcc's default C and as C++ (tests/compat/compat.mk).
 * usage: c_names OUTDIR   (writes OUTDIR/c_names.pgm and OUTDIR/c_names_<name>.ppm) */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include "animation.h"
#include "canvas.h"
#include "lighting.h"
#include "math3d.h"

static void print_vec(const char *label, vec3_t v) { printf("%s %.9g %.9g %.9g\n", label, v.x, v.y, v.z); }

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";

    /* the types' layout, which the C and C++ builds must share */
    printf("layout %d %d %d %d %d %d %d\n", (int)sizeof(vec3_t), (int)sizeof(vec4_t), (int)sizeof(mat4_t),
           (int)sizeof(canvas_t), (int)offsetof(canvas_t, pixels), (int)sizeof(light_t), (int)offsetof(light_t, position));

    /* rotations about each axis, by pi/5, of (1, 2, 3) */
    vec3_t p = vec3_from_cartesian(1, 2, 3);
    float angle = M_PI / 5;
    printf("angle %.9g\n", angle);
    print_vec("rotate_x", mat4_mul_vec3(mat4_rotate_x(angle), p));
    print_vec("rotate_y", mat4_mul_vec3(mat4_rotate_y(angle), p));
    print_vec("rotate_z", mat4_mul_vec3(mat4_rotate_z(angle), p));
    /* translate(0.5, -1, 2) . rotate_z(angle) . rotate_y(-angle): the rotations first */
    mat4_t m = mat4_mul(mat4_translate(0.5, -1, 2), mat4_mul(mat4_rotate_z(angle), mat4_rotate_y(-angle)));
    print_vec("product", mat4_transform_vec3(m, p));

    /* a Bezier path, its points in a heap array allocated the C way: without a cast (which
     * only the C++ build of this file needs) */
#ifdef __cplusplus
    vec3_t *path = (vec3_t *)malloc(5 * sizeof *path);
#else
    vec3_t *path = malloc(5 * sizeof *path);
#endif
    if (!path) return 1;
    vec3_t p0 = {.x = 0, .y = 0, .z = 0}, p1 = {1, 2, 0}, p2 = {3, 2, 1}, p3 = (vec3_t){4, 0, 2};
    for (int i = 0; i <= 4; i++) {
        path[i] = bezier(p0, p1, p2, p3, i / 4.0);
        printf("bezier %d %.9g %.9g %.9g\n", i, path[i].x, path[i].y, path[i].z);
    }
    free(path);

    /* a 40 x 30 canvas cleared to 0.25 with one horizontal line along row 15 */
    canvas_t *canvas = canvas_create(40, 30);
    if (!canvas) return 1;
    canvas_clear(canvas, 0.25);
    draw_line_f(canvas, 5, 15, 35, 15, 1);
    printf("pixel 0 0 %.9g\n", canvas->pixels[0][0]);
    printf("pixel 20 15 %.9g\n", canvas->pixels[15][20]);

    char path_name[1024];
    snprintf(path_name, sizeof path_name, "%s/c_names.pgm", dir);
    printf("save canvas_save_pgm %d\n", canvas_save_pgm(canvas, path_name));
    const char *names[4] = {"save_canvas_ppm", "save_canvas_to_ppm", "save_canvas_as_ppm", "canvas_save_ppm"};
    int (*savers[4])(const canvas_t *, const char *) = {save_canvas_ppm, save_canvas_to_ppm, save_canvas_as_ppm,
                                                         canvas_save_ppm};
    for (int i = 0; i < 4; i++) {
        snprintf(path_name, sizeof path_name, "%s/c_names_%s.ppm", dir, names[i]);
        printf("save %s %d\n", names[i], savers[i](canvas, path_name));
        /* saves that must fail: the path is the folder itself; a null canvas */
        printf("failed_save %s %d %d\n", names[i], savers[i](canvas, dir), savers[i](NULL, path_name));
    }
    /* called by name too, as programs do */
    snprintf(path_name, sizeof path_name, "%s/c_names_direct.ppm", dir);
    printf("direct %d\n", save_canvas_ppm(canvas, path_name) + save_canvas_to_ppm(canvas, path_name) +
                              save_canvas_as_ppm(canvas, path_name) + canvas_save_ppm(canvas, path_name));

    canvas_free(canvas);
    free_canvas(canvas_create(2, 2));
    canvas_destroy(canvas_create(3, 3));
    canvas_destroy(NULL);
    printf("done\n");
    return 0;
}
