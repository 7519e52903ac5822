// canvas.cpp — canvas allocation, the report's splat and DDA line.
#include "canvas.h"
#include "splat.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <new>

namespace {

constexpr std::size_t kAlign = 64;

std::size_t round_up(std::size_t n, std::size_t a) { return (n + a - 1) / a * a; }

// One allocation: [canvas_t][row pointers][pad][pixels], so a canvas is one block to free.
struct layout {
    std::size_t rows_offset, data_offset, total;
};

layout canvas_layout(int width, int height) {
    layout l{};
    l.rows_offset = round_up(sizeof(canvas_t), alignof(float *));
    l.data_offset = round_up(l.rows_offset + sizeof(float *) * std::size_t(height), kAlign);
    l.total = l.data_offset + sizeof(float) * std::size_t(width) * std::size_t(height);
    return l;
}

}  // namespace

namespace tiny3d {

status check_canvas_size(int width, int height) {
    if (width <= 0 || height <= 0)
        return error{"", 0, -1,
                     "canvas size " + std::to_string(width) + "x" + std::to_string(height) +
                         ": width and height must be positive"};
    if (width > CANVAS_MAX_SIDE || height > CANVAS_MAX_SIDE ||
        static_cast<long long>(width) * height > CANVAS_MAX_PIXELS)
        return error{"", 0, -1,
                     "canvas size " + std::to_string(width) + "x" + std::to_string(height) +
                         " exceeds the limit (sides <= " + std::to_string(CANVAS_MAX_SIDE) + ", at most " +
                         std::to_string(CANVAS_MAX_PIXELS) + " pixels)"};
    return {};
}

result<canvas_ptr> make_canvas(int width, int height) {
    status s = check_canvas_size(width, height);
    if (!s) return s.err();
    canvas_t *c = create_canvas(width, height);
    if (!c)
        return error{"", 0, -1,
                     "out of memory for a " + std::to_string(width) + "x" + std::to_string(height) + " canvas"};
    return canvas_ptr(c);
}

}  // namespace tiny3d

canvas_t *create_canvas(int width, int height) {
    if (!tiny3d::check_canvas_size(width, height)) return nullptr;
    const layout l = canvas_layout(width, height);
    void *block = ::operator new(l.total, std::align_val_t{kAlign}, std::nothrow);
    if (!block) return nullptr;
    auto *bytes = static_cast<unsigned char *>(block);
    auto *c = new (bytes) canvas_t{};
    c->width = width;
    c->height = height;
    c->pixels = reinterpret_cast<float **>(bytes + l.rows_offset);
    c->data = reinterpret_cast<float *>(bytes + l.data_offset);
    std::fill(c->data, c->data + std::size_t(width) * std::size_t(height), 0.0f);
    for (int y = 0; y < height; ++y) c->pixels[y] = c->data + std::size_t(y) * std::size_t(width);
    return c;
}

void destroy_canvas(canvas_t *canvas) {
    if (!canvas) return;
    canvas->~canvas_t();
    ::operator delete(static_cast<void *>(canvas), std::align_val_t{kAlign});
}

void remove_canvas(canvas_t *canvas) { destroy_canvas(canvas); }

std::size_t canvas_count_differing(const canvas_t *canvas, float value) {
    if (!canvas) return 0;
    const float *begin = canvas->data, *end = canvas->data + std::size_t(canvas->width) * std::size_t(canvas->height);
    return std::size_t(std::count_if(begin, end, [value](float v) { return v != value; }));
}

float get_pixel(const canvas_t *canvas, int x, int y) {
    if (!canvas || x < 0 || y < 0 || x >= canvas->width || y >= canvas->height) return 0.0f;
    return canvas->pixels[y][x];
}

void set_pixel_f(canvas_t *c, float x, float y, float intensity) { tiny3d::detail::splat(c, x, y, intensity); }
