// loader_util.h — private helpers shared by the OBJ and PLY loaders (not installed).
#ifndef TINY3D_LOADER_UTIL_H
#define TINY3D_LOADER_UTIL_H

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "tiny3d_result.h"

namespace tiny3d::loader {

// Largest position / corner count a mesh can hold with 32-bit indices (one value is kept
// free so "count + 1" never wraps).
inline constexpr std::uint64_t max_elements = std::numeric_limits<std::uint32_t>::max() - 1;

inline error at_line(const std::string &file, long line, std::string reason) {
    return error{file, line, -1, std::move(reason)};
}
inline error at_byte(const std::string &file, std::uint64_t offset, std::string reason) {
    return error{file, 0, static_cast<long>(offset), std::move(reason)};
}

// A whole token as a finite float (a leading '+' is accepted; out-of-range values such as
// 1e39 and nan / inf are rejected).
bool parse_finite_float(std::string_view token, float &out);
// A whole token as a finite double.
bool parse_finite_double(std::string_view token, double &out);
// A whole token as a signed 64-bit integer (leading '+' accepted, no overflow).
bool parse_int64(std::string_view token, long long &out);

bool is_space(char c);
// The next whitespace-separated token of `line` starting at `pos` (pos is advanced); empty
// at the end.
std::string_view next_token(std::string_view line, std::size_t &pos);
// "'abc'" shortened to a printable excerpt for messages.
std::string quote(std::string_view token);

}  // namespace tiny3d::loader

#endif
