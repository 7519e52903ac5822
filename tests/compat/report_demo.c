/* report_demo.c — the libtiny3d report's own demo flow, with the report's names only:
 * create_canvas / draw_line_f / save_canvas / remove_canvas, generate_soccer_ball,
 * mat4_identity / mat4_multiply / mat4_translate / mat4_scale / mat4_rotate_xyz /
 * mat4_frustum_asymmetric / apply_transform, the 7-parameter render_wireframe,
 * vec3_from_spherical / vec3_to_spherical / vec3_normalize_fast / vec3_slerp,
 * lambert_intensity and vec3_bezier.
 * usage: report_demo OUTDIR   (writes OUTDIR/report_soccer.pgm) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "tiny3d.h"

#define WIDTH 200
#define HEIGHT 200

static float length(vec3_t v) { return sqrtf(v.x * v.x + v.y * v.y + v.z * v.z); }

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";

    vec3_t *vertices = NULL;
    int (*edges)[2] = NULL;
    int vertex_count = 0, edge_count = 0;
    /* the report's generate_soccer_ball returns nothing: success shows in the arrays
     * (also built as C, where that is the form declared) */
    generate_soccer_ball(&vertices, &vertex_count, &edges, &edge_count);
    if (!vertices || !edges) {
        fprintf(stderr, "soccer ball generation failed\n");
        return 1;
    }
    printf("Soccer ball generated: %d vertices, %d edges\n", vertex_count, edge_count);
    printf("soccer_counts %d %d\n", vertex_count, edge_count);
    float r_min = 1e30f, r_max = 0, e_min = 1e30f, e_max = 0;
    for (int i = 0; i < vertex_count; i++) {
        float r = length(vertices[i]);
        r_min = fminf(r_min, r);
        r_max = fmaxf(r_max, r);
    }
    for (int i = 0; i < edge_count; i++) {
        vec3_t a = vertices[edges[i][0]], b = vertices[edges[i][1]];
        vec3_t d = {b.x - a.x, b.y - a.y, b.z - a.z};
        e_min = fminf(e_min, length(d));
        e_max = fmaxf(e_max, length(d));
    }
    printf("soccer_radius %.9g %.9g\n", r_min, r_max);
    printf("soccer_edge %.9g %.9g\n", e_min, e_max);

    /* the report's camera: scale, rotate, push away, glFrustum */
    canvas_t *canvas = create_canvas(WIDTH, HEIGHT);
    if (!canvas) return 1;
    mat4_t scale = mat4_scale(1.0f, 1.0f, 1.0f);
    mat4_t rotate = mat4_rotate_xyz(0.3f, 0.5f, 0.0f);
    mat4_t translate = mat4_translate(0, 0, -2.5f);
    mat4_t model = mat4_multiply(translate, mat4_multiply(rotate, scale));
    mat4_t proj = mat4_multiply(mat4_frustum_asymmetric(-1, 1, -1, 1, 1, 10), mat4_identity());
    render_wireframe(canvas, vertices, vertex_count, edges, edge_count, model, proj);
    vec3_t centre = apply_transform(mat4_multiply(proj, model), (vec3_t){0, 0, 0});
    printf("centre_ndc %.9g %.9g %.9g\n", centre.x, centre.y, centre.z);

    char filename[1024];
    snprintf(filename, sizeof filename, "%s/report_soccer.pgm", dir);
    save_canvas(canvas, filename);
    printf("Saved: %s\n", filename);
    remove_canvas(canvas);

    /* lighting and animation: the first edge lit from above, moved along a Bezier path */
    vec3_t light_dir = vec3_from_spherical(1, 0, 0.25f); /* tilted 0.25 rad from +z */
    float r, theta, phi;
    vec3_to_spherical(light_dir, &r, &theta, &phi);
    printf("light %.9g %.9g %.9g -> %.9g %.9g %.9g\n", light_dir.x, light_dir.y, light_dir.z, r, theta, phi);
    vec3_t p0 = {0, 0, 0}, p1 = {1, 2, 0}, p2 = {3, 2, 1}, p3 = {4, 0, 0};
    for (int k = 0; k <= 4; k++) {
        float t = k / 4.0f;
        vec3_t offset = vec3_bezier(p0, p1, p2, p3, t);
        vec3_t a = vertices[edges[0][0]], b = vertices[edges[0][1]];
        vec3_t a_moved = {a.x + offset.x, a.y + offset.y, a.z + offset.z};
        vec3_t b_moved = {b.x + offset.x, b.y + offset.y, b.z + offset.z};
        printf("lit_edge %.9g %.9g %.9g %.9g %.9g %.9g %.9g -> %.9g\n", t, a.x, a.y, a.z, b.x, b.y, b.z,
               lambert_intensity(a_moved, b_moved, light_dir));
        printf("bezier %.9g -> %.9g %.9g %.9g\n", t, offset.x, offset.y, offset.z);
    }
    vec3_t unit = vec3_normalize_fast((vec3_t){0, 0, 5});
    vec3_t half = vec3_slerp((vec3_t){0, 0, 1}, (vec3_t){1, 0, 0}, 0.5f);
    printf("normalize_slerp -> %.9g %.9g %.9g %.9g %.9g %.9g\n", unit.x, unit.y, unit.z, half.x, half.y, half.z);

    free(vertices);
    free(edges);
    return 0;
}
