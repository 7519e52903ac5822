// output_test.cpp — saving where saving cannot work, and demos that cannot write their
// frames.
//
// Library (tiny3d::save_pgm / save_ppm / save_canvas, all through write_file_atomic): a
// missing folder, a folder where no file can be created, /dev/full, a path that is a
// folder, a file-size limit hit in the middle of the write (RLIMIT_FSIZE: the same failure
// as a full disk, and it works as root, where permission bits do not stop writes). Each must
// return an error naming the path and the reason, leave an existing file byte for byte as
// it was, and leave no temporary file behind.
//
// Programs: every demo binary in $BUILD/demo (BUILD is set by `make test`; default "build")
// is run with --out pointing at a folder it cannot create, and at a folder where the
// file-size limit makes every frame write fail: it must exit non-zero, say why on stderr,
// and never print "wrote" for a frame, and no frame or temporary file may appear.
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "canvas.h"
#include "harness.h"

namespace {

namespace fs = std::filesystem;

constexpr int SIDE = 64;                // px: a 64×64 P5 file is 4 KiB + header
constexpr rlim_t FILE_SIZE_LIMIT = 1024;  // bytes: smaller than any frame written here
const std::string PREVIOUS = "previous contents, not a PGM\n";

std::string slurp(const std::string &path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void spit(const std::string &path, const std::string &bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// A fresh private folder under /tmp, removed with its contents at the end.
struct temp_folder {
    std::string path;
    temp_folder() {
        char name[] = "/tmp/tiny3d_output_XXXXXX";
        path = ::mkdtemp(name) ? name : "";
    }
    ~temp_folder() {
        std::error_code ec;
        if (!path.empty()) fs::remove_all(path, ec);
    }
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        std::error_code ec;
        for (const auto &e : fs::directory_iterator(path, ec)) out.push_back(e.path().filename().string());
        std::sort(out.begin(), out.end());
        return out;
    }
};

tiny3d::canvas_ptr test_canvas() {
    tiny3d::canvas_ptr c = std::move(tiny3d::make_canvas(SIDE, SIDE).value());
    for (int y = 0; y < SIDE; ++y)
        for (int x = 0; x < SIDE; ++x) c->pixels[y][x] = float((x + y) % 7) / 6.0f;
    return c;
}

// Runs fn with the soft file-size limit lowered (SIGXFSZ ignored, so write() fails with
// EFBIG instead of killing the process), then restores both.
template <class Fn>
void with_file_size_limit(Fn &&fn) {
    rlimit old{};
    ::getrlimit(RLIMIT_FSIZE, &old);
    rlimit low = old;
    low.rlim_cur = FILE_SIZE_LIMIT;
    auto *previous_handler = std::signal(SIGXFSZ, SIG_IGN);
    ::setrlimit(RLIMIT_FSIZE, &low);
    fn();
    ::setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, previous_handler);
}

bool mentions(const tiny3d::status &s, const std::string &what) {
    return !s.ok() && s.message().find(what) != std::string::npos;
}

}  // namespace

TEST(save_into_a_missing_folder) {
    temp_folder tmp;
    const std::string path = tmp.path + "/no/such/folder/x.pgm";
    const tiny3d::status s = tiny3d::save_pgm(*test_canvas(), path);
    CHECK(!s.ok());
    CHECK_MSG(mentions(s, path) && mentions(s, "No such file or directory"), s.message());
    CHECK(!fs::exists(tmp.path + "/no"));
    CHECK(tmp.names().empty());
    CHECK(!save_canvas(test_canvas().get(), path.c_str()));
}

TEST(save_where_no_file_can_be_created) {
    // /proc accepts no new files, even from root: the temporary file cannot be made.
    const std::string path = "/proc/tiny3d_output_test.pgm";
    const tiny3d::status s = tiny3d::save_pgm(*test_canvas(), path);
    CHECK(!s.ok());
    CHECK_MSG(mentions(s, path) && mentions(s, "temporary"), s.message());
    CHECK(!fs::exists(path));
    // A folder without write permission (effective only when not root: root ignores it).
    if (::geteuid() != 0) {
        temp_folder tmp;
        const std::string target = tmp.path + "/keep.pgm";
        spit(target, PREVIOUS);
        ::chmod(tmp.path.c_str(), 0555);
        const tiny3d::status r = tiny3d::save_pgm(*test_canvas(), target);
        ::chmod(tmp.path.c_str(), 0755);
        CHECK_MSG(mentions(r, "Permission denied"), r.message());
        CHECK_EQ(slurp(target), PREVIOUS);
        CHECK_EQ(tmp.names().size(), std::size_t(1));
    }
}

TEST(save_to_dev_full_reports_no_space) {
    const tiny3d::status s = tiny3d::save_pgm(*test_canvas(), "/dev/full");
    CHECK_MSG(mentions(s, "/dev/full") && mentions(s, "No space left on device"), s.message());
    struct stat st {};
    CHECK(::stat("/dev/full", &st) == 0 && S_ISCHR(st.st_mode));  // the device is still a device
    CHECK(!tiny3d::save_ppm(*test_canvas(), "/dev/full").ok());
}

TEST(save_to_a_path_that_is_a_folder) {
    temp_folder tmp;
    fs::create_directory(tmp.path + "/sub");
    const tiny3d::status s = tiny3d::save_pgm(*test_canvas(), tmp.path + "/sub");
    CHECK_MSG(mentions(s, tmp.path + "/sub") && mentions(s, "folder"), s.message());
    CHECK(fs::is_directory(tmp.path + "/sub") && fs::is_empty(tmp.path + "/sub"));
    CHECK_EQ(tmp.names(), std::vector<std::string>{"sub"});
}

TEST(write_failing_midway_keeps_the_previous_file_and_leaves_no_temporary) {
    temp_folder tmp;
    const std::string target = tmp.path + "/frame.pgm";
    spit(target, PREVIOUS);
    tiny3d::status pgm, ppm;
    bool report_ok = true;
    with_file_size_limit([&] {
        pgm = tiny3d::save_pgm(*test_canvas(), target);
        ppm = tiny3d::save_ppm(*test_canvas(), target);
        report_ok = save_canvas(test_canvas().get(), target.c_str());
    });
    CHECK_MSG(mentions(pgm, target) && mentions(pgm, "File too large"), pgm.message());
    CHECK(!ppm.ok());
    CHECK(!report_ok);
    CHECK_EQ(slurp(target), PREVIOUS);
    CHECK_EQ(tmp.names(), std::vector<std::string>{"frame.pgm"});
    // And without the limit the same save works and replaces the file.
    CHECK(tiny3d::save_pgm(*test_canvas(), target).ok());
    CHECK_EQ(slurp(target).substr(0, 10), std::string("P5\n64 64\n2"));
    CHECK_EQ(tmp.names(), std::vector<std::string>{"frame.pgm"});
}

TEST(invalid_canvas_is_an_error_not_a_file) {
    temp_folder tmp;
    canvas_t empty{0, 0, nullptr, nullptr};
    CHECK(!tiny3d::save_pgm(empty, tmp.path + "/x.pgm").ok());
    CHECK(!save_canvas(nullptr, (tmp.path + "/x.pgm").c_str()));
    CHECK(!save_canvas(test_canvas().get(), nullptr));
    CHECK(!tiny3d::save_pgm(*test_canvas(), "").ok());
    CHECK(tmp.names().empty());
}

// ---- demo programs ----------------------------------------------------------------------

namespace {

struct run_result {
    int exit_code;
    std::string out, err;
};

std::string build_dir() {
    const char *b = std::getenv("BUILD");
    return b && *b ? b : "build";
}

// Runs `command` through /bin/sh with stdout and stderr captured into files in `scratch`.
run_result run(const std::string &command, const std::string &scratch) {
    const std::string out = scratch + "/stdout.txt", err = scratch + "/stderr.txt";
    const int status = std::system((command + " >" + out + " 2>" + err).c_str());
    run_result r{WIFEXITED(status) ? WEXITSTATUS(status) : 128, slurp(out), slurp(err)};
    fs::remove(out);
    fs::remove(err);
    return r;
}

// The command line that makes demo `name` write its first frame (or its one image) into
// `out_dir` (the Makefile's DEMO_ARGS_<name> for the demos that need more than --out).
std::string demo_command(const std::string &binary, const std::string &name, const std::string &out_dir) {
    if (name == "ply_render") return binary + " tests/data/tetra_ascii.ply 90 45 -135 " + out_dir + "/ply_render.pgm";
    // clock writes its two images and takes no --frames.
    std::string args = " --out " + out_dir + (name == "clock" ? "" : " --frames 0:0") + " --size 64x64";
    if (name == "wireframe" || name == "render") args = " tests/data/cube_quads.obj" + args;
    return binary + args;
}

std::vector<fs::path> demo_binaries() {
    std::vector<fs::path> out;
    std::error_code ec;
    for (const auto &e : fs::directory_iterator(fs::path(build_dir()) / "demo", ec))
        if (e.is_regular_file() && e.path().extension().empty() && ::access(e.path().c_str(), X_OK) == 0)
            out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST(demos_exist_to_be_checked) {
    CHECK_MSG(!demo_binaries().empty(), "no demo binaries under " + build_dir() + "/demo (run from the source root)");
}

TEST(demos_exit_nonzero_when_the_output_folder_cannot_be_made) {
    temp_folder scratch;
    for (const fs::path &bin : demo_binaries()) {
        const std::string name = bin.filename().string();
        // Under /dev/full (a device, not a folder): nothing can be created there.
        const run_result r = run(demo_command(bin.string(), name, "/dev/full/frames"), scratch.path);
        CHECK_MSG(r.exit_code != 0, name + " exited 0");
        CHECK_MSG(r.err.find("/dev/full") != std::string::npos, name + " stderr: " + r.err);
        CHECK_MSG(r.out.find("wrote") == std::string::npos && r.err.find("wrote") == std::string::npos,
                  name + " claims a frame: " + r.out);
    }
}

TEST(demos_never_report_a_frame_they_did_not_write) {
    temp_folder scratch;
    for (const fs::path &bin : demo_binaries()) {
        const std::string name = bin.filename().string();
        const std::string out_dir = scratch.path + "/" + name;
        fs::create_directory(out_dir);
        // Every frame write fails half-way (file-size limit, SIGXFSZ ignored: EFBIG).
        const std::string limited = "trap '' XFSZ; ulimit -f 1; " + demo_command(bin.string(), name, out_dir);
        const run_result r = run("sh -c \"" + limited + "\"", scratch.path);
        CHECK_MSG(r.exit_code != 0, name + " exited 0");
        CHECK_MSG(r.err.find("File too large") != std::string::npos, name + " stderr: " + r.err);
        CHECK_MSG(r.out.find("wrote") == std::string::npos, name + " claims a frame: " + r.out);
        std::error_code ec;
        CHECK_MSG(fs::is_empty(out_dir, ec), name + " left files in " + out_dir);
    }
}
