// alloc_failure_test.cpp — memory that runs out at every possible moment of a load, a
// render and a save. This program replaces the global operator new (every form,
// tests/alloc_tracker.h) with one that counts allocations and, when armed with N, fails
// the N-th (std::bad_alloc, or null for the nothrow forms). A reference run counts the allocations a small job makes; then
// the job runs again once for every N from 1 to that count. Each run must end in an error
// saying what ran out, or (where the library could do without the memory) in exactly the
// reference image; never an exception out of the library, never an abort, and no leak
// (the sanitized build of `make test` runs LeakSanitizer at exit), nothing left in the
// output folder but a complete frame.
//
// The job: load an OBJ file (a quad and a triangle, with texture coordinates), make its
// raster mesh, make a canvas, draw it with 4 samples per pixel (then again with 1) on a
// context of two threads, check the frame's status, save it as PGM. Each run has a fresh render context
// (so that the frame's buffers grow in it), made before arming: its constructor allocates
// its own fixed-size state (driven by no input) and threads; worker_pool's fall-back to
// fewer threads is tested by hostile_places_test.
#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>

#include "alloc_tracker.h"
#include "harness.h"
#include "program_runner.h"
#include "tiny3d.h"

namespace failing_alloc {

void arm(long n) { alloc_tracker::fail_allocation(n < 0 ? 0 : std::size_t(n)); }
void disarm() { alloc_tracker::failing_allocation().store(0); }
long count() { return long(alloc_tracker::allocations()); }

}  // namespace failing_alloc

namespace {

namespace fs = std::filesystem;

const char *kMesh =
    "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nv 0 0 0.5\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "f 1/1 2/2 3/3 4/4\nf 1/1 5/3 2/2\n";

struct outcome {
    bool ok = false;
    std::string message;  // the error, if any
};

// The job (see the top of the file); `ctx` made beforehand.
outcome job(tiny3d::render_context &ctx, tiny3d::sample_count samples, const std::string &mesh_path,
            const std::string &frame_path) {
    auto loaded = tiny3d::load_mesh(mesh_path, tiny3d::load_options{});
    if (!loaded) return {false, loaded.message()};
    auto shape = tiny3d::make_raster_mesh(loaded->geometry, {});
    if (!shape) return {false, shape.message()};
    auto canvas = tiny3d::make_canvas(40, 30);
    if (!canvas) return {false, canvas.message()};
    tiny3d::draw_params params;
    params.view_projection = mat4_multiply(tiny3d::mat4_perspective(1.0f, 4.0f / 3.0f, 0.5f, 10.0f),
                                           tiny3d::mat4_look_at({0.3f, 0.4f, 3.0f}, {0, 0, 0}, {0, 1, 0}));
    params.shade = tiny3d::shading::flat;
    params.cull = tiny3d::cull_mode::none;
    if (tiny3d::status s = ctx.begin_frame(**canvas, 0.1f, samples); !s) return {false, s.message()};
    ctx.draw(*shape, params);
    ctx.end_frame();
    if (tiny3d::status s = ctx.frame_status(); !s) return {false, s.message()};
    if (tiny3d::status s = tiny3d::save_pgm(**canvas, frame_path); !s) return {false, s.message()};
    return {true, ""};
}

}  // namespace

namespace {

void fail_each_allocation(tiny3d::sample_count samples) {
    program_runner::temp_dir dir;
    const std::string mesh_path = (dir.path / "mesh.obj").string();
    {
        std::FILE *f = std::fopen(mesh_path.c_str(), "wb");
        std::fputs(kMesh, f);
        std::fclose(f);
    }
    const fs::path out = dir.path / "out";
    fs::create_directory(out);
    const std::string frame = (out / "frame.pgm").string();
    // A fresh context per run (made before arming), so that each run grows its buffers.
    auto reference_ctx = std::make_unique<tiny3d::render_context>(2);
    failing_alloc::arm(-1);
    const outcome reference = job(*reference_ctx, samples, mesh_path, frame);
    const long total = failing_alloc::count();
    failing_alloc::disarm();
    CHECK_MSG(reference.ok, reference.message);
    const std::string expected = program_runner::file_bytes(frame);
    CHECK(program_runner::parse_pgm(expected).width == 40);
    CHECK(total > 20);  // (the job allocates: else this test tests nothing)

    long errors = 0;
    for (long n = 1; n <= total; ++n) {
        fs::remove(frame);
        outcome r;
        bool escaped = false;
        auto ctx = std::make_unique<tiny3d::render_context>(2);
        failing_alloc::arm(n);
        try {
            r = job(*ctx, samples, mesh_path, frame);
        } catch (...) {
            escaped = true;
        }
        failing_alloc::disarm();
        const std::string at = "allocation " + std::to_string(n) + " of " + std::to_string(total) + ": ";
        CHECK_MSG(!escaped, at + "an exception left the library");
        const auto files = program_runner::files_in(out);
        if (r.ok) {
            // The library did without that memory (e.g. a reservation): the same frame.
            CHECK_MSG(files.size() == 1 && program_runner::file_bytes(frame) == expected, at + "a different frame");
        } else if (!escaped) {
            ++errors;
            CHECK_MSG(r.message.find("out of memory") != std::string::npos, at + r.message);
            CHECK_MSG(files.empty(), at + "a file was left in the output folder");
        }
    }
    CHECK(errors > total / 2);  // most allocations are needed: their failure is an error
}

}  // namespace

TEST(every_allocation_of_a_load_render_and_save_can_fail_without_an_abort) {
    fail_each_allocation(tiny3d::sample_count::x4);  // (multisampled: drawn at end_frame)
    fail_each_allocation(tiny3d::sample_count::x1);
}
