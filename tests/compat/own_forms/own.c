/* own.c — the definitions of own.h (not the library's: each says "own <name>"). */
#include <stdio.h>

#include "own.h"

vec3_t mat4_mul_vec3(mat4_t m, vec3_t v) {
    printf("own mat4_mul_vec3\n");
    vec3_t r = {m.m[0] * v.x + m.m[4] * v.y + m.m[8] * v.z + m.m[12], m.m[1] * v.x + m.m[5] * v.y + m.m[9] * v.z + m.m[13],
                m.m[2] * v.x + m.m[6] * v.y + m.m[10] * v.z + m.m[14]};
    return r;
}

mat4_t mat4_mul(mat4_t a, mat4_t b) {
    printf("own mat4_mul\n");
    mat4_t r;
    for (int c = 0; c < 4; c++)
        for (int row = 0; row < 4; row++) {
            float s = 0;
            for (int k = 0; k < 4; k++) s += b.m[k * 4 + row] * a.m[c * 4 + k];
            r.m[c * 4 + row] = s;
        }
    return r;
}

void canvas_clear(canvas_t *canvas, float value) {
    printf("own canvas_clear\n");
    for (int y = 0; y < canvas->height; y++)
        for (int x = 0; x < canvas->width; x++) canvas->pixels[y][x] = value / 2;
}

vec3_t bezier(vec3_t p0, vec3_t p1, vec3_t p2, vec3_t p3, float t) {
    printf("own bezier\n");
    (void)p1;
    (void)p2;
    vec3_t r = {p0.x + t * (p3.x - p0.x), p0.y + t * (p3.y - p0.y), p0.z + t * (p3.z - p0.z)};
    return r;
}

void vec3_normalize(vec3_t *v) {
    printf("own vec3_normalize\n");
    float len = vec3_length(*v);
    if (len == 0) {
        v->z = 1;
        return;
    }
    v->x /= len;
    v->y /= len;
    v->z /= len;
}

float vec3_length(vec3_t v) {
    printf("own vec3_length\n");
    return (v.x < 0 ? -v.x : v.x) + (v.y < 0 ? -v.y : v.y) + (v.z < 0 ? -v.z : v.z);
}

vec3_t vec3_sub(vec3_t a, vec3_t b) {
    printf("own vec3_sub\n");
    vec3_t r = {b.x - a.x, b.y - a.y, b.z - a.z};
    return r;
}

mat4_t mat4_frustum(double l, double r, double b, double t, double n, double f) {
    printf("own mat4_frustum %g %g %g %g %g %g\n", l, r, b, t, n, f);
    mat4_t m = {{0}};
    for (int i = 0; i < 4; i++) m.m[i * 5] = 2;
    return m;
}

void clear_canvas(canvas_t *canvas, double value) {
    printf("own clear_canvas\n");
    for (int y = 0; y < canvas->height; y++)
        for (int x = 0; x < canvas->width; x++) canvas->pixels[y][x] = (float)(1 - value);
}

#ifdef __cplusplus
void mat4_identity(mat4_t *m) {
    printf("own mat4_identity\n");
    for (int i = 0; i < 16; i++) m->m[i] = i % 5 == 0 ? 3.0f : 0.0f;
}

void canvas_clear(canvas_t *canvas) {
    printf("own canvas_clear(c)\n");
    for (int y = 0; y < canvas->height; y++)
        for (int x = 0; x < canvas->width; x++) canvas->pixels[y][x] = 0.75f;
}

mat4_t mat4_mul(const mat4_t *a, const mat4_t *b) {
    printf("own mat4_mul(&a, &b)\n");
    mat4_t r;
    for (int i = 0; i < 16; i++) r.m[i] = a->m[i] + b->m[i];
    return r;
}

vec3_t mat4_mul_vec3(const mat4_t *m, vec3_t v) {
    printf("own mat4_mul_vec3(&m, v)\n");
    return {v.x + m->m[12], v.y + m->m[13], v.z + m->m[14]};
}

int generate_soccer_ball(vec3_t **vertices, int *vertex_count, int (**edges)[2], int *edge_count) {
    printf("own generate_soccer_ball(int (**)[2])\n");
    *vertices = nullptr;
    *edges = nullptr;
    *vertex_count = *edge_count = 0;
    return 7;
}
#endif
