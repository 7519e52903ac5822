// compat/canvas_alias.h — other libtiny3d implementations' names for the canvas API.
//
// Included at the end of canvas.h (and self-contained: including it alone includes
// canvas.h). Each name is a thin inline alias of the one implementation in canvas.h; none
// has an algorithm of its own. documentation/compat.md has the full table.
#ifndef TINY3D_COMPAT_CANVAS_ALIAS_H
#define TINY3D_COMPAT_CANVAS_ALIAS_H

#include <cstddef>
#include <type_traits>

#include "../canvas.h"
#include "user_first.h"

// The form 15 of the 20 surveyed implementations share, which user programs read directly
// (canvas->width, canvas->pixels[y][x]): keep these three members first.
static_assert(std::is_same_v<decltype(canvas_t::width), int> && offsetof(canvas_t, width) == 0 &&
                  std::is_same_v<decltype(canvas_t::height), int> && offsetof(canvas_t, height) == sizeof(int) &&
                  std::is_same_v<decltype(canvas_t::pixels), float **>,
              "canvas_t must start with int width, int height, float **pixels");

// create_canvas under its other name: a width × height canvas of zeros, or a null pointer
// when a side is ≤ 0, the size exceeds CANVAS_MAX_SIDE / CANVAS_MAX_PIXELS, or memory
// runs out.
inline canvas_t *canvas_create(int width, int height) { return create_canvas(width, height); }

// destroy_canvas under its other names; a null pointer is ignored.
inline void canvas_destroy(canvas_t *canvas) { destroy_canvas(canvas); }
inline void free_canvas(canvas_t *canvas) { destroy_canvas(canvas); }
inline void canvas_free(canvas_t *canvas) { destroy_canvas(canvas); }

// save_canvas with the C return convention its users test for: returns 0 on success and
// −1 on failure (save_canvas itself returns true on success). The file is binary PGM (P5),
// written atomically, so a failed save leaves nothing behind; tiny3d::save_pgm gives the
// reason. A null canvas or path fails.
inline int canvas_save_pgm(const canvas_t *canvas, const char *path) {
    return save_canvas(canvas, path) ? 0 : -1;
}

// canvas_clear(c) — every pixel := 0 (black). The two-argument canvas_clear(c, value) is
// canvas.h's own. A null canvas is ignored.
inline void canvas_clear(canvas_t *canvas) { canvas_clear(canvas, 0.0f); }
// clear_canvas(c, value) — canvas_clear(c, value): every pixel := value clamped to 0..1
// (NaN → 0).
inline void clear_canvas(canvas_t *canvas, float value) { canvas_clear(canvas, value); }

// ---- names programs also give their own functions (compat/user_first.h) ----------------
// A program that defines or declares its own function of one of these names calls its own.

// save_canvas under four more names, with canvas_save_pgm's convention: 0 on success, −1
// on failure (binary PGM, atomic write: nothing is left behind on failure; a null canvas
// or path fails). Callers that ignore the result (written for void forms) compile
// unchanged. Templates, so a program's own function of the name wins; their address can
// still be taken as int (*)(const canvas_t *, const char *), and NULL converts as usual.
template <class = void>
int save_canvas_as_pgm(const canvas_t *canvas, const char *path) {
    return canvas_save_pgm(canvas, path);
}
template <class = void>
int canvas_save_to_pgm(const canvas_t *canvas, const char *path) {
    return canvas_save_pgm(canvas, path);
}
template <class = void>
int save_canvas_pgm(const canvas_t *canvas, const char *path) {
    return canvas_save_pgm(canvas, path);
}
template <class = void>
int save_canvas_to_pgm(const canvas_t *canvas, const char *path) {
    return canvas_save_pgm(canvas, path);
}

// draw_line_f with a 7th `intensity` argument (the report's form above has six), in the
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
