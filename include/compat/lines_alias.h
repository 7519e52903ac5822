// compat/lines_alias.h — the 7-argument draw_line_f other libtiny3d programs call.
//
// Included at the end of lines.h (and self-contained: including it alone includes lines.h).
// A thin inline alias of tiny3d::draw_line_coverage; documentation/compat.md has the full
// table.
#ifndef TINY3D_COMPAT_LINES_ALIAS_H
#define TINY3D_COMPAT_LINES_ALIAS_H

#include "../lines.h"
#include "user_first.h"

// draw_line_f with a 7th `intensity` argument (the report's form in lines.h has six), in the
// same coordinates as the six-argument form: the report's, integer coordinates are pixel
// centres (canvas.h's conventions). The report's line has no intensity (its splats always
// add 1), so this form is tiny3d::draw_line_coverage with round caps, moved by half a
// pixel into library coordinates: each pixel gets intensity × the exact area of it the
// stroke covers, combined "over" (v + c·(1 − v)). Its image therefore differs from the
// six-argument form's even at intensity 1 (no over-inking); intensity is clamped to ≤ 1,
// ≤ 0 or NaN draws nothing. Thickness in pixels. fallback parameters: a program's own
// 7-argument draw_line_f (float, double or int parameters) is always the better match.
inline void draw_line_f(tiny3d::compat::fallback<canvas_t *> canvas, tiny3d::compat::fallback<float> x0,
                        tiny3d::compat::fallback<float> y0, tiny3d::compat::fallback<float> x1,
                        tiny3d::compat::fallback<float> y1, tiny3d::compat::fallback<float> thickness,
                        tiny3d::compat::fallback<float> intensity) {
    tiny3d::line_style style;
    style.cap = tiny3d::line_cap::round;
    style.intensity = intensity.value;
    const float to_library = 0.5f;  // report coordinates + 0.5 = library coordinates
    tiny3d::draw_line_coverage(canvas.value, x0.value + to_library, y0.value + to_library, x1.value + to_library,
                               y1.value + to_library, thickness.value, style);
}

#endif
