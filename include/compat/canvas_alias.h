// compat/canvas_alias.h — other libtiny3d implementations' names for the canvas API.
//
// Included at the end of canvas.h (and self-contained: including it alone includes
// canvas.h). Each name is a thin alias of the one implementation in canvas.h; none has an
// algorithm of its own. The first part is C and C++ (C linkage), the rest C++ only. At its end it pulls in lines.h for the report's programs. documentation/compat.md has the full table.
#ifndef TINY3D_COMPAT_CANVAS_ALIAS_H
#define TINY3D_COMPAT_CANVAS_ALIAS_H

#include "../canvas.h"

// ---- C and C++: functions with C linkage, each in its own object file of the archive
// (src/compat/), so a program that defines one of these names itself links its own -------
TINY3D_C_BEGIN

// create_canvas under its other name: a width × height canvas of zeros, or NULL when a side
// is ≤ 0, the size exceeds CANVAS_MAX_SIDE / CANVAS_MAX_PIXELS, or memory runs out.
canvas_t *canvas_create(int width, int height);

// destroy_canvas under its other names; NULL is ignored.
void canvas_destroy(canvas_t *canvas);
void free_canvas(canvas_t *canvas);
void canvas_free(canvas_t *canvas);

// save_canvas with the C return convention its users test for: returns 0 on success and
// −1 on failure (save_canvas itself returns true on success). The file is binary PGM (P5),
// written atomically, so a failed save leaves nothing behind; tiny3d::save_pgm gives the
// reason. A null canvas or path fails.
int canvas_save_pgm(const canvas_t *canvas, const char *path);

// The four names other implementations give their PPM save: the canvas as a binary colour
// PPM (P6, R = G = B = round(clamp(v, 0, 1) · 255)), written atomically as
// tiny3d::save_ppm writes it (temporary file + rename: a failed save leaves nothing
// behind and an existing file untouched). Errors are reported as the report's save_canvas
// reports them, by the result alone (nothing is printed), in canvas_save_pgm's convention:
// 0 on success, −1 on failure (a null canvas or path, a missing folder, no permission, a
// full disk, …); tiny3d::save_ppm gives the reason.
int save_canvas_ppm(const canvas_t *canvas, const char *path);
int save_canvas_to_ppm(const canvas_t *canvas, const char *path);
int save_canvas_as_ppm(const canvas_t *canvas, const char *path);
int canvas_save_ppm(const canvas_t *canvas, const char *path);

TINY3D_C_END

#ifdef __cplusplus
#include <cstddef>
#include <type_traits>

#include "user_first.h"

// The form 15 of the 20 surveyed implementations share, which user programs read directly
// (canvas->width, canvas->pixels[y][x]): keep these three members first.
static_assert(std::is_same_v<decltype(canvas_t::width), int> && offsetof(canvas_t, width) == 0 &&
                  std::is_same_v<decltype(canvas_t::height), int> && offsetof(canvas_t, height) == sizeof(int) &&
                  std::is_same_v<decltype(canvas_t::pixels), float **>,
              "canvas_t must start with int width, int height, float **pixels");

// ---- C++ only: names programs also give their own functions (compat/user_first.h) -------
// A program that defines or declares its own function of one of these names calls its own.
// C has one function per name: there canvas_clear is canvas.h's (canvas, value) form and
// these are not declared (documentation/compat.md).

// canvas_clear(c) — every pixel := 0 (black); the two-argument canvas_clear(c, value) is
// canvas.h's own. A null canvas is ignored. A template: a program's own one-argument
// canvas_clear wins.
template <class = void>
void canvas_clear(canvas_t *canvas) {
    canvas_clear(canvas, 0.0f);
}
// clear_canvas(c, value) — canvas_clear(c, value): every pixel := value clamped to 0..1
// (NaN → 0). fallback parameters: a program's own clear_canvas (float, double or int
// value) is always the better match.
inline void clear_canvas(tiny3d::compat::fallback<canvas_t *> canvas, tiny3d::compat::fallback<float> value) {
    canvas_clear(canvas.value, value.value);
}

// save_canvas under four more names, with canvas_save_pgm's convention: 0 on success, −1
// on failure (binary PGM, atomic write: nothing is left behind on failure; a null canvas
// or path fails). Callers that ignore the result (written for void forms) compile
// unchanged. Templates, so a program's own function of the name wins; their address can
// still be taken as int (*)(const canvas_t *, const char *), and NULL converts as usual.
template <class = void> int save_canvas_as_pgm(const canvas_t *canvas, const char *path) { return canvas_save_pgm(canvas, path); }
template <class = void> int canvas_save_to_pgm(const canvas_t *canvas, const char *path) { return canvas_save_pgm(canvas, path); }
template <class = void> int save_canvas_pgm(const canvas_t *canvas, const char *path) { return canvas_save_pgm(canvas, path); }
template <class = void> int save_canvas_to_pgm(const canvas_t *canvas, const char *path) { return canvas_save_pgm(canvas, path); }

#endif  // __cplusplus

// ---- the report's canvas.h also declared draw_line_f ------------------------------------
// Its home is lines.h (the lines module draws on the canvas; the canvas module knows
// nothing of lines). Included here so that a program written for the report that includes
// canvas.h alone still calls draw_line_f (and the 7-argument form, compat/lines_alias.h).
// lines.h includes canvas.h itself, so either order of inclusion gives both complete.
#include "../lines.h"

#endif
