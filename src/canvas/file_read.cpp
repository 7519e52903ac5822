// file_read.cpp — read_file_bytes: the library's one file reader (see canvas.h).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <new>
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
    const bool stream = S_ISFIFO(st.st_mode);
    if (!S_ISREG(st.st_mode) && !stream)
        return fail(std::string("cannot read: ") + file_kind(st.st_mode) + ", expected a regular file or a pipe");
    // A regular file's size is known before anything is allocated; a pipe's is not, and a
    // pseudo-file's (/proc) is given as 0: every file is read to the end of its stream, the
    // limit checked as bytes arrive.
    const std::uint64_t size = stream ? 0 : static_cast<std::uint64_t>(st.st_size);
    if (size > max_bytes)
        return fail("file is " + std::to_string(size) + " bytes, more than the " + std::to_string(max_bytes) +
                    "-byte limit");
    if (stream) {  // blocking reads from here: a pipe's writer may be slower than this reader
        const int flags = ::fcntl(f.fd, F_GETFL);
        if (flags >= 0) (void)::fcntl(f.fd, F_SETFL, flags & ~O_NONBLOCK);
    }
    constexpr std::size_t kChunk = std::size_t(1) << 16;
    std::string bytes;
    std::size_t have = 0;
    bool probed = probe == nullptr;
    std::size_t want = 0;
    try {
        for (;;) {
            // The probe's bytes first, so a refused file costs no more than them; then the size
            // the file said it has; past it (a stream, a pseudo-file, a file that grew) one
            // small read tells whether more comes before anything larger is allocated.
            constexpr std::size_t kPeek = 4096;
            want = !probed      ? std::min<std::size_t>(size > 0 ? std::size_t(size) : kPeek, read_file_probe_bytes)
                   : have < size ? std::size_t(size)
                                 : 0;
            if (want <= have) {
                char peek[kPeek];
                const long long more = read_up_to(f.fd, peek, sizeof peek);
                if (more < 0) return fail(std::string("read error: ") + std::strerror(errno));
                if (more == 0) break;
                if (have + std::size_t(more) > max_bytes)
                    return fail("more than the " + std::to_string(max_bytes) + "-byte limit" +
                                (stream ? " came through the pipe" : " (the file grew while being read)"));
                want = have + std::size_t(more) + std::max(kChunk, have / 2);
                if (bytes.size() < want) bytes.resize(want);
                std::memcpy(bytes.data() + have, peek, std::size_t(more));
                have += std::size_t(more);
            }
            want = std::size_t(std::min<std::uint64_t>(want, max_bytes + 1));
            if (bytes.size() < want) bytes.resize(want);
            const long long got = read_up_to(f.fd, bytes.data() + have, want - have);
            if (got < 0) return fail(std::string("read error: ") + std::strerror(errno));
            have += std::size_t(got);
            if (have > max_bytes)
                return fail("more than the " + std::to_string(max_bytes) + "-byte limit" +
                            (stream ? " came through the pipe" : " (the file grew while being read)"));
            const bool ended = have < want;  // (read_up_to returns short only at the end)
            if (stream && have == 0)
                return fail("cannot read: a FIFO (named pipe) that gave no bytes (no writer had it open, or it sent "
                            "nothing)");
            if (!probed) {  // (this read was the probe's)
                probed = true;
                if (status s = probe(std::string_view(bytes.data(), have), path); !s) return s.err();
            }
            if (ended) break;
        }
    } catch (const std::bad_alloc &) {
        return fail("out of memory: cannot hold " + std::to_string(want) + " bytes of it");
    }
    bytes.resize(have);
    return bytes;
}

}  // namespace tiny3d
