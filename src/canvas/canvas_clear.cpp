// canvas_clear.cpp — canvas.h's canvas_clear (C linkage; declared in canvas.h).
// Alone in its object file of libtiny3d.a: a program that defines its own canvas_clear never
// pulls this one in (the linker takes an archive member only for a symbol still undefined).

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "canvas.h"
#include "splat.h"

void canvas_clear(canvas_t *canvas, float value) {
    if (!canvas) return;
    const float v = std::isnan(value) ? 0.0f : tiny3d::detail::clamp01(value);
    std::fill(canvas->data, canvas->data + std::size_t(canvas->width) * std::size_t(canvas->height), v);
}
