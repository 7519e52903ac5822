// libFuzzer target: tiny3d::load_pgm (P2, P3, P5, P6) on arbitrary bytes, given to the
// path-based reader through an in-memory file (fuzz_require_file). Checks: fuzz_checks.h.
#include <cstddef>
#include <cstdint>

#include "fuzz_checks.h"
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    fuzz_require_file("fuzz_pnm", data, size, fuzz_checks::check_pnm_file);
    return 0;
}
