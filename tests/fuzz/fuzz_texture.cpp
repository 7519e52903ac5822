// libFuzzer target: the texture path, tiny3d::load_texture_pgm (the PNM reader, then the
// mipmap builder) on arbitrary bytes, and every lookup on what it returns. The reader takes
// a path, so the bytes go into an anonymous in-memory file (memfd) opened through
// /proc/self/fd/N: no disk traffic, nothing left behind. Checks: fuzz_checks.h.
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_checks.h"
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    const int fd = ::memfd_create("fuzz_texture", MFD_CLOEXEC);
    if (fd < 0) return 0;  // out of descriptors: nothing to test
    std::size_t done = 0;
    while (done < size) {
        const ssize_t w = ::write(fd, data + done, size - done);
        if (w <= 0) break;
        done += std::size_t(w);
    }
    if (done == size) fuzz_require(fuzz_checks::check_texture_file("/proc/self/fd/" + std::to_string(fd)));
    ::close(fd);
    return 0;
}
