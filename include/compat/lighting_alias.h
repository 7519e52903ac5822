// compat/lighting_alias.h — the lighting forms other libtiny3d programs rely on.
//
// Included at the end of lighting.h (and self-contained). light_t itself belongs to
// lighting.h; six of the surveyed implementations declare it as
//     typedef struct { vec3_t direction; float intensity; } light_t;
// and their programs brace-initialise it positionally ({{0, 0, 1}, 0.8f}), with designated
// initialisers ({.direction = …, .intensity = …}) or as a compound literal. Those programs
// compile against ours as long as light_t stays an aggregate whose FIRST two members are
// exactly these (later members must have default initialisers). These checks keep it so.
// The report's lambert_intensity(start, end, light_dir) is lighting.h's own.
#ifndef TINY3D_COMPAT_LIGHTING_ALIAS_H
#define TINY3D_COMPAT_LIGHTING_ALIAS_H

#include <cstddef>
#include <type_traits>

#include "../lighting.h"

static_assert(std::is_aggregate_v<light_t>, "light_t must stay an aggregate (brace and designated init)");
static_assert(std::is_standard_layout_v<light_t>, "light_t must stay standard-layout");
static_assert(std::is_same_v<decltype(light_t::direction), vec3_t> && offsetof(light_t, direction) == 0,
              "light_t's first member must be vec3_t direction");
static_assert(std::is_same_v<decltype(light_t::intensity), float> &&
                  offsetof(light_t, intensity) == sizeof(vec3_t),
              "light_t's second member must be float intensity");
static_assert(std::is_same_v<decltype(lambert_intensity), float(vec3_t, vec3_t, vec3_t)>,
              "the report's lambert_intensity(start, end, light_dir) form");

#endif
