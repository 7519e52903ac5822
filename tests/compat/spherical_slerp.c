/* spherical_slerp.c — a user program in the style of other libtiny3d math tests:
 * vec3_from_spherical / vec3_to_spherical / vec3_from_cartesian, the pointer form of
 * vec3_normalize_fast, vec3_slerp, with int and double literals passed to float
 * parameters. Prints "name inputs -> outputs" lines (no files). */
#include <math.h>
#include <stdio.h>

#include "math3d.h"

static void print_vec(const char *label, vec3_t v) { printf("%s %.9g %.9g %.9g\n", label, v.x, v.y, v.z); }

int main(void) {
    /* r, theta (azimuth), phi (polar), as the report defines them */
    const double spherical[][3] = {
        {1, 0, 0}, {2, M_PI / 3, M_PI / 4}, {5, -M_PI / 2, M_PI / 2}, {0.5, 3 * M_PI / 4, 2.5}, {3, 1, M_PI},
    };
    for (unsigned i = 0; i < sizeof spherical / sizeof spherical[0]; i++) {
        vec3_t v = vec3_from_spherical(spherical[i][0], spherical[i][1], spherical[i][2]);
        printf("from_spherical %.9g %.9g %.9g -> %.9g %.9g %.9g\n", (float)spherical[i][0], (float)spherical[i][1],
               (float)spherical[i][2], v.x, v.y, v.z);
    }

    vec3_t points[] = {vec3_from_cartesian(1, 2, 3), vec3_from_cartesian(-4, 0.5, -2), (vec3_t){0, 0, 7},
                       (vec3_t){.x = 3, .y = -3, .z = 0}};
    for (unsigned i = 0; i < sizeof points / sizeof points[0]; i++) {
        float r, theta, phi;
        vec3_to_spherical(points[i], &r, &theta, &phi);
        printf("to_spherical %.9g %.9g %.9g -> %.9g %.9g %.9g\n", points[i].x, points[i].y, points[i].z, r, theta, phi);
    }

    vec3_t n = {3, 4, 12};
    vec3_normalize_fast(&n); /* the pointer form */
    printf("normalize_fast 3 4 12 -> %.9g %.9g %.9g\n", n.x, n.y, n.z);

    vec3_t a = {1, 0, 0}, b = {0, 2, 0}, c = {0, 0.6, 0.8};
    for (int k = 0; k <= 4; k++) {
        float t = k / 4.0;
        vec3_t s = vec3_slerp(a, b, t);
        printf("slerp 1 0 0 0 2 0 %.9g -> %.9g %.9g %.9g\n", t, s.x, s.y, s.z);
        s = vec3_slerp(b, c, t);
        printf("slerp 0 2 0 0 0.6 0.8 %.9g -> %.9g %.9g %.9g\n", t, s.x, s.y, s.z);
    }
    print_vec("done", vec3_from_cartesian(0, 0, 0));
    return 0;
}
