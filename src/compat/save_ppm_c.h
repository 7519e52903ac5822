// save_ppm_c.h — the one body of the four C-linkage PPM save names (src/compat/*_ppm.cpp).
#ifndef TINY3D_SRC_COMPAT_SAVE_PPM_C_H
#define TINY3D_SRC_COMPAT_SAVE_PPM_C_H

#include <string>

#include "canvas.h"

namespace tiny3d::compat {
// tiny3d::save_ppm (binary P6, atomic) in canvas_save_pgm's convention: 0 on success, −1 on
// failure, a null canvas or path included. Inline: each name stays alone in its object file.
inline int save_ppm_c(const canvas_t *canvas, const char *path) {
    if (!canvas || !path) return -1;
    return save_ppm(*canvas, path).ok() ? 0 : -1;
}
}  // namespace tiny3d::compat

#endif
