/* rotating_cube.c — a user program in the style of other libtiny3d cube demos:
 * mat4_mul / mat4_mul_vec3 / mat4_transform_vec3, the typedef names vec3 and mat4,
 * mat4_t m = {0}, compound literals, designated initialisers, int literals to float
 * parameters, clear_canvas, free_canvas, and a relative include path.
 * Prints every projected vertex of FRAMES frames; saves frame 1.
 * usage: rotating_cube OUTDIR   (writes OUTDIR/rotating_cube.pgm) */
#include <stdio.h>
#include <string.h>

#include "../../include/tiny3d.h"

#define WIDTH 128
#define HEIGHT 128
#define FRAMES 8

static const vec3 cube[8] = {
    {-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1},
};
static const int edges[12][2] = {
    {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
    {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7},
};

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";
    canvas_t *canvas = canvas_create(WIDTH, HEIGHT);
    if (!canvas) return 1;

    mat4 proj = mat4_frustum_asymmetric(-1, 1, -1, 1, 1, 10);
    mat4_t unit = {0}; /* identity built by hand from a zeroed matrix */
    vec3_t origin = {0}; /* the C idiom for a zero vector */
    light_t unused_light = {0};
    (void)unused_light;
    if (origin.x != 0 || origin.y != 0 || origin.z != 0) return 3;
    unit.m[0] = unit.m[5] = unit.m[10] = unit.m[15] = 1;

    int transform_forms_agree = 1;
    for (int frame = 0; frame < FRAMES; frame++) {
        float angle = frame * 2 * M_PI / FRAMES;
        mat4 model = mat4_mul(mat4_translate(0, 0, -5), mat4_mul(mat4_rotate_xyz(0, angle, 0), mat4_scale(1, 1, 1)));
        mat4 mvp = mat4_mul(proj, mat4_mul(unit, model));

        clear_canvas(canvas, 0);
        vec3_t screen[8];
        for (int i = 0; i < 8; i++) {
            vec3_t ndc = mat4_mul_vec3(mvp, cube[i]);
            vec3_t again = mat4_transform_vec3(mvp, cube[i]);
            if (memcmp(&ndc, &again, sizeof ndc) != 0) transform_forms_agree = 0;
            screen[i] = (vec3_t){
                .x = (ndc.x + 1) * 0.5f * WIDTH,
                .y = (1 - (ndc.y + 1) * 0.5f) * HEIGHT,
                .z = ndc.z,
            };
            printf("vertex %d %d %.9g %.9g %.9g\n", frame, i, screen[i].x, screen[i].y, screen[i].z);
        }
        for (int e = 0; e < 12; e++) {
            vec3_t a = screen[edges[e][0]], b = screen[edges[e][1]];
            draw_line_f(canvas, a.x, a.y, b.x, b.y, 1.2f);
        }
        if (frame == 1) {
            char path[1024];
            snprintf(path, sizeof path, "%s/rotating_cube.pgm", dir);
            if (canvas_save_pgm(canvas, path) != 0) {
                free_canvas(canvas);
                return 1;
            }
        }
    }
    printf("transform_forms_agree %d\n", transform_forms_agree);
    free_canvas(canvas);
    return 0;
}
