/* own_helpers.c — a user program that defines its OWN helpers under names other libtiny3d
 * implementations export (vec3_normalize, vec3_dot, vec3_cross, vec3_add, vec3_scale,
 * clamp01, save_canvas_as_pgm), as the report's demo/generate_soccer.c does with
 * `static vec3_t vec3_normalize(vec3_t)`. It must compile against the normal headers (all
 * of them, through tiny3d.h) and call its own: vec3_dot & co. are only in the opt-in
 * tiny3d_compat.h, and the normal headers' vec3_normalize and save_canvas_as_pgm step aside
 * for a program's own (include/compat/user_first.h).
 * Its own PGM writer reads canvas->pixels[y][x] directly, as many programs do.
 * usage: own_helpers OUTDIR   (writes OUTDIR/own_helpers.pgm, ASCII P2) */
#include <math.h>
#include <stdio.h>

#include "tiny3d.h"

static vec3_t vec3_normalize(vec3_t v) {
    float len = sqrtf(v.x * v.x + v.y * v.y + v.z * v.z);
    if (len > 0.000001f) {
        v.x /= len;
        v.y /= len;
        v.z /= len;
    }
    return v;
}
static float vec3_dot(vec3_t a, vec3_t b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static vec3_t vec3_cross(vec3_t a, vec3_t b) {
    return (vec3_t){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
static vec3_t vec3_add(vec3_t a, vec3_t b) { return (vec3_t){a.x + b.x, a.y + b.y, a.z + b.z}; }
static vec3_t vec3_scale(vec3_t v, float s) { return (vec3_t){v.x * s, v.y * s, v.z * s}; }
static float clamp01(float v) { return v < 0 ? 0 : (v > 1 ? 1 : v); }

/* The user's own writer: ASCII P2, value = (int)(pixel * 255 + 0.5). Returns 0 on success. */
static int save_canvas_as_pgm(canvas_t *canvas, const char *filename) {
    FILE *f = fopen(filename, "w");
    if (!f) return -1;
    fprintf(f, "P2\n%d %d\n255\n", canvas->width, canvas->height);
    for (int y = 0; y < canvas->height; y++) {
        for (int x = 0; x < canvas->width; x++) fprintf(f, "%d ", (int)(clamp01(canvas->pixels[y][x]) * 255 + 0.5f));
        fprintf(f, "\n");
    }
    return fclose(f) == 0 ? 0 : -1;
}

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";
    vec3_t n = vec3_normalize((vec3_t){3, 4, 0});
    printf("own_normalize 3 4 0 -> %.9g %.9g %.9g\n", n.x, n.y, n.z);
    vec3_t tiny = vec3_normalize((vec3_t){1e-7f, 0, 0}); /* left as is by ours, not the library's */
    printf("own_normalize_tiny -> %.9g %.9g %.9g\n", tiny.x, tiny.y, tiny.z);
    vec3_t c = vec3_cross((vec3_t){1, 0, 0}, (vec3_t){0, 1, 0});
    printf("own_cross 1 0 0 0 1 0 -> %.9g %.9g %.9g\n", c.x, c.y, c.z);
    printf("own_dot 1 2 3 4 5 6 -> %.9g\n", vec3_dot((vec3_t){1, 2, 3}, (vec3_t){4, 5, 6}));
    vec3_t s = vec3_add(vec3_scale((vec3_t){1, 1, 1}, 2), (vec3_t){0.5, 0, -1});
    printf("own_add_scale -> %.9g %.9g %.9g\n", s.x, s.y, s.z);

    /* the library's own normalisation next to ours */
    vec3_t q = vec3_normalize_fast((vec3_t){3, 4, 0});
    printf("library_normalize_fast 3 4 0 -> %.9g %.9g %.9g\n", q.x, q.y, q.z);

    /* a small picture: the lit edges of a triangle, drawn with set_pixel_f at pixel centres */
    canvas_t *canvas = create_canvas(16, 8);
    if (!canvas) return 1;
    for (int x = 0; x < 16; x++) set_pixel_f(canvas, x, 3, x / 15.0f);
    char path[1024];
    snprintf(path, sizeof path, "%s/own_helpers.pgm", dir);
    int status = save_canvas_as_pgm(canvas, path);
    remove_canvas(canvas);
    return status == 0 ? 0 : 1;
}
