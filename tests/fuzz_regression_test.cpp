// fuzz_regression_test.cpp — every input the fuzzers ever crashed on, and every seed, is
// loaded again with the fuzzers' own checks (tests/fuzz/fuzz_checks.h), here with g++ and,
// in `make test`'s second pass, ASan + UBSan.
//
//  * tests/fuzz/regressions/<target>/*: minimised crash inputs. Each must now give an error
//    naming the file, or a value meeting every invariant (no crash, no garbage).
//  * tests/fuzz/corpus/<target>/*: the seed corpora, all valid files: each must LOAD (so
//    the seeds really start the fuzzer inside the format) and pass the same checks.
//  * tests/fuzz/found/<target>/*: inputs a long fuzz run grew, the fewest that still reach
//    every code edge the run reached (valid or not): each must give an error or a valid value.
// Run from the source root (as `make test` does); TINY3D_SOURCE_DIR overrides.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz/fuzz_checks.h"
#include "harness.h"

namespace {

namespace fs = std::filesystem;

fs::path fuzz_dir() {
    const char *root = std::getenv("TINY3D_SOURCE_DIR");
    return fs::path(root ? root : ".") / "tests" / "fuzz";
}

// Regular files of a folder, sorted (a missing folder gives none).
std::vector<fs::path> files_in(const fs::path &dir) {
    std::vector<fs::path> out;
    std::error_code ec;
    for (const auto &entry : fs::directory_iterator(dir, ec))
        if (entry.is_regular_file() && entry.path().filename().string()[0] != '.') out.push_back(entry.path());
    std::sort(out.begin(), out.end());
    return out;
}

std::string read_bytes(const fs::path &p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The check of one target on one file (the same calls the fuzz targets make).
std::string check_file(const std::string &target, const fs::path &file) {
    if (target == "obj") return fuzz_checks::check_obj(read_bytes(file), file.string());
    if (target == "ply") return fuzz_checks::check_ply(read_bytes(file), file.string());
    if (target == "texture") return fuzz_checks::check_texture_file(file.string());
    return fuzz_checks::check_pnm_file(file.string());
}

bool loads(const std::string &target, const fs::path &file) {
    if (target == "obj") return tiny3d::parse_obj(read_bytes(file)).ok();
    if (target == "ply") return tiny3d::parse_ply(read_bytes(file)).ok();
    if (target == "texture") return tiny3d::load_texture_pgm(file.string()).ok();
    return tiny3d::load_pgm(file.string()).ok();
}

const char *const TARGETS[] = {"obj", "ply", "pnm", "texture"};

}  // namespace

TEST(fuzz_folders_exist) {
    // Guards the other cases: run from the wrong folder they would pass on zero files.
    for (const char *t : TARGETS) {
        CHECK_MSG(fs::is_directory(fuzz_dir() / "corpus" / t), std::string("missing corpus for ") + t);
        CHECK_MSG(fs::is_directory(fuzz_dir() / "regressions" / t), std::string("missing regressions for ") + t);
        CHECK_MSG(files_in(fuzz_dir() / "corpus" / t).size() >= 3, std::string("fewer than 3 seeds for ") + t);
    }
    CHECK(files_in(fuzz_dir() / "found" / "obj").size() >= 100);  // kept from the 10 M-execution run
}

TEST(seed_corpora_load_and_pass_checks) {
    for (const char *t : TARGETS)
        for (const fs::path &f : files_in(fuzz_dir() / "corpus" / t)) {
            CHECK_MSG(loads(t, f), "seed does not load: " + f.string());
            const std::string v = check_file(t, f);
            CHECK_MSG(v.empty(), f.string() + ": " + v);
        }
}

TEST(crash_regressions_and_found_inputs_give_error_or_valid_value) {
    for (const char *t : TARGETS)
        for (const char *folder : {"regressions", "found"})
            for (const fs::path &f : files_in(fuzz_dir() / folder / t)) {
                const std::string v = check_file(t, f);
                CHECK_MSG(v.empty(), f.string() + ": " + v);
            }
}
