// zbuffer.cpp — the float depth buffer: one contiguous block, cleared without reallocation.
#include <algorithm>

#include "fill.h"

namespace tiny3d {

status zbuffer::resize(int width, int height) {
    const status size_ok = check_canvas_size(width, height);
    if (!size_ok) return size_ok;
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (data_.size() < count) data_.resize(count);  // grows only; shrinking keeps the block
    width_ = width;
    height_ = height;
    return {};
}

void zbuffer::clear(float depth) { clear_rows(0, height_, depth); }

void zbuffer::clear_rows(int y0, int y1, float depth) {
    y0 = std::max(y0, 0);
    y1 = std::min(y1, height_);
    if (y0 >= y1) return;
    detail::fill_floats(row(y0), static_cast<std::size_t>(y1 - y0) * width_, depth);
}

}  // namespace tiny3d
