/* generate_soccer.c — the program's own generate_soccer_ball in the report's printed form
 * (as the report's demo/generate_soccer.c brings its own): a tetrahedron in static arrays.
 * `edges` is the address of the caller's int (*)[2], as the report's callers pass it. */
#include <stdio.h>

#include "own.h"

void generate_soccer_ball(vec3_t **vertices, int *vertex_count, int *edges[][2], int *edge_count) {
    static vec3_t vtx[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    static int edg[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    printf("own generate_soccer_ball\n");
    *vertices = vtx;
    *vertex_count = 4;
    *(int(**)[2])edges = edg;
    *edge_count = 6;
}
