// cli_test.cpp — the one command-line contract (demo/common/demo_cli.h) as every program
// keeps it: --help on stdout with exit 0; a bad option or a malformed number ("3x", "",
// "nan", "1e999", out of range) exits 2 with a message naming the option and the value and
// writes nothing; output to a pipe is plain "wrote" lines (no carriage returns) and a time
// summary on stderr.
#include <string>
#include <vector>

#include "harness.h"
#include "program_runner.h"

using namespace program_runner;

namespace {

const std::vector<std::string> programs = {"clock", "cube", "lighting", "ply_render", "render", "shaded", "soccer",
                                           "wireframe"};

bool built(const std::string &program) {
    const bool ok = fs::exists(demo_path(program));
    CHECK_MSG(ok, demo_path(program) + " is not built (make test builds the demos first)");
    return ok;
}

// Runs `program args… --out DIR/out` (or, for ply_render, OUT = DIR/out.pgm) and checks
// exit status 2, a message naming `option` and `value`, and that nothing was written.
void check_refused(const std::string &program, std::vector<std::string> args, const std::string &option,
                   const std::string &value) {
    if (!built(program)) return;
    temp_dir dir;
    const fs::path out = dir.path / "out";
    if (program == "ply_render") args.push_back((dir.path / "out.pgm").string());
    else args.insert(args.end(), {"--out", out.string()});
    const run_result r = run(demo_path(program), args, dir.path);
    std::string line = program;
    for (const std::string &a : args) line += " " + a;
    CHECK_MSG(r.exit_code == 2, line + ": exit status " + std::to_string(r.exit_code) + ", stderr: " + r.err);
    CHECK_MSG(r.err.find(option) != std::string::npos, line + ": message does not name " + option + ": " + r.err);
    CHECK_MSG(r.err.find("'" + value + "'") != std::string::npos,
              line + ": message does not quote '" + value + "': " + r.err);
    CHECK_MSG(r.out.empty(), line + ": wrote on stdout: " + r.out);
    CHECK_MSG(!fs::exists(out) && !fs::exists(dir.path / "out.pgm"), line + ": wrote files");
}

}  // namespace

TEST(every_program_answers_help_on_stdout_with_exit_0) {
    for (const std::string &p : programs) {
        if (!built(p)) continue;
        for (const char *flag : {"--help", "-h"}) {
            temp_dir logs;
            // --help wins over anything else on the line, even a bad option.
            const run_result r = run(demo_path(p), {"--bogus", flag}, logs.path);
            CHECK_MSG(r.exit_code == 0, p + " " + flag + ": exit status " + std::to_string(r.exit_code));
            CHECK_MSG(r.out.rfind("usage: " + p, 0) == 0, p + " " + flag + ": stdout starts: " + r.out.substr(0, 60));
            CHECK_MSG(r.out.find("--help") != std::string::npos, p + ": help does not list --help");
            CHECK_MSG(r.err.empty(), p + " " + flag + ": stderr: " + r.err);
        }
    }
}

TEST(frame_programs_take_the_common_options) {
    // Every program that writes frames lists --out, --size and --png; sequences --frames.
    for (const std::string &p : programs) {
        if (p == "ply_render" || !built(p)) continue;
        temp_dir logs;
        const run_result r = run(demo_path(p), {"--help"}, logs.path);
        for (const char *option : {"--out DIR", "--size WxH", "--png"})
            CHECK_MSG(r.out.find(option) != std::string::npos, p + " --help does not list " + option);
        if (p != "clock") CHECK_MSG(r.out.find("--frames A:B") != std::string::npos, p + ": no --frames");
    }
}

TEST(malformed_numbers_exit_2_naming_option_and_value_and_write_nothing) {
    for (const std::string bad : {"3x", "", "nan", "1e999", "-2", "0", "17", " 3", "0x10"})
        check_refused("shaded", {"--threads", bad}, "--threads", bad);
    for (const std::string bad : {"3x", "", "nan", "inf", "1e999", "0", "-30", "1e-400"})
        check_refused("lighting", {"--fps", bad}, "--fps", bad);
    for (const std::string bad : {"3x", "", "x", "64", "64x", "x64", "0x64", "64x-1", "1e3x100", "64x64x2"})
        check_refused("cube", {"--size", bad}, "--size", bad);
    check_refused("cube", {"--size=nanxnan"}, "--size", "nanxnan");
    check_refused("wireframe", {"tests/data/cube_quads.obj", "--lines", "splat"}, "--lines", "splat");
    check_refused("soccer", {"--frames", "0:1e999"}, "--frames", "0:1e999");
    check_refused("clock", {"--bogus"}, "unknown option", "--bogus");
    check_refused("clock", {"extra"}, "unexpected argument", "extra");
    check_refused("cube", {"--png=yes"}, "--png", "--png=yes");
    check_refused("ply_render", {"tests/data/tetra_ascii.ply", "90", "nan", "0"}, "RY", "nan");
    check_refused("ply_render", {"tests/data/tetra_ascii.ply", "1e999", "0", "0"}, "RX", "1e999");
    check_refused("ply_render", {"tests/data/tetra_ascii.ply", "0", "0", "0", "--size", "64x32"}, "--size", "64x32");
    check_refused("ply_render", {"tests/data/tetra_ascii.ply", "0", "0", "0", "--method", "fastest"}, "--method",
                  "fastest");
}

TEST(a_missing_value_or_positional_exits_2) {
    if (!built("wireframe")) return;
    temp_dir dir;
    const fs::path out = dir.path / "out";
    run_result r = run(demo_path("wireframe"), {"--out", out.string()}, dir.path);
    CHECK_EQ(r.exit_code, 2);
    CHECK_MSG(r.err.find("missing FILE") != std::string::npos, r.err);
    r = run(demo_path("wireframe"), {"tests/data/cube_quads.obj", "--out", out.string(), "--size"}, dir.path);
    CHECK_EQ(r.exit_code, 2);
    CHECK_MSG(r.err.find("--size needs a value") != std::string::npos, r.err);
    CHECK(!fs::exists(out));
}

TEST(output_to_a_pipe_is_plain_lines_and_a_summary) {
    if (!built("cube")) return;
    temp_dir dir;
    const fs::path out = dir.path / "out";
    const run_result r =
        run(demo_path("cube"), {"--out", out.string(), "--size", "48x48", "--frames", "3:5", "--png"}, dir.path);
    CHECK_EQ(r.exit_code, 0);
    CHECK_MSG(r.out.find('\r') == std::string::npos && r.err.find('\r') == std::string::npos,
              "carriage return in a non-terminal run");
    std::string expected;
    for (const char *n : {"003", "004", "005"})
        for (const char *ext : {".pgm", ".png"}) expected += "wrote " + out.string() + "/frame_" + n + ext + "\n";
    CHECK_EQ(r.out, expected);
    CHECK_MSG(r.err.find("cube: 3 frames in ") == 0 && r.err.find("median") != std::string::npos, r.err);
    const auto files = files_in(out);
    CHECK_EQ(files.size(), std::size_t{6});
    // The PNG beside a PGM starts with the PNG signature.
    const auto png = files.find("frame_004.png");
    CHECK(png != files.end() && png->second.rfind("\x89PNG\r\n\x1a\n", 0) == 0);
    const pgm_image pgm = parse_pgm(files.count("frame_004.pgm") ? files.at("frame_004.pgm") : "");
    CHECK_EQ(pgm.width, 48);
    CHECK_EQ(pgm.height, 48);
}

TEST(options_take_both_spellings_and_the_last_value_wins) {
    if (!built("cube")) return;
    temp_dir dir;
    const fs::path out = dir.path / "out";
    const run_result r = run(demo_path("cube"),
                             {"--size=32x32", "--frames", "0:0", "--out", (dir.path / "other").string(),
                              "--out=" + out.string(), "--size", "40x24"},
                             dir.path);
    CHECK_EQ(r.exit_code, 0);
    CHECK(!fs::exists(dir.path / "other"));
    const pgm_image img = parse_pgm(file_bytes(out / "frame_000.pgm"));
    CHECK_EQ(img.width, 40);
    CHECK_EQ(img.height, 24);
}
