// loaders_field_test.cpp — files the field's loaders (tinyobjloader, happly, trimesh) read:
// each case is a small file written here, loaded with the expected mesh and warnings
// (file:line and what was skipped), and again with load_options::strict, where the
// first warning must be the error.
#include <string>
#include <vector>

#include "harness.h"
#include "math3d.h"
#include "mesh.h"

using namespace tiny3d;

namespace {

bool same(vec3_t a, vec3_t b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

const load_options strict{true, 100};

// The load succeeded with exactly `count` warnings, the first at `line` containing `words`;
// the strict load of the same text fails with that warning as its error.
template <class Parse>
void expect_warning(Parse &&parse, std::size_t count, long line, const std::string &words, int at) {
    const result<loaded_mesh> r = parse(load_options{});
    if (!r.ok()) {
        tiny_test::fail(__FILE__, at, "expected a mesh with warnings, got: " + r.message());
        return;
    }
    const std::vector<load_warning> &w = r->warnings;
    if (w.size() != count || w.empty() || w[0].line != line || w[0].reason.find(words) == std::string::npos) {
        std::string got = std::to_string(w.size()) + " warnings";
        for (const load_warning &x : w) got += "; " + x.message();
        tiny_test::fail(__FILE__, at, "expected " + std::to_string(count) + " warnings, the first at line " +
                                          std::to_string(line) + " '" + words + "', got " + got);
    }
    const result<loaded_mesh> s = parse(strict);
    if (s.ok() || s.err().line != line || s.err().reason.find(words) == std::string::npos)
        tiny_test::fail(__FILE__, at, "strict: expected the error at line " + std::to_string(line) + " '" + words +
                                          "', got: " + s.message());
}
#define EXPECT_OBJ_WARNING(text, count, line, words) \
    expect_warning([&](const load_options &o) { return parse_obj(text, "w.obj", o); }, count, line, words, __LINE__)
#define EXPECT_PLY_WARNING(text, count, line, words) \
    expect_warning([&](const load_options &o) { return parse_ply(text, "w.ply", o); }, count, line, words, __LINE__)

// A load with no warning at all (strict succeeds too).
result<mesh> clean_obj(const std::string &text) {
    const result<loaded_mesh> r = parse_obj(text, "c.obj", strict);
    if (!r) return r.err();
    return r->geometry;
}
result<mesh> clean_ply(const std::string &text) {
    const result<loaded_mesh> r = parse_ply(text, "c.ply", strict);
    if (!r) return r.err();
    return r->geometry;
}

const std::string unit_square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

}  // namespace

// ---------------------------------------------------------------- OBJ

TEST(obj_utf8_bom_is_skipped_and_the_first_vertex_kept) {
    const result<mesh> r = clean_obj("\xEF\xBB\xBFv 5 6 7\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    CHECK_MSG(r.ok(), r.message());
    if (!r.ok()) return;
    CHECK_EQ(r->positions.size(), 3u);
    CHECK(same(r->positions[0], vec3_t{5, 6, 7}));
}

TEST(obj_utf16_and_nul_bytes_say_what_to_do) {
    const std::string utf16("\xFF\xFEv\0 \0" "0\0", 8);
    const result<mesh> a = parse_obj(utf16, "u.obj");
    CHECK(!a.ok() && a.err().line == 1 && a.err().reason.find("UTF-16 text") != std::string::npos &&
          a.err().reason.find("save it as UTF-8") != std::string::npos);
    const result<mesh> b = parse_obj(std::string("v\0 0 0 0\n", 9), "u.obj");  // no BOM, every other byte 0 …
    CHECK(!b.ok() && b.err().reason.find("UTF-16") != std::string::npos);
    const result<mesh> c = parse_obj(unit_square + std::string("f 1 2\0 3\n", 9), "n.obj");  // … or a stray NUL
    CHECK(!c.ok() && c.err().line == 5 && c.err().reason.find("NUL byte") != std::string::npos);
}

TEST(obj_line_ends_lf_crlf_and_cr_alone_mixed) {
    // Line 3 ends in CR alone, line 4 in CRLF: the error on line 6 is numbered as such.
    const result<mesh> r = clean_obj("v 0 0 0\nv 1 0 0\rv 1 1 0\r\nv 0 1 0\n\rf 1 2 3 4\r");
    CHECK_MSG(r.ok(), r.message());
    if (r.ok()) CHECK(r->positions.size() == 4u && r->face_count() == 1u && r->face_size(0) == 4u);
    const result<mesh> e = parse_obj("v 0 0 0\rv 1 0 0\r\nv 1 1 0\n\rf 1 2 7\r", "cr.obj");
    CHECK(!e.ok() && e.err().line == 5);
}

TEST(obj_empty_trailing_corner_fields) {
    const result<mesh> r = clean_obj(unit_square + "vt 0 0\nvt 1 0\nvt 1 1\nf 1// 2// 3//\nf 1/1/ 2/2/ 3/3/\nf 1/ 3/ 4/\n");
    CHECK_MSG(r.ok(), r.message());
    if (!r.ok()) return;
    CHECK_EQ(r->face_count(), 3u);
    CHECK(r->corner_normals.empty());
    CHECK_EQ(r->corner_uvs.size(), 9u);
    if (r->corner_uvs.size() == 9u) CHECK(r->corner_uvs[5].x == 1 && r->corner_uvs[5].y == 1);  // face 2, corner 3 = vt 3
}

TEST(obj_values_after_xyz_are_ignored_whatever_they_hold) {
    // Vertex colours with nan, a w, garbage: positions read, nothing refused, no warning.
    const result<mesh> r = clean_obj("v 0 0 0 nan 0.5 1\nv 1 0 0 1.0\nv 0 1 0 0.1 0.2 inf\nvt 0.5 0.25 nan\nf 1/1 2/1 3/1\n");
    CHECK_MSG(r.ok(), r.message());
    if (r.ok()) CHECK(same(r->positions[2], vec3_t{0, 1, 0}) && r->corner_uvs[0].x == 0.5f && r->corner_uvs[0].y == 0.25f);
    // The used values themselves must still be finite numbers.
    const result<mesh> e = parse_obj("v 0 nan 0\n", "e.obj");
    CHECK(!e.ok() && e.err().reason.find("expected a finite decimal number") != std::string::npos);
}

TEST(obj_attribute_indices_without_vt_or_vn_lines_drop_the_attribute) {
    // Positions valid, no vt / vn lines: the mesh loads without uvs / normals, one warning each.
    const std::string text = unit_square + "f 1/1/1 2/2/2 3/3/3\nf 1/1/1 3/3/3 4/4/4\n";
    EXPECT_OBJ_WARNING(text, 2u, 5, "texture indices but the file has no 'vt' lines: texture coordinates dropped");
    const result<loaded_mesh> r = parse_obj(text, "w.obj", {});
    if (!r.ok()) return;
    CHECK(r->geometry.corner_uvs.empty() && r->geometry.corner_normals.empty());
    CHECK_EQ(r->geometry.face_count(), 2u);
    CHECK(r->warnings.size() == 2 && r->warnings[1].reason.find("'vn' lines: normals dropped") != std::string::npos);
    // Relative attribute indices with no lists at all: dropped too.
    EXPECT_OBJ_WARNING(unit_square + "f 1//-1 2//-1 3//-1\n", 1u, 5, "normals dropped");
    // With vt lines present, an index beyond them stays an error.
    const result<mesh> e = parse_obj(unit_square + "vt 0 0\nvt 1 1\nf 1/1 2/2 3/3\n", "e.obj");
    CHECK(!e.ok() && e.err().line == 7 &&
          e.err().reason == "texture index 3 out of range: the file has 2 texture coordinates");
}

TEST(obj_messages_say_what_is_expected_and_count_right) {
    auto reason = [](const std::string &text) {
        const result<mesh> r = parse_obj(text, "m.obj");
        return r.ok() ? std::string("(loaded)") : r.err().reason;
    };
    CHECK_EQ(reason(unit_square + "f 0 1 2\n"), std::string("index 0 in '0': OBJ indices start at 1 (or -1 for the latest)"));
    CHECK_EQ(reason(unit_square + "f 1\n"), std::string("face with 1 corner: a face needs at least 3"));
    CHECK_EQ(reason(unit_square + "f 1 2\n"), std::string("face with 2 corners: a face needs at least 3"));
    CHECK_EQ(reason("v 0 0 0\nf 1 1 2\n"), std::string("vertex index 2 out of range: the file has 1 vertex"));
    CHECK_EQ(reason(unit_square + "f 1 2 9\n"), std::string("vertex index 9 out of range: the file has 4 vertices"));
    CHECK_EQ(reason("v 0 0\n"), std::string("'v' needs 3 numbers (x y z), found 2"));
    CHECK_EQ(reason(unit_square + "f 1 2 x\n"),
             std::string("bad face corner 'x': expected v, v/vt, v//vn or v/vt/vn with integer indices"));
}

TEST(obj_l_polylines_become_edges_and_p_is_skipped) {
    // A lines-only file: 4 positions, a closed polyline 1-2-3-4-1 and a repeated segment.
    const std::string text = unit_square + "l 1 2 3 4 1\nl 2/1 1\np 1 2\n";
    EXPECT_OBJ_WARNING(text, 1u, 7, "points ('p') are not read");
    const result<loaded_mesh> r = parse_obj(text, "lines.obj", {});
    if (!r.ok()) return;
    const mesh &m = r->geometry;
    CHECK_EQ(m.face_count(), 0u);
    CHECK_EQ(m.lines.size(), 5u);  // as written: 1-2, 2-3, 3-4, 4-1, 2-1
    const std::vector<std::pair<std::uint32_t, std::uint32_t>> expected = {{0, 1}, {0, 3}, {1, 2}, {2, 3}};
    CHECK_EQ(m.edges.size(), expected.size());
    for (std::size_t e = 0; e < m.edges.size() && e < expected.size(); ++e)
        CHECK(m.edges[e].a == expected[e].first && m.edges[e].b == expected[e].second);
    CHECK(mesh_validate(m).ok());
    // Faces and lines together: a triangle plus a dangling segment 3-4 (shares no face edge).
    const result<mesh> both = clean_obj(unit_square + "f 1 2 3\nl 3 4\nl -1 -4\n");
    CHECK(both.ok() && both->edges.size() == 5u);
    // A line needs 2 corners; out-of-range line indices are errors like face ones.
    EXPECT_OBJ_WARNING(unit_square + "l 1\n", 1u, 5, "line element with 1 corner: at least 2 are needed");
    const result<mesh> bad = parse_obj(unit_square + "l 1 5\n", "l.obj");
    CHECK(!bad.ok() && bad.err().line == 5 && bad.err().reason.find("vertex index 5 out of range") != std::string::npos);
}

TEST(obj_unknown_statements_warn_once_per_keyword) {
    const std::string text = unit_square + "curv 0 1 1 2\ncurv 0 1 2 3\ncurv 0 1 3 4\nvp 0.5\nf 1 2 3\n";
    EXPECT_OBJ_WARNING(text, 2u, 5, "statement 'curv' is not read: skipped");
    const result<loaded_mesh> r = parse_obj(text, "w.obj", {});
    CHECK(r.ok() && r->warnings[0].reason == "statement 'curv' is not read: skipped (2 more like it)");
    // o, g, s, usemtl, mtllib: no warning.
    CHECK(clean_obj("mtllib a.mtl\no thing\ng group\ns off\nusemtl m\n" + unit_square + "f 1 2 3\n").ok());
}

TEST(warnings_beyond_the_limit_are_counted_not_listed) {
    std::string text = unit_square;
    for (int k = 0; k < 30; ++k) text += "kw" + std::to_string(k) + " 1\n";
    const result<loaded_mesh> r = parse_obj(text, "many.obj", load_options{false, 10});
    CHECK(r.ok());
    if (!r.ok()) return;
    CHECK_EQ(r->warnings.size(), 10u);
    CHECK_EQ(r->warnings_not_listed, 20u);
    CHECK_EQ(r->warnings[9].line, 14);
    CHECK_EQ(r->warnings[9].message(), std::string("many.obj:14: statement 'kw9' is not read: skipped"));
}

// ---------------------------------------------------------------- PLY

namespace {
const std::string ply_vertices = "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n";
const std::string ply_square = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
}  // namespace

TEST(ply_face_element_before_vertex) {
    const result<mesh> r = clean_ply("ply\nformat ascii 1.0\nelement face 2\nproperty list uchar int vertex_indices\n" +
                                     ply_vertices + "end_header\n3 0 1 2\n3 0 2 3\n" + ply_square);
    CHECK_MSG(r.ok(), r.message());
    if (!r.ok()) return;
    CHECK(r->positions.size() == 4u && r->face_count() == 2u && same(r->positions[2], vec3_t{1, 1, 0}));
    const std::vector<std::uint32_t> expected = {0, 1, 2, 0, 2, 3};
    CHECK(r->indices == expected);
}

TEST(ply_header_lines_ending_in_cr_alone) {
    std::string header = "ply\rformat ascii 1.0\r" + ply_vertices + "element face 1\rproperty list uchar int vertex_indices\rend_header\r";
    for (char &c : header)
        if (c == '\n') c = '\r';
    const result<mesh> ascii = clean_ply(header + "0 0 0\r1 0 0\r1 1 0\r0 1 0\r4 0 1 2 3\r");
    CHECK_MSG(ascii.ok(), ascii.message());
    if (ascii.ok()) CHECK(ascii->face_count() == 1u && ascii->face_size(0) == 4u);
    // Binary after a CR-only header: the data starts right after end_header's CR, even
    // when its first byte is an LF (10 = 0x0A as the low byte of x).
    std::string bin = "ply\rformat binary_little_endian 1.0\relement vertex 1\rproperty int x\rproperty int y\r"
                      "property int z\rend_header\r";
    const int xyz[3] = {10, 2, 3};
    bin.append(reinterpret_cast<const char *>(xyz), sizeof xyz);
    const result<mesh> b = clean_ply(bin);
    CHECK_MSG(b.ok(), b.message());
    if (b.ok()) CHECK(same(b->positions[0], vec3_t{10, 2, 3}));
}

TEST(ply_extra_ascii_values_skipped_with_a_warning) {
    const std::string text = "ply\nformat ascii 1.0\n" + ply_vertices + "element face 1\nproperty list uchar int vertex_indices\n"
                             "end_header\n0 0 0 7 7 7 7\n1 0 0 7 7 7 7\n1 1 0 7 7 7 7\n0 1 0\n3 0 1 2 9\n";
    // Line 10: 7 values where x y z are declared; lines 11-12 fold into it; line 14 is the face's.
    EXPECT_PLY_WARNING(text, 2u, 10, "line has 7 values, the header declares 3 for 'vertex': 4 extra values skipped");
    const result<loaded_mesh> r = parse_ply(text, "w.ply", {});
    if (!r.ok()) return;
    CHECK(r->warnings[0].reason.find("skipped (2 more like it)") != std::string::npos);
    CHECK(same(r->geometry.positions[1], vec3_t{1, 0, 0}));
    CHECK(r->warnings.size() == 2 && r->warnings[1].line == 14 &&
          r->warnings[1].reason.find("line has 5 values, the header declares 4 for 'face': 1 extra value skipped") == 0);
    // Too few values on a line is an error naming both counts.
    const result<mesh> e = parse_ply("ply\nformat ascii 1.0\n" + ply_vertices + "end_header\n0.0 0 0\n1 0\n1 1 0\n0 1 0\n", "f.ply");
    CHECK(!e.ok() && e.err().line == 9 && e.err().reason == "line has 2 values, the header declares 3");
}

TEST(ply_nonfinite_values_in_skipped_properties) {
    const result<mesh> r = clean_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                                     "property float nx\nproperty double confidence\nend_header\n1 2 3 nan -inf\n");
    CHECK_MSG(r.ok(), r.message());
}

TEST(ply_unknown_header_line_skipped_with_a_warning) {
    const std::string text = "ply\nformat ascii 1.0\nBlender export\n" + ply_vertices + "end_header\n" + ply_square;
    EXPECT_PLY_WARNING(text, 1u, 3, "unknown header line 'Blender' skipped");
}

TEST(ply_tristrips_with_restarts_and_alternating_winding) {
    // Strip 0 1 2 3 4 (three triangles), restart, strip 4 3 5 with a join repeating 5.
    const std::string text = "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
                             "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
                             "0 0 0\n0 1 0\n1 0 0\n1 1 0\n2 0 0\n2 1 0\n10 0 1 2 3 4 -1 4 3 5 5\n";
    const result<mesh> r = clean_ply(text);
    CHECK_MSG(r.ok(), r.message());
    if (!r.ok()) return;
    // Expected: (0 1 2) (2 1 3) (2 3 4) | (4 3 5); (3 5 5) and (5 5 ·) repeat an index → dropped.
    const std::vector<std::uint32_t> expected = {0, 1, 2, 2, 1, 3, 2, 3, 4, 4, 3, 5};
    CHECK(r->indices == expected);
    CHECK_EQ(r->face_count(), 4u);
    // Every triangle of the first strip has the same orientation (z of the 2D cross product).
    for (std::size_t f = 0; f < 3; ++f) {
        const vec3_t a = r->positions[r->indices[3 * f]], b = r->positions[r->indices[3 * f + 1]],
                     c = r->positions[r->indices[3 * f + 2]];
        CHECK((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) < 0);  // all clockwise, like the first
    }
    const result<mesh> bad = parse_ply("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                       "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
                                       "end_header\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2 -2\n", "s.ply");
    CHECK(!bad.ok() && bad.err().line == 13 && bad.err().reason.find("(-1 restarts a strip)") != std::string::npos);
}

TEST(ply_messages_count_right) {
    const std::string head = "ply\nformat ascii 1.0\n" + ply_vertices + "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const result<mesh> one = parse_ply(head + ply_square + "1 0\n", "m.ply");
    CHECK(!one.ok() && one.err().reason == "face 0 has 1 corner: a face needs at least 3");
    const result<mesh> range = parse_ply(head + ply_square + "3 0 1 4\n", "m.ply");
    CHECK(!range.ok() && range.err().reason == "face 0: vertex index 4 out of range: the file has 4 vertices");
}
