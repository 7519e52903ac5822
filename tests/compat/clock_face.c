/* clock_face.c — a user program in the style of other libtiny3d clock demos:
 * canvas_create / canvas_clear(c) / draw_line_f / canvas_save_pgm / canvas_destroy,
 * M_PI from <math.h>, an int angle loop, a double expression stored into float.
 * usage: clock_face OUTDIR   (writes OUTDIR/clock_face.pgm) */
#include <math.h>
#include <stdio.h>

#include "canvas.h"

#define WIDTH 400
#define HEIGHT 400
#define RADIUS 180.0f

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";
    canvas_t *canvas = canvas_create(WIDTH, HEIGHT);
    if (!canvas) {
        fprintf(stderr, "Failed to create canvas.\n");
        return 1;
    }
    canvas_clear(canvas);

    const float c_x = WIDTH / 2.0f;
    const float c_y = HEIGHT / 2.0f;
    for (int angle = 0; angle < 360; angle += 15) {
        float rad = angle * M_PI / 180.0f;
        float x = c_x + RADIUS * cosf(rad);
        float y = c_y + RADIUS * sinf(rad);
        draw_line_f(canvas, c_x, c_y, x, y, 1.5f);
    }

    char path[1024];
    snprintf(path, sizeof path, "%s/clock_face.pgm", dir);
    if (canvas_save_pgm(canvas, path) != 0) {
        fprintf(stderr, "cannot save %s\n", path);
        canvas_destroy(canvas);
        return 1;
    }
    printf("saved %s\n", path);

    /* A save that must fail: the folder does not exist. */
    snprintf(path, sizeof path, "%s/no_such_folder/clock_face.pgm", dir);
    printf("failed_save %d\n", canvas_save_pgm(canvas, path));
    printf("centre %.9g\n", canvas->pixels[HEIGHT / 2][WIDTH / 2]);

    canvas_destroy(canvas);
    return 0;
}
