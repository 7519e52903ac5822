// ply_loader.cpp — PLY (ascii, binary little / big endian) → mesh. Accepted headers and
// limits: loaders.h.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "loader_util.h"
#include "loaders.h"

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
status parse_header(std::string_view bytes, const std::string &name, header &h) {
    std::size_t pos = 0;
    long line = 0;
    bool have_format = false;
    for (;;) {
        if (pos >= bytes.size()) return at_line(name, line, "header has no 'end_header' line");
        std::size_t end = bytes.find('\n', pos);
        if (end == std::string_view::npos) return at_line(name, line + 1, "header has no 'end_header' line");
        std::string_view text = bytes.substr(pos, end - pos);
        pos = end + 1;
        ++line;
        std::size_t p = 0;
        const std::string_view key = loader::next_token(text, p);
        if (line == 1) {
            if (key != "ply" || !loader::next_token(text, p).empty()) return at_line(name, 1, "not a PLY file (first line must be 'ply')");
            continue;
        }
        if (key == "end_header") {
            if (!have_format) return at_line(name, line, "header has no 'format' line");
            h.data_offset = pos;
            h.data_line = line + 1;
            return {};
        }
        if (key.empty() || key == "comment" || key == "obj_info") continue;
        if (key == "format") {
            const std::string_view f = loader::next_token(text, p), version = loader::next_token(text, p);
            if (f == "ascii") h.format = ply_format::ascii;
            else if (f == "binary_little_endian") h.format = ply_format::binary_le;
            else if (f == "binary_big_endian") h.format = ply_format::binary_be;
            else return at_line(name, line, "unknown format " + quote(f));
            if (version != "1.0") return at_line(name, line, "unsupported PLY version " + quote(version));
            have_format = true;
        } else if (key == "element") {
            element e;
            e.name = std::string(loader::next_token(text, p));
            const std::string_view count = loader::next_token(text, p);
            long long n = 0;
            if (e.name.empty() || !loader::parse_int64(count, n) || n < 0)
                return at_line(name, line, "bad element line (expected 'element NAME COUNT')");
            e.count = static_cast<std::uint64_t>(n);
            e.header_line = line;
            h.elements.push_back(std::move(e));
        } else if (key == "property") {
            if (h.elements.empty()) return at_line(name, line, "property before any element");
            property prop;
            std::string_view type = loader::next_token(text, p);
            if (type == "list") {
                prop.is_list = true;
                const std::string_view count_type = loader::next_token(text, p);
                if (!scalar_type_named(count_type, prop.count_type) || prop.count_type.kind == number_kind::floating)
                    return at_line(name, line, "bad list count type " + quote(count_type));
                type = loader::next_token(text, p);
            }
            if (!scalar_type_named(type, prop.value_type)) return at_line(name, line, "unknown property type " + quote(type));
            prop.name = std::string(loader::next_token(text, p));
            if (prop.name.empty()) return at_line(name, line, "property without a name");
            h.elements.back().properties.push_back(std::move(prop));
        } else {
            return at_line(name, line, "unknown header line " + quote(key));
        }
    }
}

// Where the loader puts each property of the elements it reads.
enum class role { skip, x, y, z, face_indices };

struct plan {
    std::vector<std::vector<role>> roles;  // per element, per property
    std::size_t vertex_element = SIZE_MAX, face_element = SIZE_MAX;
};

status make_plan(const header &h, const std::string &name, plan &pl) {
    pl.roles.resize(h.elements.size());
    for (std::size_t i = 0; i < h.elements.size(); ++i) {
        const element &e = h.elements[i];
        pl.roles[i].assign(e.properties.size(), role::skip);
        const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
        if ((is_vertex && pl.vertex_element != SIZE_MAX) || (is_face && pl.face_element != SIZE_MAX))
            return at_line(name, e.header_line, "element '" + e.name + "' appears twice");
        if (is_vertex) {
            pl.vertex_element = i;
            int found = 0;
            for (std::size_t k = 0; k < e.properties.size(); ++k) {
                const property &p = e.properties[k];
                const role r = p.name == "x" ? role::x : p.name == "y" ? role::y : p.name == "z" ? role::z : role::skip;
                if (r == role::skip) continue;
                if (p.is_list) return at_line(name, e.header_line, "vertex property '" + p.name + "' is a list");
                pl.roles[i][k] = r;
                ++found;
            }
            if (found != 3) return at_line(name, e.header_line, "element 'vertex' needs properties x, y and z");
            if (e.count > loader::max_elements)
                return at_line(name, e.header_line, "too many vertices (" + std::to_string(e.count) + ")");
        }
        if (is_face) {
            pl.face_element = i;
            for (std::size_t k = 0; k < e.properties.size(); ++k) {
                const property &p = e.properties[k];
                if (p.name != "vertex_indices" && p.name != "vertex_index") continue;
                if (!p.is_list || p.value_type.kind == number_kind::floating)
                    return at_line(name, e.header_line, "face property '" + p.name + "' must be a list of integers");
                pl.roles[i][k] = role::face_indices;
            }
            if (std::count(pl.roles[i].begin(), pl.roles[i].end(), role::face_indices) != 1)
                return at_line(name, e.header_line, "element 'face' needs one list 'vertex_indices' (or 'vertex_index')");
        }
    }
    if (pl.vertex_element == SIZE_MAX) return at_line(name, 1, "no 'vertex' element");
    if (pl.face_element != SIZE_MAX && pl.face_element < pl.vertex_element)
        return at_line(name, h.elements[pl.face_element].header_line, "element 'face' comes before 'vertex'");
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
            return at_line(name, e.header_line, "element '" + e.name + "' announces " + std::to_string(e.count) +
                                                    " entries, more than the " + std::to_string(available) +
                                                    " bytes of data can hold");
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

// Data source for either encoding; errors name a byte offset (binary) or a line (ascii).
class reader {
public:
    reader(std::string_view bytes, const header &h, const std::string &name)
        : bytes_(bytes), pos_(h.data_offset), line_(h.data_line), format_(h.format), name_(name) {}

    status read(const scalar_type &t, value &out) {
        return format_ == ply_format::ascii ? read_ascii(t, out) : read_binary(t, out);
    }
    // Moves to the start of the next value (ascii: past whitespace) so that offset() and
    // line() name the place of the value read next.
    void mark() {
        if (ascii()) skip_space();
    }
    std::size_t offset() const { return pos_; }
    long line() const { return line_; }
    bool ascii() const { return format_ == ply_format::ascii; }
    // Error at the current place.
    error here(std::string reason) const {
        return ascii() ? at_line(name_, line_, std::move(reason)) : at_byte(name_, pos_, std::move(reason));
    }
    status finish() {
        if (ascii()) {
            skip_space();
            if (pos_ < bytes_.size()) return here("unexpected data after the last element");
        } else if (pos_ < bytes_.size()) {
            return here(std::to_string(bytes_.size() - pos_) + " bytes after the last element");
        }
        return {};
    }

private:
    void skip_space() {
        while (pos_ < bytes_.size() && loader::is_space(bytes_[pos_])) line_ += bytes_[pos_++] == '\n';
    }

    status read_ascii(const scalar_type &t, value &out) {
        skip_space();
        const std::size_t start = pos_;
        while (pos_ < bytes_.size() && !loader::is_space(bytes_[pos_])) ++pos_;
        const std::string_view tok = bytes_.substr(start, pos_ - start);
        if (tok.empty()) return here("unexpected end of file");
        out.is_float = t.kind == number_kind::floating;
        const bool ok = out.is_float ? loader::parse_finite_double(tok, out.d) : loader::parse_int64(tok, out.i);
        if (!ok) return here("bad number " + quote(tok));
        return {};
    }

    status read_binary(const scalar_type &t, value &out) {
        if (bytes_.size() - pos_ < t.size) return here("unexpected end of file (truncated data)");
        std::uint64_t bits = 0;
        for (unsigned k = 0; k < t.size; ++k) {
            const unsigned byte = static_cast<unsigned char>(bytes_[pos_ + k]);
            const unsigned shift = 8 * (format_ == ply_format::binary_le ? k : t.size - 1 - k);
            bits |= std::uint64_t(byte) << shift;
        }
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
        return {};
    }

    std::string_view bytes_;
    std::size_t pos_;
    long line_;
    ply_format format_;
    const std::string &name_;
};

}  // namespace

result<mesh> parse_ply(std::string_view bytes, const std::string &name) {
    header h;
    if (status st = parse_header(bytes, name, h); !st) return st.err();
    if (status st = check_counts_fit(h, bytes, name); !st) return st.err();
    plan pl;
    if (status st = make_plan(h, name, pl); !st) return st.err();

    mesh m;
    reader in(bytes, h, name);
    const std::uint64_t vertex_count = h.elements[pl.vertex_element].count;
    m.positions.reserve(vertex_count);
    if (pl.face_element != SIZE_MAX) m.face_start.reserve(h.elements[pl.face_element].count + 1);
    for (std::size_t ei = 0; ei < h.elements.size(); ++ei) {
        const element &e = h.elements[ei];
        if (e.properties.empty()) continue;  // nothing to read, however many entries
        const bool is_vertex = ei == pl.vertex_element;
        for (std::uint64_t n = 0; n < e.count; ++n) {
            double xyz[3] = {0, 0, 0};
            for (std::size_t k = 0; k < e.properties.size(); ++k) {
                const property &p = e.properties[k];
                const role r = pl.roles[ei][k];
                value v{};
                if (!p.is_list) {
                    in.mark();
                    const long line = in.line();
                    const std::size_t at = in.offset();
                    if (status st = in.read(p.value_type, v); !st) return st.err();
                    if (r == role::skip) continue;
                    const double c = v.is_float ? v.d : double(v.i);
                    // Coordinates must be finite floats (double data beyond float range is not).
                    if (!std::isfinite(c) || !std::isfinite(static_cast<float>(c))) {
                        const std::string why = "vertex " + std::to_string(n) + ": coordinate " + p.name + " is not a finite float";
                        return in.ascii() ? at_line(name, line, why) : at_byte(name, at, why);
                    }
                    xyz[static_cast<int>(r) - static_cast<int>(role::x)] = c;
                    continue;
                }
                in.mark();
                const std::size_t list_at = in.offset();
                const long list_line = in.line();
                if (status st = in.read(p.count_type, v); !st) return st.err();
                auto list_error = [&](const std::string &why) {
                    return in.ascii() ? at_line(name, list_line, why) : at_byte(name, list_at, why);
                };
                if (v.i < 0) return list_error("negative list length " + std::to_string(v.i));
                const std::uint64_t length = static_cast<std::uint64_t>(v.i);
                // The list must fit in what is left of the file (ascii: ≥ 2 bytes per entry).
                const std::uint64_t per_entry = in.ascii() ? 2 : p.value_type.size;
                if (length > (bytes.size() - in.offset() + 1) / per_entry)
                    return list_error("list of " + std::to_string(length) + " entries runs past the end of the file");
                if (r == role::face_indices) {
                    if (length < 3)
                        return list_error("face " + std::to_string(n) + " has " + std::to_string(length) +
                                          " corners (at least 3 needed)");
                    if (m.indices.size() + length > loader::max_elements) return list_error("too many face corners");
                }
                for (std::uint64_t j = 0; j < length; ++j) {
                    in.mark();
                    const std::size_t at = in.offset();
                    const long line = in.line();
                    if (status st = in.read(p.value_type, v); !st) return st.err();
                    if (r != role::face_indices) continue;
                    if (v.i < 0 || static_cast<std::uint64_t>(v.i) >= vertex_count) {
                        const std::string why = "face " + std::to_string(n) + ": vertex index " + std::to_string(v.i) +
                                                " out of range (" + std::to_string(vertex_count) + " vertices)";
                        return in.ascii() ? at_line(name, line, why) : at_byte(name, at, why);
                    }
                    m.indices.push_back(static_cast<std::uint32_t>(v.i));
                }
                if (r == role::face_indices) m.face_start.push_back(static_cast<std::uint32_t>(m.indices.size()));
            }
            if (is_vertex) m.positions.push_back({float(xyz[0]), float(xyz[1]), float(xyz[2])});
        }
    }
    if (status st = in.finish(); !st) return st.err();
    mesh_derive_edges(m);
    return m;
}

}  // namespace tiny3d
