// texture_pgm.cpp — grey textures from PGM files (the canvas module's reader).
#include "raster.h"

namespace tiny3d {

result<texture> load_texture_pgm(const std::string &path) {
    result<canvas_ptr> image = load_pgm(path);
    if (!image) return image.err();
    return texture_from_canvas(*image.value());
}

}  // namespace tiny3d
