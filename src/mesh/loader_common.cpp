// loader_common.cpp — number parsing, text checks, warnings and file dispatch shared by
// the loaders.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <new>

#include "canvas.h"  // read_file_bytes: the library's one file reader
#include "loader_util.h"
#include "mesh.h"

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

constexpr std::string_view utf8_bom = "\xEF\xBB\xBF";

// 1-based line of byte `offset` (LF, CRLF and CR alone each end a line).
long line_of(std::string_view text, std::size_t offset) {
    line_splitter lines(text);
    std::string_view line;
    while (lines.next(line) && lines.offset() <= offset) {
    }
    return lines.line_number();
}

}  // namespace

std::string count_of(std::uint64_t n, const char *singular, const char *plural) {
    return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

bool parse_finite_float(std::string_view token, float &out) {
    return parse_whole(token, out) && std::isfinite(out);
}
bool parse_finite_double(std::string_view token, double &out) {
    return parse_whole(token, out) && std::isfinite(out);
}
bool parse_any_double(std::string_view token, double &out) { return parse_whole(token, out); }
bool parse_int64(std::string_view token, long long &out) { return parse_whole(token, out); }

std::string quote(std::string_view token) {
    constexpr std::size_t max_shown = 32;
    std::string s = "'";
    for (char c : token.substr(0, max_shown)) s += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    if (token.size() > max_shown) s += "...";
    return s + "'";
}

std::string_view skip_utf8_bom(std::string_view text) {
    return text.substr(0, utf8_bom.size()) == utf8_bom ? text.substr(utf8_bom.size()) : text;
}

status check_text(std::string_view text, const std::string &name, const char *what) {
    // UTF-16: a byte-order mark (FF FE / FE FF), or ASCII text with every other byte 0.
    const bool bom16 = text.size() >= 2 && ((text[0] == '\xFF' && text[1] == '\xFE') || (text[0] == '\xFE' && text[1] == '\xFF'));
    const bool zero_pairs = text.size() >= 2 && ((text[0] == '\0') != (text[1] == '\0'));
    if (bom16 || zero_pairs) return at_line(name, 1, std::string("UTF-16 text: ") + what + " must be UTF-8 (or ASCII); save it as UTF-8");
    if (const void *nul = std::memchr(text.data(), '\0', text.size()))
        return at_line(name, line_of(text, std::size_t(static_cast<const char *>(nul) - text.data())),
                       std::string("NUL byte in text: ") + what + " is text (is this a binary file?)");
    return {};
}

status diagnostics::warn(error w, std::string_view kind) {
    if (options_.strict) return w;
    group *g = nullptr;
    if (!kind.empty()) {
        const auto [it, fresh] = groups_.try_emplace(std::string(kind), group{SIZE_MAX, 0});
        if (!fresh) {
            ++it->second.repeats;
            return {};
        }
        g = &it->second;
    }
    if (warnings_.size() >= options_.max_warnings) {
        ++not_listed_;
        return {};
    }
    if (g) g->listed = warnings_.size();
    warnings_.push_back(std::move(w));
    return {};
}

loaded_mesh diagnostics::finish(mesh &&m) {
    for (const auto &[kind, g] : groups_)
        if (g.listed != SIZE_MAX && g.repeats > 0)
            warnings_[g.listed].reason += " (" + std::to_string(g.repeats) + " more like it)";
    loaded_mesh out{std::move(m), std::move(warnings_), not_listed_};
    return out;
}

}  // namespace loader

namespace {

// The mesh of a load, warnings dropped.
result<mesh> geometry_of(result<loaded_mesh> &&r) {
    if (!r) return r.err();
    return std::move(r.value().geometry);
}

// Checks a text file's first bytes before the rest is read.
status probe_obj(std::string_view first_bytes, const std::string &path) {
    return loader::check_text(first_bytes, path, "an OBJ file");
}
status probe_ply(std::string_view first_bytes, const std::string &path) {
    if (first_bytes.substr(0, 3) == "ply" && (first_bytes.size() == 3 || loader::is_space(first_bytes[3]))) return {};
    return loader::at_line(path, 1, "not a PLY file (its first line must be 'ply')");
}


// The mesh of `bytes` parsed by `parse`; memory that runs out (std::bad_alloc: the
// vertices, corners and faces the input asks for) is an error naming the input and its size.
template <class Parse>
result<loaded_mesh> parse_guarded(Parse parse, std::string_view bytes, const std::string &name,
                                  const load_options &options) {
    try {
        return parse(bytes, name, options);
    } catch (const std::bad_alloc &) {
        return error{name, 0, -1,
                     "out of memory holding the mesh of these " + std::to_string(bytes.size()) + " bytes"};
    }
}

// What a file of unknown name holds: PLY if its first line is "ply", OBJ if its first
// statement (after comments and blank lines) is one of OBJ's.
mesh_format detect_format(std::string_view bytes) {
    if (probe_ply(bytes.substr(0, 4), "").ok()) return mesh_format::ply;
    loader::line_splitter lines(loader::skip_utf8_bom(bytes.substr(0, read_file_probe_bytes)));
    for (std::string_view raw; lines.next(raw);) {
        raw = raw.substr(0, raw.find('#'));
        const std::size_t start = raw.find_first_not_of(" \t\r");
        if (start == std::string_view::npos) continue;
        const std::string_view word = raw.substr(start, raw.find_first_of(" \t\r", start) - start);
        for (const char *keyword : {"v", "vt", "vn", "vp", "f", "l", "p", "o", "g", "s", "mtllib", "usemtl"})
            if (word == keyword) return mesh_format::obj;
        break;
    }
    return mesh_format::by_name;  // (unknown)
}

}  // namespace

result<loaded_mesh> parse_obj(std::string_view text, const std::string &name, const load_options &options) {
    return parse_guarded(loader::parse_obj_text, text, name, options);
}
result<loaded_mesh> parse_ply(std::string_view bytes, const std::string &name, const load_options &options) {
    return parse_guarded(loader::parse_ply_bytes, bytes, name, options);
}
result<mesh> parse_obj(std::string_view text, const std::string &name) { return geometry_of(parse_obj(text, name, {})); }
result<mesh> parse_ply(std::string_view bytes, const std::string &name) { return geometry_of(parse_ply(bytes, name, {})); }

result<loaded_mesh> parse_mesh(std::string_view bytes, const std::string &name, const load_options &options) {
    const mesh_format format = options.format == mesh_format::by_name ? detect_format(bytes) : options.format;
    if (format == mesh_format::obj) return parse_obj(bytes, name, options);
    if (format == mesh_format::ply) return parse_ply(bytes, name, options);
    return error{name, 1, -1, "unknown mesh format: neither a PLY header nor an OBJ statement at the start"};
}

result<loaded_mesh> load_obj(const std::string &path, const load_options &options) {
    result<std::string> bytes = read_file_bytes(path, max_read_file_bytes, probe_obj);
    if (!bytes) return bytes.err();
    return parse_obj(bytes.value(), path, options);
}
result<mesh> load_obj(const std::string &path) { return geometry_of(load_obj(path, {})); }

result<loaded_mesh> load_ply(const std::string &path, const load_options &options) {
    result<std::string> bytes = read_file_bytes(path, max_read_file_bytes, probe_ply);
    if (!bytes) return bytes.err();
    return parse_ply(bytes.value(), path, options);
}
result<mesh> load_ply(const std::string &path) { return geometry_of(load_ply(path, {})); }

result<loaded_mesh> load_mesh(const std::string &path, const load_options &options) {
    std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : std::string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (options.format == mesh_format::obj || (options.format == mesh_format::by_name && ext == ".obj"))
        return load_obj(path, options);
    if (options.format == mesh_format::ply || (options.format == mesh_format::by_name && ext == ".ply"))
        return load_ply(path, options);
    // Any other name (a pipe, /dev/stdin, /proc/...): the content says which.
    result<std::string> bytes = read_file_bytes(path, max_read_file_bytes);
    if (!bytes) return bytes.err();
    if (detect_format(*bytes) == mesh_format::by_name)
        return error{path, 0, -1,
                     "unknown mesh format: expected a file ending in .obj or .ply, or one starting with a PLY "
                     "header or an OBJ statement"};
    return parse_mesh(*bytes, path, options);
}
result<mesh> load_mesh(const std::string &path) { return geometry_of(load_mesh(path, {})); }

}  // namespace tiny3d
