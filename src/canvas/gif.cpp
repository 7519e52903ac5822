// gif.cpp — animated GIF89a output for grey canvases (canvas.h documents the format choices).
// Block layout from the GIF89a specification (W3C/CompuServe 1990): header, logical screen
// descriptor with a 256-entry global colour table, NETSCAPE2.0 loop block, then per frame a
// graphic control extension (delay, disposal) and an image descriptor with LZW data in
// sub-blocks of at most 255 bytes, and the trailer 0x3B.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "canvas.h"
#include "../simd_config.h"

#ifdef TINY3D_SSE2
#include <emmintrin.h>
#endif

namespace tiny3d {
namespace {

constexpr int kMinCodeSize = 8;             // 256 colours: literal codes 0..255
constexpr unsigned kClearCode = 256, kEndCode = 257, kFirstFreeCode = 258;
constexpr unsigned kTableFull = 4095;       // past this the table is cleared (codes stay ≤ 12 bits)
constexpr int kMaxCodeBits = 12;
constexpr int kGifMaxSide = 65535;          // 16-bit sizes in the descriptors
constexpr double kMinFps = 0.01, kMaxFps = 50.0;

// The PGM byte of an intensity, as save_pgm rounds it: round(clamp(v, 0, 1)·255), NaN → 0,
// halves away from zero like std::lround. With s the float product save_pgm rounds (s ≥ 0),
// floor(s + 1/2) = floor((floor(2s) + 1) / 2), and 2s is exact: integer steps only, no
// branch (the loop below vectorises).
inline std::uint8_t grey_byte(float v) {
    const float clamped = std::min(1.0f, std::max(0.0f, v));  // max(0, NaN) is 0
    const int twice = int(2.0f * (clamped * 255.0f));
    return std::uint8_t((twice + 1) >> 1);
}

// grey_byte of n intensities. The SSE2 path computes the same float steps four lanes at a
// time: MAXPS(v, 0) gives 0 for NaN as max(0, v) does, the product and the doubling round
// alike, and CVTTPS2DQ truncates as int() does (tests/gif_test.cpp checks both paths
// against save_pgm, `make test-portable` the portable one).
void to_grey_bytes(const float *values, std::uint8_t *bytes, std::size_t n) {
    std::size_t i = 0;
#ifdef TINY3D_SSE2
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f), scale = _mm_set1_ps(255.0f), two = _mm_set1_ps(2.0f);
    const __m128i half_up = _mm_set1_epi32(1);
    const auto lanes = [&](std::size_t at) {
        const __m128 clamped = _mm_min_ps(_mm_max_ps(_mm_loadu_ps(values + at), zero), one);
        const __m128i twice = _mm_cvttps_epi32(_mm_mul_ps(two, _mm_mul_ps(clamped, scale)));
        return _mm_srli_epi32(_mm_add_epi32(twice, half_up), 1);
    };
    for (; i + 16 <= n; i += 16) {
        const __m128i low = _mm_packs_epi32(lanes(i), lanes(i + 4)), high = _mm_packs_epi32(lanes(i + 8), lanes(i + 12));
        _mm_storeu_si128(reinterpret_cast<__m128i *>(bytes + i), _mm_packus_epi16(low, high));
    }
#endif
    for (; i < n; ++i) bytes[i] = grey_byte(values[i]);
}

void put_u16(std::vector<std::uint8_t> &out, unsigned v) {
    out.push_back(std::uint8_t(v & 0xFF));
    out.push_back(std::uint8_t(v >> 8));
}

// The smallest rectangle holding every index that differs between two frames.
struct rectangle {
    int left = 0, top = 0, width = 0, height = 0;
};

rectangle changed_rectangle(const std::vector<std::uint8_t> &now, const std::vector<std::uint8_t> &before, int width,
                            int height) {
    const std::size_t stride = std::size_t(width);
    auto row_differs = [&](int y) { return std::memcmp(&now[y * stride], &before[y * stride], stride) != 0; };
    int top = 0;
    while (top < height && !row_differs(top)) ++top;
    if (top == height) return {0, 0, 1, 1};  // unchanged: one pixel, equal to the one shown
    int bottom = height - 1;
    while (!row_differs(bottom)) --bottom;
    int left = width, right = -1;
    for (int y = top; y <= bottom; ++y) {
        const std::uint8_t *a = &now[y * stride], *b = &before[y * stride];
        int x = 0;
        while (x < left && a[x] == b[x]) ++x;
        left = std::min(left, x);
        int r = width - 1;
        while (r > right && a[r] == b[r]) --r;
        right = std::max(right, r);
    }
    return {left, top, right - left + 1, bottom - top + 1};
}

// GIF's variable-length-code LZW (GIF89a appendix F). The codes are packed least
// significant bit first into a byte stream, which is then cut into the data sub-blocks
// (each preceded by its length, 1..255; a 0 block ends them). The string table maps
// (prefix code, next index) to a code through an open-addressed hash table at most half
// full (4,096 codes in 8,192 slots), cleared with each clear code.
class lzw_encoder {
public:
    // Room for the codes of a rectangle of up to `pixels` indices, so that encode() never
    // allocates: a code per index at most, plus the clears (one per 3,837 codes) and the
    // first and last codes, of at most 12 bits each.
    void reserve(std::size_t pixels) { packed_.resize((pixels + pixels / 1000 + 4) * std::size_t(kMaxCodeBits) / 8 + 8); }

    // Appends the image data of the rectangle r of `indices` (rows of `stride`) to `out`:
    // the minimum code size, then the sub-blocks.
    void encode(const std::vector<std::uint8_t> &indices, int stride, const rectangle &r, std::vector<std::uint8_t> &out) {
        used_ = 0;
        bits_ = 0;
        bit_count_ = 0;
        reset();
        put_code(kClearCode);
        unsigned prefix = indices[std::size_t(r.top) * std::size_t(stride) + std::size_t(r.left)];
        bool first = true;
        for (int y = r.top; y < r.top + r.height; ++y) {
            const std::uint8_t *row = &indices[std::size_t(y) * std::size_t(stride)];
            for (int x = r.left; x < r.left + r.width; ++x) {
                if (first) {  // the first index only starts the first string
                    first = false;
                    continue;
                }
                const unsigned next = row[x];
                const std::uint32_t key = (prefix << 8) | next;
                std::uint32_t slot = hash(key);
                while (keys_[slot] != kEmpty && keys_[slot] != key) slot = (slot + 1) & (kSlots - 1);
                if (keys_[slot] == key) {  // the string goes on
                    prefix = codes_[slot];
                    continue;
                }
                put_code(prefix);
                if (next_code_ >= kTableFull) {  // table full: start again from the literals
                    put_code(kClearCode);
                    reset();
                } else {
                    keys_[slot] = key;
                    codes_[slot] = std::uint16_t(next_code_++);
                }
                prefix = next;
            }
        }
        put_code(prefix);
        put_code(kEndCode);
        if (bit_count_ > 0) packed_[used_++] = std::uint8_t(bits_);
        out.push_back(std::uint8_t(kMinCodeSize));
        for (std::size_t at = 0; at < used_; at += 255) {
            const std::size_t length = std::min<std::size_t>(255, used_ - at);
            out.push_back(std::uint8_t(length));
            out.insert(out.end(), packed_.begin() + long(at), packed_.begin() + long(at + length));
        }
        out.push_back(0);
    }

private:
    static constexpr std::uint32_t kSlots = 8192, kEmpty = 0xFFFFFFFFu;

    static std::uint32_t hash(std::uint32_t key) { return (key * 2654435761u) >> (32 - 13); }

    void reset() {
        keys_.fill(kEmpty);
        next_code_ = kFirstFreeCode;
        code_bits_ = kMinCodeSize + 1;
    }

    // Writes `code` at the current width, then widens the codes when the next code to be
    // assigned needs another bit: the decoder, which adds each string one code later than
    // the encoder, widens after adding the string that fills the current width, i.e. at the
    // same point in the stream (the widening the specification's decoder expects).
    void put_code(unsigned code) {
        bits_ |= std::uint32_t(code) << bit_count_;
        bit_count_ += code_bits_;
        while (bit_count_ >= 8) {
            packed_[used_++] = std::uint8_t(bits_);
            bits_ >>= 8;
            bit_count_ -= 8;
        }
        if (next_code_ >= (1u << code_bits_) && code_bits_ < kMaxCodeBits) ++code_bits_;
    }

    std::array<std::uint32_t, kSlots> keys_{};
    std::array<std::uint16_t, kSlots> codes_{};
    unsigned next_code_ = kFirstFreeCode;
    int code_bits_ = kMinCodeSize + 1;
    std::uint32_t bits_ = 0;  // fewer than 8 pending bits + one code of at most 12
    int bit_count_ = 0;
    std::vector<std::uint8_t> packed_;  // the codes, packed (reserve())
    std::size_t used_ = 0;
};

}  // namespace

int gif_frame_delay(double fps, long frame) {
    // Multiplied before dividing: for an integer fps, whole hundredths come out exact.
    const auto end_of = [fps](long k) { return long(std::floor(100.0 * double(k) / fps)); };
    return int(end_of(frame + 1) - end_of(frame));
}

struct gif_writer::state {
    atomic_file file;
    int width = 0, height = 0;
    gif_options options;
    long frames = 0;
    std::vector<std::uint8_t> previous, current, encoded;
    lzw_encoder lzw;
    std::optional<error> failure;
    bool finished = false;

    state(atomic_file f, int w, int h, const gif_options &o)
        : file(std::move(f)), width(w), height(h), options(o),
          previous(std::size_t(w) * std::size_t(h)), current(previous.size()) {
        // The most one frame can take, so that no frame allocates: a code per index at most
        // (plus clears, one per 3,837 codes, and the first and last codes) of at most 12
        // bits, a length byte per 255 data bytes, and the frame's blocks around the data.
        const std::size_t codes = previous.size() + previous.size() / 1000 + 4;
        const std::size_t data = codes * std::size_t(kMaxCodeBits) / 8 + 1;
        encoded.reserve(data + data / 255 + 64);
        lzw.reserve(previous.size());
    }
    status fail(error e) {
        file.abandon();
        failure = e;
        return e;
    }
    status write_encoded() {
        if (status s = file.write(encoded.data(), encoded.size()); !s) return fail(s.err());
        return {};
    }
};

gif_writer::gif_writer(std::unique_ptr<state> s) : s_(std::move(s)) {}
gif_writer::gif_writer(gif_writer &&) noexcept = default;
gif_writer &gif_writer::operator=(gif_writer &&) noexcept = default;
gif_writer::~gif_writer() = default;  // the atomic_file abandons an unfinished file

result<gif_writer> gif_writer::create(const std::string &path, int width, int height, const gif_options &options) {
    const auto refuse = [&path](const std::string &why) { return error{path, 0, -1, "cannot write GIF: " + why}; };
    if (width < 1 || height < 1 || width > kGifMaxSide || height > kGifMaxSide)
        return refuse("size " + std::to_string(width) + "x" + std::to_string(height) + " outside 1..65535 per side");
    if (status s = check_canvas_size(width, height); !s) return refuse(s.err().reason);
    if (!(options.fps >= kMinFps && options.fps <= kMaxFps))
        return refuse("fps " + std::to_string(options.fps) + " outside 0.01..50");
    if (options.loop_count < -1 || options.loop_count > 65535)
        return refuse("loop count " + std::to_string(options.loop_count) + " outside -1..65535");
    result<atomic_file> file = atomic_file::open(path);
    if (!file) return file.err();

    auto s = std::make_unique<state>(std::move(*file), width, height, options);
    std::vector<std::uint8_t> &out = s->encoded;
    const char *signature = "GIF89a";
    out.assign(signature, signature + 6);
    put_u16(out, unsigned(width));
    put_u16(out, unsigned(height));
    // Global colour table present, 8 bits per primary, not sorted, 2^(7+1) entries.
    out.insert(out.end(), {0xF7, 0, 0});  // packed fields, background index 0, no aspect ratio
    for (int i = 0; i < 256; ++i) out.insert(out.end(), 3, std::uint8_t(i));
    if (options.loop_count >= 0) {
        const char *app = "NETSCAPE2.0";
        out.insert(out.end(), {0x21, 0xFF, 11});
        out.insert(out.end(), app, app + 11);
        out.insert(out.end(), {3, 1});
        put_u16(out, unsigned(options.loop_count));
        out.push_back(0);
    }
    if (status st = s->write_encoded(); !st) return st.err();
    return gif_writer(std::move(s));
}

status gif_writer::add_frame(const canvas_t &frame) {
    if (!s_) return error{"", 0, -1, "cannot write GIF: the writer was moved from"};
    state &s = *s_;
    const std::string &path = s.file.path();
    if (s.failure) return *s.failure;
    if (s.finished) return error{path, 0, -1, "cannot add a frame: the GIF is already finished"};
    if (!frame.data || frame.width != s.width || frame.height != s.height)
        return s.fail(error{path, 0, -1,
                            "frame " + std::to_string(s.frames) + " is " +
                                (frame.data ? std::to_string(frame.width) + "x" + std::to_string(frame.height)
                                            : std::string("an invalid canvas")) +
                                ", the animation is " + std::to_string(s.width) + "x" + std::to_string(s.height)});
    const std::size_t pixels = s.current.size();
    to_grey_bytes(frame.data, s.current.data(), pixels);
    const rectangle r = s.frames == 0 ? rectangle{0, 0, s.width, s.height}
                                      : changed_rectangle(s.current, s.previous, s.width, s.height);

    std::vector<std::uint8_t> &out = s.encoded;
    out.clear();
    // Graphic control extension: disposal 1 (leave the frame in place), no transparency.
    out.insert(out.end(), {0x21, 0xF9, 4, 1 << 2});
    put_u16(out, unsigned(gif_frame_delay(s.options.fps, s.frames)));
    out.insert(out.end(), {0, 0});
    // Image descriptor: the rectangle, no local table, not interlaced.
    out.push_back(0x2C);
    for (int v : {r.left, r.top, r.width, r.height}) put_u16(out, unsigned(v));
    out.push_back(0);
    s.lzw.encode(s.current, s.width, r, out);
    if (status st = s.write_encoded(); !st) return st;
    std::swap(s.previous, s.current);
    ++s.frames;
    return {};
}

status gif_writer::finish() {
    if (!s_) return error{"", 0, -1, "cannot write GIF: the writer was moved from"};
    state &s = *s_;
    if (s.failure) return *s.failure;
    if (s.finished) return error{s.file.path(), 0, -1, "cannot finish: the GIF is already finished"};
    if (s.frames == 0) return s.fail(error{s.file.path(), 0, -1, "cannot write GIF: no frame was added"});
    s.encoded.assign(1, 0x3B);
    if (status st = s.write_encoded(); !st) return st;
    if (status st = s.file.commit(); !st) return s.fail(st.err());
    s.finished = true;
    return {};
}

long gif_writer::frame_count() const { return s_ ? s_->frames : 0; }

std::string gif_writer::path() const { return s_ ? s_->file.path() : std::string(); }

}  // namespace tiny3d
