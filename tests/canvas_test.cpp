// canvas_test.cpp — canvas allocation, the splat convention, the faithful line, PGM save.
#include "harness.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "canvas.h"

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

TEST(splat_at_pixel_centre_hits_one_pixel) {
    canvas_t *c = create_canvas(4, 4);
    set_pixel_f(c, 1.5f, 2.5f, 0.75f);
    double sum = 0;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) sum += c->pixels[y][x];
    CHECK_NEAR(c->pixels[2][1], 0.75, 0.0);
    CHECK_NEAR(sum, 0.75, 1e-7);
    destroy_canvas(c);
}

TEST(splat_weights_are_bilinear_and_sum_to_intensity) {
    canvas_t *c = create_canvas(4, 4);
    set_pixel_f(c, 1.75f, 1.25f, 0.5f);  // fx = 0.25 right of centre (1.5), fy = 0.25 above (1.5)
    // sx = 1.25 -> x0 = 1, dx = .25 ; sy = 0.75 -> y0 = 0, dy = .75
    CHECK_NEAR(c->pixels[0][1], 0.5 * 0.75 * 0.25, 1e-7);
    CHECK_NEAR(c->pixels[0][2], 0.5 * 0.25 * 0.25, 1e-7);
    CHECK_NEAR(c->pixels[1][1], 0.5 * 0.75 * 0.75, 1e-7);
    CHECK_NEAR(c->pixels[1][2], 0.5 * 0.25 * 0.75, 1e-7);
    destroy_canvas(c);
}

TEST(splat_clamps_to_one) {
    canvas_t *c = create_canvas(2, 2);
    for (int i = 0; i < 5; ++i) set_pixel_f(c, 0.5f, 0.5f, 0.4f);
    CHECK_EQ(c->pixels[0][0], 1.0f);
    set_pixel_f(c, 1e30f, 0.5f, 1.0f);    // far off: ignored, no UB
    set_pixel_f(c, 0.5f, NAN, 1.0f);      // NaN: ignored
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
