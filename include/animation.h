// animation.h — Bezier paths, constant-speed motion, looped timelines, frame timing,
// orientation.
//
// Conventions (pinned by tests/animation_test.cpp):
//  * Time is in seconds on one clock (tiny3d::anim_clock); objects are placed by time, not
//    by frame number, so several objects stay in sync at any frame rate.
//  * A looped animation of period P seconds is a function of its phase
//    loop_phase(t, P) = t/P − floor(t/P) ∈ [0, 1): times one period apart give the same
//    phase (exactly when t/P is an integer), hence the same picture.
//  * Path parameter u of a path of n cubic segments runs over [0, n): segment floor(u),
//    local t = u − floor(u). Constant-speed motion uses a distance fraction f ∈ [0, 1)
//    instead (f of the path's total arc length from its start).
#ifndef TINY3D_ANIMATION_H
#define TINY3D_ANIMATION_H

#include "math3d.h"
#include "tiny3d_result.h"

#ifdef __cplusplus
#include <cstddef>
#include <span>
#include <vector>
#endif

// ---- the libtiny3d report's API (C linkage; all a C program sees, with bezier) ---------
TINY3D_C_BEGIN

// The report's cubic Bezier: B(t) = (1−t)³p0 + 3(1−t)²t p1 + 3(1−t)t² p2 + t³p3.
// t in [0, 1] (other t extrapolate the polynomial). B(0) = p0 and B(1) = p3 exactly.
vec3_t vec3_bezier(vec3_t p0, vec3_t p1, vec3_t p2, vec3_t p3, float t);
TINY3D_C_END

#ifdef __cplusplus
namespace tiny3d {

struct cubic_bezier {
    vec3_t p0, p1, p2, p3;
};

// B(t) of the segment (vec3_bezier).
vec3_t bezier_point(const cubic_bezier &c, float t);
// dB/dt = 3[(1−t)²(p1−p0) + 2(1−t)t(p2−p1) + t²(p3−p2)]; at the ends 3(p1−p0) and 3(p3−p2).
// Units: length per unit of t (not normalised).
vec3_t bezier_tangent(const cubic_bezier &c, float t);

// Arc length as a function of the path parameter, tabulated once per path, for
// constant-speed motion. Stations sit at u_i = i / samples_per_segment; the length between
// neighbouring stations is integrated exactly enough (4-point Gauss–Legendre on |B'|, in
// double). parameter_at_length inverts by binary search and cubic Hermite interpolation
// with the exact end slopes du/ds = 1/|B'| (limited for monotonicity), so the speed error
// falls as 1/samples³ (64 samples per segment: < 1e-3 on a strongly uneven segment).
// tests/bench/bezier.cpp charts the speed error against the table size and cost.
class arc_length_table {
public:
    arc_length_table() = default;
    // Error for no segments, samples_per_segment < 1 or > MAX_SAMPLES, or non-finite
    // control points.
    static result<arc_length_table> build(std::span<const cubic_bezier> segments,
                                          int samples_per_segment);
    static constexpr int MAX_SAMPLES = 1 << 16;

    double total_length() const { return cumulative_.empty() ? 0.0 : cumulative_.back(); }
    // Path parameter u ∈ [0, segment count] whose arc length from the start is s
    // (s clamped to [0, total_length()]). A zero-length path gives 0.
    double parameter_at_length(double s) const;
    int samples_per_segment() const { return samples_; }
    std::size_t station_count() const { return cumulative_.size(); }

private:
    struct end_slopes {
        double left, right;  // du/ds at the interval's two ends
    };
    std::vector<double> cumulative_;  // arc length from the start at station i
    std::vector<end_slopes> slopes_;  // per interval between stations
    int samples_ = 0;
};

// A closed path of cubic segments with position and tangent continuous at every joint,
// including the one where the loop closes (segment n−1's end joins segment 0's start).
class looped_path {
public:
    looped_path() = default;
    static constexpr int DEFAULT_SAMPLES_PER_SEGMENT = 64;  // speed error < 1e-3 (tested)

    // The closed uniform Catmull–Rom spline through the points (≥ 3, consecutive points —
    // including last→first — distinct), as Bezier segments: segment i runs from P_i to
    // P_{i+1} with inner controls P_i + (P_{i+1} − P_{i−1})/6 and P_{i+1} − (P_{i+2} − P_i)/6
    // (indices mod n), so the tangent at P_i is (P_{i+1} − P_{i−1})/2 on both sides.
    static result<looped_path> through_points(std::span<const vec3_t> points,
                                              int samples_per_segment = DEFAULT_SAMPLES_PER_SEGMENT);
    // Given segments; checks each joint (i → i+1 and the closing n−1 → 0): end point equals
    // the next start and end tangent 3(p3 − p2) equals the next 3(p1 − p0), within
    // `tolerance` (absolute, in path units). The error names the joint.
    static result<looped_path> from_segments(std::vector<cubic_bezier> segments,
                                             float tolerance = 1e-5f,
                                             int samples_per_segment = DEFAULT_SAMPLES_PER_SEGMENT);

    std::size_t segment_count() const { return segments_.size(); }
    const cubic_bezier &segment(std::size_t i) const { return segments_[i]; }
    double length() const { return table_.total_length(); }

    // By path parameter u (wraps modulo segment_count()).
    vec3_t point(double u) const;
    vec3_t tangent(double u) const;
    // Constant speed: the point at distance fraction f of the length (f wraps modulo 1).
    vec3_t point_at_fraction(double f) const;
    vec3_t tangent_at_fraction(double f) const;
    // Path parameter (in [0, segment_count())) at distance fraction f (wraps modulo 1).
    double parameter_at_fraction(double f) const;

private:
    // Builds the table and takes the (already checked) segments.
    static result<looped_path> assemble(std::vector<cubic_bezier> segments, int samples_per_segment);
    std::vector<cubic_bezier> segments_;
    arc_length_table table_;
};

// ---- time ------------------------------------------------------------------------------

// One clock in seconds shared by every animated object.
struct anim_clock {
    double seconds = 0.0;
    // The time of frame `frame` at `frames_per_second` (> 0): frame / fps.
    static anim_clock at_frame(long frame, double frames_per_second) {
        return {static_cast<double>(frame) / frames_per_second};
    }
};

// t/P − floor(t/P) ∈ [0, 1) for a loop of period P > 0 seconds; P ≤ 0 or non-finite
// input gives 0.
double loop_phase(double seconds, double period_s);

// ---- frame timing ----------------------------------------------------------------------

// Frame times in seconds, fed by the caller: from a clock (frame_clock::steady_seconds())
// while rendering, or from any sequence of timestamps (tests, offline renders). Two ways:
//   tick(t)       a frame ends at timestamp t; its time is t minus the previous tick (the
//                 first tick only starts the clock) — frame-to-frame intervals, as a
//                 display loop measures them;
//   add_frame(d)  a frame took d seconds (e.g. render time measured around the work).
// rolling_fps() is over the last `window` frames (60 by default, as a display counter
// would): their count divided by their summed time. summary() covers every frame since
// construction or reset(). Every frame time is kept (8 bytes a frame); reserve() ahead
// and recording allocates nothing.
struct frame_summary {
    std::size_t frames = 0;
    double min_s = 0, median_s = 0, max_s = 0;  // median of an even count: mean of the middle two
    double mean_s = 0, total_s = 0;
};

class frame_clock {
public:
    static constexpr std::size_t DEFAULT_WINDOW = 60;
    explicit frame_clock(std::size_t window = DEFAULT_WINDOW) : window_(window ? window : 1) {}

    // Error (nothing recorded) for a non-finite timestamp or one before the previous tick.
    status tick(double timestamp_s);
    // Error (nothing recorded) for a negative or non-finite duration.
    status add_frame(double seconds);
    void reserve(std::size_t frames) { frames_.reserve(frames); }
    void reset();  // forgets every frame and the last tick

    std::size_t frame_count() const { return frames_.size(); }
    std::size_t window() const { return window_; }
    double last_frame_seconds() const { return frames_.empty() ? 0.0 : frames_.back(); }
    const std::vector<double> &frame_seconds() const { return frames_; }
    // Mean frame time over the last min(window, frame_count()) frames; 0 with no frames.
    double rolling_mean_seconds() const;
    // 1 / rolling_mean_seconds(); 0 with no frames or when they all took 0 s.
    double rolling_fps() const { return fps(rolling_mean_seconds()); }
    // Min / median / max / mean / total over every frame (all 0 with none). Sorts a copy.
    frame_summary summary() const;

    static double fps(double frame_seconds) { return frame_seconds > 0.0 ? 1.0 / frame_seconds : 0.0; }
    // A monotonic clock in seconds (arbitrary origin) to feed tick() or time add_frame().
    static double steady_seconds();

private:
    std::vector<double> frames_;
    std::size_t window_;
    double last_tick_ = 0.0;
    bool ticked_ = false;
};

// ---- orientation -----------------------------------------------------------------------

// A looped orientation: key rotations spaced evenly over one period (key k at phase k/n);
// between keys, shortest-path quaternion slerp (tiny3d::quat_slerp), and after the last key
// back to key 0. Consecutive keys should differ by less than 180° (slerp takes the short way).
class orientation_loop {
public:
    orientation_loop() : keys_{quat_identity()} {}
    // Error for no keys or a non-finite key. Keys are normalised.
    static result<orientation_loop> from_keys(std::vector<quat> keys);
    // `turns` whole turns (any sign, |turns| ≥ 1; 0 = still) about `axis` per period, as
    // 3·|turns| keys 120° apart, so slerp turns at constant angular speed.
    static result<orientation_loop> spin(vec3_t axis, int turns);
    quat at_phase(double phase) const;  // phase wraps modulo 1

private:
    std::vector<quat> keys_;
};

// ---- a moving object -------------------------------------------------------------------

// What one object does over time: it travels its looped path at constant speed, once per
// path_period_s, starting path_offset (a distance fraction) along it, while it turns with
// `orientation`, once per orientation_period_s; it is uniformly scaled by `scale`.
struct motion {
    looped_path path;
    double path_period_s = 1.0;
    double path_offset = 0.0;
    orientation_loop orientation;
    double orientation_period_s = 1.0;
    float scale = 1.0f;
};
// The object's model matrix at clock time t: T(path point) · R(orientation) · S(scale).
mat4_t motion_model_at(const motion &m, double seconds);

}  // namespace tiny3d
#endif  // __cplusplus

#include "compat/animation_alias.h"  // other libtiny3d programs' name bezier(…)

#endif
