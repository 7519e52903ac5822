// save_canvas_as_ppm.cpp — other libtiny3d programs' name, C linkage (declared in compat/canvas_alias.h).
// Alone in its object file of libtiny3d.a: a program that defines its own save_canvas_as_ppm never
// pulls this one in (the linker takes an archive member only for a symbol still undefined).

#include "canvas.h"
#include "save_ppm_c.h"

int save_canvas_as_ppm(const canvas_t *canvas, const char *path) { return tiny3d::compat::save_ppm_c(canvas, path); }
