/* main.c — a program that defines its OWN functions under names the library also has
 * (own.h, own.c, generate_soccer.c) and includes the library's headers: it must compile,
 * link and call its own functions — built as strict C11, as gcc's default C and as C++
 * (tests/compat/compat.mk). Each call prints the result; own functions print "own <name>".
 * usage: own_forms OUTDIR */
#include <stdio.h>

#include "animation.h"
#include "lighting.h"
#include "own.h"

static void print_mat(const char *label, mat4_t m) {
    printf("%s", label);
    for (int i = 0; i < 16; i++) printf(" %.9g", m.m[i]);
    printf("\n");
}

int main(void) {
    mat4_t t = mat4_translate(1, 2, 3), s = mat4_scale(2, 2, 2);
    vec3_t p = {1, 1, 1};
    vec3_t q = mat4_mul_vec3(mat4_frustum_asymmetric(-1, 1, -1, 1, 1, 10), (vec3_t){0, 0, -2});
    printf("mat4_mul_vec3 %.9g %.9g %.9g\n", q.x, q.y, q.z);
    print_mat("mat4_mul", mat4_mul(t, s));
    vec3_t b = bezier(p, (vec3_t){5, 5, 5}, (vec3_t){-5, -5, -5}, (vec3_t){3, 1, -1}, 0.5f);
    printf("bezier %.9g %.9g %.9g\n", b.x, b.y, b.z);
    vec3_t z = {0, 0, 0};
    vec3_normalize(&z);
    printf("vec3_normalize %.9g %.9g %.9g\n", z.x, z.y, z.z);
    printf("vec3_length %.9g\n", vec3_length((vec3_t){1, -2, 3}));
    vec3_t d = vec3_sub((vec3_t){1, 1, 1}, (vec3_t){4, 5, 6});
    printf("vec3_sub %.9g %.9g %.9g\n", d.x, d.y, d.z);
    print_mat("mat4_frustum", mat4_frustum(-1, 1, -1, 1, 1, 10));

    canvas_t *canvas = create_canvas(4, 4);
    if (!canvas) return 1;
    canvas_clear(canvas, 0.5f);
    printf("canvas_clear %.9g\n", canvas->pixels[1][1]);
    clear_canvas(canvas, 0.25f);
    printf("clear_canvas %.9g\n", canvas->pixels[1][1]);

    vec3_t *vertices = NULL;
    int (*edges)[2] = NULL;
    int vertex_count = 0, edge_count = 0;
#ifdef __cplusplus
    generate_soccer_ball(&vertices, &vertex_count, (int *(*)[2])&edges, &edge_count);
#else
    generate_soccer_ball(&vertices, &vertex_count, &edges, &edge_count);
#endif
    printf("generate_soccer_ball %d %d %.9g %d %d\n", vertex_count, edge_count, vertices[3].z, edges[5][0],
           edges[5][1]);

    /* the library's own functions still work beside them */
    printf("lambert %.9g\n", lambert_intensity((vec3_t){0, 0, 0}, (vec3_t){0, 0, 2}, (vec3_t){0, 0, 1}));
    vec3_t v = vec3_bezier((vec3_t){0, 0, 0}, (vec3_t){0, 0, 0}, (vec3_t){4, 4, 4}, (vec3_t){4, 4, 4}, 0.5f);
    printf("vec3_bezier %.9g %.9g %.9g\n", v.x, v.y, v.z);

#ifdef __cplusplus
    mat4_t m;
    mat4_identity(&m);
    print_mat("mat4_identity(&m)", m);
    canvas_clear(canvas);
    printf("canvas_clear(c) %.9g\n", canvas->pixels[1][1]);
    print_mat("mat4_mul(&a, &b)", mat4_mul(&t, &s));
    vec3_t r = mat4_mul_vec3(&t, p);
    printf("mat4_mul_vec3(&m, v) %.9g %.9g %.9g\n", r.x, r.y, r.z);
    printf("generate_soccer_ball(int (**)[2]) %d\n", generate_soccer_ball(&vertices, &vertex_count, &edges, &edge_count));
#endif
    destroy_canvas(canvas);
    return 0;
}
