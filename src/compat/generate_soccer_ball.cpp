// generate_soccer_ball.cpp — the report's generator for C programs (declared in mesh.h, C part).
// Alone in its object file of libtiny3d.a: a program that defines its own generate_soccer_ball never
// pulls this one in (the linker takes an archive member only for a symbol still undefined).

#include "mesh.h"

// The C form: void, `edges` the address of the caller's int (*)[2] (mesh.h says why).
// Success shows in *vertices != NULL.
extern "C" void generate_soccer_ball(vec3_t **vertices, int *vertex_count, int (**edges)[2], int *edge_count) {
    tiny3d::soccer_ball_arrays(vertices, vertex_count, edges, edge_count);
}
