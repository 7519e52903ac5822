// frames_test.cpp — frame ranges for render farms: a sequence rendered in two halves
// (separate processes, separate folders, as two farm jobs would) gives byte-for-byte the
// frames of one full run, and malformed --frames values fail with a message.
//
// Runs the demo programs from $BUILD/demo (BUILD is set by `make test`, which builds the
// demos first; default "build").
#include <map>
#include <string>
#include <vector>

#include "harness.h"
#include "program_runner.h"

using namespace program_runner;

namespace {

// Small frames keep the test fast (the pixels of a range do not depend on the size).
constexpr const char *frame_size = "96x72";

// Full run vs two halves in other folders: same file names, same bytes.
void check_halves_equal_full_run(const std::string &demo, const std::vector<std::string> &extra_args) {
    const std::string program = demo_path(demo);
    CHECK_MSG(fs::exists(program), program + " is not built (make test builds the demos first)");
    if (!fs::exists(program)) return;
    temp_dir full, first, second, logs;
    CHECK(!full.path.empty() && !first.path.empty() && !second.path.empty() && !logs.path.empty());
    const auto args = [&](const fs::path &out, const std::vector<std::string> &more) {
        std::vector<std::string> a = extra_args;
        a.insert(a.end(), {"--out", out.string(), "--size", frame_size});
        a.insert(a.end(), more.begin(), more.end());
        return a;
    };
    const run_result whole = run(program, args(full.path, {}), logs.path);
    CHECK_MSG(whole.exit_code == 0, demo + " full run failed: " + whole.err);
    const auto reference = files_in(full.path);
    const int n = int(reference.size());
    CHECK_MSG(n >= 2, demo + ": expected a sequence of frames, got " + std::to_string(n));
    if (n < 2) return;
    const int half = n / 2;
    const std::string range_a = "0:" + std::to_string(half - 1), range_b = std::to_string(half) + ":" + std::to_string(n - 1);
    const run_result a = run(program, args(first.path, {"--frames", range_a}), logs.path);
    const run_result b = run(program, args(second.path, {"--frames", range_b}), logs.path);
    CHECK_MSG(a.exit_code == 0, demo + " --frames " + range_a + " failed: " + a.err);
    CHECK_MSG(b.exit_code == 0, demo + " --frames " + range_b + " failed: " + b.err);
    const auto part_a = files_in(first.path), part_b = files_in(second.path);
    CHECK_EQ(int(part_a.size()), half);
    CHECK_EQ(int(part_b.size()), n - half);
    std::map<std::string, std::string> joined = part_a;
    for (const auto &[name, bytes] : part_b) CHECK_MSG(joined.emplace(name, bytes).second, name + " rendered twice");
    CHECK_EQ(joined.size(), reference.size());
    for (const auto &[name, bytes] : reference) {
        const auto it = joined.find(name);
        CHECK_MSG(it != joined.end(), demo + ": " + name + " missing from the split runs");
        if (it != joined.end()) CHECK_MSG(it->second == bytes, demo + ": " + name + " differs between the runs");
    }
}

}  // namespace

TEST(cube_in_two_halves_equals_one_run) { check_halves_equal_full_run("cube", {}); }
TEST(soccer_in_two_halves_equals_one_run) { check_halves_equal_full_run("soccer", {}); }
TEST(soccer_report_lines_in_two_halves_equals_one_run) { check_halves_equal_full_run("soccer", {"--report"}); }
TEST(wireframe_in_two_halves_equals_one_run) { check_halves_equal_full_run("wireframe", {"tests/data/cube_quads.obj"}); }
TEST(wireframe_tabulated_in_two_halves_equals_one_run) {
    check_halves_equal_full_run("wireframe", {"tests/data/cube_quads.obj", "--lines", "tabulated"});
}
// Filled and shaded frames with two worker threads: the split must not change a pixel.
TEST(shaded_in_two_halves_equals_one_run) { check_halves_equal_full_run("shaded", {"--threads", "2"}); }

TEST(render_in_two_halves_equals_one_run) {
    check_halves_equal_full_run("render", {"tests/data/cube_quads.obj", "--turntable", "6"});
}

TEST(lighting_in_two_halves_equals_one_run) { check_halves_equal_full_run("lighting", {"--fps", "10"}); }

// The lighting demo places everything by time: frame k at f fps shows t = k / f, so
// frame 10 at 30 fps and frame 20 at 60 fps (t = 1/3 s) are the same bytes, frame 10 at
// 60 fps (t = 1/6 s) is not, and the loop's length in frames is period · fps.
TEST(lighting_frames_are_placed_by_time) {
    const std::string program = demo_path("lighting");
    CHECK_MSG(fs::exists(program), program + " is not built");
    if (!fs::exists(program)) return;
    temp_dir at30, at60, logs;
    const auto render = [&](const fs::path &out, const std::string &fps, const std::string &frames) {
        const run_result r =
            run(program, {"--out", out.string(), "--size", frame_size, "--fps", fps, "--frames", frames}, logs.path);
        CHECK_MSG(r.exit_code == 0, "lighting --fps " + fps + " --frames " + frames + " failed: " + r.err);
    };
    render(at30.path, "30", "10:10");
    render(at60.path, "60", "20:20");
    render(at60.path, "60", "10:10");
    const auto a = files_in(at30.path), b = files_in(at60.path);
    CHECK(a.count("frame_010.pgm") && b.count("frame_020.pgm") && b.count("frame_010.pgm"));
    if (!a.count("frame_010.pgm") || !b.count("frame_020.pgm") || !b.count("frame_010.pgm")) return;
    CHECK(parse_pgm(a.at("frame_010.pgm")).width == 96);
    CHECK_MSG(a.at("frame_010.pgm") == b.at("frame_020.pgm"), "frame 10 at 30 fps differs from frame 20 at 60 fps");
    CHECK_MSG(a.at("frame_010.pgm") != b.at("frame_010.pgm"), "frame 10 is the same at 30 and 60 fps");
    // A 4 s loop: 60 frames at 15 fps (0..59), 240 at 60 fps; a 2 s loop at 15 fps: 30.
    temp_dir out;
    CHECK_EQ(run(program, {"--out", out.path.string(), "--size", frame_size, "--fps", "15", "--frames", "59:59"}, logs.path)
                 .exit_code,
             0);
    CHECK_EQ(run(program, {"--out", out.path.string(), "--fps", "15", "--frames", "60:60"}, logs.path).exit_code, 2);
    CHECK_EQ(run(program, {"--out", out.path.string(), "--fps", "15", "--period", "2", "--frames", "30:30"}, logs.path)
                 .exit_code,
             2);
    CHECK_EQ(run(program, {"--out", out.path.string(), "--fps", "60", "--frames", "240:240"}, logs.path).exit_code, 2);
    CHECK_EQ(files_in(out.path).size(), std::size_t(1));  // only frame 59; the refused runs wrote nothing
}

TEST(bad_frame_ranges_fail_with_a_message) {
    const std::string program = demo_path("cube");
    CHECK_MSG(fs::exists(program), program + " is not built");
    if (!fs::exists(program)) return;
    temp_dir out, logs;
    for (const std::string bad : {"5:2", "0:100000", "-1:3", "abc", "3", "1:2:3", ""}) {
        const run_result r = run(program, {"--out", out.path.string(), "--size", frame_size, "--frames", bad},
                                 logs.path);
        CHECK_MSG(r.exit_code == 2, "--frames '" + bad + "': exit status " + std::to_string(r.exit_code) + ", not 2");
        CHECK_MSG(r.err.find("--frames") != std::string::npos, "--frames '" + bad + "': message was: " + r.err);
    }
    const run_result missing = run(program, {"--out", out.path.string(), "--frames"}, logs.path);
    CHECK(missing.exit_code != 0);
    CHECK(!missing.err.empty());
    // Nothing was written by the refused runs.
    CHECK(files_in(out.path).empty());
}

TEST(wireframe_bad_line_method_fails_with_a_message) {
    const std::string program = demo_path("wireframe");
    CHECK_MSG(fs::exists(program), program + " is not built");
    if (!fs::exists(program)) return;
    temp_dir out, logs;
    const run_result r = run(program, {"tests/data/cube_quads.obj", "--out", out.path.string(), "--lines", "splat"},
                             logs.path);
    CHECK(r.exit_code != 0);
    CHECK_MSG(r.err.find("--lines") != std::string::npos && r.err.find("splat") != std::string::npos,
              "message was: " + r.err);
    CHECK(files_in(out.path).empty());
}
