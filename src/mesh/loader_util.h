// loader_util.h — private helpers shared by the OBJ and PLY loaders (not installed).
#ifndef TINY3D_LOADER_UTIL_H
#define TINY3D_LOADER_UTIL_H

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <unordered_map>

#include "mesh.h"
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

// "1 corner", "3 corners": a count with its noun, singular for one.
std::string count_of(std::uint64_t n, const char *singular, const char *plural);

// A whole token as a finite float (a leading '+' is accepted; out-of-range values such as
// 1e39 and nan / inf are rejected).
bool parse_finite_float(std::string_view token, float &out);
// A whole token as a finite double.
bool parse_finite_double(std::string_view token, double &out);
// A whole token as a double; nan and inf are accepted (for values that are skipped).
bool parse_any_double(std::string_view token, double &out);
// A whole token as a signed 64-bit integer (leading '+' accepted, no overflow).
bool parse_int64(std::string_view token, long long &out);

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }
// The next whitespace-separated token of `line` starting at `pos` (pos is advanced); empty
// at the end.
inline std::string_view next_token(std::string_view line, std::size_t &pos) {
    while (pos < line.size() && is_space(line[pos])) ++pos;
    const std::size_t start = pos;
    while (pos < line.size() && !is_space(line[pos])) ++pos;
    return line.substr(start, pos - start);
}
// "'abc'" shortened to a printable excerpt for messages.
std::string quote(std::string_view token);

// Text checks before parsing: a UTF-16 byte-order mark or NUL bytes are errors naming
// the line ("UTF-16 text: save the file as UTF-8"). `what` names the format ("an OBJ file").
status check_text(std::string_view text, const std::string &name, const char *what);

// The parsers behind parse_obj and parse_ply (which turn memory running out into an error).
result<loaded_mesh> parse_obj_text(std::string_view text, const std::string &name, const load_options &options);
result<loaded_mesh> parse_ply_bytes(std::string_view bytes, const std::string &name, const load_options &options);
// The text without a leading UTF-8 byte-order mark.
std::string_view skip_utf8_bom(std::string_view text);

// Splits text into lines ending in LF, CRLF or CR alone (mixed freely); the line end is
// not part of the line. Linear time: the next LF and CR are searched once each (memchr),
// not once per line.
class line_splitter {
public:
    explicit line_splitter(std::string_view text, std::size_t start = 0)
        : t_(text), pos_(start), lf_(find('\n')), cr_(find('\r')) {}
    // The next line, or false at the end of the text. line_number() is then its number.
    bool next(std::string_view &line) {
        if (pos_ >= t_.size()) return false;
        if (lf_ < pos_) lf_ = find('\n');
        if (cr_ < pos_) cr_ = find('\r');
        const std::size_t end = std::min(lf_, cr_);
        line = t_.substr(pos_, end - pos_);
        end_ = end;
        pos_ = std::min(end + 1, t_.size());
        if (end == cr_ && end + 1 == lf_) ++pos_;  // CRLF is one line end
        ++line_;
        return true;
    }
    long line_number() const { return line_; }
    std::size_t offset() const { return pos_; }  // the first byte after the line's end
    // The last line's end as written: "\n", "\r\n", "\r", or empty at the end of the text.
    std::string_view line_end() const { return t_.substr(std::min(end_, t_.size()), pos_ - std::min(end_, t_.size())); }

private:
    std::size_t find(char c) const {
        const void *hit = std::memchr(t_.data() + pos_, c, t_.size() - pos_);
        return hit ? std::size_t(static_cast<const char *>(hit) - t_.data()) : t_.size();
    }
    std::string_view t_;
    std::size_t pos_, lf_, cr_, end_ = 0;
    long line_ = 0;
};

// Collects a load's warnings: lists the first options.max_warnings, counts the rest,
// folds repeats of one kind into the first, and in strict mode turns a warning into the
// error it returns.
class diagnostics {
public:
    diagnostics(const std::string &file, const load_options &options) : file_(file), options_(options) {}

    // Records "file:line: reason". `kind` (if not empty) groups repeats: a warning of a
    // kind seen before is counted into the first one. Strict: returns the warning as an
    // error (the caller stops).
    status warn_line(long line, std::string reason, std::string_view kind = {}) {
        return warn(at_line(file_, line, std::move(reason)), kind);
    }
    status warn_byte(std::uint64_t offset, std::string reason, std::string_view kind = {}) {
        return warn(at_byte(file_, offset, std::move(reason)), kind);
    }
    status warn(error w, std::string_view kind);

    // The mesh with the warnings gathered (repeat counts appended to their reasons).
    loaded_mesh finish(mesh &&m);

private:
    struct group {
        std::size_t listed;  // index into warnings_, or SIZE_MAX when not listed
        std::uint64_t repeats = 0;
    };
    const std::string &file_;
    const load_options &options_;
    std::vector<load_warning> warnings_;
    std::size_t not_listed_ = 0;
    std::unordered_map<std::string, group> groups_;
};

}  // namespace tiny3d::loader

#endif
