// compat/renderer_alias.h — the renderer names other libtiny3d programs call.
//
// Included at the end of renderer.h (and self-contained). The shared form
// clip_to_circular_viewport(canvas_t *, float x, float y) → bool (6 of the surveyed
// implementations) is pipeline.h's own function, so nothing is aliased here; this header
// pins that form at compile time so a change that would break those programs fails to
// build. The int x, int y form (2 implementations) is deliberately NOT added: its callers
// already compile against the float form (int → float), while an int overload would make
// mixed calls such as (c, 1.5f, 2) ambiguous. project_vertex, render_wireframe and
// generate_soccer_ball have no form shared between implementations; the report's are
// the ones declared (pipeline.h, wireframe.h, mesh.h). documentation/compat.md has the full table.
#ifndef TINY3D_COMPAT_RENDERER_ALIAS_H
#define TINY3D_COMPAT_RENDERER_ALIAS_H

#include <type_traits>

#include "../renderer.h"

static_assert(std::is_same_v<decltype(clip_to_circular_viewport), bool(canvas_t *, float, float)>,
              "other libtiny3d programs call clip_to_circular_viewport(canvas_t *, float, float) -> bool");
static_assert(std::is_same_v<decltype(render_wireframe(static_cast<canvas_t *>(nullptr),
                                                       static_cast<vec3_t *>(nullptr), 0,
                                                       static_cast<int (*)[2]>(nullptr), 0, mat4_t{},
                                                       mat4_t{})),
                             void>,
              "the report's 7-parameter render_wireframe must stay callable");

#endif
