// libFuzzer target: tiny3d::parse_ply (ascii, binary little and big endian) on arbitrary
// bytes (checks: fuzz_checks.h). The seed corpus holds one file of each format.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_checks.h"
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char *>(data), size);
    fuzz_require(fuzz_checks::check_ply(bytes, "fuzz.ply"));
    return 0;
}
