// install_test.cpp — a library user's first steps, as README.md tells them: the README's
// programs (prog.cpp in C++, main.c in C, built by gcc as a C program), each built with the
// README's command against this tree, and built outside the tree
// from a staged `make install DESTDIR=… PREFIX=…` with the README's pkg-config command
// (pkg-config pointed at the staged tiny3d.pc, PKG_CONFIG_SYSROOT_DIR = the staging root).
// On a machine without pkg-config the staged tiny3d.pc is read by hand instead: its
// variables expanded, its Cflags and Libs used for the same build. Each built program must
// run and write its image; make uninstall then removes what make install copied.
// TINY3D_TEST_WITHOUT_PKG_CONFIG=1 in the environment tests that path on a machine that
// has pkg-config.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "harness.h"
#include "program_runner.h"
#include "renderer.h"

using namespace program_runner;

namespace {

constexpr const char *prefix = "/opt/tiny3d";

// The text between `start` (included) and the next "\n```" after it, or "".
std::string block_from(const std::string &text, const std::string &start) {
    const std::size_t at = text.find(start);
    if (at == std::string::npos) return "";
    const std::size_t end = text.find("\n```", at);
    return end == std::string::npos ? "" : text.substr(at, end - at + 1);
}

// The whole line of `text` that starts with `start`, or "".
std::string line_from(const std::string &text, const std::string &start) {
    const std::size_t at = text.find("\n" + start);
    if (at == std::string::npos) return "";
    return text.substr(at + 1, text.find('\n', at + 1) - at - 1);
}

std::string replaced(std::string s, const std::string &from, const std::string &to) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
    return s;
}

// Runs the built program in a fresh folder; it must print "wrote knot.pgm" and write a
// 320 × 240 image with a dark corner and a lit knot.
void check_program_runs(const fs::path &program, const fs::path &folder) {
    fs::create_directories(folder);
    const run_result r = run_shell("cd " + shell_quoted(folder.string()) + " && " + shell_quoted(program.string()), folder);
    CHECK_MSG(r.exit_code == 0, program.string() + ": exit " + std::to_string(r.exit_code) + ": " + r.err);
    CHECK_EQ(r.out, std::string("wrote knot.pgm\n"));
    const pgm_image img = parse_pgm(file_bytes(folder / "knot.pgm"));
    CHECK_EQ(img.width, 320);
    CHECK_EQ(img.height, 240);
    if (img.width != 320 || img.height != 240) return;
    int lit = 0;
    for (const unsigned char v : img.pixels) lit += v > 40;
    CHECK_EQ(int(img.at(0, 0)), 0);
    CHECK_MSG(lit > 320 * 240 / 10, std::to_string(lit) + " lit pixels");
}

// Runs the built C program (README's main.c) in a fresh folder; it must print "wrote
// soccer.pgm" and write the report's soccer ball exactly as the same calls draw it here.
void check_c_program_runs(const fs::path &program, const fs::path &folder) {
    fs::create_directories(folder);
    const run_result r = run_shell("cd " + shell_quoted(folder.string()) + " && " + shell_quoted(program.string()), folder);
    CHECK_MSG(r.exit_code == 0, program.string() + ": exit " + std::to_string(r.exit_code) + ": " + r.err);
    CHECK_EQ(r.out, std::string("wrote soccer.pgm\n"));
    const pgm_image img = parse_pgm(file_bytes(folder / "soccer.pgm"));
    canvas_t *expected = create_canvas(320, 240);
    vec3_t *vertices = nullptr;
    int(*edges)[2] = nullptr;
    int vertex_count = 0, edge_count = 0;
    CHECK_EQ(generate_soccer_ball(&vertices, &vertex_count, &edges, &edge_count), 1);
    CHECK(expected != nullptr);
    if (!expected || !vertices || img.width != 320 || img.height != 240) {
        CHECK_MSG(false, "soccer.pgm missing or not 320 x 240");
        free_soccer_ball(vertices, edges);
        destroy_canvas(expected);
        return;
    }
    render_wireframe(expected, vertices, vertex_count, edges, edge_count,
                     mat4_multiply(mat4_translate(0, 0, -3), mat4_rotate_xyz(0.3f, 0.5f, 0)),
                     mat4_frustum_asymmetric(-0.5f, 0.5f, -0.375f, 0.375f, 1, 10));
    int differing = 0, lit = 0;
    for (int y = 0; y < 240; ++y)
        for (int x = 0; x < 320; ++x) {
            const float v = std::fmin(std::fmax(expected->pixels[y][x], 0.0f), 1.0f);
            differing += int(img.at(x, y)) != int(std::lround(v * 255.0f));
            lit += img.at(x, y) > 40;
        }
    CHECK_EQ(differing, 0);
    CHECK_MSG(lit > 2000, std::to_string(lit) + " lit pixels");
    free_soccer_ball(vertices, edges);
    destroy_canvas(expected);
}

// tiny3d.pc's fields with its ${variables} expanded (name → value; fields end in ':').
std::vector<std::pair<std::string, std::string>> read_pc(const std::string &text) {
    std::vector<std::pair<std::string, std::string>> entries;
    auto expand = [&entries](std::string v) {
        for (const auto &[name, value] : entries)
            if (name.back() != ':') v = replaced(v, "${" + name + "}", value);
        return v;
    };
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        const std::string line = text.substr(at, end - at);
        at = end + 1;
        const std::size_t colon = line.find(':'), equals = line.find('=');
        if (equals != std::string::npos && (colon == std::string::npos || equals < colon))
            entries.emplace_back(line.substr(0, equals), expand(line.substr(equals + 1)));
        else if (colon != std::string::npos)
            entries.emplace_back(line.substr(0, colon + 1), expand(line.substr(colon + 1 + (line[colon + 1] == ' '))));
    }
    return entries;
}

std::string pc_value(const std::vector<std::pair<std::string, std::string>> &pc, const std::string &name) {
    for (const auto &[key, value] : pc)
        if (key == name) return value;
    return "";
}

// Flags with the staging root put before every -I and -L path (what PKG_CONFIG_SYSROOT_DIR does).
std::string with_sysroot(const std::string &flags, const std::string &root) {
    return replaced(replaced(" " + flags, " -I/", " -I" + root + "/"), " -L/", " -L" + root + "/");
}

std::string squeezed(const std::string &s) {
    std::string out;
    for (const char c : s)
        if (!(c == ' ' || c == '\n') || (!out.empty() && out.back() != ' ')) out += (c == '\n' ? ' ' : c);
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

}  // namespace

TEST(readme_program_builds_against_the_tree_and_from_a_staged_install) {
    const std::string readme = file_bytes("README.md");
    const std::string program = block_from(readme, "// prog.cpp");
    const std::string tree_command = line_from(readme, "g++ -std=c++20 -Iinclude prog.cpp");
    const std::string pc_command = line_from(readme, "g++ -std=c++20 prog.cpp $(pkg-config --cflags --libs tiny3d)");
    const std::string c_program = block_from(readme, "/* main.c");
    const std::string c_tree_command = line_from(readme, "gcc -Iinclude main.c build/libtiny3d.a");
    const std::string c_pc_command = line_from(readme, "gcc main.c $(pkg-config --cflags --libs tiny3d)");
    CHECK_MSG(!program.empty(), "README.md has no ```cpp block starting '// prog.cpp'");
    CHECK_MSG(!c_program.empty(), "README.md has no ```c block starting '/* main.c'");
    CHECK_MSG(!tree_command.empty() && !pc_command.empty() && !c_tree_command.empty() && !c_pc_command.empty(),
              "README.md lacks one of the four build commands");
    if (program.empty() || tree_command.empty() || pc_command.empty() || c_program.empty() || c_tree_command.empty() ||
        c_pc_command.empty())
        return;
    temp_dir dir;
    for (const auto &[name, text] : {std::pair{"prog.cpp", &program}, std::pair{"main.c", &c_program}}) {
        std::FILE *f = std::fopen((dir.path / name).string().c_str(), "wb");
        CHECK(f != nullptr);
        if (!f) return;
        std::fwrite(text->data(), 1, text->size(), f);
        std::fclose(f);
    }

    // 1. Against the tree, from the checkout's top folder, the README's command as written
    //    (only the file names moved into the temporary folder, and $BUILD for build/).
    std::string command = replaced(tree_command, " prog.cpp", " " + shell_quoted((dir.path / "prog.cpp").string()));
    command = replaced(command, " build/", " " + build_dir() + "/");
    command = replaced(command, "-o prog", "-o " + shell_quoted((dir.path / "prog_tree").string()));
    run_result r = run_shell(command, dir.path);
    CHECK_MSG(r.exit_code == 0, command + "\n" + r.err);
    if (r.exit_code == 0) check_program_runs(dir.path / "prog_tree", dir.path / "run_tree");
    command = replaced(c_tree_command, " main.c", " " + shell_quoted((dir.path / "main.c").string()));
    command = replaced(command, " build/", " " + build_dir() + "/");
    command = replaced(command, "-o main", "-o " + shell_quoted((dir.path / "main_tree").string()));
    r = run_shell(command, dir.path);
    CHECK_MSG(r.exit_code == 0, command + "\n" + r.err);
    if (r.exit_code == 0) check_c_program_runs(dir.path / "main_tree", dir.path / "run_c_tree");

    // 2. make install into a staging root.
    const fs::path stage = dir.path / "stage";
    const std::string make = "env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory -s BUILD=" +
                             shell_quoted(build_dir()) + " PREFIX=" + prefix + " DESTDIR=" + shell_quoted(stage.string());
    r = run_shell(make + " install", dir.path);
    CHECK_MSG(r.exit_code == 0, "make install failed: " + r.err);
    const fs::path root = stage / "opt/tiny3d";
    for (const char *file : {"include/tiny3d/tiny3d.h", "lib/libtiny3d.a", "lib/pkgconfig/tiny3d.pc"})
        CHECK_MSG(fs::is_regular_file(root / file), std::string(file) + " not installed");
    // Every header of the tree (the module headers, renderer.h, the compat headers), in place.
    std::size_t headers = 0;
    for (const auto &entry : fs::recursive_directory_iterator("include")) {
        if (!entry.is_regular_file() || entry.path().extension() != ".h") continue;
        ++headers;
        const fs::path installed = root / "include/tiny3d" / fs::relative(entry.path(), "include");
        CHECK_MSG(fs::is_regular_file(installed), installed.string() + " not installed");
    }
    CHECK(headers >= 20);

    // 3. tiny3d.pc as written: the final paths (PREFIX, not DESTDIR), the flags a build needs.
    const auto pc = read_pc(file_bytes(root / "lib/pkgconfig/tiny3d.pc"));
    CHECK_EQ(pc_value(pc, "prefix"), std::string(prefix));
    CHECK_EQ(pc_value(pc, "Name:"), std::string("tiny3d"));
    CHECK(!pc_value(pc, "Version:").empty());
    const std::string cflags = pc_value(pc, "Cflags:"), libs = pc_value(pc, "Libs:");
    // No -std= (the flags serve C and C++); the C++ runtime, libm and threads for C programs.
    CHECK_EQ(cflags, std::string("-I") + prefix + "/include/tiny3d");
    CHECK_EQ(libs, std::string("-L") + prefix + "/lib -ltiny3d -lstdc++ -lm -pthread");

    // 4. Outside the tree (run in the temporary folder), from the staged files only.
    const std::string staged_flags = with_sysroot(cflags + " " + libs, stage.string());
    // TINY3D_TEST_WITHOUT_PKG_CONFIG=1 takes the path of a machine without pkg-config.
    const char *without = std::getenv("TINY3D_TEST_WITHOUT_PKG_CONFIG");
    const bool have_pkg_config =
        !(without && *without == '1') && run_shell("command -v pkg-config", dir.path).exit_code == 0;
    // Exported: the README's command runs pkg-config in a $(...) of its own.
    const std::string env = "export PKG_CONFIG_LIBDIR=" + shell_quoted((root / "lib/pkgconfig").string()) +
                            " PKG_CONFIG_SYSROOT_DIR=" + shell_quoted(stage.string()) + "; ";
    std::string build = "cd " + shell_quoted(dir.path.string()) + " && ";
    std::string c_build = build;
    if (have_pkg_config) {
        r = run_shell(env + "pkg-config --cflags --libs tiny3d", dir.path);
        CHECK_EQ(r.exit_code, 0);
        CHECK_EQ(squeezed(r.out), squeezed(staged_flags));
        build += env + replaced(pc_command, "-o prog", "-o prog_installed");
        c_build += env + replaced(c_pc_command, "-o main", "-o main_installed");
    } else {
        std::fprintf(stderr, "note: no pkg-config here: building with the flags read from tiny3d.pc\n");
        build += "g++ -std=c++20 prog.cpp" + staged_flags + " -o prog_installed";
        c_build += "gcc main.c" + staged_flags + " -o main_installed";
    }
    r = run_shell(build, dir.path);
    CHECK_MSG(r.exit_code == 0, build + "\n" + r.err);
    if (r.exit_code == 0) check_program_runs(dir.path / "prog_installed", dir.path / "run_installed");
    // The C program, built by gcc from the installed headers and tiny3d.pc's flags alone.
    r = run_shell(c_build, dir.path);
    CHECK_MSG(r.exit_code == 0, c_build + "\n" + r.err);
    if (r.exit_code == 0) check_c_program_runs(dir.path / "main_installed", dir.path / "run_c_installed");

    // 5. make uninstall removes every installed file.
    r = run_shell(make + " uninstall", dir.path);
    CHECK_MSG(r.exit_code == 0, "make uninstall failed: " + r.err);
    for (const char *file : {"include/tiny3d", "lib/libtiny3d.a", "lib/pkgconfig/tiny3d.pc"})
        CHECK_MSG(!fs::exists(root / file), std::string(file) + " left after make uninstall");
}
