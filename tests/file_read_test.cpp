// file_read_test.cpp — read_file_bytes, the one reader of meshes, images and textures:
// non-regular files refused before reading (a FIFO must not hang the test), sizes checked
// with fstat before any allocation, the format probe before the rest is read.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <string>

#include "alloc_tracker.h"
#include "harness.h"
#include "temp_folder.h"
#include "tiny3d.h"

using namespace tiny3d;

namespace {

using alloc_tracker::largest_allocation_during;

// A file of `size` bytes of zeros without writing them (sparse where the file system can).
std::string sparse_file(temp_folder &tmp, const std::string &leaf, off_t size) {
    const std::string p = tmp.named(leaf);
    const int fd = ::open(p.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd >= 0) {
        CHECK(::ftruncate(fd, size) == 0);
        ::close(fd);
    }
    return p;
}

bool says(const error &e, const std::string &path, const std::string &words) {
    return e.file == path && e.reason.find(words) != std::string::npos;
}

}  // namespace

TEST(regular_files_are_read_whole) {
    temp_folder tmp;
    const std::string bytes = std::string("abc\0def", 7) + std::string(100000, 'x');
    const std::string p = tmp.file("whole.bin", bytes);
    const result<std::string> r = read_file_bytes(p);
    CHECK(r.ok() && *r == bytes);
    const result<std::string> empty = read_file_bytes(tmp.file("empty.bin", ""));
    CHECK(empty.ok() && empty->empty());
    const result<std::string> missing = read_file_bytes(tmp.path + "/none");
    CHECK(!missing.ok() && says(missing.err(), tmp.path + "/none", "cannot open: No such file"));
}

TEST(fifos_without_a_writer_devices_and_directories_are_refused_at_once) {
    temp_folder tmp;
    const std::string fifo = tmp.named("pipe.obj");
    CHECK(::mkfifo(fifo.c_str(), 0600) == 0);
    // No writer: a blocking open would wait forever; these return at once.
    const result<mesh> a = load_obj(fifo);
    CHECK(!a.ok() && says(a.err(), fifo, "a FIFO (named pipe) that gave no bytes (no writer had it open"));
    const result<mesh> b = load_mesh(fifo);
    CHECK(!b.ok() && says(b.err(), fifo, "FIFO"));
    const std::string pgm = tmp.named("pipe.pgm");
    CHECK(::mkfifo(pgm.c_str(), 0600) == 0);
    const result<canvas_ptr> c = load_pgm(pgm);
    CHECK(!c.ok() && says(c.err(), pgm, "FIFO"));
    const result<mesh> dir = load_ply(tmp.path);
    CHECK(!dir.ok() && says(dir.err(), tmp.path, "a directory, expected a regular file"));
    // /dev/zero, directly and through a symlink named like a mesh.
    const result<std::string> zero = read_file_bytes("/dev/zero");
    CHECK(!zero.ok() && says(zero.err(), "/dev/zero", "a character device"));
    const std::string link = tmp.named("zero.ply");
    CHECK(::symlink("/dev/zero", link.c_str()) == 0);
    std::size_t biggest = largest_allocation_during([&] {
        const result<mesh> z = load_mesh(link);
        CHECK(!z.ok() && says(z.err(), link, "character device"));
    });
    CHECK(biggest < 4096);
}

TEST(oversized_files_fail_before_reading) {
    temp_folder tmp;
    const std::string small = tmp.file("ten.bin", "0123456789");
    const result<std::string> r = read_file_bytes(small, 9);
    CHECK(!r.ok() && says(r.err(), small, "file is 10 bytes, more than the 9-byte limit"));
    CHECK(read_file_bytes(small, 10).ok());
    // 3 GB of nothing: an error at once, no allocation near its size.
    const std::string huge = sparse_file(tmp, "huge.obj", off_t(3) << 30);
    const std::size_t biggest = largest_allocation_during([&] {
        const result<mesh> m = load_obj(huge);
        CHECK(!m.ok() && says(m.err(), huge, "file is 3221225472 bytes, more than the 2147483648-byte limit"));
    });
    CHECK(biggest < 4096);
    // An image beyond the largest canvas's file.
    const std::string big_pgm = sparse_file(tmp, "big.pgm", off_t(3) << 30);
    const result<canvas_ptr> img = load_pgm(big_pgm);
    CHECK(!img.ok() && says(img.err(), big_pgm, "-byte limit"));
}

TEST(the_format_probe_judges_the_first_bytes_first) {
    temp_folder tmp;
    // 64 MB of zeros (sparse): the text loader stops after the first 64 KiB.
    const off_t size = off_t(64) << 20;
    const std::string zeros_obj = sparse_file(tmp, "zeros.obj", size);
    const std::string zeros_ply = sparse_file(tmp, "zeros.ply", size);
    const std::string zeros_pgm = sparse_file(tmp, "zeros.pgm", size);
    const std::size_t biggest = largest_allocation_during([&] {
        const result<mesh> o = load_obj(zeros_obj);
        CHECK(!o.ok() && o.err().line == 1 && says(o.err(), zeros_obj, "NUL byte in text"));
        const result<mesh> p = load_ply(zeros_ply);
        CHECK(!p.ok() && says(p.err(), zeros_ply, "not a PLY file"));
        const result<canvas_ptr> g = load_pgm(zeros_pgm);
        CHECK(!g.ok() && says(g.err(), zeros_pgm, "not a PGM/PPM file"));
    });
    CHECK(biggest <= read_file_probe_bytes + 4096);
    // A probe that accepts lets the whole file through.
    const std::string obj = tmp.file("ok.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    CHECK(load_obj(obj).ok());
    const std::string ply = tmp.file("ok.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                               "property float y\nproperty float z\nend_header\n1 2 3\n");
    CHECK(load_ply(ply).ok());
}
