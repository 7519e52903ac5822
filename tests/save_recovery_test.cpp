// save_recovery_test.cpp — the temporary file of an atomic save: a save killed half-way
// leaves "<path>.tmp", and the next save of the same path takes it over and renames it away
// (no stale file stays); a temporary held by a live save is left alone (a unique name is
// used); a symlink or folder in the temporary's place is never written through.
//
// The killed save is real: a child process with a 4 KiB file-size limit and SIGXFSZ at its
// default action dies inside write(2), exactly like a SIGKILL mid-save.
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

#include "harness.h"
#include "program_runner.h"
#include "canvas.h"

namespace fs = std::filesystem;
using program_runner::file_bytes;
using program_runner::files_in;
using program_runner::temp_dir;

namespace {

constexpr int kSide = 160;  // 25,600 bytes of pixels: far beyond the child's 4 KiB limit

// A canvas whose pixel (x, y) holds ((x + 3y) mod 256) / 255, and its PGM by hand.
tiny3d::canvas_ptr pattern(int shift) {
    tiny3d::canvas_ptr c = tiny3d::make_canvas(kSide, kSide).value();
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) c->pixels[y][x] = float((x + 3 * y + shift) % 256) / 255.0f;
    return c;
}
std::string expected_pgm(int shift) {
    std::string s = "P5\n" + std::to_string(kSide) + " " + std::to_string(kSide) + "\n255\n";
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) s += char((x + 3 * y + shift) % 256);
    return s;
}

// Runs save_pgm(pattern(shift), path) in a child killed by SIGXFSZ after 4096 bytes.
bool killed_save(const std::string &path, int shift) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        const rlimit no_core{0, 0}, small{4096, 4096};
        ::setrlimit(RLIMIT_CORE, &no_core);
        ::signal(SIGXFSZ, SIG_DFL);
        ::setrlimit(RLIMIT_FSIZE, &small);
        (void)tiny3d::save_pgm(*pattern(shift), path);
        ::_exit(0);  // not reached: the write beyond 4 KiB kills the process
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFSIGNALED(status) && WTERMSIG(status) == SIGXFSZ;
}

void write_text(const fs::path &p, const std::string &text) {
    std::FILE *f = std::fopen(p.c_str(), "wb");
    std::fwrite(text.data(), 1, text.size(), f);
    std::fclose(f);
}

}  // namespace

TEST(the_next_save_removes_the_temporary_a_killed_save_left) {
    temp_dir dir;
    const std::string frame = (dir.path / "frame_000.pgm").string();
    // First run: killed mid-save, nothing saved yet.
    CHECK(killed_save(frame, 0));
    auto files = files_in(dir.path);
    CHECK_EQ(files.size(), std::size_t(1));
    CHECK(files.count("frame_000.pgm.tmp") == 1);
    CHECK_EQ(files["frame_000.pgm.tmp"].size(), std::size_t(4096));
    // A later run saves the same frame: the stale file is taken over, only the frame stays.
    CHECK(tiny3d::save_pgm(*pattern(0), frame).ok());
    files = files_in(dir.path);
    CHECK_EQ(files.size(), std::size_t(1));
    CHECK(files["frame_000.pgm"] == expected_pgm(0));
    // Killed while replacing a saved frame: the frame stays intact, and again the next save
    // of it leaves nothing behind.
    CHECK(killed_save(frame, 7));
    CHECK(file_bytes(frame) == expected_pgm(0));
    CHECK(fs::exists(frame + ".tmp"));
    CHECK(tiny3d::save_pgm(*pattern(7), frame).ok());
    files = files_in(dir.path);
    CHECK_EQ(files.size(), std::size_t(1));
    CHECK(files["frame_000.pgm"] == expected_pgm(7));
}

TEST(a_stale_temporary_larger_than_the_image_is_truncated) {
    temp_dir dir;
    const fs::path frame = dir.path / "f.pgm";
    write_text(dir.path / "f.pgm.tmp", std::string(100000, 'x'));
    CHECK(tiny3d::save_pgm(*pattern(3), frame.string()).ok());
    const auto files = files_in(dir.path);
    CHECK_EQ(files.size(), std::size_t(1));
    CHECK(file_bytes(frame) == expected_pgm(3));
    CHECK_EQ((fs::status(frame).permissions() & fs::perms::all), fs::perms(0644));
}

TEST(a_temporary_held_by_a_live_save_is_left_alone) {
    temp_dir dir;
    const fs::path frame = dir.path / "f.pgm", held = dir.path / "f.pgm.tmp";
    write_text(held, "in progress");
    const int fd = ::open(held.c_str(), O_RDWR);
    CHECK(fd >= 0 && ::flock(fd, LOCK_EX | LOCK_NB) == 0);  // what a live save holds
    CHECK(tiny3d::save_pgm(*pattern(1), frame.string()).ok());
    const auto files = files_in(dir.path);
    CHECK_EQ(files.size(), std::size_t(2));  // the frame and the held file, no third
    CHECK(file_bytes(frame) == expected_pgm(1));
    CHECK(file_bytes(held) == "in progress");
    ::close(fd);
}

TEST(a_symlink_or_folder_in_the_temporarys_place_is_not_written_through) {
    temp_dir dir;
    const fs::path victim = dir.path / "victim.txt", frame = dir.path / "f.pgm";
    write_text(victim, "keep me");
    fs::create_symlink(victim, dir.path / "f.pgm.tmp");
    CHECK(tiny3d::save_pgm(*pattern(2), frame.string()).ok());
    CHECK(file_bytes(victim) == "keep me");
    CHECK(file_bytes(frame) == expected_pgm(2));
    CHECK(fs::is_symlink(dir.path / "f.pgm.tmp"));

    const fs::path frame2 = dir.path / "g.pgm";
    fs::create_directory(dir.path / "g.pgm.tmp");
    CHECK(tiny3d::save_pgm(*pattern(4), frame2.string()).ok());
    CHECK(file_bytes(frame2) == expected_pgm(4));
    CHECK(fs::is_directory(dir.path / "g.pgm.tmp"));
    std::size_t others = 0;  // no unique temporaries left over
    for (const auto &e : fs::directory_iterator(dir.path))
        others += e.path().filename().string().find(".tmp-") != std::string::npos;
    CHECK_EQ(others, std::size_t(0));
}
