// obj_loader.cpp — Wavefront OBJ text → mesh. Accepted statements and limits: mesh.h (loaders).
#include <algorithm>
#include <string>
#include <vector>

#include "loader_util.h"
#include "mesh.h"

namespace tiny3d {

namespace {

using loader::at_line;
using loader::count_of;
using loader::quote;

constexpr long long no_index = -1;       // the corner gives no such attribute
constexpr long long before_first = -2;   // a relative index given while the list was empty

// One face corner as written: position, texture and normal references (0 = absent),
// still 1-based or negative.
struct corner_ref {
    long long v = 0, vt = 0, vn = 0;
};

const char *const corner_forms = "expected v, v/vt, v//vn or v/vt/vn with integer indices";

// Splits "v", "v/vt", "v//vn", "v/vt/vn" (and "v/", "v//", "v/vt/") into its references.
// An empty string on success, else what is wrong.
std::string parse_corner(std::string_view token, corner_ref &c) {
    long long *slots[3] = {&c.v, &c.vt, &c.vn};
    std::size_t start = 0;
    for (int field = 0; field < 3; ++field) {
        const std::size_t slash = token.find('/', start);
        const std::string_view part = token.substr(start, slash == std::string_view::npos ? slash : slash - start);
        if (!part.empty()) {
            if (!loader::parse_int64(part, *slots[field])) return "bad face corner " + quote(token) + ": " + corner_forms;
            if (*slots[field] == 0) return "index 0 in " + quote(token) + ": OBJ indices start at 1 (or -1 for the latest)";
        } else if (field == 0) {
            return "bad face corner " + quote(token) + ": the position index is missing (" + corner_forms + ")";
        }
        if (slash == std::string_view::npos) return {};
        start = slash + 1;
    }
    return "bad face corner " + quote(token) + ": more than 3 fields (" + corner_forms + ")";
}

// Resolves a 1-based or negative (relative) OBJ reference against `count` elements read
// so far; positive references may point forward and are checked at the end.
long long resolve(long long ref, std::size_t count) {
    return ref > 0 ? ref - 1 : static_cast<long long>(count) + ref;
}

// One corner attribute (texture coordinates or normals): its list, and the reference of
// every corner, checked in finish() once forward references are known.
template <class T>
struct attribute {
    const char *index_name, *singular, *plural, *statement;  // "texture", "texture coordinate", …, "vt"
    std::vector<T> values;
    std::vector<long long> refs;  // per corner: 0-based, no_index or before_first
    long first_line = 0;          // the first face line naming one
    bool any = false;

    // The reference of a corner; false (an error) for a relative one before the first.
    bool add(long long written, long line) {
        long long r = no_index;
        if (written != 0) {
            r = resolve(written, values.size());
            if (r < 0) {
                if (!values.empty()) return false;
                r = before_first;
            }
            if (!any) first_line = line;
            any = true;
        }
        refs.push_back(r);
        return true;
    }

    // Fills `out` (one per corner, zero where none); drops the attribute with a warning if
    // the file has none of these lines at all; errors for references out of range.
    status resolve_into(std::vector<T> &out, const T &zero, const std::vector<long> &corner_line,
                        loader::diagnostics &diag, const std::string &name) {
        if (!any) return {};
        if (values.empty())
            return diag.warn_line(first_line, std::string("faces give ") + index_name + " indices but the file has no '" +
                                                  statement + "' lines: " + plural + " dropped");
        out.assign(refs.size(), zero);
        for (std::size_t k = 0; k < refs.size(); ++k) {
            const long long r = refs[k];
            if (r == no_index) continue;
            if (r == before_first)
                return at_line(name, corner_line[k], std::string("relative ") + index_name + " index points before the first '" +
                                                         statement + "' line");
            if (r >= static_cast<long long>(values.size()))
                return at_line(name, corner_line[k], std::string(index_name) + " index " + std::to_string(r + 1) +
                                                         " out of range: the file has " +
                                                         count_of(values.size(), singular, plural));
            out[k] = values[r];
        }
        return {};
    }
};

class obj_parser {
public:
    obj_parser(const std::string &name, const load_options &options) : name_(name), diag_(name, options) {}

    status statement(std::string_view text, long line) {
        std::size_t pos = 0;
        const std::string_view keyword = loader::next_token(text, pos);
        if (keyword.empty()) return {};
        if (keyword == "v") return numbers(text, pos, line, 3, "'v' needs 3 numbers (x y z)", [&](const float *x) {
            m_.positions.push_back({x[0], x[1], x[2]});
        });
        if (keyword == "vt") return numbers(text, pos, line, 2, "'vt' needs a number (u [v])", [&](const float *x) {
            uvs_.values.push_back({x[0], x[1]});
        });
        if (keyword == "vn") return numbers(text, pos, line, 3, "'vn' needs 3 numbers (x y z)", [&](const float *x) {
            normals_.values.push_back({x[0], x[1], x[2]});
        });
        if (keyword == "f") return face(text, pos, line);
        if (keyword == "l") return polyline(text, pos, line);
        if (keyword == "o" || keyword == "g" || keyword == "s" || keyword == "usemtl" || keyword == "mtllib") return {};
        if (keyword == "p")
            return diag_.warn_line(line, "points ('p') are not read: statement skipped", "p");
        return diag_.warn_line(line, "statement " + quote(keyword) + " is not read: skipped", keyword);
    }

    result<loaded_mesh> finish() {
        // The line segments' references go after the face corners', checked the same way.
        if (pos_ref_.size() + segment_refs_.size() > loader::max_elements)
            return at_line(name_, segment_line_.back(), "too many line corners");
        pos_ref_.insert(pos_ref_.end(), segment_refs_.begin(), segment_refs_.end());
        for (long l : segment_line_) corner_line_.insert(corner_line_.end(), 2, l);
        for (std::size_t k = 0; k < pos_ref_.size(); ++k)
            if (pos_ref_[k] >= static_cast<long long>(m_.positions.size()))
                return at_line(name_, corner_line_[k], "vertex index " + std::to_string(pos_ref_[k] + 1) +
                                                           " out of range: the file has " +
                                                           count_of(m_.positions.size(), "vertex", "vertices"));
        for (std::size_t k = 0; k < m_.indices.size(); ++k) m_.indices[k] = static_cast<std::uint32_t>(pos_ref_[k]);
        for (std::size_t k = m_.indices.size(); k < pos_ref_.size(); k += 2) {
            const std::uint32_t a = std::uint32_t(pos_ref_[k]), b = std::uint32_t(pos_ref_[k + 1]);
            if (a != b) m_.lines.push_back({std::min(a, b), std::max(a, b)});
        }
        if (status s = uvs_.resolve_into(m_.corner_uvs, vec2{0.0f, 0.0f}, corner_line_, diag_, name_); !s) return s.err();
        if (status s = normals_.resolve_into(m_.corner_normals, vec3_t{0.0f, 0.0f, 0.0f}, corner_line_, diag_, name_); !s)
            return s.err();
        mesh_derive_edges(m_);
        return diag_.finish(std::move(m_));
    }

private:
    // Reads `used` numbers (x y z; u v), of which the first `required` must be there
    // (missing optional ones are 0). Values after them (w, colours) are ignored whatever
    // they hold.
    template <class Store>
    status numbers(std::string_view text, std::size_t pos, long line, int used, const char *needs, Store &&store) {
        const int required = used == 2 ? 1 : 3;
        float x[3] = {0.0f, 0.0f, 0.0f};
        for (int i = 0; i < used; ++i) {
            const std::string_view tok = loader::next_token(text, pos);
            if (tok.empty()) {
                if (i < required) return at_line(name_, line, std::string(needs) + ", found " + std::to_string(i));
                break;
            }
            if (!loader::parse_finite_float(tok, x[i]))
                return at_line(name_, line, "bad number " + quote(tok) + ": expected a finite decimal number");
        }
        if (m_.positions.size() >= loader::max_elements) return at_line(name_, line, "too many elements");
        store(x);
        return {};
    }

    // Adds a corner's position reference (0-based; may point forward).
    status position(long long written, std::string_view tok, long line) {
        const long long v = resolve(written, m_.positions.size());
        if (v < 0) return at_line(name_, line, "relative index in " + quote(tok) + " points before the first vertex");
        if (pos_ref_.size() >= loader::max_elements) return at_line(name_, line, "too many face corners");
        pos_ref_.push_back(v);
        corner_line_.push_back(line);
        return {};
    }

    status face(std::string_view text, std::size_t pos, long line) {
        const std::size_t first = m_.indices.size();
        for (std::string_view tok = loader::next_token(text, pos); !tok.empty(); tok = loader::next_token(text, pos)) {
            corner_ref c;
            if (std::string why = parse_corner(tok, c); !why.empty()) return at_line(name_, line, why);
            if (status s = position(c.v, tok, line); !s) return s;
            if (!uvs_.add(c.vt, line) || !normals_.add(c.vn, line))
                return at_line(name_, line, "relative index in " + quote(tok) + " points before the first element");
            m_.indices.push_back(0);  // resolved in finish(), once forward references are known
        }
        const std::size_t corners = m_.indices.size() - first;
        if (corners < 3)
            return at_line(name_, line, "face with " + count_of(corners, "corner", "corners") + ": a face needs at least 3");
        m_.face_start.push_back(static_cast<std::uint32_t>(m_.indices.size()));
        return {};
    }

    // `l v1 v2 ...` (corners v or v/vt): segments between consecutive corners, kept apart
    // from the face corners until finish().
    status polyline(std::string_view text, std::size_t pos, long line) {
        std::vector<long long> &refs = line_refs_;
        refs.clear();
        for (std::string_view tok = loader::next_token(text, pos); !tok.empty(); tok = loader::next_token(text, pos)) {
            corner_ref c;
            if (std::string why = parse_corner(tok, c); !why.empty() || c.vn != 0)
                return at_line(name_, line, why.empty() ? "bad line corner " + quote(tok) + ": expected v or v/vt" : why);
            const long long v = resolve(c.v, m_.positions.size());
            if (v < 0) return at_line(name_, line, "relative index in " + quote(tok) + " points before the first vertex");
            refs.push_back(v);
        }
        if (refs.size() < 2)
            return diag_.warn_line(line, "line element with " + count_of(refs.size(), "corner", "corners") +
                                             ": at least 2 are needed, skipped");
        for (std::size_t i = 0; i + 1 < refs.size(); ++i) {
            segment_refs_.push_back(refs[i]);
            segment_refs_.push_back(refs[i + 1]);
            segment_line_.push_back(line);
        }
        return {};
    }

private:
    const std::string &name_;
    loader::diagnostics diag_;
    mesh m_;
    attribute<vec2> uvs_{"texture", "texture coordinate", "texture coordinates", "vt", {}, {}, 0, false};
    attribute<vec3_t> normals_{"normal", "normal", "normals", "vn", {}, {}, 0, false};
    std::vector<long long> pos_ref_;      // per corner: 0-based position
    std::vector<long> corner_line_;       // per corner: its line, for messages
    std::vector<long long> segment_refs_, line_refs_;
    std::vector<long> segment_line_;
};

}  // namespace

result<loaded_mesh> loader::parse_obj_text(std::string_view text, const std::string &name, const load_options &options) {
    if (status s = loader::check_text(text, name, "an OBJ file"); !s) return s.err();
    obj_parser parser(name, options);
    std::string logical;  // a statement continued over lines with a trailing backslash
    long statement_line = 0;
    loader::line_splitter lines(loader::skip_utf8_bom(text));
    for (std::string_view raw; lines.next(raw);) {
        if (logical.empty()) statement_line = lines.line_number();
        const std::size_t hash = raw.find('#');
        if (hash != std::string_view::npos) raw = raw.substr(0, hash);
        if (!raw.empty() && raw.back() == '\\') {
            logical.append(raw.substr(0, raw.size() - 1)).push_back(' ');
            continue;
        }
        status st;
        if (logical.empty()) {
            st = parser.statement(raw, statement_line);
        } else {
            logical.append(raw);
            st = parser.statement(logical, statement_line);
            logical.clear();
        }
        if (!st) return st.err();
    }
    if (!logical.empty()) {
        const status st = parser.statement(logical, statement_line);
        if (!st) return st.err();
    }
    return parser.finish();
}

}  // namespace tiny3d
