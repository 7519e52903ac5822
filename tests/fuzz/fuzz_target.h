// tests/fuzz/fuzz_target.h — the common body of the libFuzzer targets: run a check from
// fuzz_checks.h on the input and stop (with the reason on stderr) when it is violated, so
// libFuzzer records the input as a crash.
#ifndef TINY3D_FUZZ_TARGET_H
#define TINY3D_FUZZ_TARGET_H

#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

inline void fuzz_require(const std::string &violation) {
    if (violation.empty()) return;
    std::fprintf(stderr, "fuzz check failed: %s\n", violation.c_str());
    std::abort();
}

// For readers that take a path: the bytes go into an anonymous in-memory file (memfd)
// named `name`, and check(path) runs on /proc/self/fd/N: no disk traffic, nothing left
// behind. Out of descriptors (or a short write): nothing is tested.
template <class Check>
void fuzz_require_file(const char *name, const std::uint8_t *data, std::size_t size, Check check) {
    const int fd = ::memfd_create(name, MFD_CLOEXEC);
    if (fd < 0) return;
    std::size_t done = 0;
    while (done < size) {
        const ssize_t w = ::write(fd, data + done, size - done);
        if (w <= 0) break;
        done += std::size_t(w);
    }
    if (done == size) fuzz_require(check("/proc/self/fd/" + std::to_string(fd)));
    ::close(fd);
}

#endif
