/* compat_header.c — a user program written against the rarer forms, with the opt-in
 * tiny3d_compat.h: out-parameter matrix builders, pointer forms of the matrix product and
 * slerp, mat4_frustum, vec3_create, vec3_update_spherical; and, with it included, the
 * normal headers' draw_line_f with a 7th intensity argument and the four other names of
 * the PGM save (taken as function pointers).
 * usage: compat_header OUTDIR   (writes OUTDIR/compat_<name>.pgm for each save name) */
#include <stdio.h>

#include "tiny3d_compat.h"

static void print_mat(const char *label, const mat4_t *m) {
    printf("%s", label);
    for (int i = 0; i < 16; i++) printf(" %.9g", m->m[i]);
    printf("\n");
}

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";

    mat4_t t, r, s, model, tmp;
    mat4_translate(&t, 1, 2, 3);
    mat4_rotate_xyz(&r, (vec3_t){0.1, 0.2, 0.3});
    mat4_scale(&s, 2, 2, 2);
    mat4_multiply(&tmp, &r, &s);
    mat4_mul(&model, &t, &tmp);
    vec3_t p = vec3_create(1, 1, 1);
    vec3_t q = mat4_mul_vec3(&model, p);
    printf("model_point 1 1 1 -> %.9g %.9g %.9g\n", q.x, q.y, q.z);

    mat4_t identity;
    mat4_identity(&identity);
    mat4_t product = mat4_multiply(&identity, &model); /* value-returning pointer form */
    print_mat("identity_times_model", &product);
    print_mat("model", &model);

    mat4_t frustum = mat4_frustum(-1, 2, -0.5, 1.5, 1, 20);
    mat4_t frustum_out;
    mat4_frustum_asymmetric(&frustum_out, -1, 2, -0.5, 1.5, 1, 20);
    print_mat("frustum", &frustum);
    print_mat("frustum_out", &frustum_out);

    vec3_t a = vec3_create(1, 0, 0), b = vec3_create(0, 1, 0);
    vec3_t mid = vec3_slerp(&a, &b, 0.5);
    vec3_t before = mid;
    vec3_update_spherical(&mid);
    printf("slerp_mid -> %.9g %.9g %.9g\n", mid.x, mid.y, mid.z);
    printf("update_spherical_unchanged %d\n", before.x == mid.x && before.y == mid.y && before.z == mid.z);

    /* a horizontal line of intensity 0.5 along row 10 (integer coordinates are pixel
     * centres, as for the six-argument draw_line_f) */
    canvas_t *canvas = canvas_create(32, 20);
    if (!canvas) return 1;
    draw_line_f(canvas, 2, 10, 30, 10, 1, 0.5);

    const char *names[4] = {"save_canvas_as_pgm", "canvas_save_to_pgm", "save_canvas_pgm", "save_canvas_to_pgm"};
    int (*savers[4])(const canvas_t *, const char *) = {save_canvas_as_pgm, canvas_save_to_pgm, save_canvas_pgm,
                                                         save_canvas_to_pgm};
    for (int i = 0; i < 4; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/compat_%s.pgm", dir, names[i]);
        printf("save %s %d\n", names[i], savers[i](canvas, path));
    }
    char bad[1024];
    snprintf(bad, sizeof bad, "%s/no_such_folder/x.pgm", dir);
    printf("failed_save %d\n", save_canvas_as_pgm(canvas, bad));
    free_canvas(canvas);
    return 0;
}
