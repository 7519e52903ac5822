// ply_loader.cpp — PLY (ascii, binary little / big endian) → mesh. Accepted headers and
// limits: mesh.h (loaders).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "loader_util.h"
#include "mesh.h"

namespace tiny3d {

namespace {

using loader::at_byte;
using loader::at_line;
using loader::quote;

enum class number_kind { signed_int, unsigned_int, floating };

struct scalar_type {
    number_kind kind;
    unsigned size;  // bytes in binary files
};

bool scalar_type_named(std::string_view name, scalar_type &t) {
    struct named {
        const char *a, *b;
        scalar_type type;
    };
    static constexpr named types[] = {
        {"char", "int8", {number_kind::signed_int, 1}},      {"uchar", "uint8", {number_kind::unsigned_int, 1}},
        {"short", "int16", {number_kind::signed_int, 2}},    {"ushort", "uint16", {number_kind::unsigned_int, 2}},
        {"int", "int32", {number_kind::signed_int, 4}},      {"uint", "uint32", {number_kind::unsigned_int, 4}},
        {"float", "float32", {number_kind::floating, 4}},    {"double", "float64", {number_kind::floating, 8}},
    };
    for (const named &n : types)
        if (name == n.a || name == n.b) {
            t = n.type;
            return true;
        }
    return false;
}

struct property {
    std::string name;
    bool is_list = false;
    scalar_type count_type{};  // lists only
    scalar_type value_type{};
};

struct element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<property> properties;
    long header_line = 0;
};

enum class ply_format { ascii, binary_le, binary_be };

struct header {
    ply_format format = ply_format::ascii;
    std::vector<element> elements;
    std::size_t data_offset = 0;  // first byte after end_header's line
    long data_line = 0;           // line number of the first data line (ascii)
};

// Parses the header; on success h.data_offset points at the data.
status parse_header(std::string_view bytes, const std::string &name, header &h, loader::diagnostics &diag) {
    loader::line_splitter lines(bytes);
    std::string_view text;
    std::size_t p = 0;
    if (!lines.next(text) || loader::next_token(text, p) != "ply" || !loader::next_token(text, p).empty())
        return at_line(name, 1, "not a PLY file (its first line must be 'ply')");
    // Binary data starts right after end_header's line end: a lone CR if the header's
    // lines end so (Rhino), else the LF (of LF or CRLF).
    const bool cr_only = lines.line_end() == "\r";
    bool have_format = false;
    while (lines.next(text)) {
        const long line = lines.line_number();
        p = 0;
        const std::string_view key = loader::next_token(text, p);
        if (key == "end_header") {
            if (!have_format) return at_line(name, line, "header has no 'format' line");
            const std::size_t end = std::size_t(text.data() - bytes.data()) + text.size();
            const std::size_t lf = bytes.find('\n', end);
            h.data_offset = cr_only ? std::min(end + 1, bytes.size()) : lf == std::string_view::npos ? bytes.size() : lf + 1;
            h.data_line = line + 1;
            return {};
        }
        if (key.empty() || key == "comment" || key == "obj_info") continue;
        if (key == "format") {
            const std::string_view f = loader::next_token(text, p), version = loader::next_token(text, p);
            if (f == "ascii") h.format = ply_format::ascii;
            else if (f == "binary_little_endian") h.format = ply_format::binary_le;
            else if (f == "binary_big_endian") h.format = ply_format::binary_be;
            else return at_line(name, line, "unknown format " + quote(f) + ": expected ascii, binary_little_endian or binary_big_endian");
            if (version != "1.0") return at_line(name, line, "unsupported PLY version " + quote(version) + ": expected 1.0");
            have_format = true;
        } else if (key == "element") {
            element e;
            e.name = std::string(loader::next_token(text, p));
            const std::string_view count = loader::next_token(text, p);
            long long n = 0;
            if (e.name.empty() || !loader::parse_int64(count, n) || n < 0)
                return at_line(name, line, "bad element line: expected 'element NAME COUNT' with a count of 0 or more");
            e.count = static_cast<std::uint64_t>(n);
            e.header_line = line;
            h.elements.push_back(std::move(e));
        } else if (key == "property") {
            if (h.elements.empty()) return at_line(name, line, "property before any element: expected an 'element' line first");
            property prop;
            std::string_view type = loader::next_token(text, p);
            if (type == "list") {
                prop.is_list = true;
                const std::string_view count_type = loader::next_token(text, p);
                if (!scalar_type_named(count_type, prop.count_type) || prop.count_type.kind == number_kind::floating)
                    return at_line(name, line, "bad list count type " + quote(count_type) + ": expected an integer type");
                type = loader::next_token(text, p);
            }
            if (!scalar_type_named(type, prop.value_type))
                return at_line(name, line, "unknown property type " + quote(type) +
                                               ": expected char, uchar, short, ushort, int, uint, float or double");
            prop.name = std::string(loader::next_token(text, p));
            if (prop.name.empty()) return at_line(name, line, "property without a name");
            h.elements.back().properties.push_back(std::move(prop));
        } else if (status s = diag.warn_line(line, "unknown header line " + quote(key) + " skipped (not comment, obj_info, "
                                                   "format, element, property or end_header)", "header"); !s) {
            return s;
        }
    }
    return at_line(name, lines.line_number(), "header has no 'end_header' line");
}

// Where the loader puts each property of the elements it reads.
enum class role { skip, x, y, z, face_indices, strip_indices };

struct plan {
    std::vector<std::vector<role>> roles;  // per element, per property
    std::size_t vertex_element = SIZE_MAX;
};

bool is_index_list(const property &p) { return p.name == "vertex_indices" || p.name == "vertex_index"; }

status make_plan(const header &h, const std::string &name, plan &pl) {
    pl.roles.resize(h.elements.size());
    bool have_face = false, have_strips = false;
    for (std::size_t i = 0; i < h.elements.size(); ++i) {
        const element &e = h.elements[i];
        pl.roles[i].assign(e.properties.size(), role::skip);
        const bool is_vertex = e.name == "vertex", is_face = e.name == "face", is_strips = e.name == "tristrips";
        if ((is_vertex && pl.vertex_element != SIZE_MAX) || (is_face && have_face) || (is_strips && have_strips))
            return at_line(name, e.header_line, "element '" + e.name + "' appears twice");
        if (is_vertex) {
            pl.vertex_element = i;
            int found = 0;
            for (std::size_t k = 0; k < e.properties.size(); ++k) {
                const property &p = e.properties[k];
                const role r = p.name == "x" ? role::x : p.name == "y" ? role::y : p.name == "z" ? role::z : role::skip;
                if (r == role::skip) continue;
                if (p.is_list) return at_line(name, e.header_line, "vertex property '" + p.name + "' is a list: expected a number");
                pl.roles[i][k] = r;
                ++found;
            }
            if (found != 3) return at_line(name, e.header_line, "element 'vertex' needs properties x, y and z");
            if (e.count > loader::max_elements)
                return at_line(name, e.header_line, "too many vertices (" + std::to_string(e.count) + ")");
        }
        if (is_face || is_strips) {
            have_face |= is_face;
            have_strips |= is_strips;
            for (std::size_t k = 0; k < e.properties.size(); ++k) {
                const property &p = e.properties[k];
                if (!is_index_list(p)) continue;
                if (!p.is_list || p.value_type.kind == number_kind::floating)
                    return at_line(name, e.header_line, "property '" + p.name + "' of '" + e.name + "' must be a list of integers");
                pl.roles[i][k] = is_face ? role::face_indices : role::strip_indices;
            }
            if (std::count(pl.roles[i].begin(), pl.roles[i].end(), is_face ? role::face_indices : role::strip_indices) != 1)
                return at_line(name, e.header_line, "element '" + e.name + "' needs one list 'vertex_indices' (or 'vertex_index')");
        }
    }
    if (pl.vertex_element == SIZE_MAX) return at_line(name, 1, "no 'vertex' element");
    return {};
}

// Least bytes one instance of the element takes: binary = the scalars plus list counts
// (empty lists); ascii = one character and one separator per property.
std::uint64_t min_instance_bytes(const element &e, ply_format f) {
    std::uint64_t n = 0;
    for (const property &p : e.properties)
        n += f == ply_format::ascii ? 2 : (p.is_list ? p.count_type.size : p.value_type.size);
    return n;
}

// Rejects headers announcing more data than the file holds, before anything is allocated.
status check_counts_fit(const header &h, std::string_view bytes, const std::string &name) {
    // The ascii estimate counts a separator after every token; the last may have none.
    const std::uint64_t available = bytes.size() - h.data_offset + (h.format == ply_format::ascii ? 1 : 0);
    std::uint64_t needed = 0;
    for (const element &e : h.elements) {
        const std::uint64_t per = min_instance_bytes(e, h.format);
        if (per == 0) continue;
        if (e.count > available / per || needed + e.count * per > available)
            return at_line(name, e.header_line, "element '" + e.name + "' announces " +
                                                    loader::count_of(e.count, "entry", "entries") + ", more than the " +
                                                    loader::count_of(available, "byte", "bytes") + " of data can hold");
        needed += e.count * per;
    }
    return {};
}

// One decoded value: integers exactly, floats as double.
struct value {
    bool is_float;
    long long i;
    double d;
};

bool is_line_end(char c) { return c == '\n' || c == '\r'; }

// Data source for either encoding; errors name a byte offset (binary) or a line (ascii).
// ASCII data is one entry per line: begin_entry() moves to the next non-blank line,
// values are read from it only, end_entry() skips (and reports) values left on it.
class reader {
public:
    reader(std::string_view bytes, const header &h, const std::string &name)
        : bytes_(bytes), pos_(h.data_offset), line_(h.data_line), format_(h.format), name_(name) {}

    bool ascii() const { return format_ == ply_format::ascii; }
    std::size_t offset() const { return pos_; }
    // Error at the current place (ascii: the entry's line).
    error here(std::string reason) const {
        return ascii() ? at_line(name_, line_, std::move(reason)) : at_byte(name_, pos_, std::move(reason));
    }
    error at(std::size_t offset, std::string reason) const {
        return ascii() ? at_line(name_, line_, std::move(reason)) : at_byte(name_, offset, std::move(reason));
    }

    // Starts entry n of element e, which declares `declared` values before list contents.
    // False at a failure (see failure()).
    bool begin_entry(const element &e, std::uint64_t n, std::size_t declared) {
        values_ = 0;
        declared_ = declared;
        return !ascii() || begin_ascii_entry(e, n);
    }
    // A list of `length` values follows on this entry's line.
    void declare_list(std::uint64_t length) { declared_ += length; }
    // Ascii: the rest of the entry's line must be blank; extra values are skipped with a
    // warning (strict: a failure). Moves past the line end.
    bool end_entry(const element &e, loader::diagnostics &diag) { return !ascii() || end_ascii_entry(e, diag); }

    // Reads one value; `finite` = a float must be finite (skipped ones may be nan / inf).
    bool read(const scalar_type &t, value &out, bool finite) {
        ++values_;
        return ascii() ? read_ascii(t, out, finite) : read_binary(t, out);
    }
    // What the last false return was about.
    const error &failure() const { return failure_; }

    status finish() {
        if (ascii()) {
            skip_blank_lines();
            if (pos_ < bytes_.size()) return here("unexpected data after the last element");
        } else if (pos_ < bytes_.size()) {
            return here(std::to_string(bytes_.size() - pos_) + " bytes after the last element");
        }
        return {};
    }

private:
    bool fail(std::string reason) {
        failure_ = here(std::move(reason));
        return false;
    }
    void skip_space() {
        while (pos_ < bytes_.size() && loader::is_space(bytes_[pos_]) && !is_line_end(bytes_[pos_])) ++pos_;
    }
    // One line end: LF, CRLF or CR alone.
    void skip_line_end() {
        if (pos_ >= bytes_.size()) return;
        if (bytes_[pos_] == '\r' && pos_ + 1 < bytes_.size() && bytes_[pos_ + 1] == '\n') ++pos_;
        ++pos_;
        ++line_;
    }
    void skip_blank_lines() {
        for (skip_space(); pos_ < bytes_.size() && is_line_end(bytes_[pos_]); skip_space()) skip_line_end();
    }

    bool begin_ascii_entry(const element &e, std::uint64_t n) {
        skip_blank_lines();
        if (pos_ < bytes_.size()) return true;
        return fail("unexpected end of file: element '" + e.name + "' has " + loader::count_of(e.count, "entry", "entries") +
                    ", the data ends after " + std::to_string(n));
    }

    bool end_ascii_entry(const element &e, loader::diagnostics &diag) {
        skip_space();
        const long line = line_;
        std::size_t extra = 0;
        for (; pos_ < bytes_.size() && !is_line_end(bytes_[pos_]); skip_space()) {
            ++extra;
            while (pos_ < bytes_.size() && !loader::is_space(bytes_[pos_])) ++pos_;
        }
        if (extra > 0) {
            const status s = diag.warn_line(line, "line has " + std::to_string(values_ + extra) + " values, the header declares " +
                                                      std::to_string(declared_) + " for '" + e.name + "': " +
                                                      loader::count_of(extra, "extra value", "extra values") + " skipped",
                                            "extra values " + e.name);
            if (!s) {
                failure_ = s.err();
                return false;
            }
        }
        skip_line_end();
        return true;
    }

    bool read_ascii(const scalar_type &t, value &out, bool finite) {
        skip_space();
        const std::size_t start = pos_;
        while (pos_ < bytes_.size() && !loader::is_space(bytes_[pos_])) ++pos_;
        const std::string_view tok = bytes_.substr(start, pos_ - start);
        if (tok.empty())
            return fail("line has " + std::to_string(values_ - 1) + " values, the header declares " + std::to_string(declared_));
        out.is_float = t.kind == number_kind::floating;
        const bool ok = !out.is_float ? loader::parse_int64(tok, out.i)
                        : finite      ? loader::parse_finite_double(tok, out.d)
                                      : loader::parse_any_double(tok, out.d);
        if (!ok) return fail("bad number " + quote(tok) + (out.is_float ? ": expected a finite decimal number" : ": expected an integer"));
        return true;
    }

    // The `size` bytes at p as an unsigned integer in the file's byte order.
    std::uint64_t load_bits(const unsigned char *p, unsigned size) const {
        std::uint64_t bits = 0;
        if (format_ == ply_format::binary_le)
            for (unsigned k = size; k-- > 0;) bits = bits << 8 | p[k];
        else
            for (unsigned k = 0; k < size; ++k) bits = bits << 8 | p[k];
        return bits;
    }

    bool read_binary(const scalar_type &t, value &out) {
        if (bytes_.size() - pos_ < t.size) return fail("unexpected end of file (truncated data)");
        const std::uint64_t bits = load_bits(reinterpret_cast<const unsigned char *>(bytes_.data()) + pos_, t.size);
        out.is_float = t.kind == number_kind::floating;
        if (t.kind == number_kind::floating) {
            if (t.size == 4) {
                float f;
                const std::uint32_t b32 = static_cast<std::uint32_t>(bits);
                std::memcpy(&f, &b32, sizeof f);
                out.d = f;
            } else {
                std::memcpy(&out.d, &bits, sizeof out.d);
            }
        } else if (t.kind == number_kind::signed_int) {
            const unsigned unused = 64 - 8 * t.size;  // sign-extend from the top stored bit
            out.i = static_cast<long long>(bits << unused) >> unused;
        } else {
            out.i = static_cast<long long>(bits);
        }
        pos_ += t.size;
        return true;
    }

    std::string_view bytes_;
    std::size_t pos_;
    long line_;
    ply_format format_;
    const std::string &name_;
    std::size_t values_ = 0, declared_ = 0;  // of the current entry (ascii messages)
    error failure_;
};

// Turns the triangle strips of one `tristrips` list into triangles (−1 restarts a strip;
// odd triangles of a strip are flipped so all keep the strip's winding; triangles
// repeating an index, which only join strips, are dropped).
class strip_builder {
public:
    void restart() { run_ = 0; }
    void add(std::uint32_t v, mesh &m) {
        if (run_ >= 2) {
            const bool odd = (run_ - 2) % 2 == 1;
            const std::uint32_t a = odd ? b_ : a_, b = odd ? a_ : b_;
            if (a != b && b != v && a != v) {
                m.indices.insert(m.indices.end(), {a, b, v});
                m.face_start.push_back(static_cast<std::uint32_t>(m.indices.size()));
            }
        }
        a_ = b_;
        b_ = v;
        ++run_;
    }

private:
    std::uint64_t run_ = 0;
    std::uint32_t a_ = 0, b_ = 0;
};

// Reads one list property of entry n (face indices, strips, or skipped).
status read_list(reader &in, const property &p, role r, std::uint64_t n, std::string_view bytes,
                 std::uint64_t vertex_count, const element &e, mesh &m) {
    value v{};
    const std::size_t list_at = in.offset();
    if (!in.read(p.count_type, v, true)) return in.failure();
    if (v.i < 0) return in.at(list_at, "negative list length " + std::to_string(v.i));
    const std::uint64_t length = static_cast<std::uint64_t>(v.i);
    in.declare_list(length);
    // The list must fit in what is left of the file (ascii: ≥ 2 bytes per entry).
    const std::uint64_t per_entry = in.ascii() ? 2 : p.value_type.size;
    if (length > (bytes.size() - in.offset() + 1) / per_entry)
        return in.at(list_at, "list of " + std::to_string(length) + " entries runs past the end of the file");
    if (r == role::face_indices && length < 3)
        return in.at(list_at, "face " + std::to_string(n) + " has " + loader::count_of(length, "corner", "corners") +
                                  ": a face needs at least 3");
    // Strips give at most 3 corners per index.
    const std::uint64_t corners = r == role::strip_indices ? 3 * length : r == role::face_indices ? length : 0;
    if (m.indices.size() + corners > loader::max_elements) return in.at(list_at, "too many face corners");
    strip_builder strip;
    for (std::uint64_t j = 0; j < length; ++j) {
        const std::size_t at = in.offset();
        if (!in.read(p.value_type, v, false)) return in.failure();
        if (r == role::skip) continue;
        if (r == role::strip_indices && v.i == -1) {
            strip.restart();
            continue;
        }
        if (v.i < 0 || static_cast<std::uint64_t>(v.i) >= vertex_count)
            return in.at(at, e.name + " " + std::to_string(n) + ": vertex index " + std::to_string(v.i) +
                                 " out of range: the file has " + loader::count_of(vertex_count, "vertex", "vertices") +
                                 (r == role::strip_indices ? " (-1 restarts a strip)" : ""));
        if (r == role::face_indices) m.indices.push_back(static_cast<std::uint32_t>(v.i));
        else strip.add(static_cast<std::uint32_t>(v.i), m);
    }
    if (r == role::face_indices) m.face_start.push_back(static_cast<std::uint32_t>(m.indices.size()));
    return {};
}

}  // namespace

result<loaded_mesh> loader::parse_ply_bytes(std::string_view bytes, const std::string &name, const load_options &options) {
    loader::diagnostics diag(name, options);
    header h;
    if (status st = parse_header(bytes, name, h, diag); !st) return st.err();
    if (status st = check_counts_fit(h, bytes, name); !st) return st.err();
    plan pl;
    if (status st = make_plan(h, name, pl); !st) return st.err();

    mesh m;
    reader in(bytes, h, name);
    const std::uint64_t vertex_count = h.elements[pl.vertex_element].count;
    m.positions.reserve(vertex_count);
    for (std::size_t ei = 0; ei < h.elements.size(); ++ei) {
        const element &e = h.elements[ei];
        if (e.properties.empty()) continue;  // nothing to read, however many entries
        if (e.name == "face") m.face_start.reserve(m.face_start.size() + e.count);
        const bool is_vertex = ei == pl.vertex_element;
        for (std::uint64_t n = 0; n < e.count; ++n) {
            if (!in.begin_entry(e, n, e.properties.size())) return in.failure();
            double xyz[3] = {0, 0, 0};
            for (std::size_t k = 0; k < e.properties.size(); ++k) {
                const property &p = e.properties[k];
                const role r = pl.roles[ei][k];
                if (p.is_list) {
                    if (status st = read_list(in, p, r, n, bytes, vertex_count, e, m); !st) return st.err();
                    continue;
                }
                value v{};
                const std::size_t at = in.offset();
                if (!in.read(p.value_type, v, r != role::skip)) return in.failure();
                if (r == role::skip) continue;
                const double c = v.is_float ? v.d : double(v.i);
                // Coordinates must be finite floats (double data beyond float range is not).
                if (!std::isfinite(c) || !std::isfinite(static_cast<float>(c)))
                    return in.at(at, "vertex " + std::to_string(n) + ": coordinate " + p.name +
                                         " is not a finite float");
                xyz[static_cast<int>(r) - static_cast<int>(role::x)] = c;
            }
            if (!in.end_entry(e, diag)) return in.failure();
            if (is_vertex) m.positions.push_back({float(xyz[0]), float(xyz[1]), float(xyz[2])});
        }
    }
    if (status st = in.finish(); !st) return st.err();
    mesh_derive_edges(m);
    return diag.finish(std::move(m));
}

}  // namespace tiny3d
