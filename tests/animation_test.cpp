// animation_test.cpp — Bezier, arc length, looped paths, clock, orientation, motion.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "animation.h"
#include "math3d.h"
#include "harness.h"

namespace {

// An S-shaped segment whose speed |B'| varies by ~10× along t (plain t is far from
// constant speed on it).
const tiny3d::cubic_bezier S_CURVE = {{0, 0, 0}, {0.2f, 3, 0}, {4, -2, 1}, {5, 0.5f, 0.2f}};

// Reference B(t) by de Casteljau in double (a different algorithm from the Bernstein form).
void casteljau(const tiny3d::cubic_bezier &c, double t, double out[3]) {
    const vec3_t p[4] = {c.p0, c.p1, c.p2, c.p3};
    for (int axis = 0; axis < 3; ++axis) {
        double v[4];
        for (int i = 0; i < 4; ++i) v[i] = axis == 0 ? p[i].x : axis == 1 ? p[i].y : p[i].z;
        for (int level = 3; level > 0; --level)
            for (int i = 0; i < level; ++i) v[i] = (1 - t) * v[i] + t * v[i + 1];
        out[axis] = v[0];
    }
}

// Reference arc length of a segment: chord sum over many points in double.
double reference_length(const tiny3d::cubic_bezier &c, int chords = 200000) {
    double prev[3], cur[3], total = 0;
    casteljau(c, 0, prev);
    for (int i = 1; i <= chords; ++i) {
        casteljau(c, double(i) / chords, cur);
        total += std::sqrt((cur[0] - prev[0]) * (cur[0] - prev[0]) + (cur[1] - prev[1]) * (cur[1] - prev[1]) +
                           (cur[2] - prev[2]) * (cur[2] - prev[2]));
        std::copy(cur, cur + 3, prev);
    }
    return total;
}

double length(vec3_t v) { return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z); }

std::vector<vec3_t> loop_points() {
    return {{-3, 0, 0}, {-1, 2, 1}, {2, 1.5f, -1}, {3, -1, 0}, {0, -2, 2}};
}

}  // namespace

TEST(bezier_endpoints_are_exact) {
    const auto &c = S_CURVE;
    CHECK(vec3_bezier(c.p0, c.p1, c.p2, c.p3, 0.0f) == c.p0);
    CHECK(vec3_bezier(c.p0, c.p1, c.p2, c.p3, 1.0f) == c.p3);
}

TEST(bezier_matches_double_de_casteljau) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> coord(-10, 10), param(0, 1);
    double worst = 0;
    for (int i = 0; i < 1000; ++i) {
        const tiny3d::cubic_bezier c = {{coord(rng), coord(rng), coord(rng)}, {coord(rng), coord(rng), coord(rng)},
                                        {coord(rng), coord(rng), coord(rng)}, {coord(rng), coord(rng), coord(rng)}};
        const float t = param(rng);
        double ref[3];
        casteljau(c, t, ref);
        const vec3_t b = tiny3d::bezier_point(c, t);
        worst = std::max({worst, std::fabs(b.x - ref[0]), std::fabs(b.y - ref[1]), std::fabs(b.z - ref[2])});
    }
    CHECK_NEAR(worst, 0.0, 2e-5);  // a few ulps of coordinates up to 10
}

TEST(bezier_tangent_at_ends_and_against_finite_differences) {
    const auto &c = S_CURVE;
    const vec3_t start = tiny3d::bezier_tangent(c, 0.0f), end = tiny3d::bezier_tangent(c, 1.0f);
    CHECK(start == (c.p1 - c.p0) * 3.0f);
    CHECK(end == (c.p3 - c.p2) * 3.0f);
    // Central differences of the double reference (error O(h²) ≈ 1e-8).
    const double h = 1e-4;
    for (double t = 0.05; t < 1.0; t += 0.1) {
        double a[3], b[3];
        casteljau(c, t - h, a);
        casteljau(c, t + h, b);
        const vec3_t d = tiny3d::bezier_tangent(c, float(t));
        CHECK_NEAR(d.x, (b[0] - a[0]) / (2 * h), 1e-4);
        CHECK_NEAR(d.y, (b[1] - a[1]) / (2 * h), 1e-4);
        CHECK_NEAR(d.z, (b[2] - a[2]) / (2 * h), 1e-4);
    }
}

TEST(straight_control_polygon_gives_a_straight_path) {
    // Controls on the line through (1,2,3) with direction (2,−1,0.5), unevenly spaced.
    const vec3_t o = {1, 2, 3}, d = {2, -1, 0.5f};
    const tiny3d::cubic_bezier c = {o, o + d * 0.7f, o + d * 0.2f, o + d * 1.0f};
    const double dlen = length(d);
    for (int i = 0; i <= 100; ++i) {
        const vec3_t p = tiny3d::bezier_point(c, i / 100.0f) - o;
        // Distance from the line: |p × d| / |d|.
        const vec3_t x = {p.y * d.z - p.z * d.y, p.z * d.x - p.x * d.z, p.x * d.y - p.y * d.x};
        CHECK_NEAR(length(x) / dlen, 0.0, 1e-6);
    }
}

TEST(arc_length_table_total_matches_reference) {
    const auto table = tiny3d::arc_length_table::build(std::span(&S_CURVE, 1), 64);
    CHECK(table.ok());
    const double ref = reference_length(S_CURVE);
    CHECK_NEAR(table->total_length() / ref, 1.0, 1e-7);
    CHECK_NEAR(table->parameter_at_length(0.0), 0.0, 0.0);
    CHECK_NEAR(table->parameter_at_length(ref * 2), 1.0, 1e-12);  // clamped
    CHECK_NEAR(table->parameter_at_length(std::nan("")), 0.0, 0.0);
}

TEST(arc_length_table_speed_within_one_percent) {
    // Speed of s ↦ B(u(s)) is |B'(u)|·du/ds; constant speed means 1. du/ds by a central
    // difference of the (piecewise linear) table, B' analytic.
    auto worst_speed_error = [](int samples, bool use_table) {
        const auto table = tiny3d::arc_length_table::build(std::span(&S_CURVE, 1), samples);
        const double total = table->total_length();
        double worst = 0;
        for (int i = 1; i < 1000; ++i) {
            const double s = total * (i + 0.37) / 1000.0, ds = total * 1e-7;
            double u, du_ds;
            if (use_table) {
                u = table->parameter_at_length(s);
                du_ds = (table->parameter_at_length(s + ds) - table->parameter_at_length(s - ds)) / (2 * ds);
            } else {
                u = s / total;  // plain t: parameter proportional to the wanted distance
                du_ds = 1.0 / total;
            }
            const double speed = length(tiny3d::bezier_tangent(S_CURVE, float(u))) * du_ds;
            worst = std::max(worst, std::fabs(speed - 1.0));
        }
        return worst;
    };
    CHECK(worst_speed_error(1, false) > 0.3);  // plain t is 40 % off constant speed here
    CHECK_NEAR(worst_speed_error(tiny3d::looped_path::DEFAULT_SAMPLES_PER_SEGMENT, true), 0.0, 1e-3);
    CHECK_NEAR(worst_speed_error(16, true), 0.0, 0.01);
    // Hermite inverse: error falls like 1/samples³; 4× the samples, ≥ 16× smaller error.
    CHECK(worst_speed_error(64, true) * 16 < worst_speed_error(16, true));
}

TEST(arc_length_table_rejects_bad_input) {
    CHECK(!tiny3d::arc_length_table::build({}, 16).ok());
    CHECK(!tiny3d::arc_length_table::build(std::span(&S_CURVE, 1), 0).ok());
    tiny3d::cubic_bezier bad = S_CURVE;
    bad.p2.y = INFINITY;
    CHECK(!tiny3d::arc_length_table::build(std::span(&bad, 1), 16).ok());
}

TEST(looped_path_is_continuous_at_every_joint) {
    const auto pts = loop_points();
    const auto path = tiny3d::looped_path::through_points(pts);
    CHECK(path.ok());
    const std::size_t n = path->segment_count();
    CHECK_EQ(n, pts.size());
    for (std::size_t i = 0; i < n; ++i) {
        const auto &a = path->segment(i), &b = path->segment((i + 1) % n);  // i = n−1: the closing joint
        CHECK(a.p0 == pts[i]);  // passes through the points
        CHECK(a.p3 == b.p0);
        const vec3_t ta = tiny3d::bezier_tangent(a, 1), tb = tiny3d::bezier_tangent(b, 0);
        CHECK_NEAR(length(ta - tb), 0.0, 1e-5 * length(ta));
        // Approaching the joint by path parameter from both sides.
        const double u = double(i + 1), eps = 1e-6;
        CHECK_NEAR(length(path->point(u - eps) - path->point(u + eps)), 0.0, 1e-4);
    }
    // Wrapping: u and u + n are the same point; fraction 0 and 1 too, exactly.
    CHECK(path->point(0.3) == path->point(0.3 + double(n)));
    CHECK(path->point_at_fraction(0.0) == path->point_at_fraction(1.0));
    CHECK(path->point_at_fraction(0.0) == pts[0]);
}

TEST(looped_path_from_segments_checks_joints) {
    const auto good = tiny3d::looped_path::through_points(loop_points());
    std::vector<tiny3d::cubic_bezier> segs;
    for (std::size_t i = 0; i < good->segment_count(); ++i) segs.push_back(good->segment(i));
    CHECK(tiny3d::looped_path::from_segments(segs).ok());
    auto kinked = segs;
    kinked.back().p2.x += 0.5f;  // tangent jump at the closing joint
    const auto k = tiny3d::looped_path::from_segments(kinked);
    CHECK(!k.ok() && k.message().find("tangent") != std::string::npos);
    auto gap = segs;
    gap[1].p0.y += 0.1f;
    const auto g = tiny3d::looped_path::from_segments(gap);
    CHECK(!g.ok() && g.message().find("joint 0 -> 1") != std::string::npos);
    // Too few / coincident points.
    CHECK(!tiny3d::looped_path::through_points(std::vector<vec3_t>{{0, 0, 0}, {1, 0, 0}}).ok());
    CHECK(!tiny3d::looped_path::through_points(std::vector<vec3_t>{{0, 0, 0}, {1, 0, 0}, {0, 0, 0}}).ok());
}

TEST(looped_path_constant_speed_by_fraction) {
    const auto path = tiny3d::looped_path::through_points(loop_points());
    // Equal fraction steps cover equal distances (chords of short steps ≈ arcs).
    const int steps = 4000;
    const double expected = path->length() / steps;
    double worst = 0;
    for (int i = 0; i < steps; ++i) {
        const double d = length(path->point_at_fraction(double(i + 1) / steps) - path->point_at_fraction(double(i) / steps));
        worst = std::max(worst, std::fabs(d / expected - 1.0));
    }
    CHECK_NEAR(worst, 0.0, 0.01);
}

TEST(loop_phase_and_clock) {
    CHECK_EQ(tiny3d::loop_phase(0.0, 4.0), 0.0);
    CHECK_EQ(tiny3d::loop_phase(4.0, 4.0), 0.0);
    CHECK_EQ(tiny3d::loop_phase(-1.0, 4.0), 0.75);
    CHECK_NEAR(tiny3d::loop_phase(5.0, 4.0), 0.25, 1e-15);
    CHECK_EQ(tiny3d::loop_phase(1.0, 0.0), 0.0);
    CHECK_EQ(tiny3d::loop_phase(std::nan(""), 1.0), 0.0);
    // The period of N frames at any fps is one loop: frame N has phase 0 exactly.
    for (double fps : {24.0, 25.0, 29.97, 30.0, 7.0, 60.0}) {
        const double period = tiny3d::anim_clock::at_frame(120, fps).seconds;
        CHECK_EQ(tiny3d::loop_phase(tiny3d::anim_clock::at_frame(120, fps).seconds, period), 0.0);
    }
    // Same time at different frame rates: same phase.
    CHECK_EQ(tiny3d::anim_clock::at_frame(30, 30).seconds, tiny3d::anim_clock::at_frame(60, 60).seconds);
}

// ---- frame clock: fed timestamps, no real timing -------------------------------------------

TEST(frame_clock_ticks_give_intervals_rolling_fps_and_summary) {
    // Intervals exact in binary, so every expected value is exact.
    tiny3d::frame_clock clock;
    CHECK_EQ(clock.rolling_fps(), 0.0);  // nothing yet
    CHECK(clock.tick(10.0).ok());        // the first tick only starts the clock
    CHECK_EQ(clock.frame_count(), std::size_t(0));
    for (double t : {10.03125, 10.0625, 10.125, 10.25}) CHECK(clock.tick(t).ok());
    CHECK_EQ(clock.frame_count(), std::size_t(4));
    CHECK(clock.frame_seconds() == (std::vector<double>{0.03125, 0.03125, 0.0625, 0.125}));
    CHECK_EQ(clock.last_frame_seconds(), 0.125);
    CHECK_EQ(clock.rolling_mean_seconds(), 0.0625);  // 4 frames in 0.25 s
    CHECK_EQ(clock.rolling_fps(), 16.0);
    const tiny3d::frame_summary s = clock.summary();
    CHECK_EQ(s.frames, std::size_t(4));
    CHECK_EQ(s.min_s, 0.03125);
    CHECK_EQ(s.max_s, 0.125);
    CHECK_EQ(s.median_s, 0.046875);  // even count: mean of 0.03125 and 0.0625
    CHECK_EQ(s.total_s, 0.25);
    CHECK_EQ(s.mean_s, 0.0625);
    // A window of 2 sees the last two frames only: 2 / (0.0625 + 0.125).
    tiny3d::frame_clock narrow(2);
    for (double t : {10.0, 10.03125, 10.0625, 10.125, 10.25}) CHECK(narrow.tick(t).ok());
    CHECK_NEAR(narrow.rolling_fps(), 2.0 / 0.1875, 1e-12);
    CHECK_EQ(narrow.summary().median_s, 0.046875);  // the summary still covers every frame
    // Odd count: the middle one.
    CHECK(narrow.add_frame(1.0).ok());
    CHECK_EQ(narrow.summary().median_s, 0.0625);
    CHECK_EQ(narrow.summary().max_s, 1.0);
}

TEST(frame_clock_rolling_fps_follows_a_change_of_rate) {
    // 100 frames at 30 fps, then 100 at 60 fps; timestamps from frame numbers (no drift).
    tiny3d::frame_clock clock;  // window 60
    clock.reserve(200);
    const double *storage = clock.frame_seconds().data();
    CHECK(clock.tick(0.0).ok());
    for (int k = 1; k <= 100; ++k) CHECK(clock.tick(k / 30.0).ok());
    CHECK_NEAR(clock.rolling_fps(), 30.0, 1e-9);
    for (int k = 1; k <= 30; ++k) CHECK(clock.tick(100 / 30.0 + k / 60.0).ok());
    // The window holds 30 frames of 1/30 s and 30 of 1/60 s: mean 0.025 s, 40 fps.
    CHECK_NEAR(clock.rolling_mean_seconds(), 0.025, 1e-12);
    CHECK_NEAR(clock.rolling_fps(), 40.0, 1e-9);
    for (int k = 31; k <= 100; ++k) CHECK(clock.tick(100 / 30.0 + k / 60.0).ok());
    CHECK_NEAR(clock.rolling_fps(), 60.0, 1e-9);
    const tiny3d::frame_summary s = clock.summary();
    CHECK_EQ(s.frames, std::size_t(200));
    CHECK_NEAR(s.min_s, 1 / 60.0, 1e-12);
    CHECK_NEAR(s.max_s, 1 / 30.0, 1e-12);
    CHECK_NEAR(s.median_s, 0.5 * (1 / 60.0 + 1 / 30.0), 1e-12);  // 100 of each
    CHECK_NEAR(s.total_s, 100 / 30.0 + 100 / 60.0, 1e-12);
    CHECK_EQ(clock.frame_seconds().data(), storage);  // reserved: recording did not reallocate
    CHECK_NEAR(tiny3d::frame_clock::fps(s.median_s), 40.0, 1e-9);
}

TEST(frame_clock_refuses_bad_times_and_resets) {
    tiny3d::frame_clock clock;
    CHECK(!clock.tick(std::nan("")).ok());
    CHECK(clock.tick(5.0).ok());
    const tiny3d::status back = clock.tick(4.5);  // time going backwards
    CHECK(!back.ok() && back.message().find("before the previous") != std::string::npos);
    CHECK(!clock.tick(INFINITY).ok());
    CHECK_EQ(clock.frame_count(), std::size_t(0));  // nothing recorded by the refusals
    CHECK(clock.tick(5.0).ok());                    // an equal timestamp: a frame of 0 s
    CHECK_EQ(clock.frame_count(), std::size_t(1));
    CHECK_EQ(clock.rolling_fps(), 0.0);  // all frames took 0 s: no rate
    CHECK(!clock.add_frame(-0.001).ok());
    CHECK(!clock.add_frame(INFINITY).ok());
    CHECK(clock.add_frame(0.5).ok());
    CHECK_EQ(clock.rolling_fps(), 4.0);  // 2 frames in 0.5 s
    clock.reset();
    CHECK_EQ(clock.frame_count(), std::size_t(0));
    CHECK_EQ(clock.summary().frames, std::size_t(0));
    CHECK_EQ(clock.summary().max_s, 0.0);
    CHECK(clock.tick(1.0).ok());  // after reset the first tick starts the clock again
    CHECK_EQ(clock.frame_count(), std::size_t(0));
    CHECK_EQ(tiny3d::frame_clock(0).window(), std::size_t(1));
    CHECK_EQ(tiny3d::frame_clock::fps(0.0), 0.0);
}

TEST(orientation_slerp_takes_the_short_way_and_stays_unit) {
    // Keys: identity and a 160° turn about z given as its NEGATED quaternion (the same
    // rotation). The short way turns +80° at the midpoint, not −100°.
    const tiny3d::quat turn = tiny3d::quat_from_axis_angle({0, 0, 1}, float(160 * M_PI / 180));
    const auto loop = tiny3d::orientation_loop::from_keys({tiny3d::quat_identity(), {-turn.x, -turn.y, -turn.z, -turn.w}});
    CHECK(loop.ok());
    const vec3_t mid = tiny3d::quat_rotate(loop->at_phase(0.25), {1, 0, 0});  // halfway key 0 → key 1
    CHECK_NEAR(std::atan2(mid.y, mid.x), 80 * M_PI / 180, 1e-5);
    for (int i = 0; i < 200; ++i) {
        const tiny3d::quat q = loop->at_phase(i / 200.0);
        CHECK_NEAR(std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w), 1.0, 1e-6);
    }
}

TEST(spin_turns_uniformly_and_closes) {
    const auto spin = tiny3d::orientation_loop::spin({0, 0, 2}, 1);
    CHECK(spin.ok());
    for (int i = 0; i < 48; ++i) {
        const double phase = i / 48.0;
        const vec3_t v = tiny3d::quat_rotate(spin->at_phase(phase), {1, 0, 0});
        CHECK_NEAR(v.x, std::cos(2 * M_PI * phase), 2e-6);
        CHECK_NEAR(v.y, std::sin(2 * M_PI * phase), 2e-6);
    }
    const auto back = tiny3d::orientation_loop::spin({0, 0, 1}, -2);  // two turns clockwise
    const vec3_t v = tiny3d::quat_rotate(back->at_phase(0.125), {1, 0, 0});  // −90°
    CHECK_NEAR(v.y, -1.0, 2e-6);
    const tiny3d::quat a = spin->at_phase(0.0), b = spin->at_phase(1.0);
    CHECK(a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w);
}

TEST(objects_on_one_clock_stay_in_sync_at_any_frame_rate) {
    tiny3d::motion m;
    m.path = tiny3d::looped_path::through_points(loop_points()).value();
    m.path_period_s = 4.0;
    m.path_offset = 0.3;
    m.orientation = tiny3d::orientation_loop::spin({0, 1, 0}, 1).value();
    m.orientation_period_s = 2.0;
    m.scale = 0.5f;
    // Frame 45 at 30 fps and frame 90 at 60 fps are the same instant: same matrix.
    const mat4_t a = tiny3d::motion_model_at(m, tiny3d::anim_clock::at_frame(45, 30).seconds);
    const mat4_t b = tiny3d::motion_model_at(m, tiny3d::anim_clock::at_frame(90, 60).seconds);
    const mat4_t c = tiny3d::motion_model_at(m, 0.0), d = tiny3d::motion_model_at(m, 4.0);  // one period
    for (int i = 0; i < 16; ++i) {
        CHECK_EQ(a.m[i], b.m[i]);
        CHECK_EQ(c.m[i], d.m[i]);
    }
    // Translation = the path point at the offset fraction; scale 0.5 on the rotation part.
    const vec3_t p = m.path.point_at_fraction(0.3);
    CHECK_EQ(c.m[12], p.x);
    CHECK_NEAR(std::sqrt(c.m[0] * c.m[0] + c.m[1] * c.m[1] + c.m[2] * c.m[2]), 0.5, 1e-6);
}
