// png_test.cpp — the library's PNG bytes (canvas.h: crc32, adler32, encode_png, save_png)
// against a small independent reader of stored-block PNG files written here.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "canvas.h"
#include "harness.h"

namespace {

std::vector<std::uint8_t> bytes_of(const std::string &s) { return {s.begin(), s.end()}; }

std::uint32_t be32(const std::vector<std::uint8_t> &b, std::size_t at) {
    return (std::uint32_t(b[at]) << 24) | (std::uint32_t(b[at + 1]) << 16) | (std::uint32_t(b[at + 2]) << 8) |
           std::uint32_t(b[at + 3]);
}

// Bitwise CRC-32 (no table), an independent check of the library's table version.
std::uint32_t crc32_bitwise(const std::uint8_t *p, std::size_t n) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < n; ++i) {
        c ^= p[i];
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return ~c;
}

struct decoded_png {
    bool ok = false;
    std::string why;
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> raw;  // inflated scan lines (filter byte + pixels per row)
    std::vector<std::string> chunk_types;
};

// A small independent PNG reader for stored-block zlib streams: checks the signature,
// every chunk CRC, the zlib header, each stored block's LEN/NLEN and the Adler-32.
decoded_png decode_stored_png(const std::vector<std::uint8_t> &png) {
    decoded_png d;
    const std::uint8_t signature[8] = {0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A};
    if (png.size() < 8 || !std::equal(signature, signature + 8, png.begin())) return d.why = "signature", d;
    std::vector<std::uint8_t> z;
    std::size_t p = 8;
    while (p + 12 <= png.size()) {
        const std::uint32_t len = be32(png, p);
        if (p + 12 + len > png.size()) return d.why = "chunk overruns file", d;
        const std::string type(png.begin() + std::ptrdiff_t(p + 4), png.begin() + std::ptrdiff_t(p + 8));
        if (crc32_bitwise(&png[p + 4], len + 4) != be32(png, p + 8 + len)) return d.why = "CRC of " + type, d;
        d.chunk_types.push_back(type);
        if (type == "IHDR") {
            d.width = be32(png, p + 8);
            d.height = be32(png, p + 12);
            if (png[p + 16] != 8 || png[p + 17] != 0 || png[p + 18] != 0 || png[p + 19] != 0 || png[p + 20] != 0)
                return d.why = "IHDR fields", d;
        }
        if (type == "IDAT") z.insert(z.end(), png.begin() + std::ptrdiff_t(p + 8), png.begin() + std::ptrdiff_t(p + 8 + len));
        p += 12 + len;
    }
    if (p != png.size()) return d.why = "trailing bytes", d;
    if (z.size() < 6 || (z[0] * 256 + z[1]) % 31 != 0 || (z[0] & 0x0F) != 8) return d.why = "zlib header", d;
    std::size_t q = 2;
    bool final_block = false;
    while (!final_block) {
        if (q + 5 > z.size()) return d.why = "truncated block", d;
        final_block = z[q] & 1;
        if ((z[q] >> 1) != 0) return d.why = "not a stored block", d;
        const unsigned len = z[q + 1] | (z[q + 2] << 8), nlen = z[q + 3] | (z[q + 4] << 8);
        if ((len ^ 0xFFFFu) != nlen) return d.why = "LEN/NLEN", d;
        if (q + 5 + len > z.size()) return d.why = "block overruns", d;
        d.raw.insert(d.raw.end(), z.begin() + std::ptrdiff_t(q + 5), z.begin() + std::ptrdiff_t(q + 5 + len));
        q += 5 + len;
    }
    if (q + 4 != z.size()) return d.why = "adler position", d;
    // Adler-32 straight from RFC 1950's definition, in 64-bit sums.
    std::uint64_t a = 1, b = 0;
    for (const std::uint8_t v : d.raw) {
        a = (a + v) % 65521;
        b = (b + a) % 65521;
    }
    if (((b << 16) | a) != be32(z, q)) return d.why = "adler", d;
    d.ok = true;
    return d;
}

}  // namespace

// ---- PNG ----------------------------------------------------------------------------

TEST(checksums_match_published_check_values) {
    CHECK_EQ(tiny3d::crc32(bytes_of("123456789")), 0xCBF43926u);
    CHECK_EQ(tiny3d::crc32(bytes_of("IEND")), 0xAE426082u);  // the CRC every PNG ends with
    CHECK_EQ(tiny3d::crc32(bytes_of("")), 0u);
    CHECK_EQ(tiny3d::adler32(bytes_of("Wikipedia")), 0x11E60398u);
    CHECK_EQ(tiny3d::adler32(bytes_of("")), 1u);
    // Long input: the library defers the modulo; compare with a per-byte-modulo version.
    std::vector<std::uint8_t> ff(100000, 0xFF);
    std::uint64_t a = 1, b = 0;
    for (const std::uint8_t v : ff) { a = (a + v) % 65521; b = (b + a) % 65521; }
    CHECK_EQ(tiny3d::adler32(ff), std::uint32_t((b << 16) | a));
    CHECK_EQ(tiny3d::crc32(ff), crc32_bitwise(ff.data(), ff.size()));
}

TEST(png_of_a_small_canvas_decodes_to_its_values) {
    auto c = tiny3d::make_canvas(3, 2).value();
    const float values[6] = {0.0f, 0.5f, 1.0f, 0.2f, 0.999f, 0.001f};
    for (int i = 0; i < 6; ++i) c->data[i] = values[i];
    // round(v · 255): 0, 127.5 → 128, 255, 51, 254.745 → 255, 0.255 → 0
    const std::uint8_t expected[2][4] = {{0, 0, 128, 255}, {0, 51, 255, 0}};
    const std::vector<std::uint8_t> png = tiny3d::encode_png(*c);
    const decoded_png d = decode_stored_png(png);
    CHECK_MSG(d.ok, d.why);
    CHECK_EQ(d.width, 3u);
    CHECK_EQ(d.height, 2u);
    CHECK(d.chunk_types == std::vector<std::string>({"IHDR", "IDAT", "IEND"}));
    CHECK_EQ(d.raw.size(), std::size_t(8));
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) CHECK_EQ(int(d.raw[std::size_t(y * 4 + x)]), int(expected[y][x]));
    // The last 12 bytes are the fixed IEND chunk.
    const std::uint8_t iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
    CHECK(std::equal(iend, iend + 12, png.end() - 12));
}

TEST(png_splits_large_images_into_stored_blocks) {
    auto c = tiny3d::make_canvas(301, 257).value();  // 302 · 257 = 77,614 raw bytes: two stored blocks
    std::mt19937 rng(808);
    std::uniform_real_distribution<float> u(-0.2f, 1.2f);
    for (int i = 0; i < 301 * 257; ++i) c->data[i] = u(rng);
    const decoded_png d = decode_stored_png(tiny3d::encode_png(*c));
    CHECK_MSG(d.ok, d.why);
    CHECK_EQ(d.raw.size(), std::size_t(302 * 257));
    int wrong = 0;
    for (int y = 0; y < 257; ++y) {
        wrong += d.raw[std::size_t(y * 302)] != 0;
        for (int x = 0; x < 301; ++x) {
            const double v = std::min(1.0, std::max(0.0, double(c->pixels[y][x])));
            wrong += d.raw[std::size_t(y * 302 + 1 + x)] != std::uint8_t(std::floor(v * 255.0 + 0.5));
        }
    }
    CHECK_EQ(wrong, 0);
}

TEST(save_png_reports_failures_and_leaves_nothing) {
    auto c = tiny3d::make_canvas(4, 4).value();
    const tiny3d::status s = tiny3d::save_png(*c, "/nonexistent-folder-tiny3d/x.png");
    CHECK(!s.ok());
    if (!s.ok()) CHECK(s.message().find("/nonexistent-folder-tiny3d/x.png") != std::string::npos);
    char tmpl[] = "/tmp/png_test_XXXXXX";
    const char *dir = mkdtemp(tmpl);
    CHECK(dir != nullptr);
    if (!dir) return;
    const std::string path = std::string(dir) + "/c.png";
    CHECK(tiny3d::save_png(*c, path).ok());
    std::FILE *f = std::fopen(path.c_str(), "rb");
    CHECK(f != nullptr);
    if (f) {
        std::vector<std::uint8_t> bytes(4096);
        bytes.resize(std::fread(bytes.data(), 1, bytes.size(), f));
        std::fclose(f);
        CHECK(bytes == tiny3d::encode_png(*c));
    }
    std::remove(path.c_str());
    rmdir(dir);
}
