// compat_util.h — helpers shared by the tests of the user-style programs tests/compat/*:
// running one (its stdout as lines), reading the numbers it prints, reading the images it
// writes, and double-precision vectors for the references.
#ifndef TINY3D_COMPAT_UTIL_H
#define TINY3D_COMPAT_UTIL_H

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "harness.h"
#include "program_runner.h"
#include "tiny3d.h"

namespace compat_util {

namespace fs = std::filesystem;
using program_runner::file_bytes;

// ---- running a compat program ------------------------------------------------------------

// A fresh empty folder for one program's files, removed when the test case ends.
struct scratch_dir : program_runner::temp_dir {
    std::string file(const std::string &name) const { return (path / name).string(); }
};

struct program_run {
    int exit_code = -1;
    std::vector<std::string> lines;  // stdout, one entry per line
};

// Runs $BUILD/compat/<name> with the folder as its only argument; a program that is
// missing or does not exit with 0 fails the test case (its stderr is shown).
inline program_run run_program(const std::string &name, const scratch_dir &dir) {
    program_run r;
    const std::string exe = program_runner::build_dir() + "/compat/" + name;
    if (!CHECK_MSG(fs::exists(exe), "missing " + exe + ": build it with `make BUILD=" + program_runner::build_dir() + " tests`"))
        return r;
    const program_runner::temp_dir logs;
    const program_runner::run_result run = program_runner::run(exe, {dir.path.string()}, logs.path);
    std::istringstream out(run.out);
    for (std::string line; std::getline(out, line);) r.lines.push_back(line);
    r.exit_code = run.exit_code;
    CHECK_MSG(r.exit_code == 0, name + " exited with " + std::to_string(r.exit_code) + ": " + run.err);
    return r;
}

// The builds `make tests` makes of one program: as C++ (NAME) and, for the C programs
// (COMPAT_C_NAMES in tests/compat/compat.mk), as strict C11 (c11/NAME) and in gcc's default
// C (gnu/NAME). A test case that checks a C program runs each of the three.
inline std::vector<std::string> c_and_cxx_builds(const std::string &name) {
    return {name, "c11/" + name, "gnu/" + name};
}

// The numbers of every line that starts with `key` (the key itself and "->" skipped).
inline std::vector<std::vector<double>> numbers_after(const program_run &r, const std::string &key) {
    std::vector<std::vector<double>> rows;
    for (const std::string &line : r.lines) {
        std::istringstream in(line);
        std::string word;
        if (!(in >> word) || word != key) continue;
        std::vector<double> values;
        while (in >> word) {
            if (word == "->") continue;
            char *end = nullptr;
            const double v = std::strtod(word.c_str(), &end);
            if (end != word.c_str() && *end == '\0') values.push_back(v);
        }
        rows.push_back(values);
    }
    return rows;
}

// The rows of numbers_after(r, key), each required to hold exactly `width` numbers (a
// malformed row fails the test case and is dropped).
inline std::vector<std::vector<double>> rows_of(const program_run &r, const std::string &key, std::size_t width) {
    std::vector<std::vector<double>> rows;
    for (std::vector<double> &v : numbers_after(r, key))
        if (CHECK_MSG(v.size() == width, "'" + key + "' line with " + std::to_string(v.size()) + " numbers"))
            rows.push_back(std::move(v));
    return rows;
}

// The numbers of the one `key` line, which must hold exactly `width` numbers; empty (and the
// test case failed) otherwise.
inline std::vector<double> single_row(const program_run &r, const std::string &key, std::size_t width) {
    std::vector<std::vector<double>> rows = rows_of(r, key, width);
    if (!CHECK_MSG(rows.size() == 1, "expected one '" + key + "' line, got " + std::to_string(rows.size())))
        return {};
    return rows[0];
}

// ---- images ---------------------------------------------------------------------------------

// 8-bit sample the PGM writer stores for an intensity: round(clamp(v, 0, 1)·255).
inline int sample_of(float v) { return int(std::lround(std::fmin(std::fmax(double(v), 0.0), 1.0) * 255.0)); }

// The samples of a PGM file (P2 or P5) via the library's reader; empty on failure.
struct gray_image {
    int width = 0, height = 0;
    std::vector<int> samples;
    int at(int x, int y) const { return samples[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};
inline gray_image read_image(const std::string &path) {
    gray_image img;
    auto loaded = tiny3d::load_pgm(path);
    if (!loaded) {
        std::fprintf(stderr, "%s\n", loaded.message().c_str());
        return img;
    }
    const canvas_t &c = **loaded;
    img.width = c.width;
    img.height = c.height;
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x) img.samples.push_back(sample_of(c.pixels[y][x]));
    return img;
}

// Number of pixels where the file differs from the canvas quantised the same way.
inline int differing_pixels(const gray_image &img, const canvas_t &expected) {
    if (img.width != expected.width || img.height != expected.height) return -1;
    int diff = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) diff += img.at(x, y) != sample_of(expected.pixels[y][x]);
    return diff;
}

// ---- double-precision references ---------------------------------------------------------------

struct dvec3 {
    double x, y, z;
};
inline dvec3 operator+(dvec3 a, dvec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline dvec3 operator-(dvec3 a, dvec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline dvec3 operator*(double s, dvec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(dvec3 a, dvec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline dvec3 unit(dvec3 v) {
    const double n = std::sqrt(dot(v, v));
    return n > 0 ? (1.0 / n) * v : dvec3{0, 0, 0};
}
dvec3 row3(const std::vector<double> &v, std::size_t first) { return {v[first], v[first + 1], v[first + 2]}; }
// v[first .. first+2] within `tolerance` of `expected`, componentwise.
void check_near3(const std::vector<double> &v, std::size_t first, dvec3 expected, double tolerance) {
    CHECK_NEAR(v[first], expected.x, tolerance);
    CHECK_NEAR(v[first + 1], expected.y, tolerance);
    CHECK_NEAR(v[first + 2], expected.z, tolerance);
}

constexpr double kFloatTolerance = 2e-6;  // a few float roundings of O(1) values
// The report's vec3_normalize_fast / vec3_slerp (Quake inverse sqrt) are documented to
// 1.8e-3 relative error (math3d.h); they are what these programs call.
constexpr double kQuakeTolerance = 3e-3;


}  // namespace compat_util

#endif
