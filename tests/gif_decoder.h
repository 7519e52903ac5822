// tests/gif_decoder.h — the tests' own GIF89a decoder, written from the specification (the
// blocks and sub-blocks of its sections 17-27 and the variable-length-code LZW of its
// appendix F); it shares no code with the library's writer. decode_gif composites each
// image onto the picture (disposal "do not dispose"; a transparent index, which the writer
// never sets, is reported as a problem) and returns the whole picture after every image,
// with the blocks' fields, or a problem naming the byte.
#ifndef TINY3D_TEST_GIF_DECODER_H
#define TINY3D_TEST_GIF_DECODER_H

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace gif_decoder {

using bytes = std::vector<std::uint8_t>;

struct rect {
    int left, top, width, height;
};

struct decoded_gif {
    std::string problem;          // empty when the file decoded
    int width = 0, height = 0;
    bool grey_table = false;      // a 256-entry global table with entry i = (i, i, i)
    int loop_count = -2;          // NETSCAPE2.0 value, -1 when the block is absent
    std::vector<bytes> frames;    // the whole picture after each image, composited
    std::vector<int> delays;      // hundredths of a second
    std::vector<int> disposals;
    std::vector<rect> rects;
    int clear_codes = 0;          // clear codes seen after the first code of an image
};

inline std::string read_all(const std::string &path) {
    std::ifstream f(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

// Variable-length-code LZW decoding (GIF89a appendix F): codes least significant bit first,
// starting at min_code_size + 1 bits; a clear code resets the table and the width; each
// code after the first adds (previous string + first index of the current one); the width
// grows by one when the table's next free code reaches 2^width (never past 12 bits).
inline std::string lzw_decode(const bytes &data, int min_code_size, std::size_t expected, bytes &out, int &clears) {
    const int clear = 1 << min_code_size, end = clear + 1;
    std::vector<int> prefix(4096, -1), suffix(4096, 0), length(4096, 1);
    for (int i = 0; i < clear; ++i) suffix[i] = i;
    int width = min_code_size + 1, next = end + 1, previous = -1;
    std::size_t bit = 0;
    bool first_code = true;
    bytes string;
    auto first_of = [&](int code) {
        while (prefix[code] >= 0) code = prefix[code];
        return suffix[code];
    };
    auto emit = [&](int code) {
        string.assign(std::size_t(length[code]), 0);
        for (int c = code, i = length[code] - 1; i >= 0; c = prefix[c], --i) string[std::size_t(i)] = std::uint8_t(suffix[c]);
        out.insert(out.end(), string.begin(), string.end());
    };
    for (;;) {
        if (bit + std::size_t(width) > data.size() * 8) return "LZW data ends without an end code";
        int code = 0;
        for (int i = 0; i < width; ++i, ++bit) code |= ((data[bit / 8] >> (bit % 8)) & 1) << i;
        if (code == clear) {
            if (!first_code) ++clears;
            width = min_code_size + 1;
            next = end + 1;
            previous = -1;
            first_code = false;
            continue;
        }
        first_code = false;
        if (code == end) break;
        if (previous < 0) {
            if (code >= clear) return "first code after a clear is not a literal: " + std::to_string(code);
            emit(code);
        } else if (code < next) {
            emit(code);
            if (next < 4096) {
                prefix[next] = previous, suffix[next] = first_of(code), length[next] = length[previous] + 1;
                ++next;
            }
        } else if (code == next && next < 4096) {
            prefix[next] = previous, suffix[next] = first_of(previous), length[next] = length[previous] + 1;
            ++next;
            emit(code);
        } else {
            return "code " + std::to_string(code) + " beyond the table (next free " + std::to_string(next) + ")";
        }
        if (next == (1 << width) && width < 12) ++width;
        previous = code;
        if (out.size() > expected) return "more pixels than the image holds";
    }
    if (out.size() != expected) return "image holds " + std::to_string(out.size()) + " of " + std::to_string(expected) + " pixels";
    return "";
}

inline decoded_gif decode_gif(const std::string &file) {
    decoded_gif g;
    std::size_t at = 0;
    auto need = [&](std::size_t n) { return at + n <= file.size(); };
    auto u8 = [&]() { return int(std::uint8_t(file[at++])); };
    auto u16 = [&]() { const int lo = u8(); return lo | (u8() << 8); };
    auto fail = [&](const std::string &why) { g.problem = why + " at byte " + std::to_string(at); return g; };
    if (file.compare(0, 6, "GIF89a") != 0) return fail("no GIF89a signature");
    at = 6;
    if (!need(7)) return fail("short screen descriptor");
    g.width = u16(), g.height = u16();
    const int packed = u8();
    at += 2;  // background colour, aspect ratio
    if (!(packed & 0x80)) return fail("no global colour table");
    const int entries = 2 << (packed & 7);
    if (!need(std::size_t(entries) * 3)) return fail("short colour table");
    g.grey_table = entries == 256;
    for (int i = 0; i < entries; ++i)
        for (int c = 0; c < 3; ++c) g.grey_table = g.grey_table && u8() == i;
    bytes picture(std::size_t(g.width) * std::size_t(g.height), 0);
    int delay = -1, disposal = -1;
    g.loop_count = -1;
    auto read_sub_blocks = [&](bytes &into) {
        for (;;) {
            if (!need(1)) return false;
            const int n = u8();
            if (n == 0) return true;
            if (!need(std::size_t(n))) return false;
            into.insert(into.end(), file.begin() + long(at), file.begin() + long(at + std::size_t(n)));
            at += std::size_t(n);
        }
    };
    for (;;) {
        if (!need(1)) return fail("no trailer");
        const int introducer = u8();
        if (introducer == 0x3B) break;
        if (introducer == 0x21) {
            if (!need(1)) return fail("short extension");
            const int label = u8();
            bytes body;
            if (!read_sub_blocks(body)) return fail("short extension data");
            if (label == 0xF9) {
                if (body.size() != 4) return fail("graphic control extension of " + std::to_string(body.size()) + " bytes");
                disposal = (body[0] >> 2) & 7;
                if (body[0] & 1) return fail("transparency set");
                delay = body[1] | (body[2] << 8);
            } else if (label == 0xFF) {
                const std::string id(body.begin(), body.begin() + std::min<long>(11, long(body.size())));
                if (id != "NETSCAPE2.0" || body.size() != 14 || body[11] != 1) return fail("unknown application block");
                g.loop_count = body[12] | (body[13] << 8);
            }
            continue;
        }
        if (introducer != 0x2C) return fail("unknown block " + std::to_string(introducer));
        if (!need(10)) return fail("short image descriptor");
        rect r{u16(), u16(), u16(), u16()};
        const int image_packed = u8();
        if (image_packed & 0xC0) return fail("local table or interlace");
        if (r.width < 1 || r.height < 1 || r.left + r.width > g.width || r.top + r.height > g.height)
            return fail("image outside the screen");
        if (delay < 0) return fail("image without a graphic control extension");
        const int min_code_size = u8();
        bytes data, indices;
        if (!read_sub_blocks(data)) return fail("short image data");
        if (std::string e = lzw_decode(data, min_code_size, std::size_t(r.width) * std::size_t(r.height), indices,
                                       g.clear_codes);
            !e.empty())
            return fail("frame " + std::to_string(g.frames.size()) + ": " + e);
        for (int y = 0; y < r.height; ++y)
            for (int x = 0; x < r.width; ++x)
                picture[std::size_t(r.top + y) * std::size_t(g.width) + std::size_t(r.left + x)] =
                    indices[std::size_t(y) * std::size_t(r.width) + std::size_t(x)];
        g.frames.push_back(picture);
        g.delays.push_back(delay);
        g.disposals.push_back(disposal);
        g.rects.push_back(r);
        delay = -1;
    }
    if (at != file.size()) return fail("bytes after the trailer");
    return g;
}

}  // namespace gif_decoder

#endif
