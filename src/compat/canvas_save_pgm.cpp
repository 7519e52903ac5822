// canvas_save_pgm.cpp — other libtiny3d programs' name, C linkage (declared in compat/canvas_alias.h).
// Alone in its object file of libtiny3d.a: a program that defines its own canvas_save_pgm never
// pulls this one in (the linker takes an archive member only for a symbol still undefined).

#include "canvas.h"

int canvas_save_pgm(const canvas_t *canvas, const char *path) { return save_canvas(canvas, path) ? 0 : -1; }
