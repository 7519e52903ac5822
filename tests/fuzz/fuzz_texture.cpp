// libFuzzer target: the texture path, tiny3d::load_texture_pgm (the PNM reader, then the
// mipmap builder) on arbitrary bytes, and every lookup on what it returns; the bytes reach
// the path-based reader through an in-memory file (fuzz_require_file). Checks: fuzz_checks.h.
#include <cstddef>
#include <cstdint>

#include "fuzz_checks.h"
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    fuzz_require_file("fuzz_texture", data, size, fuzz_checks::check_texture_file);
    return 0;
}
