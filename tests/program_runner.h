// tests/program_runner.h — running the built programs (demos, render) from a test: their
// paths, temporary folders, a run with stdout and stderr captured, the files a run wrote,
// and reading PGM frames back.
//
// Programs come from $BUILD/demo (BUILD is set by `make test`, which builds the demos
// first; default "build"). Tests run from the checkout's top folder (tests/data/...).
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace program_runner {

namespace fs = std::filesystem;

inline std::string build_dir() {
    const char *build = std::getenv("BUILD");
    return build && *build ? build : "build";
}

inline std::string demo_path(const std::string &name) { return build_dir() + "/demo/" + name; }

// A fresh temporary folder, removed with everything in it when the object goes.
struct temp_dir {
    fs::path path;
    temp_dir() {
        std::string tmpl = (fs::temp_directory_path() / "tiny3d_test_XXXXXX").string();
        if (::mkdtemp(tmpl.data())) path = tmpl;
    }
    ~temp_dir() {
        std::error_code ec;
        if (!path.empty()) fs::remove_all(path, ec);
    }
    temp_dir(const temp_dir &) = delete;
    temp_dir &operator=(const temp_dir &) = delete;
};

// The text in single quotes for /bin/sh.
inline std::string shell_quoted(const std::string &s) {
    std::string q = "'";
    for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

inline std::string file_bytes(const fs::path &path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct run_result {
    int exit_code = -1;  // -1: did not exit normally
    std::string out;     // stdout
    std::string err;     // stderr
};

// Runs a shell command line with stdout and stderr captured into files under `logs`.
inline run_result run_shell(const std::string &command, const fs::path &logs) {
    const fs::path out_file = logs / "stdout", err_file = logs / "stderr";
    const std::string cmd =
        command + " >" + shell_quoted(out_file.string()) + " 2>" + shell_quoted(err_file.string()) + " </dev/null";
    run_result r;
    const int status = std::system(cmd.c_str());
    r.exit_code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = file_bytes(out_file);
    r.err = file_bytes(err_file);
    return r;
}

// Runs `program args…` (each argument quoted).
inline run_result run(const std::string &program, const std::vector<std::string> &args, const fs::path &logs) {
    std::string cmd = shell_quoted(program);
    for (const std::string &a : args) cmd += " " + shell_quoted(a);
    return run_shell(cmd, logs);
}

// File name → bytes, for every regular file in `dir` (empty if dir does not exist).
inline std::map<std::string, std::string> files_in(const fs::path &dir) {
    std::map<std::string, std::string> files;
    std::error_code ec;
    for (const auto &e : fs::directory_iterator(dir, ec)) {
        if (!e.is_regular_file()) continue;
        files[e.path().filename().string()] = file_bytes(e.path());
    }
    return files;
}

// A binary P5 PGM as written by the library (header "P5\nW H\n255\n"): width, height and
// the bytes; width = 0 when the text is not such a file.
struct pgm_image {
    int width = 0, height = 0;
    std::vector<unsigned char> pixels;
    unsigned char at(int x, int y) const { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

inline pgm_image parse_pgm(const std::string &bytes) {
    pgm_image img;
    int w = 0, h = 0, maxval = 0, used = 0;
    if (std::sscanf(bytes.c_str(), "P5 %d %d %d%n", &w, &h, &maxval, &used) != 3 || maxval != 255 || w <= 0 || h <= 0)
        return img;
    const std::size_t start = std::size_t(used) + 1, count = std::size_t(w) * std::size_t(h);
    if (bytes.size() != start + count) return img;
    img.width = w;
    img.height = h;
    img.pixels.assign(bytes.begin() + long(start), bytes.end());
    return img;
}

}  // namespace program_runner
