// loader_common.cpp — file reading, number parsing and dispatch shared by the loaders.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "loader_util.h"
#include "loaders.h"

namespace tiny3d {

namespace loader {

namespace {

// from_chars does not take a leading '+'; a lone sign is still rejected below.
std::string_view strip_plus(std::string_view t) {
    return (t.size() > 1 && t[0] == '+' && t[1] != '-' && t[1] != '+') ? t.substr(1) : t;
}

template <class T>
bool parse_whole(std::string_view token, T &out) {
    token = strip_plus(token);
    if (token.empty()) return false;
    const char *first = token.data(), *last = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(first, last, out);
    return ec == std::errc() && ptr == last;
}

}  // namespace

bool parse_finite_float(std::string_view token, float &out) {
    return parse_whole(token, out) && std::isfinite(out);
}
bool parse_finite_double(std::string_view token, double &out) {
    return parse_whole(token, out) && std::isfinite(out);
}
bool parse_int64(std::string_view token, long long &out) { return parse_whole(token, out); }

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

std::string_view next_token(std::string_view line, std::size_t &pos) {
    while (pos < line.size() && is_space(line[pos])) ++pos;
    const std::size_t start = pos;
    while (pos < line.size() && !is_space(line[pos])) ++pos;
    return line.substr(start, pos - start);
}

std::string quote(std::string_view token) {
    constexpr std::size_t max_shown = 32;
    std::string s = "'";
    for (char c : token.substr(0, max_shown)) s += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    if (token.size() > max_shown) s += "...";
    return s + "'";
}

}  // namespace loader

result<std::string> read_file_bytes(const std::string &path) {
    constexpr long long max_file_bytes = 1LL << 31;
    auto fail = [&](const std::string &why) { return error{path, 0, -1, why}; };
    std::unique_ptr<std::FILE, int (*)(std::FILE *)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!f) return fail(std::string("cannot open: ") + std::strerror(errno));
    std::string bytes;
    char chunk[1 << 16];
    for (;;) {
        const std::size_t n = std::fread(chunk, 1, sizeof chunk, f.get());
        if (n > 0) {
            if (static_cast<long long>(bytes.size() + n) > max_file_bytes) return fail("file larger than 2 GiB");
            bytes.append(chunk, n);
        }
        if (n < sizeof chunk) break;
    }
    if (std::ferror(f.get())) return fail(std::string("read error: ") + std::strerror(errno));
    return bytes;
}

result<mesh> load_obj(const std::string &path) {
    result<std::string> bytes = read_file_bytes(path);
    if (!bytes) return bytes.err();
    return parse_obj(bytes.value(), path);
}

result<mesh> load_ply(const std::string &path) {
    result<std::string> bytes = read_file_bytes(path);
    if (!bytes) return bytes.err();
    return parse_ply(bytes.value(), path);
}

result<mesh> load_mesh(const std::string &path) {
    std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : std::string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".obj") return load_obj(path);
    if (ext == ".ply") return load_ply(path);
    return error{path, 0, -1, "unknown mesh format (expected a .obj or .ply file)"};
}

}  // namespace tiny3d
