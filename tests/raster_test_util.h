// raster_test_util.h — helpers shared by the raster tests: a light rig of ambient light
// only (every pixel shades to the given value).
#ifndef TINY3D_RASTER_TEST_UTIL_H
#define TINY3D_RASTER_TEST_UTIL_H

#include <span>

#include "renderer.h"

namespace raster_test {

// Shade = ambient everywhere (no directional light).
inline tiny3d::light_rig constant_light(float ambient) {
    return tiny3d::make_light_rig(std::span<const light_t>(), ambient).value();
}

}  // namespace raster_test

#endif
