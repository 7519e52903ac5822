// gif_test.cpp — tiny3d::gif_writer (canvas.h). Every file written is read back by the
// tests' own GIF89a decoder (tests/gif_decoder.h, written from the specification: blocks,
// sub-blocks and the variable-length-code LZW of its appendix F; no code of the writer), and
// every decoded frame is compared byte for byte with the bytes the canvas was made from,
// and with the samples save_pgm writes for the same canvas.
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "alloc_tracker.h"
#include "gif_decoder.h"
#include "harness.h"
#include "temp_folder.h"
#include "canvas.h"

namespace {

using namespace gif_decoder;

// A canvas holding byte b as b / 255 (which save_pgm writes back as b).
tiny3d::canvas_ptr canvas_of(const bytes &b, int w, int h) {
    tiny3d::canvas_ptr c = tiny3d::make_canvas(w, h).value();
    for (std::size_t i = 0; i < b.size(); ++i) c->data[i] = float(b[i]) / 255.0f;
    return c;
}

// Writes the frames (each w × h bytes) as a GIF and decodes it; checks every frame.
decoded_gif round_trip(temp_folder &dir, const std::vector<bytes> &frames, int w, int h, tiny3d::gif_options o = {}) {
    const std::string path = dir.named("round.gif");
    auto writer = tiny3d::gif_writer::create(path, w, h, o);
    CHECK_MSG(writer.ok(), writer.message());
    if (!writer) return {};
    for (const bytes &f : frames) {
        tiny3d::status s = writer->add_frame(*canvas_of(f, w, h));
        CHECK_MSG(s.ok(), s.message());
    }
    tiny3d::status s = writer->finish();
    CHECK_MSG(s.ok(), s.message());
    const decoded_gif g = decode_gif(read_all(path));
    CHECK_MSG(g.problem.empty(), g.problem);
    CHECK_EQ(g.width, w);
    CHECK_EQ(g.height, h);
    CHECK(g.grey_table);
    CHECK_EQ(g.frames.size(), frames.size());
    for (std::size_t k = 0; k < std::min(g.frames.size(), frames.size()); ++k) {
        CHECK_MSG(g.frames[k] == frames[k], "frame " + std::to_string(k) + " differs");
        CHECK_EQ(g.disposals[k], 1);
        CHECK_EQ(g.delays[k], tiny3d::gif_frame_delay(o.fps, long(k)));
    }
    return g;
}

// Deterministic noise bytes (a 32-bit linear congruential generator, high byte).
bytes noise(std::size_t n, std::uint32_t seed) {
    bytes b(n);
    for (auto &v : b) {
        seed = seed * 1664525u + 1013904223u;
        v = std::uint8_t(seed >> 24);
    }
    return b;
}

bool folder_is_empty(const std::string &path) { return std::filesystem::is_empty(path); }

}  // namespace

TEST(delays_track_the_true_times) {
    const int thirty[] = {3, 3, 4, 3, 3, 4};
    for (int k = 0; k < 6; ++k) CHECK_EQ(tiny3d::gif_frame_delay(30.0, k), thirty[k]);
    for (double fps : {0.01, 7.0, 12.5, 24.0, 25.0, 29.97, 30.0, 44.1, 50.0}) {
        long sum = 0;
        for (long k = 0; k < 2000; ++k) {
            const int d = tiny3d::gif_frame_delay(fps, k);
            sum += d;
            CHECK(d >= 2);  // viewers slow delays of 0 or 1 down to 10
            // the running sum is the true end time of frame k, rounded down to a hundredth
            const double end = 100.0 * double(k + 1) / fps;
            CHECK(double(sum) <= end + 1e-9 && double(sum) > end - 1.0);
        }
    }
    CHECK_EQ(tiny3d::gif_frame_delay(50.0, 17), 2);
    CHECK_EQ(tiny3d::gif_frame_delay(0.01, 0), 10000);
}

TEST(one_by_one_canvas) {
    temp_folder dir;
    const decoded_gif g = round_trip(dir, {{0}, {255}, {255}, {128}}, 1, 1);
    CHECK_EQ(g.loop_count, 0);  // forever by default
    for (const rect &r : g.rects) CHECK(r.width == 1 && r.height == 1);
}

TEST(odd_sizes_and_changed_rectangles) {
    temp_folder dir;
    for (auto [w, h] : {std::pair{7, 3}, {1, 17}, {33, 5}, {31, 29}}) {
        std::vector<bytes> frames;
        for (int k = 0; k < 5; ++k) {
            bytes f(std::size_t(w * h), 40);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    if ((x - k) * (x - k) + (y - h / 2) * (y - h / 2) <= 4) f[std::size_t(y * w + x)] = std::uint8_t(200 + 10 * k);
            frames.push_back(f);
        }
        const decoded_gif g = round_trip(dir, frames, w, h);
        if (g.rects.size() != 5) continue;
        CHECK(g.rects[0].width == w && g.rects[0].height == h);  // the first frame whole
        // Each later rectangle is exactly the bounding box of the pixels that changed.
        for (int k = 1; k < 5; ++k) {
            int left = w, top = h, right = -1, bottom = -1;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    if (frames[std::size_t(k)][std::size_t(y * w + x)] != frames[std::size_t(k - 1)][std::size_t(y * w + x)])
                        left = std::min(left, x), right = std::max(right, x), top = std::min(top, y), bottom = std::max(bottom, y);
            if (right < 0) left = top = right = bottom = 0;
            const rect r = g.rects[std::size_t(k)];
            CHECK_EQ(r.left, left);
            CHECK_EQ(r.top, top);
            CHECK_EQ(r.width, right - left + 1);
            CHECK_EQ(r.height, bottom - top + 1);
        }
    }
}

TEST(noise_fills_the_lzw_table_many_times) {
    temp_folder dir;
    const int w = 301, h = 199;  // 59,899 incompressible indices per frame: a clear every ~3,800 codes
    std::vector<bytes> frames = {noise(std::size_t(w * h), 1), noise(std::size_t(w * h), 2)};
    bytes third = frames[1];
    for (int y = 50; y < 120; ++y)
        for (int x = 17; x < 250; ++x) third[std::size_t(y * w + x)] = std::uint8_t(x ^ y);
    frames.push_back(third);
    frames.push_back(bytes(std::size_t(w * h), 255));  // then one long run: strings up to long lengths
    const decoded_gif g = round_trip(dir, frames, w, h);
    CHECK(g.clear_codes >= 25);  // each of the two noise frames alone fills the table 15 times
}

TEST(every_byte_value_and_save_pgm_rounding) {
    // Intensities that are not byte / 255 (ties, negatives, above 1, NaN): the GIF holds
    // exactly the samples of the PGM that save_pgm writes for the same canvas.
    // Every half-way point (k + 1/2) / 255 and the 8 floats each side of it, on a width that
    // leaves a remainder after blocks of 16 (the vector path and the scalar tail both see them).
    temp_folder dir;
    const int w = 257, h = 17;
    tiny3d::canvas_ptr c = tiny3d::make_canvas(w, h).value();
    int i = 0;
    for (int k = -1; k < 256; ++k) {
        float v = (float(k) + 0.5f) / 255.0f;
        for (int step = 0; step < 8; ++step) v = std::nextafter(v, -1.0f);
        for (int step = 0; step < 17 && i < w * h; ++step, ++i, v = std::nextafter(v, 2.0f)) c->data[i] = v;
    }
    for (; i < w * h; ++i) c->data[i] = float(i % 300) / 280.0f - 0.05f;
    for (int at : {0, 16, 31, w * h - 1}) c->data[at] = std::numeric_limits<float>::quiet_NaN();
    for (int at : {1, 17, w * h - 2}) c->data[at] = 7.0f;
    for (int at : {2, 18, w * h - 3}) c->data[at] = -std::numeric_limits<float>::infinity();
    c->data[3] = std::numeric_limits<float>::infinity();
    const std::string gif = dir.named("r.gif"), pgm = dir.named("r.pgm");
    auto writer = tiny3d::gif_writer::create(gif, w, h);
    CHECK(writer.ok() && writer->add_frame(*c).ok() && writer->finish().ok());
    CHECK(tiny3d::save_pgm(*c, pgm).ok());
    const std::string p = read_all(pgm);
    const bytes samples(p.end() - w * h, p.end());
    const decoded_gif g = decode_gif(read_all(gif));
    CHECK_MSG(g.problem.empty(), g.problem);
    CHECK(g.frames.size() == 1 && g.frames[0] == samples);
}

TEST(a_frame_equal_to_the_one_before_holds_its_delay) {
    temp_folder dir;
    const int w = 20, h = 11;
    const bytes a = noise(std::size_t(w * h), 9);
    tiny3d::gif_options o;
    o.fps = 12.5;
    const decoded_gif g = round_trip(dir, {a, a, a}, w, h, o);
    CHECK_EQ(g.rects.size(), std::size_t{3});
    for (std::size_t k = 1; k < g.rects.size(); ++k) {
        CHECK(g.rects[k].width == 1 && g.rects[k].height == 1);
        CHECK_EQ(g.delays[k], 8);
    }
}

TEST(first_frames_all_black) {
    temp_folder dir;
    const int w = 40, h = 30;
    std::vector<bytes> frames(3, bytes(std::size_t(w * h), 0));
    for (int k = 0; k < 3; ++k) {
        bytes f(std::size_t(w * h), 0);
        for (int y = 10; y < 16; ++y)
            for (int x = 5 + 8 * k; x < 12 + 8 * k; ++x) f[std::size_t(y * w + x)] = std::uint8_t(90 * k + 60);
        frames.push_back(f);
    }
    const decoded_gif g = round_trip(dir, frames, w, h);
    if (g.rects.size() == 6) {
        CHECK(g.rects[1].width == 1 && g.rects[2].width == 1);
        CHECK(g.rects[3].left == 5 && g.rects[3].top == 10 && g.rects[3].width == 7 && g.rects[3].height == 6);
    }
}

TEST(loop_count_on_request) {
    temp_folder dir;
    for (int loops : {-1, 0, 3, 65535}) {
        tiny3d::gif_options o;
        o.loop_count = loops;
        CHECK_EQ(round_trip(dir, {{1, 2}, {3, 4}}, 2, 1, o).loop_count, loops);
    }
}

TEST(frame_of_another_size_is_an_error_and_leaves_nothing) {
    temp_folder dir;
    const std::string path = dir.named("size.gif");
    auto writer = tiny3d::gif_writer::create(path, 8, 8);
    CHECK(writer.ok());
    CHECK(writer->add_frame(*tiny3d::make_canvas(8, 8).value()).ok());
    const tiny3d::status s = writer->add_frame(*tiny3d::make_canvas(10, 8).value());
    CHECK(!s.ok());
    if (!s.ok()) {
        CHECK_EQ(s.err().file, path);
        CHECK_MSG(s.message().find("frame 1 is 10x8, the animation is 8x8") != std::string::npos, s.message());
    }
    CHECK(folder_is_empty(dir.path));  // the temporary is gone at once
    CHECK(!writer->add_frame(*tiny3d::make_canvas(8, 8).value()).ok());  // the writer has failed
    CHECK(!writer->finish().ok());
    CHECK(folder_is_empty(dir.path));
}

TEST(errors_name_the_file_and_leave_nothing) {
    temp_folder dir;
    const std::string missing = dir.path + "/no_such_folder/a.gif";
    auto w1 = tiny3d::gif_writer::create(missing, 4, 4);
    CHECK(!w1.ok());
    if (!w1.ok()) CHECK_MSG(w1.message().find(missing) == 0 && w1.message().find("No such file") != std::string::npos, w1.message());
    CHECK(folder_is_empty(dir.path));

    // Disk full: /dev/full is written in place and fails with ENOSPC.
    auto full = tiny3d::gif_writer::create("/dev/full", 4, 4);
    CHECK(!full.ok());
    if (!full.ok()) CHECK_MSG(full.message().find("/dev/full") == 0 && full.message().find("No space left") != std::string::npos, full.message());

    for (double fps : {0.0, 50.5, std::numeric_limits<double>::quiet_NaN()}) {
        tiny3d::gif_options o;
        o.fps = fps;
        CHECK(!tiny3d::gif_writer::create(dir.path + "/f.gif", 4, 4, o).ok());
    }
    tiny3d::gif_options loops;
    loops.loop_count = 65536;
    CHECK(!tiny3d::gif_writer::create(dir.path + "/l.gif", 4, 4, loops).ok());
    CHECK(!tiny3d::gif_writer::create(dir.path + "/s.gif", 0, 4).ok());
    CHECK(!tiny3d::gif_writer::create(dir.path + "/s.gif", 65536, 1).ok());
    CHECK(folder_is_empty(dir.path));

    // No frame: finish refuses and leaves nothing.
    auto empty = tiny3d::gif_writer::create(dir.path + "/e.gif", 4, 4);
    CHECK(empty.ok() && !empty->finish().ok());
    CHECK(folder_is_empty(dir.path));
}

TEST(unfinished_writer_leaves_nothing_and_keeps_the_old_file) {
    temp_folder dir;
    const std::string path = dir.file("old.gif", "the previous file");
    {
        auto writer = tiny3d::gif_writer::create(path, 16, 16);
        CHECK(writer.ok());
        CHECK(writer->add_frame(*canvas_of(noise(256, 4), 16, 16)).ok());
        auto moved = std::move(*writer);  // the moved-to writer owns the file
        CHECK(!writer->add_frame(*canvas_of(noise(256, 4), 16, 16)).ok());
        CHECK_EQ(moved.frame_count(), 1L);
    }
    CHECK_EQ(read_all(path), std::string("the previous file"));
    std::size_t files = 0;
    for ([[maybe_unused]] const auto &e : std::filesystem::directory_iterator(dir.path)) ++files;
    CHECK_EQ(files, std::size_t{1});
}

TEST(a_write_failing_half_way_leaves_nothing) {
    // A child process limited to 4 KiB of file size (SIGXFSZ ignored: write returns EFBIG):
    // the writer's temporary grows past the limit while noise frames are added.
    temp_folder dir;
    const std::string path = dir.path + "/big.gif";
    const pid_t child = ::fork();
    if (child == 0) {
        ::signal(SIGXFSZ, SIG_IGN);
        rlimit limit{4096, 4096};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        auto writer = tiny3d::gif_writer::create(path, 64, 64);
        if (!writer) ::_exit(2);
        tiny3d::status s;
        for (int k = 0; k < 10 && s.ok(); ++k) s = writer->add_frame(*canvas_of(noise(64 * 64, std::uint32_t(k)), 64, 64));
        const bool named = !s.ok() && s.message().find(path) == 0 && s.message().find("write failed") != std::string::npos;
        ::_exit(named && folder_is_empty(dir.path) ? 0 : 3);
    }
    int status = 0;
    CHECK_EQ(::waitpid(child, &status, 0), child);
    CHECK(WIFEXITED(status));
    CHECK_EQ(WEXITSTATUS(status), 0);
    CHECK(folder_is_empty(dir.path));
}

TEST(no_allocation_per_frame_in_steady_state) {
    temp_folder dir;
    const int w = 97, h = 61;
    auto writer = tiny3d::gif_writer::create(dir.named("alloc.gif"), w, h);
    CHECK(writer.ok());
    std::vector<tiny3d::canvas_ptr> canvases;
    for (std::uint32_t k = 0; k < 6; ++k) canvases.push_back(canvas_of(noise(std::size_t(w * h), k), w, h));
    for (int k = 0; k < 2; ++k) CHECK(writer->add_frame(*canvases[std::size_t(k)]).ok());
    const std::size_t before = alloc_tracker::allocations();
    for (int k = 2; k < 6; ++k) CHECK(writer->add_frame(*canvases[std::size_t(k)]).ok());
    CHECK_EQ(alloc_tracker::allocations() - before, std::size_t{0});
    CHECK(writer->finish().ok());
}
