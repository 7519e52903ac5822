// motion.cpp — loop phase, looped orientation (quaternion slerp), moving objects.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "animation.h"

namespace tiny3d {

double loop_phase(double seconds, double period_s) {
    if (!(period_s > 0.0) || !std::isfinite(period_s) || !std::isfinite(seconds)) return 0.0;
    const double cycles = seconds / period_s;
    const double phase = cycles - std::floor(cycles);
    return phase < 1.0 ? phase : 0.0;  // cycles just below an integer can round up to 1
}

result<orientation_loop> orientation_loop::from_keys(std::vector<quat> keys) {
    if (keys.empty()) return error{"", 0, -1, "orientation loop: no keys"};
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const quat q = keys[i];
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) || !std::isfinite(q.w))
            return error{"", 0, -1, "orientation loop: key " + std::to_string(i) + " is not finite"};
        keys[i] = quat_normalize(q);
    }
    orientation_loop loop;
    loop.keys_ = std::move(keys);
    return loop;
}

result<orientation_loop> orientation_loop::spin(vec3_t axis, int turns) {
    // Keys 120° apart: under 180°, so shortest-path slerp turns the intended way, and slerp
    // between two rotations about one axis is exactly uniform rotation about it.
    constexpr int KEYS_PER_TURN = 3;
    if (turns == 0) return from_keys({quat_identity()});
    const int key_count = KEYS_PER_TURN * std::abs(turns);
    const double step = (turns > 0 ? 2.0 : -2.0) * M_PI / KEYS_PER_TURN;
    std::vector<quat> keys(static_cast<std::size_t>(key_count));
    for (int k = 0; k < key_count; ++k) keys[k] = quat_from_axis_angle(axis, static_cast<float>(step * k));
    return from_keys(std::move(keys));
}

quat orientation_loop::at_phase(double phase) const {
    const std::size_t n = keys_.size();
    const double position = loop_phase(phase, 1.0) * static_cast<double>(n);
    const std::size_t k = std::min(static_cast<std::size_t>(position), n - 1);
    const float t = static_cast<float>(position - static_cast<double>(k));
    if (t == 0.0f) return keys_[k];  // on a key: exactly that key (keeps loops pixel-exact)
    return quat_slerp(keys_[k], keys_[(k + 1) % n], t);
}

mat4_t motion_model_at(const motion &m, double seconds) {
    const vec3_t where = m.path.point_at_fraction(loop_phase(seconds, m.path_period_s) + m.path_offset);
    const quat turn = m.orientation.at_phase(loop_phase(seconds, m.orientation_period_s));
    return mat4_multiply(mat4_translate(where.x, where.y, where.z),
                         mat4_multiply(quat_to_mat4(turn), mat4_scale(m.scale, m.scale, m.scale)));
}

}  // namespace tiny3d
