// file_read.cpp — read_file_bytes: the library's one file reader (see canvas.h).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>

#include "canvas.h"

namespace tiny3d {
namespace {

// What a non-regular file is, for the message.
const char *file_kind(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

// Reads up to n bytes into p, retrying short reads and EINTR; returns the bytes read
// (fewer at the end of the file) or −1 with errno set.
long long read_up_to(int fd, char *p, std::size_t n) {
    std::size_t got = 0;
    while (got < n) {
        const ssize_t r = ::read(fd, p + got, n - got);
        if (r < 0) {
            if (errno == EINTR) continue;
            return -1;
        }
        if (r == 0) break;
        got += std::size_t(r);
    }
    return static_cast<long long>(got);
}

struct fd_closer {
    int fd;
    ~fd_closer() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

result<std::string> read_file_bytes(const std::string &path, std::uint64_t max_bytes, file_probe probe) {
    auto fail = [&](const std::string &why) { return error{path, 0, -1, why}; };
    // O_NONBLOCK: opening a FIFO without a writer would otherwise wait forever.
    const fd_closer f{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
    if (f.fd < 0) return fail(std::string("cannot open: ") + std::strerror(errno));
    struct stat st {};
    if (::fstat(f.fd, &st) != 0) return fail(std::string("cannot read: ") + std::strerror(errno));
    if (!S_ISREG(st.st_mode)) return fail(std::string("cannot read: ") + file_kind(st.st_mode) + ", expected a regular file");
    const std::uint64_t size = static_cast<std::uint64_t>(st.st_size);
    if (size > max_bytes)
        return fail("file is " + std::to_string(size) + " bytes, more than the " + std::to_string(max_bytes) +
                    "-byte limit");
    // The probe's bytes first, so a refused file costs no more than them.
    std::string bytes(probe ? std::min<std::size_t>(std::size_t(size), read_file_probe_bytes) : std::size_t(size), '\0');
    long long got = read_up_to(f.fd, bytes.data(), bytes.size());
    if (got < 0) return fail(std::string("read error: ") + std::strerror(errno));
    if (probe)
        if (status s = probe(std::string_view(bytes.data(), std::size_t(got)), path); !s) return s.err();
    const std::size_t have = std::size_t(got);
    bytes.resize(have == bytes.size() ? std::size_t(size) : have);
    got = read_up_to(f.fd, bytes.data() + have, bytes.size() - have);
    if (got < 0) return fail(std::string("read error: ") + std::strerror(errno));
    bytes.resize(have + std::size_t(got));
    return bytes;
}

}  // namespace tiny3d
