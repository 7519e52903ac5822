// frame_clock.cpp — frame times, rolling FPS and min / median / max (include/animation.h).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <string>

#include "animation.h"

namespace tiny3d {

status frame_clock::tick(double timestamp_s) {
    if (!std::isfinite(timestamp_s)) return error{"", 0, -1, "frame clock: timestamp is not finite"};
    if (ticked_ && timestamp_s < last_tick_)
        return error{"", 0, -1,
                     "frame clock: timestamp " + std::to_string(timestamp_s) + " s is before the previous one (" +
                         std::to_string(last_tick_) + " s)"};
    if (ticked_) frames_.push_back(timestamp_s - last_tick_);
    last_tick_ = timestamp_s;
    ticked_ = true;
    return {};
}

status frame_clock::add_frame(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0.0)
        return error{"", 0, -1, "frame clock: frame time " + std::to_string(seconds) + " s is not a finite time ≥ 0"};
    frames_.push_back(seconds);
    return {};
}

void frame_clock::reset() {
    frames_.clear();
    ticked_ = false;
    last_tick_ = 0.0;
}

double frame_clock::rolling_mean_seconds() const {
    const std::size_t n = std::min(window_, frames_.size());
    if (n == 0) return 0.0;
    return std::accumulate(frames_.end() - std::ptrdiff_t(n), frames_.end(), 0.0) / double(n);
}

frame_summary frame_clock::summary() const {
    frame_summary s;
    s.frames = frames_.size();
    if (frames_.empty()) return s;
    std::vector<double> sorted = frames_;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t n = sorted.size();
    s.min_s = sorted.front();
    s.max_s = sorted.back();
    s.median_s = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    s.total_s = std::accumulate(frames_.begin(), frames_.end(), 0.0);
    s.mean_s = s.total_s / double(n);
    return s;
}

double frame_clock::steady_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace tiny3d
