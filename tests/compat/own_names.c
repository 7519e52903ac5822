/* own_names.c — a user program that defines its OWN functions under the names the normal
 * headers also provide (save_canvas_pgm, save_canvas_as_pgm, canvas_save_to_pgm, the
 * 7-argument draw_line_f, vec3_normalize, mat4_perspective, create_cube), each with a
 * signature a little different from the library's: char * for const char *, a void
 * result, double parameters called with float variables and int literals, a pointer form,
 * degrees instead of radians, its own cube. It includes tiny3d.h and must compile, link and
 * call its own functions; each prints "own <name>" when called.
 * usage: own_names OUTDIR   (writes OUTDIR/own_<name>.pgm, ASCII P2, per save name) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "tiny3d.h"

/* The program's own writer: ASCII P2, value = (int)(pixel * 255 + 0.5), clamped. */
static int write_p2(const canvas_t *canvas, const char *path) {
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    fprintf(f, "P2\n%d %d\n255\n", canvas->width, canvas->height);
    for (int y = 0; y < canvas->height; y++) {
        for (int x = 0; x < canvas->width; x++) {
            float v = canvas->pixels[y][x];
            fprintf(f, "%d ", (int)((v < 0 ? 0 : v > 1 ? 1 : v) * 255 + 0.5f));
        }
        fprintf(f, "\n");
    }
    return fclose(f) == 0 ? 0 : -1;
}

/* char * path (the library's is const char *) */
static int save_canvas_pgm(canvas_t *canvas, char *path) {
    printf("own save_canvas_pgm\n");
    return write_p2(canvas, path);
}
/* exactly the library's parameter types, but no result */
static void save_canvas_as_pgm(const canvas_t *canvas, const char *path) {
    printf("own save_canvas_as_pgm\n");
    write_p2(canvas, path);
}
/* an external definition (not static), non-const canvas */
int canvas_save_to_pgm(canvas_t *canvas, const char *path);
int canvas_save_to_pgm(canvas_t *canvas, const char *path) {
    printf("own canvas_save_to_pgm\n");
    return write_p2(canvas, path);
}

/* double parameters; an unsmoothed line that SETS pixels to the intensity, one pixel per
 * unit step of the longer axis */
static void draw_line_f(canvas_t *c, double x0, double y0, double x1, double y1, double thickness, double intensity) {
    printf("own draw_line_f %.9g\n", thickness);
    double dx = x1 - x0, dy = y1 - y0;
    int steps = (int)ceil(fmax(fabs(dx), fabs(dy)));
    for (int i = 0; i <= steps; i++) {
        double t = steps ? (double)i / steps : 0;
        int x = (int)floor(x0 + t * dx), y = (int)floor(y0 + t * dy);
        if (x >= 0 && y >= 0 && x < c->width && y < c->height) c->pixels[y][x] = (float)intensity;
    }
}

/* the pointer form */
static void vec3_normalize(vec3_t *v) {
    printf("own vec3_normalize\n");
    float len = sqrtf(v->x * v->x + v->y * v->y + v->z * v->z);
    if (len > 0) {
        v->x /= len;
        v->y /= len;
        v->z /= len;
    }
}

/* degrees, double parameters */
static mat4_t mat4_perspective(double fov_degrees, double aspect, double near_plane, double far_plane) {
    printf("own mat4_perspective\n");
    double f = 1 / tan(fov_degrees * M_PI / 360);
    mat4_t m = {0};
    m.m[0] = (float)(f / aspect);
    m.m[5] = (float)f;
    m.m[10] = (float)((far_plane + near_plane) / (near_plane - far_plane));
    m.m[11] = -1;
    m.m[14] = (float)(2 * far_plane * near_plane / (near_plane - far_plane));
    return m;
}

/* the library's parameter types, no result, the unit cube [0, 1]^3 with its own order */
static void create_cube(vec3_t **verts, int **edges, int *vcount, int *ecount) {
    printf("own create_cube\n");
    static const int pairs[24] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 0, 4, 1, 5, 2, 6, 3, 7};
    *verts = (vec3_t *)malloc(8 * sizeof(vec3_t));
    *edges = (int *)malloc(sizeof pairs);
    for (int i = 0; i < 8; i++) {
        int bit_x = (i & 1) ^ ((i >> 1) & 1); /* 0 1 1 0 around each square */
        (*verts)[i] = (vec3_t){(float)bit_x, (float)((i >> 1) & 1), (float)(i >> 2)};
    }
    for (int i = 0; i < 24; i++) (*edges)[i] = pairs[i];
    *vcount = 8;
    *ecount = 12;
}

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";

    vec3_t *verts;
    int *edges, vcount, ecount;
    create_cube(&verts, &edges, &vcount, &ecount);
    for (int i = 0; i < vcount; i++) printf("cube_vertex %d %.9g %.9g %.9g\n", i, verts[i].x, verts[i].y, verts[i].z);

    mat4_t p = mat4_perspective(90, 2, 1, 10); /* int literals */
    printf("perspective_ints");
    for (int i = 0; i < 16; i++) printf(" %.9g", p.m[i]);
    printf("\n");
    float fov = 60, aspect = 1.5f, near_plane = 0.5f, far_plane = 20;
    p = mat4_perspective(fov, aspect, near_plane, far_plane); /* float variables to double */
    printf("perspective_floats");
    for (int i = 0; i < 16; i++) printf(" %.9g", p.m[i]);
    printf("\n");

    vec3_t v = {0, 3, 4};
    vec3_normalize(&v);
    printf("normalize 0 3 4 -> %.9g %.9g %.9g\n", v.x, v.y, v.z);

    canvas_t *canvas = create_canvas(24, 16);
    if (!canvas) return 1;
    float x0 = 2, y0 = 3.5f, x1 = 20, y1 = 3.5f;
    draw_line_f(canvas, x0, y0, x1, y1, 1.0f, 0.5f); /* float variables to double */
    draw_line_f(canvas, 2, 10, 2, 14, 3, 1);           /* int literals */
    free(verts);
    free(edges);

    char path[1024];
    snprintf(path, sizeof path, "%s/own_save_canvas_pgm.pgm", dir);
    printf("save save_canvas_pgm %d\n", save_canvas_pgm(canvas, path));
    snprintf(path, sizeof path, "%s/own_save_canvas_as_pgm.pgm", dir);
    save_canvas_as_pgm(canvas, path);
    snprintf(path, sizeof path, "%s/own_canvas_save_to_pgm.pgm", dir);
    printf("save canvas_save_to_pgm %d\n", canvas_save_to_pgm(canvas, path));
    destroy_canvas(canvas);
    return 0;
}
