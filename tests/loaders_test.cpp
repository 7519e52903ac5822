// loaders_test.cpp — OBJ and PLY loaders: every accepted form against hand-written expected
// meshes, binary files in both byte orders produced by a tiny writer below, and each
// malformed input giving an error at the right line / byte offset.
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "harness.h"
#include "canvas.h"
#include "math3d.h"
#include "mesh.h"

using namespace tiny3d;

namespace {

const std::string data_dir = "tests/data/";

bool same(vec3_t a, vec3_t b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// Checks that r failed at `place` — a 1-based line (text) or a byte offset (binary) — with
// a reason containing `words`.
enum class place_kind { line, byte };
void expect_error(const result<mesh> &r, place_kind kind, long place, const std::string &words, int at) {
    const std::string where = (kind == place_kind::line ? "line " : "byte ") + std::to_string(place);
    if (r.ok()) {
        tiny_test::fail(__FILE__, at, "expected an error at " + where + ", got a mesh");
        return;
    }
    const long got = kind == place_kind::line ? r.err().line : r.err().byte_offset;
    if (got != place || r.err().reason.find(words) == std::string::npos)
        tiny_test::fail(__FILE__, at, "expected " + where + " '" + words + "', got: " + r.message());
}
#define EXPECT_LINE_ERROR(r, at_line, words) expect_error(r, place_kind::line, at_line, words, __LINE__)
#define EXPECT_BYTE_ERROR(r, off, words) expect_error(r, place_kind::byte, off, words, __LINE__)

// ---- a tiny binary PLY writer (both byte orders, any scalar type) ----
struct ply_writer {
    bool big_endian;
    std::string bytes;
    void raw(const void *p, std::size_t n) {
        const char *c = static_cast<const char *>(p);
        for (std::size_t k = 0; k < n; ++k) bytes.push_back(c[big_endian ? n - 1 - k : k]);  // host is LE
    }
    template <class T>
    void put(T v) { raw(&v, sizeof v); }
};

// The tetrahedron of tests/data/tetra_ascii.ply, written in binary with a mix of types.
std::string binary_tetra(bool big_endian) {
    ply_writer w{big_endian, {}};
    w.bytes = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
              " 1.0\ncomment made by loaders_test\n"
              "element vertex 4\nproperty double z\nproperty uchar red\nproperty list ushort short junk\n"
              "property float x\nproperty int16 y\n"
              "element material 1\nproperty list uint char name\n"
              "element face 4\nproperty int8 tag\nproperty list uchar uint vertex_indices\nend_header\n";
    const int xyz[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    for (int i = 0; i < 4; ++i) {
        w.put(double(xyz[i][2]));
        w.put(std::uint8_t(200));
        w.put(std::uint16_t(i));  // i junk shorts
        for (int j = 0; j < i; ++j) w.put(std::int16_t(-j));
        w.put(float(xyz[i][0]));
        w.put(std::int16_t(xyz[i][1]));
    }
    w.put(std::uint32_t(3));
    w.bytes += "abc";
    const unsigned faces[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
    for (const auto &f : faces) {
        w.put(std::int8_t(-5));
        w.put(std::uint8_t(3));
        for (unsigned idx : f) w.put(std::uint32_t(idx));
    }
    return w.bytes;
}

void check_tetra(const mesh &m) {
    CHECK_EQ(m.positions.size(), 4u);
    CHECK_EQ(m.face_count(), 4u);
    CHECK_EQ(m.edges.size(), 6u);
    if (m.positions.size() != 4 || m.face_count() != 4) return;
    CHECK(same(m.positions[0], vec3_t{1, 1, 1}));
    CHECK(same(m.positions[3], vec3_t{-1, -1, 1}));
    const std::vector<std::uint32_t> expected = {0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2};
    CHECK(m.indices == expected);
}

}  // namespace

// ---------------------------------------------------------------- OBJ

TEST(obj_every_face_form_and_ngons) {
    const char *text =
        "# comment line\n"
        "mtllib x.mtl\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0   # trailing comment\nv 0 1 0 1.0\nv +0.5 2e0 -0\n"
        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0.25\n"
        "vn 0 0 1\nvn 0 0 -1\n"
        "g group\nusemtl m\ns 1\n"
        "f 1 2 3\n"
        "f 1/1 2/2 3/3\n"
        "f 1//1 2//2 3//1\n"
        "f 1/1/1 2/2/2 3/3/2 4/4/1 5/1/1\n"
        "l 1 2\n";
    const result<mesh> r = parse_obj(text, "forms.obj");
    CHECK_MSG(r.ok(), r.message());
    if (!r.ok()) return;
    const mesh &m = *r;
    CHECK_EQ(m.positions.size(), 5u);
    CHECK_EQ(m.face_count(), 4u);
    CHECK_EQ(m.face_size(3), 5u);
    CHECK(same(m.positions[4], vec3_t{0.5f, 2.0f, 0.0f}));
    CHECK_EQ(m.corner_uvs.size(), m.indices.size());
    CHECK_EQ(m.corner_normals.size(), m.indices.size());
    // Face 0 has no attributes → zeros; face 1 corner 2 = vt 3; face 3 corner 3 = vt 4 (0.25, 0).
    CHECK(m.corner_uvs[0].x == 0 && m.corner_uvs[0].y == 0);
    CHECK(m.corner_uvs[5].x == 1 && m.corner_uvs[5].y == 1);
    CHECK(m.corner_uvs[12].x == 0.25f && m.corner_uvs[12].y == 0);
    CHECK(same(m.corner_normals[7], vec3_t{0, 0, -1}));   // face 2 corner 1 = vn 2
    CHECK(same(m.corner_normals[1], vec3_t{0, 0, 0}));    // face 0: none
    CHECK(same(m.corner_normals[11], vec3_t{0, 0, -1}));  // face 3 corner 2 = vn 2
    // Triangles: 0-1, 1-2, 0-2; the pentagon adds 2-3, 3-4, 0-4 (it shares 0-1, 1-2).
    CHECK_EQ(m.edges.size(), 6u);
}

TEST(obj_negative_indices_crlf_and_continuation) {
    const char *text = "v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nf -3 -2 -1\r\nv 0 1 \\\n 0\nf 1 -2 \\\r\n -1\n";
    const result<mesh> r = parse_obj(text, "neg.obj");
    CHECK_MSG(r.ok(), r.message());
    if (!r.ok()) return;
    const std::vector<std::uint32_t> expected = {0, 1, 2, 0, 2, 3};
    CHECK(r->indices == expected);
    CHECK(same(r->positions[3], vec3_t{0, 1, 0}));
    CHECK(r->corner_uvs.empty());
    CHECK(r->corner_normals.empty());
}

TEST(obj_forward_reference_allowed) {
    const result<mesh> r = parse_obj("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "fwd.obj");
    CHECK_MSG(r.ok(), r.message());
}

TEST(obj_file_on_disk) {
    const result<mesh> r = load_obj(data_dir + "cube_quads.obj");
    CHECK_MSG(r.ok(), r.message());
    if (!r.ok()) return;
    CHECK_EQ(r->positions.size(), 8u);
    CHECK_EQ(r->face_count(), 6u);
    CHECK_EQ(r->edges.size(), 12u);
    CHECK_EQ(r->corner_uvs.size(), 24u);
    CHECK(mesh_validate(*r).ok());
    const result<mesh> missing = load_obj(data_dir + "no_such_file.obj");
    CHECK(!missing.ok());
    CHECK(!missing.ok() && missing.message().find("no_such_file.obj") != std::string::npos);
    const result<mesh> by_ext = load_mesh(data_dir + "cube_quads.obj");
    CHECK(by_ext.ok());
    CHECK(!load_mesh("model.stl").ok());
}

TEST(obj_malformed_files_name_the_line) {
    EXPECT_LINE_ERROR(parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "a.obj"), 4, "out of range");
    EXPECT_LINE_ERROR(parse_obj("v 0 0 0\nv 1 0 0\n\nf 1 2 0\n", "a.obj"), 4, "index 0 in '0': OBJ indices start at 1");
    EXPECT_LINE_ERROR(parse_obj("v 0 0 0\nv 1 0 0\nf 1 2\n", "a.obj"), 3, "2 corners");
    EXPECT_LINE_ERROR(parse_obj("v 0 0 0\nv 1 x 0\n", "a.obj"), 2, "bad number");
    EXPECT_LINE_ERROR(parse_obj("v 0 0\n", "a.obj"), 1, "needs 3");
    EXPECT_LINE_ERROR(parse_obj("v nan 0 0\n", "a.obj"), 1, "bad number");
    EXPECT_LINE_ERROR(parse_obj("v 1e39 0 0\n", "a.obj"), 1, "bad number");
    EXPECT_LINE_ERROR(parse_obj("v 0 0 0\nf -1 -2 -3\n", "a.obj"), 2, "before the first");
    EXPECT_LINE_ERROR(parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n# c\nf 1/1 2/1 3/2\n", "a.obj"), 6,
                      "texture index 2 out of range: the file has 1 texture coordinate");
    EXPECT_LINE_ERROR(parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//2 2//1 3//1\n", "a.obj"), 5, "normal index 2");
    EXPECT_LINE_ERROR(parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n", "a.obj"), 4, "bad face corner");
    EXPECT_LINE_ERROR(parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf /1 2 3\n", "a.obj"), 4, "position index is missing");
    EXPECT_LINE_ERROR(parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n", "a.obj"), 4,
                      "bad face corner");
    const result<mesh> r = parse_obj("v 0 0 0\nf 1 1 2\n", "named.obj");
    CHECK(!r.ok() && r.message().rfind("named.obj:2: ", 0) == 0);
}

// ---------------------------------------------------------------- PLY

TEST(ply_ascii_file_skips_extra_properties_and_elements) {
    const result<mesh> r = load_ply(data_dir + "tetra_ascii.ply");
    CHECK_MSG(r.ok(), r.message());
    if (r.ok()) check_tetra(*r);
}

TEST(ply_binary_both_byte_orders) {
    for (bool big : {false, true}) {
        const result<mesh> r = parse_ply(binary_tetra(big), big ? "be.ply" : "le.ply");
        CHECK_MSG(r.ok(), r.message());
        if (r.ok()) check_tetra(*r);
    }
    // The same bytes read with the wrong byte order give an error, not garbage.
    std::string swapped = binary_tetra(true);
    swapped.replace(swapped.find("binary_big_endian"), 17, "binary_little_endian");
    CHECK(!parse_ply(swapped, "swapped.ply").ok());
}

TEST(ply_header_any_order_and_vertex_index_name) {
    const char *text =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty double z\nproperty double x\nproperty double y\n"
        "element face 1\nproperty list int int vertex_index\nend_header\n"
        "3 1 2\n6 4 5\n9 7 8\n3 2 1 0\n";
    const result<mesh> r = parse_ply(text, "order.ply");
    CHECK_MSG(r.ok(), r.message());
    if (!r.ok()) return;
    CHECK(same(r->positions[0], vec3_t{1, 2, 3}));
    CHECK(same(r->positions[2], vec3_t{7, 8, 9}));
    CHECK_EQ(r->face_count(), 1u);
    CHECK_EQ(r->indices[0], 2u);
}

TEST(ply_malformed_ascii_names_the_line) {
    const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uchar int vertex_indices\nend_header\n";  // data at line 10
    EXPECT_LINE_ERROR(parse_ply(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "a.ply"), 13, "out of range");
    EXPECT_LINE_ERROR(parse_ply(head + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n", "a.ply"), 11, "bad number");
    EXPECT_LINE_ERROR(parse_ply(head + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "a.ply"), 13, "2 corners");
    EXPECT_LINE_ERROR(parse_ply(head + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "a.ply"), 13, "out of range");
    EXPECT_LINE_ERROR(parse_ply(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n7\n", "a.ply"), 14, "after the last element");
    EXPECT_LINE_ERROR(parse_ply(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n", "a.ply"), 13, "line has 3 values, the header declares 4");
    EXPECT_LINE_ERROR(parse_ply(head + "0.0000000 0 0\n1.0000000 0 0\n", "a.ply"), 12,
                      "unexpected end of file: element 'vertex' has 3 entries, the data ends after 2");
    EXPECT_LINE_ERROR(parse_ply(head + "0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n", "a.ply"), 11, "bad number");
    EXPECT_LINE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n",
                                "a.ply"),
                      3, "x, y and z");
    EXPECT_LINE_ERROR(parse_ply("ply\nformat ascii 2.0\nend_header\n", "a.ply"), 2, "version");
    EXPECT_LINE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "a.ply"), 4, "end_header");
    EXPECT_LINE_ERROR(parse_ply("plyx\n", "a.ply"), 1, "not a PLY");
    EXPECT_LINE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty flot x\nend_header\n", "a.ply"), 4,
                      "unknown property type");
    EXPECT_LINE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex -1\nend_header\n", "a.ply"), 3, "bad element");
}

TEST(ply_counts_checked_before_allocating) {
    // 2^40 vertices announced in a file of about 100 bytes: an error at once, at the header line.
    const std::string huge = "ply\nformat binary_little_endian 1.0\nelement vertex 1099511627776\n"
                             "property float x\nproperty float y\nproperty float z\nend_header\n" +
                             std::string(12, '\0');
    EXPECT_LINE_ERROR(parse_ply(huge, "huge.ply"), 3, "announces");
    const std::string many_faces = "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                                   "property float z\nelement face 4000000000\nproperty list uchar int vertex_indices\n"
                                   "end_header\n";
    EXPECT_LINE_ERROR(parse_ply(many_faces, "faces.ply"), 7, "announces");
    // Each element fits the data alone, not both together: 2 vertices × 12 bytes and 2
    // "extra" entries × 12 bytes need 48 of the 36 bytes there: the second one is refused at
    // its header line, with the bytes there are.
    const std::string together = "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n"
                                 "property float y\nproperty float z\nelement extra 2\nproperty float a\n"
                                 "property float b\nproperty float c\nend_header\n" +
                                 std::string(36, '\0');
    EXPECT_LINE_ERROR(parse_ply(together, "together.ply"), 7, "more than the 36 bytes");
    // An empty element with a giant count costs nothing and is accepted.
    const result<mesh> empty = parse_ply("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                                         "property float z\nelement nothing 18446744073\nend_header\n",
                                         "empty.ply");
    CHECK_MSG(empty.ok(), empty.message());
}

TEST(ply_malformed_binary_names_the_byte) {
    const std::string good = binary_tetra(false);
    const std::size_t data = good.find("end_header\n") + 11;
    // Cut inside vertex 1: the announced counts no longer fit → error at the header line.
    constexpr std::size_t vertex0_bytes = 17;  // z double, red, ushort count 0, x float, y int16
    EXPECT_LINE_ERROR(parse_ply(good.substr(0, data + vertex0_bytes + 5), "t.ply"), 4, "announces");
    // Cut inside face 2's indices (the counts still fit): the list is found to run past the
    // end at its count byte; cut right after face 3's tag: the count read is truncated.
    constexpr std::size_t face_bytes = 1 + 1 + 3 * 4;  // tag, count, three uint32
    const std::size_t faces = good.size() - 4 * face_bytes;
    EXPECT_BYTE_ERROR(parse_ply(good.substr(0, faces + 2 * face_bytes + 8), "t.ply"), long(faces + 2 * face_bytes + 1),
                      "past the end");
    const std::size_t cut = faces + 3 * face_bytes + 1;
    EXPECT_BYTE_ERROR(parse_ply(good.substr(0, cut), "t.ply"), long(cut), "truncated");
    // A face index out of range: patch the first index of face 0 to 9.
    std::string bad = good;
    bad[faces + 2] = 9;
    EXPECT_BYTE_ERROR(parse_ply(bad, "idx.ply"), long(faces + 2), "out of range");
    // A face with 2 corners: count byte 2.
    bad = good;
    bad[faces + 1] = 2;
    EXPECT_BYTE_ERROR(parse_ply(bad, "two.ply"), long(faces + 1), "2 corners");
    // A list count running past the end of the file.
    bad = good;
    bad[faces + 1] = char(200);
    EXPECT_BYTE_ERROR(parse_ply(bad, "long.ply"), long(faces + 1), "past the end");
    // Trailing bytes.
    EXPECT_BYTE_ERROR(parse_ply(good + "xy", "tail.ply"), long(good.size()), "after the last element");
    // A NaN coordinate (vertex 0's z, a double).
    bad = good;
    const double nan = std::nan("");
    std::memcpy(&bad[data], &nan, sizeof nan);
    EXPECT_BYTE_ERROR(parse_ply(bad, "nan.ply"), long(data), "not a finite");
    // Every prefix of the file is an error (and never a crash).
    for (std::size_t n = 0; n < good.size(); ++n) CHECK(!parse_ply(good.substr(0, n), "prefix.ply").ok());
}

TEST(loaders_survive_seeded_mutations) {
    // Random byte edits of valid files: each parse returns a mesh that validates, or an error.
    std::mt19937 rng(20261123);
    const std::string ascii_ply = read_file_bytes(data_dir + "tetra_ascii.ply").value();
    const std::string obj = read_file_bytes(data_dir + "cube_quads.obj").value();
    const std::string sources[] = {binary_tetra(false), binary_tetra(true), ascii_ply, obj};
    const char interesting[] = {'0', '9', '-', ' ', '\n', '/', '\\', char(0xff), char(0), 'e'};
    int meshes = 0, errors = 0;
    for (int round = 0; round < 1500; ++round) {
        const std::size_t which = round % 4;
        std::string bytes = sources[which];
        const int edits = 1 + int(rng() % 3);
        for (int e = 0; e < edits; ++e) {
            const std::size_t at = rng() % bytes.size();
            bytes[at] = (rng() & 1) ? interesting[rng() % sizeof interesting] : char(rng());
        }
        const result<mesh> r = which == 3 ? parse_obj(bytes, "m.obj") : parse_ply(bytes, "m.ply");
        if (r.ok()) {
            ++meshes;
            CHECK_MSG(mesh_validate(*r).ok(), mesh_validate(*r).message());
        } else {
            ++errors;
            CHECK(!r.err().reason.empty());
        }
    }
    CHECK(meshes > 0);
    CHECK(errors > 0);
}
