// line_test_util.h — helpers shared by the line tests: blank canvases, total ink, and the
// per-pixel error of a drawn canvas against a double-precision reference image.
#ifndef TINY3D_LINE_TEST_UTIL_H
#define TINY3D_LINE_TEST_UTIL_H

#include <algorithm>
#include <cmath>
#include <vector>

#include "canvas.h"

namespace line_test {

constexpr double kPi = 3.14159265358979323846;

inline tiny3d::canvas_ptr blank(int w, int h) { return std::move(tiny3d::make_canvas(w, h).value()); }

inline double ink(const canvas_t &c) {
    double s = 0;
    for (int i = 0; i < c.width * c.height; ++i) s += c.data[i];
    return s;
}

struct error_stats {
    double sum = 0, max = 0;
    long pixels = 0;
    double mean() const { return sum / double(std::max(pixels, 1L)); }
};

// Accumulates |drawn − reference| over the pixels either image touches.
inline void compare(const canvas_t &drawn, const std::vector<double> &ref, error_stats &e) {
    for (int i = 0; i < drawn.width * drawn.height; ++i) {
        if (drawn.data[i] == 0.0f && ref[std::size_t(i)] == 0.0) continue;
        const double d = std::fabs(double(drawn.data[i]) - ref[std::size_t(i)]);
        e.sum += d;
        e.max = std::max(e.max, d);
        ++e.pixels;
    }
}

}  // namespace line_test

#endif
