// free_canvas.cpp — other libtiny3d programs' name, C linkage (declared in compat/canvas_alias.h).
// Alone in its object file of libtiny3d.a: a program that defines its own free_canvas never
// pulls this one in (the linker takes an archive member only for a symbol still undefined).

#include "canvas.h"

void free_canvas(canvas_t *canvas) { destroy_canvas(canvas); }
