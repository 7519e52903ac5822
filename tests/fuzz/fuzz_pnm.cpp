// libFuzzer target: tiny3d::load_pgm (P2, P3, P5, P6) on arbitrary bytes. The reader takes
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
    const int fd = ::memfd_create("fuzz_pnm", MFD_CLOEXEC);
    if (fd < 0) return 0;  // out of descriptors: nothing to test
    std::size_t done = 0;
    while (done < size) {
        const ssize_t w = ::write(fd, data + done, size - done);
        if (w <= 0) break;
        done += std::size_t(w);
    }
    if (done == size) fuzz_require(fuzz_checks::check_pnm_file("/proc/self/fd/" + std::to_string(fd)));
    ::close(fd);
    return 0;
}
