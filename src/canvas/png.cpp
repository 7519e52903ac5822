// png.cpp — minimal greyscale PNG writer: stored deflate blocks, CRC-32 and Adler-32.
//
// File layout (PNG spec, RFC 2083; zlib RFC 1950; deflate RFC 1951):
//   signature 89 50 4E 47 0D 0A 1A 0A
//   chunk = length (4 bytes, big-endian, data only) + type (4) + data + CRC-32 of type+data
//   IHDR: width, height (4 each), bit depth 8, colour type 0 (grey), compression 0,
//         filter 0, interlace 0
//   IDAT: zlib stream = header 78 01, deflate blocks, Adler-32 of the raw data (big-endian)
//         raw data = for each row: filter byte 0, then width grey bytes
//         stored block = BFINAL|BTYPE=00 byte, LEN, NLEN = ~LEN (little-endian), LEN bytes
//   IEND: empty
#include <algorithm>
#include <array>
#include <cmath>

#include "canvas.h"

namespace tiny3d {
namespace {

// CRC-32 table for the reflected polynomial 0xEDB88320, built at compile time.
constexpr std::array<std::uint32_t, 256> make_crc_table() {
    constexpr std::uint32_t polynomial = 0xEDB88320u;
    std::array<std::uint32_t, 256> table{};
    for (std::uint32_t n = 0; n < 256; ++n) {
        std::uint32_t c = n;
        for (int bit = 0; bit < 8; ++bit) c = (c & 1) ? polynomial ^ (c >> 1) : c >> 1;
        table[n] = c;
    }
    return table;
}
constexpr std::array<std::uint32_t, 256> crc_table = make_crc_table();

constexpr std::size_t max_stored_block = 65535;  // LEN is 16 bits
constexpr std::uint8_t png_signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
// zlib header: CMF 0x78 (deflate, 32 KiB window), FLG 0x01 (fastest; (CMF·256+FLG) % 31 == 0).
constexpr std::uint8_t zlib_header[2] = {0x78, 0x01};
constexpr std::uint8_t grey_bit_depth = 8, grey_colour_type = 0;

void put_u32_be(std::vector<std::uint8_t> &out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(v >> shift));
}

void put_chunk(std::vector<std::uint8_t> &out, const char (&type)[5], std::span<const std::uint8_t> data) {
    put_u32_be(out, std::uint32_t(data.size()));
    const std::size_t type_at = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    put_u32_be(out, crc32(std::span(out).subspan(type_at)));
}

std::uint8_t grey_byte(float v) {
    if (!(v > 0.0f)) return 0;  // also NaN
    if (v >= 1.0f) return 255;
    return std::uint8_t(std::lround(v * 255.0f));
}

}  // namespace

std::uint32_t crc32(std::span<const std::uint8_t> bytes) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (const std::uint8_t b : bytes) c = crc_table[(c ^ b) & 0xFFu] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

std::uint32_t adler32(std::span<const std::uint8_t> bytes) {
    constexpr std::uint32_t modulus = 65521;  // largest prime below 2^16
    // 5552 bytes is the most that can be summed before b may overflow 32 bits.
    constexpr std::size_t max_run = 5552;
    std::uint32_t a = 1, b = 0;
    for (std::size_t start = 0; start < bytes.size(); start += max_run) {
        const std::size_t end = std::min(bytes.size(), start + max_run);
        for (std::size_t i = start; i < end; ++i) {
            a += bytes[i];
            b += a;
        }
        a %= modulus;
        b %= modulus;
    }
    return (b << 16) | a;
}

std::vector<std::uint8_t> encode_png(const canvas_t &canvas) {
    const std::size_t w = std::size_t(std::max(canvas.width, 0)), h = std::size_t(std::max(canvas.height, 0));
    std::vector<std::uint8_t> raw;
    raw.reserve(h * (w + 1));
    for (std::size_t y = 0; y < h; ++y) {
        raw.push_back(0);  // filter type 0: none
        for (std::size_t x = 0; x < w; ++x) raw.push_back(grey_byte(canvas.data[y * w + x]));
    }

    std::vector<std::uint8_t> z(zlib_header, zlib_header + 2);
    std::size_t pos = 0;
    do {  // at least one (possibly empty) final block
        const std::size_t len = std::min(max_stored_block, raw.size() - pos);
        const bool final_block = pos + len == raw.size();
        z.push_back(final_block ? 1 : 0);  // BFINAL bit, BTYPE 00 = stored
        z.push_back(std::uint8_t(len));
        z.push_back(std::uint8_t(len >> 8));
        z.push_back(std::uint8_t(~len));
        z.push_back(std::uint8_t(~len >> 8));
        z.insert(z.end(), raw.begin() + std::ptrdiff_t(pos), raw.begin() + std::ptrdiff_t(pos + len));
        pos += len;
    } while (pos < raw.size());
    put_u32_be(z, adler32(raw));

    std::vector<std::uint8_t> header;
    put_u32_be(header, std::uint32_t(w));
    put_u32_be(header, std::uint32_t(h));
    header.insert(header.end(), {grey_bit_depth, grey_colour_type, 0, 0, 0});

    std::vector<std::uint8_t> png(png_signature, png_signature + 8);
    put_chunk(png, "IHDR", header);
    put_chunk(png, "IDAT", z);
    put_chunk(png, "IEND", {});
    return png;
}

status save_png(const canvas_t &canvas, const std::string &path) {
    if (!canvas.data || canvas.width <= 0 || canvas.height <= 0)
        return error{path, 0, -1, "cannot save PNG: empty canvas"};
    return save_encoded(path, canvas, [&] { return encode_png(canvas); });
}

}  // namespace tiny3d
