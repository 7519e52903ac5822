// bezier.cpp — cubic Bezier segments, arc-length tables, closed C1 paths.
#include <algorithm>
#include <cmath>
#include <string>

#include "animation.h"

vec3_t vec3_bezier(vec3_t p0, vec3_t p1, vec3_t p2, vec3_t p3, float t) {
    // Bernstein form, as the report writes it.
    const float u = 1.0f - t;
    const float b0 = u * u * u, b1 = 3.0f * u * u * t, b2 = 3.0f * u * t * t, b3 = t * t * t;
    return {b0 * p0.x + b1 * p1.x + b2 * p2.x + b3 * p3.x, b0 * p0.y + b1 * p1.y + b2 * p2.y + b3 * p3.y,
            b0 * p0.z + b1 * p1.z + b2 * p2.z + b3 * p3.z};
}

namespace tiny3d {

namespace {

// dB/dt in double precision (the integrand of the arc length).
double tangent_length(const cubic_bezier &c, double t) {
    const double u = 1.0 - t;
    const double w0 = 3.0 * u * u, w1 = 6.0 * u * t, w2 = 3.0 * t * t;
    const double x = w0 * (double(c.p1.x) - c.p0.x) + w1 * (double(c.p2.x) - c.p1.x) + w2 * (double(c.p3.x) - c.p2.x);
    const double y = w0 * (double(c.p1.y) - c.p0.y) + w1 * (double(c.p2.y) - c.p1.y) + w2 * (double(c.p3.y) - c.p2.y);
    const double z = w0 * (double(c.p1.z) - c.p0.z) + w1 * (double(c.p2.z) - c.p1.z) + w2 * (double(c.p3.z) - c.p2.z);
    return std::sqrt(x * x + y * y + z * z);
}

// ∫_a^b |B'(t)| dt by 4-point Gauss–Legendre (exact for polynomials of degree ≤ 7; |B'| is
// smooth, so on the short intervals of a table the error is far below float precision).
double arc_length(const cubic_bezier &c, double a, double b) {
    static constexpr double NODE[2] = {0.3399810435848562648, 0.8611363115940525752};
    static constexpr double WEIGHT[2] = {0.6521451548625461426, 0.3478548451374538574};
    const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
    double sum = 0.0;
    for (int k = 0; k < 2; ++k)
        sum += WEIGHT[k] * (tangent_length(c, mid - half * NODE[k]) + tangent_length(c, mid + half * NODE[k]));
    return sum * half;
}

// Fritsch–Carlson: end slopes up to 3× the secant keep a cubic Hermite piece monotone.
constexpr double HERMITE_SLOPE_LIMIT = 3.0;

bool finite(vec3_t v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

float distance(vec3_t a, vec3_t b) {
    const vec3_t d = a - b;
    return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

// w mod n in [0, n), then the segment index and the local t.
void locate(double u, std::size_t n, std::size_t &segment, float &t) {
    const double count = static_cast<double>(n);
    double w = u - count * std::floor(u / count);
    if (!(w >= 0.0 && w < count)) w = 0.0;  // NaN / rounding up to n
    const double whole = std::floor(w);
    segment = std::min(static_cast<std::size_t>(whole), n - 1);
    t = static_cast<float>(w - static_cast<double>(segment));
}

}  // namespace

vec3_t bezier_point(const cubic_bezier &c, float t) { return vec3_bezier(c.p0, c.p1, c.p2, c.p3, t); }

vec3_t bezier_tangent(const cubic_bezier &c, float t) {
    const float u = 1.0f - t;
    return (c.p1 - c.p0) * (3.0f * u * u) + (c.p2 - c.p1) * (6.0f * u * t) + (c.p3 - c.p2) * (3.0f * t * t);
}

// ---- arc_length_table ------------------------------------------------------------------

result<arc_length_table> arc_length_table::build(std::span<const cubic_bezier> segments,
                                                 int samples_per_segment) {
    if (segments.empty()) return error{"", 0, -1, "arc-length table: no segments"};
    if (samples_per_segment < 1 || samples_per_segment > MAX_SAMPLES)
        return error{"", 0, -1,
                     "arc-length table: samples per segment " + std::to_string(samples_per_segment) +
                         " outside 1.." + std::to_string(MAX_SAMPLES)};
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const cubic_bezier &c = segments[i];
        if (!finite(c.p0) || !finite(c.p1) || !finite(c.p2) || !finite(c.p3))
            return error{"", 0, -1, "arc-length table: segment " + std::to_string(i) + " is not finite"};
    }
    arc_length_table table;
    table.samples_ = samples_per_segment;
    const std::size_t intervals = segments.size() * static_cast<std::size_t>(samples_per_segment);
    table.cumulative_.reserve(intervals + 1);
    table.slopes_.reserve(intervals);
    table.cumulative_.push_back(0.0);
    double total = 0.0;
    const double step = 1.0 / samples_per_segment;
    for (const cubic_bezier &c : segments)
        for (int i = 0; i < samples_per_segment; ++i) {
            const double t0 = i * step, t1 = (i + 1) * step;
            const double piece = arc_length(c, t0, t1);
            total += piece;
            table.cumulative_.push_back(total);
            // du/ds = 1/|B'| at both ends of the interval, limited to 3× the secant slope
            // (Fritsch–Carlson), so the Hermite inverse stays monotone; a zero-speed end
            // (cusp) takes the limit too.
            const double secant = piece > 0.0 ? step / piece : 0.0;
            const double limit = HERMITE_SLOPE_LIMIT * secant;
            auto slope = [&](double t) {
                const double speed = tangent_length(c, t);
                return speed * limit > 1.0 ? 1.0 / speed : limit;
            };
            table.slopes_.push_back({slope(t0), slope(t1)});
        }
    return table;
}

double arc_length_table::parameter_at_length(double s) const {
    if (cumulative_.size() < 2 || !(total_length() > 0.0)) return 0.0;
    s = std::clamp(s, 0.0, total_length());  // NaN stays NaN: caught below
    if (!(s >= 0.0)) s = 0.0;
    // Station i with cumulative_[i] ≤ s < cumulative_[i + 1] (the last interval at s = total).
    const auto above = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
    const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(above - cumulative_.begin()),
                                                cumulative_.size() - 1) - 1;
    const double h = cumulative_[i + 1] - cumulative_[i];
    const double u0 = static_cast<double>(i) / samples_, du = 1.0 / samples_;
    if (!(h > 0.0)) return u0;
    // Cubic Hermite interpolation of u(s) with the exact end slopes du/ds = 1/|B'|: the
    // speed error falls as h³ instead of the h of linear interpolation.
    const double x = (s - cumulative_[i]) / h, x2 = x * x, x3 = x2 * x;
    const double h01 = -2.0 * x3 + 3.0 * x2, h10 = x3 - 2.0 * x2 + x, h11 = x3 - x2;
    return u0 + h01 * du + h * (h10 * slopes_[i].left + h11 * slopes_[i].right);
}

// ---- looped_path -------------------------------------------------------------------------

result<looped_path> looped_path::assemble(std::vector<cubic_bezier> segments, int samples_per_segment) {
    auto table = arc_length_table::build(segments, samples_per_segment);
    if (!table) return table.err();
    looped_path path;
    path.segments_ = std::move(segments);
    path.table_ = std::move(table.value());
    return path;
}

result<looped_path> looped_path::through_points(std::span<const vec3_t> points, int samples_per_segment) {
    constexpr std::size_t MIN_POINTS = 3;
    const std::size_t n = points.size();
    if (n < MIN_POINTS)
        return error{"", 0, -1, "looped path: " + std::to_string(n) + " points, need at least 3"};
    std::vector<cubic_bezier> segments(n);
    for (std::size_t i = 0; i < n; ++i) {
        const vec3_t prev = points[(i + n - 1) % n], a = points[i], b = points[(i + 1) % n],
                     next = points[(i + 2) % n];
        if (!finite(a)) return error{"", 0, -1, "looped path: point " + std::to_string(i) + " is not finite"};
        if (a == b)
            return error{"", 0, -1,
                         "looped path: points " + std::to_string(i) + " and " + std::to_string((i + 1) % n) +
                             " coincide"};
        // Catmull–Rom tangent (P_{i+1} − P_{i−1})/2, and Bezier inner control = end ± tangent/3.
        segments[i] = {a, a + (b - prev) * (1.0f / 6.0f), b - (next - a) * (1.0f / 6.0f), b};
    }
    return assemble(std::move(segments), samples_per_segment);
}

result<looped_path> looped_path::from_segments(std::vector<cubic_bezier> segments, float tolerance,
                                               int samples_per_segment) {
    const std::size_t n = segments.size();
    if (n == 0) return error{"", 0, -1, "looped path: no segments"};
    for (std::size_t i = 0; i < n; ++i) {
        const cubic_bezier &a = segments[i], &b = segments[(i + 1) % n];
        const std::string joint = "looped path: joint " + std::to_string(i) + " -> " + std::to_string((i + 1) % n);
        if (!(distance(a.p3, b.p0) <= tolerance)) return error{"", 0, -1, joint + ": position jumps"};
        if (!(distance(bezier_tangent(a, 1.0f), bezier_tangent(b, 0.0f)) <= tolerance))
            return error{"", 0, -1, joint + ": tangent jumps"};
    }
    return assemble(std::move(segments), samples_per_segment);
}

namespace {
// Evaluates `eval` (bezier_point or bezier_tangent) on the segment that u falls in.
template <class Eval>
vec3_t evaluate_wrapped(const std::vector<cubic_bezier> &segments, double u, Eval eval) {
    if (segments.empty()) return {0.0f, 0.0f, 0.0f};
    std::size_t s;
    float t;
    locate(u, segments.size(), s, t);
    return eval(segments[s], t);
}
}  // namespace

vec3_t looped_path::point(double u) const { return evaluate_wrapped(segments_, u, bezier_point); }
vec3_t looped_path::tangent(double u) const { return evaluate_wrapped(segments_, u, bezier_tangent); }

double looped_path::parameter_at_fraction(double f) const {
    const double wrapped = f - std::floor(f);
    return table_.parameter_at_length(wrapped * length());
}

vec3_t looped_path::point_at_fraction(double f) const { return point(parameter_at_fraction(f)); }
vec3_t looped_path::tangent_at_fraction(double f) const { return tangent(parameter_at_fraction(f)); }

}  // namespace tiny3d
