// canvas_test.cpp — canvas allocation, the splat convention, the faithful line, PGM save.
#include "harness.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "canvas.h"
#include "lines.h"

TEST(create_canvas_contiguous_rows) {
    canvas_t *c = create_canvas(7, 5);
    CHECK(c != nullptr);
    if (!c) return;
    CHECK_EQ(c->width, 7);
    CHECK_EQ(c->height, 5);
    for (int y = 0; y < 5; ++y) CHECK(c->pixels[y] == c->data + y * 7);
    CHECK_EQ(get_pixel(c, 3, 3), 0.0f);
    destroy_canvas(c);
}

TEST(create_canvas_rejects_bad_sizes) {
    CHECK(create_canvas(0, 5) == nullptr);
    CHECK(create_canvas(5, -1) == nullptr);
    CHECK(create_canvas(40000, 40000) == nullptr);
    CHECK(!tiny3d::check_canvas_size(0, 5).ok());
    CHECK(tiny3d::check_canvas_size(0, 5).message().find("positive") != std::string::npos);
    CHECK(!tiny3d::make_canvas(-3, 3).ok());
}

TEST(canvas_limits_sit_exactly_at_the_stated_values) {
    // canvas.h: sides 1..CANVAS_MAX_SIDE, at most CANVAS_MAX_PIXELS pixels (checked, not
    // allocated, here).
    CHECK(tiny3d::check_canvas_size(CANVAS_MAX_SIDE, 1).ok());
    CHECK(tiny3d::check_canvas_size(1, CANVAS_MAX_SIDE).ok());
    CHECK(!tiny3d::check_canvas_size(CANVAS_MAX_SIDE + 1, 1).ok());
    CHECK(!tiny3d::check_canvas_size(1, CANVAS_MAX_SIDE + 1).ok());
    CHECK_EQ(16384LL * 16384LL, CANVAS_MAX_PIXELS);
    CHECK(tiny3d::check_canvas_size(16384, 16384).ok());
    CHECK(!tiny3d::check_canvas_size(16384, 16385).ok());
    CHECK(!tiny3d::check_canvas_size(16385, 16384).ok());
    CHECK(tiny3d::check_canvas_size(16385, 16384).message().find("exceeds the limit") != std::string::npos);
}

TEST(clear_count_and_get_pixel_keep_their_contracts) {
    canvas_t *c = create_canvas(7, 3);
    CHECK(c != nullptr);
    if (!c) return;
    // canvas_clear stores clamp(value) to 0..1, NaN as 0.
    canvas_clear(c, 2.5f);
    CHECK_EQ(canvas_count_differing(c, 1.0f), std::size_t(0));
    canvas_clear(c, -0.5f);
    CHECK_EQ(canvas_count_differing(c, 0.0f), std::size_t(0));
    canvas_clear(c, 0.25f);
    CHECK_EQ(canvas_count_differing(c, 0.25f), std::size_t(0));
    CHECK_EQ(canvas_count_differing(c, 0.5f), std::size_t(21));
    c->pixels[1][0] = 0.875f;  // the first pixel of row 1 follows the last of row 0 in memory
    c->pixels[2][6] = 0.5f;
    CHECK_EQ(canvas_count_differing(c, 0.25f), std::size_t(2));
    // get_pixel: the pixel inside, 0 one step past every edge (never the neighbouring row).
    CHECK_EQ(get_pixel(c, 0, 1), 0.875f);
    CHECK_EQ(get_pixel(c, 6, 2), 0.5f);
    CHECK_EQ(get_pixel(c, 7, 0), 0.0f);
    CHECK_EQ(get_pixel(c, -1, 1), 0.0f);
    CHECK_EQ(get_pixel(c, 0, 3), 0.0f);
    CHECK_EQ(get_pixel(c, 0, -1), 0.0f);
    canvas_clear(c, NAN);
    CHECK_EQ(canvas_count_differing(c, 0.0f), std::size_t(0));
    destroy_canvas(c);
}

// set_pixel_f keeps the report's convention: integer coordinates are pixel centres.
TEST(splat_at_pixel_centre_hits_one_pixel) {
    canvas_t *c = create_canvas(4, 4);
    set_pixel_f(c, 1.0f, 2.0f, 0.75f);
    double sum = 0;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) sum += c->pixels[y][x];
    CHECK_NEAR(c->pixels[2][1], 0.75, 0.0);
    CHECK_NEAR(sum, 0.75, 1e-7);
    destroy_canvas(c);
}

TEST(splat_weights_are_bilinear_and_sum_to_intensity) {
    canvas_t *c = create_canvas(4, 4);
    set_pixel_f(c, 1.25f, 0.75f, 0.5f);  // 0.25 right of centre 1, 0.25 above centre 1
    // x0 = 1, dx = .25 ; y0 = 0, dy = .75
    CHECK_NEAR(c->pixels[0][1], 0.5 * 0.75 * 0.25, 1e-7);
    CHECK_NEAR(c->pixels[0][2], 0.5 * 0.25 * 0.25, 1e-7);
    CHECK_NEAR(c->pixels[1][1], 0.5 * 0.75 * 0.75, 1e-7);
    CHECK_NEAR(c->pixels[1][2], 0.5 * 0.25 * 0.75, 1e-7);
    destroy_canvas(c);
}

TEST(splat_clamps_to_one) {
    canvas_t *c = create_canvas(2, 2);
    for (int i = 0; i < 5; ++i) set_pixel_f(c, 0.0f, 0.0f, 0.4f);
    CHECK_EQ(c->pixels[0][0], 1.0f);
    set_pixel_f(c, 1e30f, 0.0f, 1.0f);    // far off: ignored, no UB
    set_pixel_f(c, 0.0f, NAN, 1.0f);      // NaN: ignored
    CHECK_EQ(c->pixels[0][1], 0.0f);
    destroy_canvas(c);
}

TEST(faithful_line_far_endpoints_are_clipped_not_lost) {
    canvas_t *c = create_canvas(32, 16);
    draw_line_f(c, -1e9f, 8.0f, 1e9f, 8.0f, 1.5f);
    // A horizontal line through y = 8 inks the rows around it across the whole width.
    CHECK(c->pixels[8][0] > 0.0f);
    CHECK(c->pixels[8][16] > 0.0f);
    CHECK(c->pixels[8][31] > 0.0f);
    CHECK_EQ(c->pixels[0][16], 0.0f);
    destroy_canvas(c);
}

TEST(save_pgm_binary_bytes) {
    canvas_t *c = create_canvas(3, 2);
    c->pixels[0][0] = 1.0f;
    c->pixels[0][1] = 0.5f;
    c->pixels[1][2] = 0.2f;
    const std::string path = "/tmp/tiny3d_canvas_test_" + std::to_string(getpid()) + ".pgm";
    CHECK(save_canvas(c, path.c_str()));
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    const std::string expect = std::string("P5\n3 2\n255\n") + char(255) + char(128) + char(0) + char(0) +
                               char(0) + char(51);
    CHECK(bytes == expect);
    std::remove(path.c_str());
    destroy_canvas(c);
}

TEST(save_errors_leave_nothing) {
    canvas_t *c = create_canvas(3, 2);
    tiny3d::status s = tiny3d::save_pgm(*c, "/nonexistent_dir_tiny3d/x.pgm");
    CHECK(!s.ok());
    CHECK(s.message().find("/nonexistent_dir_tiny3d/x.pgm") != std::string::npos);
    CHECK(!tiny3d::save_pgm(*c, "/tmp").ok());
    tiny3d::status full = tiny3d::save_pgm(*c, "/dev/full");
    CHECK(!full.ok());
    struct stat st {};
    CHECK(stat("/dev/full", &st) == 0 && S_ISCHR(st.st_mode));  // the device is still a device
    destroy_canvas(c);
}

// ---- PGM / PPM reading ---------------------------------------------------------------------

namespace {

std::string temp_path(const std::string &name) {
    return "/tmp/tiny3d_canvas_test_" + std::to_string(getpid()) + "_" + name;
}

void write_bytes(const std::string &path, const std::string &bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
}

// Files in /tmp whose name starts with `prefix` (to check that failed saves leave none).
int files_starting_with(const std::string &prefix) {
    int n = 0;
    FILE *p = popen(("ls /tmp 2>/dev/null | grep -c '^" + prefix + "'").c_str(), "r");
    if (p) {
        if (fscanf(p, "%d", &n) != 1) n = -1;
        pclose(p);
    }
    return n;
}

}  // namespace

TEST(pgm_round_trip_p5_and_p2_odd_sizes) {
    const int sizes[][2] = {{1, 1}, {7, 5}, {13, 3}, {3, 17}};
    for (auto sz : sizes) {
        canvas_t *c = create_canvas(sz[0], sz[1]);
        for (int i = 0; i < sz[0] * sz[1]; ++i) c->data[i] = float((i * 37) % 256) / 255.0f;
        for (auto enc : {tiny3d::pgm_encoding::binary_p5, tiny3d::pgm_encoding::ascii_p2}) {
            const std::string path = temp_path("rt.pgm");
            CHECK(tiny3d::save_pgm(*c, path, enc).ok());
            auto back = tiny3d::load_pgm(path);
            CHECK_MSG(back.ok(), back.message());
            if (back.ok()) {
                CHECK_EQ((*back)->width, sz[0]);
                CHECK_EQ((*back)->height, sz[1]);
                double worst = 0;
                for (int i = 0; i < sz[0] * sz[1]; ++i) worst = std::max(worst, double(std::fabs((*back)->data[i] - c->data[i])));
                CHECK_NEAR(worst, 0.0, 1e-6);  // k/255 survives the 8-bit round trip
            }
            std::remove(path.c_str());
        }
        destroy_canvas(c);
    }
}

TEST(pgm_reader_comments_maxval_16bit_and_colour) {
    const std::string path = temp_path("read.pnm");
    write_bytes(path, "P2\n# a comment\n3 # width then height\n1\n# maxval next\n10\n0 5\n10\n");
    auto a = tiny3d::load_pgm(path);
    CHECK_MSG(a.ok(), a.message());
    if (a.ok()) {
        CHECK_NEAR((*a)->data[1], 0.5, 1e-7);
        CHECK_NEAR((*a)->data[2], 1.0, 1e-7);
    }
    // 16-bit binary: big-endian samples.
    write_bytes(path, std::string("P5\n2 1\n65535\n") + char(0x80) + char(0x00) + char(0xff) + char(0xff));
    auto b = tiny3d::load_pgm(path);
    CHECK_MSG(b.ok(), b.message());
    if (b.ok()) {
        CHECK_NEAR((*b)->data[0], 32768.0 / 65535.0, 1e-7);
        CHECK_NEAR((*b)->data[1], 1.0, 1e-7);
    }
    // Two bytes per sample from maxval 256 on (Netpbm: maxval > 255), 1 byte up to 255.
    write_bytes(path, std::string("P5\n2 1\n256\n") + char(0x01) + char(0x00) + char(0x00) + char(0x80));
    auto wide = tiny3d::load_pgm(path);
    CHECK_MSG(wide.ok(), wide.message());
    if (wide.ok()) {
        CHECK_NEAR((*wide)->data[0], 1.0, 1e-7);
        CHECK_NEAR((*wide)->data[1], 0.5, 1e-7);
    }
    write_bytes(path, std::string("P5\n2 1\n255\n") + char(0xff) + char(0x33));
    auto narrow = tiny3d::load_pgm(path);
    CHECK_MSG(narrow.ok(), narrow.message());
    if (narrow.ok()) CHECK_NEAR((*narrow)->data[1], 0.2, 1e-7);
    // Colour to grey by Rec. 709 luminance: pure green is 0.7152.
    write_bytes(path, std::string("P6 1 1 255\n") + char(0) + char(255) + char(0));
    auto c = tiny3d::load_pgm(path);
    CHECK_MSG(c.ok(), c.message());
    if (c.ok()) CHECK_NEAR((*c)->data[0], 0.7152, 1e-6);
    write_bytes(path, "P3\n1 1\n100\n100 0 100\n");
    auto d = tiny3d::load_pgm(path);
    if (d.ok()) CHECK_NEAR((*d)->data[0], 0.2126 + 0.0722, 1e-6);
    CHECK(d.ok());
    std::remove(path.c_str());
}

TEST(ppm_write_round_trip_and_errors) {
    canvas_t *c = create_canvas(5, 3);
    for (int i = 0; i < 15; ++i) c->data[i] = float(i * 17) / 255.0f;
    for (auto enc : {tiny3d::ppm_encoding::binary_p6, tiny3d::ppm_encoding::ascii_p3}) {
        const std::string path = temp_path("rt.ppm");
        CHECK(tiny3d::save_ppm(*c, path, enc).ok());
        auto back = tiny3d::load_pgm(path);  // R = G = B: luminance weights sum to 1
        CHECK_MSG(back.ok(), back.message());
        if (back.ok())
            for (int i = 0; i < 15; ++i) CHECK_NEAR((*back)->data[i], c->data[i], 1e-6);
        std::remove(path.c_str());
    }
    CHECK(!tiny3d::save_ppm(*c, "/nonexistent_dir_tiny3d/x.ppm").ok());
    CHECK(!tiny3d::save_ppm(*c, "/dev/full").ok());
    destroy_canvas(c);
}

TEST(pgm_reader_errors_name_file_and_place) {
    const std::string path = temp_path("bad.pgm");
    struct bad_case {
        std::string bytes, where;  // expected fragment of the message
    };
    const bad_case cases[] = {
        {"", ":1: not a PGM"},
        {"P7\n1 1\n255\n", ":1: not a PGM"},
        {"P5\n4 4\n255\n" + std::string(10, 'x'), ": byte 11: truncated"},    // 16 bytes needed
        {"P5\n2 2\n65535\n" + std::string(6, 'x'), ": byte 13: truncated"},  // 2 bytes per sample
        {"P2\n3 2\n255\n1 2 3 4\n", ":3: truncated"},  // too short to hold 6 samples
        {"P2\n2 2\n255\n1 2 3 x\n", ":4: expected a sample"},
        {"P2\n2 1\n255\n1 300\n", ":4: sample 300 exceeds maxval"},
        {"P5\n1 1\n100\n" + std::string(1, char(200)), ": byte 11: sample 200 exceeds"},
        {"P5\n1 1\n100\n" + std::string(1, char(101)), ": byte 11: sample 101 exceeds"},  // maxval + 1
        {"P5\n1 1\n1000\n" + std::string(1, char(0x03)) + char(0xe9), ": byte 12: sample 1001 exceeds"},
        {"P2\n2 2\n", ":3: unexpected end of file: expected maxval"},
        {"P2\n2 -2\n255\n", ":2: expected height"},
        {"P2\n2x 2\n255\n", ":2: malformed width"},
        {"P2\n2 2\n0\n", ":3: maxval must be 1..65535"},
        {"P5\n2 2\n70000\n", ":3: maxval must be 1..65535"},
        {"P5\n100000 100000\n255\n", "exceeds the limit"},        // oversized, before allocating
        {"P5\n16000 16000\n255\n\n", ": byte 19: truncated"},  // claims 256 MB, has 1 byte
        {"P5\n1 1\n255", ":3: expected one whitespace byte"},
        {"P2\n0 3\n255\n", "must be positive"},
        {"P2\n99999999999 1\n255\n", ":2: width is too large"},
    };
    for (const bad_case &b : cases) {
        write_bytes(path, b.bytes);
        auto r = tiny3d::load_pgm(path);
        CHECK(!r.ok());
        if (!r.ok()) {
            CHECK_MSG(r.message().find(path) == 0, r.message());
            CHECK_MSG(r.message().find(b.where) != std::string::npos, r.message() + "  (wanted '" + b.where + "')");
        }
    }
    std::remove(path.c_str());
    auto missing = tiny3d::load_pgm("/nonexistent_dir_tiny3d/none.pgm");
    CHECK(!missing.ok() && missing.message().find("cannot open") != std::string::npos);
    auto folder = tiny3d::load_pgm("/tmp");
    CHECK(!folder.ok());
}

TEST(failed_saves_leave_no_file) {
    canvas_t *c = create_canvas(3, 3);
    const std::string prefix = "tiny3d_canvas_test_" + std::to_string(getpid()) + "_folder";
    const std::string folder = "/tmp/" + prefix;
    CHECK(mkdir(folder.c_str(), 0755) == 0);
    CHECK(!tiny3d::save_pgm(*c, folder).ok());  // the target is a folder
    CHECK(!tiny3d::save_ppm(*c, folder).ok());
    CHECK(!tiny3d::save_pgm(*c, folder + "/missing/x.pgm").ok());
    CHECK_EQ(files_starting_with(prefix), 1);  // just the folder, no temporaries
    FILE *p = popen(("ls -A " + folder + " | wc -l").c_str(), "r");
    int inside = -1;
    if (p) {
        if (fscanf(p, "%d", &inside) != 1) inside = -1;
        pclose(p);
    }
    CHECK_EQ(inside, 0);
    rmdir(folder.c_str());
    destroy_canvas(c);
}
