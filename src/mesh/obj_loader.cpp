// obj_loader.cpp — Wavefront OBJ text → mesh. Accepted statements and limits: loaders.h.
#include <string>
#include <vector>

#include "loader_util.h"
#include "loaders.h"

namespace tiny3d {

namespace {

using loader::at_line;
using loader::quote;

constexpr long long no_index = -1;

// One face corner as written: position, texture and normal references (0 = absent),
// still 1-based or negative.
struct corner_ref {
    long long v = 0, vt = 0, vn = 0;
};

// Splits "v", "v/vt", "v//vn", "v/vt/vn" into its references. False if malformed.
bool parse_corner(std::string_view token, corner_ref &c) {
    long long *slots[3] = {&c.v, &c.vt, &c.vn};
    std::size_t start = 0;
    for (int field = 0; field < 3; ++field) {
        const std::size_t slash = token.find('/', start);
        const std::string_view part = token.substr(start, slash == std::string_view::npos ? slash : slash - start);
        // The position is required; vt may be empty only when vn follows ("v//vn").
        if (!part.empty()) {
            if (!loader::parse_int64(part, *slots[field]) || *slots[field] == 0) return false;
        } else if (field == 0 || (field == 1 && slash == std::string_view::npos) || field == 2) {
            return false;
        }
        if (slash == std::string_view::npos) return true;
        start = slash + 1;
    }
    return false;  // a fourth field
}

// Resolves a 1-based or negative (relative) OBJ reference against `count` elements read
// so far; positive references may point forward and are checked at the end.
long long resolve(long long ref, std::size_t count) {
    return ref > 0 ? ref - 1 : static_cast<long long>(count) + ref;
}

class obj_parser {
public:
    explicit obj_parser(const std::string &name) : name_(name) {}

    status statement(std::string_view text, long line) {
        std::size_t pos = 0;
        const std::string_view keyword = loader::next_token(text, pos);
        if (keyword == "v") return numbers(text, pos, line, 3, "v", [&](const float *x) {
            m_.positions.push_back({x[0], x[1], x[2]});
        });
        if (keyword == "vt") return numbers(text, pos, line, 1, "vt", [&](const float *x) {
            uvs_.push_back({x[0], x[1]});
        });
        if (keyword == "vn") return numbers(text, pos, line, 3, "vn", [&](const float *x) {
            normals_.push_back({x[0], x[1], x[2]});
        });
        if (keyword == "f") return face(text, pos, line);
        return {};  // comments are gone already; other statements are skipped
    }

    result<mesh> finish() {
        for (std::size_t k = 0; k < m_.indices.size(); ++k) {
            const long line = face_line_[corner_face_[k]];
            if (pos_ref_[k] >= static_cast<long long>(m_.positions.size()))
                return at_line(name_, line, "vertex index " + std::to_string(pos_ref_[k] + 1) + " out of range (" +
                                                std::to_string(m_.positions.size()) + " vertices)");
            if (uv_ref_[k] >= static_cast<long long>(uvs_.size()))
                return at_line(name_, line, "texture index " + std::to_string(uv_ref_[k] + 1) + " out of range (" +
                                                std::to_string(uvs_.size()) + " texture coordinates)");
            if (normal_ref_[k] >= static_cast<long long>(normals_.size()))
                return at_line(name_, line, "normal index " + std::to_string(normal_ref_[k] + 1) + " out of range (" +
                                                std::to_string(normals_.size()) + " normals)");
            m_.indices[k] = static_cast<std::uint32_t>(pos_ref_[k]);
        }
        if (any_uv_) {
            m_.corner_uvs.resize(m_.indices.size(), vec2{0.0f, 0.0f});
            for (std::size_t k = 0; k < uv_ref_.size(); ++k)
                if (uv_ref_[k] != no_index) m_.corner_uvs[k] = uvs_[uv_ref_[k]];
        }
        if (any_normal_) {
            m_.corner_normals.resize(m_.indices.size(), vec3_t{0.0f, 0.0f, 0.0f});
            for (std::size_t k = 0; k < normal_ref_.size(); ++k)
                if (normal_ref_[k] != no_index) m_.corner_normals[k] = normals_[normal_ref_[k]];
        }
        mesh_derive_edges(m_);
        return std::move(m_);
    }

private:
    // Reads at least `required` numbers (up to 4; more are ignored, e.g. vertex colours);
    // missing optional ones are 0.
    template <class Store>
    status numbers(std::string_view text, std::size_t pos, long line, int required, const char *what, Store &&store) {
        constexpr int max_read = 4;
        float x[max_read] = {0.0f, 0.0f, 0.0f, 0.0f};
        for (int i = 0; i < max_read; ++i) {
            const std::string_view tok = loader::next_token(text, pos);
            if (tok.empty()) {
                if (i < required)
                    return at_line(name_, line, std::string("'") + what + "' needs " + std::to_string(required) +
                                                    " numbers, found " + std::to_string(i));
                break;
            }
            if (!loader::parse_finite_float(tok, x[i]))
                return at_line(name_, line, "bad number " + quote(tok) + " in '" + what + "'");
        }
        if (m_.positions.size() >= loader::max_elements) return at_line(name_, line, "too many elements");
        store(x);
        return {};
    }

    status face(std::string_view text, std::size_t pos, long line) {
        const std::size_t first = m_.indices.size();
        for (std::string_view tok = loader::next_token(text, pos); !tok.empty(); tok = loader::next_token(text, pos)) {
            corner_ref c;
            if (!parse_corner(tok, c)) return at_line(name_, line, "bad face corner " + quote(tok));
            const long long v = resolve(c.v, m_.positions.size());
            const long long vt = c.vt ? resolve(c.vt, uvs_.size()) : no_index;
            const long long vn = c.vn ? resolve(c.vn, normals_.size()) : no_index;
            if (v < 0 || (c.vt && vt < 0) || (c.vn && vn < 0))
                return at_line(name_, line, "relative index in " + quote(tok) + " points before the first element");
            if (m_.indices.size() >= loader::max_elements) return at_line(name_, line, "too many face corners");
            any_uv_ |= c.vt != 0;
            any_normal_ |= c.vn != 0;
            m_.indices.push_back(0);  // resolved in finish(), once forward references are known
            pos_ref_.push_back(v);
            uv_ref_.push_back(vt);
            normal_ref_.push_back(vn);
            corner_face_.push_back(static_cast<std::uint32_t>(face_line_.size()));
        }
        const std::size_t corners = m_.indices.size() - first;
        if (corners < 3)
            return at_line(name_, line, "face with " + std::to_string(corners) + " corners (at least 3 needed)");
        m_.face_start.push_back(static_cast<std::uint32_t>(m_.indices.size()));
        face_line_.push_back(line);
        return {};
    }

    const std::string &name_;
    mesh m_;
    std::vector<vec2> uvs_;
    std::vector<vec3_t> normals_;
    std::vector<long long> pos_ref_, uv_ref_, normal_ref_;  // 0-based, per corner
    std::vector<std::uint32_t> corner_face_;
    std::vector<long> face_line_;
    bool any_uv_ = false, any_normal_ = false;
};

}  // namespace

result<mesh> parse_obj(std::string_view text, const std::string &name) {
    obj_parser parser(name);
    std::string logical;  // a statement continued over lines with a trailing backslash
    long line = 0, statement_line = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view raw = text.substr(pos, end - pos);
        pos = end + 1;
        ++line;
        if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
        if (raw.find('\0') != std::string_view::npos) return at_line(name, line, "NUL byte in text");
        if (logical.empty()) statement_line = line;
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
