// canvas_create.cpp — other libtiny3d programs' name, C linkage (declared in compat/canvas_alias.h).
// Alone in its object file of libtiny3d.a: a program that defines its own canvas_create never
// pulls this one in (the linker takes an archive member only for a symbol still undefined).

#include "canvas.h"

canvas_t *canvas_create(int width, int height) { return create_canvas(width, height); }
