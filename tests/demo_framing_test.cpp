// demo_framing_test.cpp — what the demos frame: the soccer ball crosses its circular
// viewport in part of the loop and the circle cuts it (no ink outside the circle in any
// frame, some frames reach the circle); the shaded and lighting demos keep every object
// clear of the frame's edges by at least 5 % of the width in every frame (judged from the
// ink itself: no pixel other than the background that near an edge).
//
// Runs the demo programs from $BUILD/demo (BUILD is set by `make test`, which builds the
// demos first; default "build").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "harness.h"
#include "program_runner.h"

using namespace program_runner;

TEST(soccer_ball_is_cut_by_the_circle_in_part_of_the_loop) {
    const std::string program = demo_path("soccer");
    CHECK_MSG(fs::exists(program), program + " is not built (make test builds the demos first)");
    if (!fs::exists(program)) return;
    temp_dir dir;
    constexpr int side = 200;
    const run_result r = run(program, {"--out", (dir.path / "out").string(), "--size", "200x200"}, dir.path);
    CHECK_MSG(r.exit_code == 0, r.err);
    // The circle: centre (100, 100), radius 100; a pixel whose centre lies 0.75 px beyond it
    // is wholly outside. The rim is a 1-px ring just inside it (its ink reaches no deeper
    // than radius − 3.5). Ink between radius − 5.5 and radius − 3.5 is the ball's, drawn up
    // to the circle where the circle cuts it: in the middle of the loop, not at its ends.
    const double c = side / 2.0, radius = side / 2.0;
    int frames = 0, reaching = 0, outside = 0;
    bool first_clear = false;
    for (int f = 0; f < 60; ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%03d.pgm", f);
        const pgm_image img = parse_pgm(file_bytes(dir.path / "out" / name));
        if (img.width != side) continue;
        ++frames;
        int near_rim = 0;
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                const double d = std::hypot(x + 0.5 - c, y + 0.5 - c);
                if (img.at(x, y) == 0) continue;
                outside += d > radius + 0.75;
                near_rim += d > radius - 5.5 && d < radius - 3.5;
            }
        if (f == 0) first_clear = near_rim == 0;
        reaching += near_rim >= 20;
    }
    CHECK_EQ(frames, 60);
    CHECK_EQ(outside, 0);
    CHECK(first_clear);  // at frame 0 the ball is well inside (90 % of the radius)
    CHECK_MSG(reaching >= 15 && reaching <= 45, std::to_string(reaching) + " frames reach the circle");
}

namespace {

// The fewest pixels between any ink (a pixel other than the background, read at the corner)
// and the frame's edges, over every frame `program` writes at 192 × 144.
int closest_ink_to_an_edge(const std::string &demo, int &frames) {
    const std::string program = demo_path(demo);
    CHECK_MSG(fs::exists(program), program + " is not built (make test builds the demos first)");
    frames = 0;
    if (!fs::exists(program)) return -1;
    temp_dir dir;
    const run_result r = run(program, {"--out", (dir.path / "out").string(), "--size", "192x144"}, dir.path);
    CHECK_MSG(r.exit_code == 0, r.err);
    int closest = 1 << 30;
    for (const auto &[name, bytes] : files_in(dir.path / "out")) {
        const pgm_image img = parse_pgm(bytes);
        if (img.width != 192) continue;
        ++frames;
        const unsigned char background = img.at(0, 0);
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x)
                if (img.at(x, y) != background)
                    closest = std::min({closest, x, y, img.width - 1 - x, img.height - 1 - y});
    }
    return closest;
}

}  // namespace

TEST(shaded_and_lighting_demos_keep_their_objects_off_the_frame_edges) {
    for (const char *demo : {"shaded", "lighting"}) {
        int frames = 0;
        const int closest = closest_ink_to_an_edge(demo, frames);
        CHECK_MSG(frames >= 36, std::string(demo) + ": " + std::to_string(frames) + " frames");
        // 5 % of 192 px = 9.6: at least 10 px clear on every side.
        CHECK_MSG(closest >= 10, std::string(demo) + ": ink " + std::to_string(closest) + " px from an edge");
    }
}
