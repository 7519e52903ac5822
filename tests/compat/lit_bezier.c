/* lit_bezier.c — a user program in the style of other libtiny3d lighting/animation demos:
 * bezier(p0, p1, p2, p3, t), light_t with designated initialisers, lambert_intensity,
 * clip_to_circular_viewport, set_pixel_f, draw_line_f, canvas_create / canvas_free.
 * A square travels a closed Bezier loop (p3 = p0); each frame prints its position and the
 * lit intensity of its four edges, and the path is drawn only where it lies inside the
 * circular viewport (it leaves the circle at the top).
 * usage: lit_bezier OUTDIR   (writes OUTDIR/lit_bezier.pgm) */
#include <stdio.h>

#include "animation.h"
#include "canvas.h"
#include "lighting.h"
#include "renderer.h"

#define SIZE 200
#define FRAMES 24
#define SCALE 70.0f
#define HALF_SIDE 0.25f

static void to_screen(vec3_t p, float *x, float *y) {
    *x = SIZE / 2 + SCALE * p.x;
    *y = SIZE / 2 - SCALE * p.y;
}

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";
    canvas_t *canvas = canvas_create(SIZE, SIZE);
    if (!canvas) return 1;

    vec3_t p0 = {-1, -1, 0}, p1 = {-2.5, 2.5, 0}, p2 = {2.5, 2.5, 0};
    vec3_t p3 = p0; /* closed loop: the animation ends where it starts */
    light_t light = {.direction = {1, 1, 0.5}, .intensity = 0.8};

    float prev_x = 0, prev_y = 0;
    int prev_inside = 0;
    for (int frame = 0; frame <= FRAMES; frame++) {
        float t = (float)frame / FRAMES;
        vec3_t pos = bezier(p0, p1, p2, p3, t);
        printf("frame %d %.9g -> %.9g %.9g %.9g\n", frame, t, pos.x, pos.y, pos.z);

        /* the square's corners, turned a little more each frame */
        vec3_t corner[4] = {
            {pos.x - HALF_SIDE, pos.y - HALF_SIDE, -0.1f * frame},
            {pos.x + HALF_SIDE, pos.y - HALF_SIDE, 0},
            {pos.x + HALF_SIDE, pos.y + HALF_SIDE, 0.1f * frame},
            {pos.x - HALF_SIDE, pos.y + HALF_SIDE, 0},
        };
        for (int e = 0; e < 4; e++) {
            vec3_t a = corner[e], b = corner[(e + 1) % 4];
            float lit = light.intensity * lambert_intensity(a, b, light.direction);
            printf("edge %d %d %.9g %.9g %.9g %.9g %.9g %.9g -> %.9g\n", frame, e, a.x, a.y, a.z, b.x, b.y, b.z, lit);
        }

        float x, y;
        to_screen(pos, &x, &y);
        int inside = clip_to_circular_viewport(canvas, x, y);
        if (inside && prev_inside) draw_line_f(canvas, prev_x, prev_y, x, y, 1.5f);
        if (inside) set_pixel_f(canvas, x, y, 1);
        prev_x = x;
        prev_y = y;
        prev_inside = inside;
    }

    char path[1024];
    snprintf(path, sizeof path, "%s/lit_bezier.pgm", dir);
    int status = canvas_save_pgm(canvas, path);
    canvas_free(canvas);
    return status == 0 ? 0 : 1;
}
