// pnm_read.cpp — reading PGM (P2, P5) and PPM (P3, P6, converted to grey) into a canvas.
#include <cstdint>
#include <string>

#include "canvas.h"

namespace tiny3d {
namespace {

// Largest file accepted: the largest canvas as 16-bit colour binary data, plus a header.
constexpr long long kMaxPnmBytes = CANVAS_MAX_PIXELS * 6 + 4096;
constexpr unsigned kMaxMaxval = 65535;
constexpr unsigned long kMaxHeaderNumber = 1000000000UL;  // no PNM header field needs more
// Rec. 709 luminance weights (linear, no gamma).
constexpr double kLumaR = 0.2126, kLumaG = 0.7152, kLumaB = 0.0722;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// A cursor over the file's bytes that knows its line number, for error messages.
class pnm_cursor {
public:
    pnm_cursor(const std::string &path, const std::string &bytes) : path_(path), b_(bytes) {}

    error at_line(const std::string &reason) const { return error{path_, line_, -1, reason}; }
    error at_byte(std::size_t offset, const std::string &reason) const {
        return error{path_, 0, long(offset), reason};
    }
    std::size_t pos() const { return pos_; }
    std::size_t remaining() const { return b_.size() - pos_; }
    const std::string &bytes() const { return b_; }

    // Skips whitespace and '#' comments (to the end of their line).
    void skip_blanks() {
        while (pos_ < b_.size()) {
            const char c = b_[pos_];
            if (c == '#') {
                while (pos_ < b_.size() && b_[pos_] != '\n') ++pos_;
            } else if (is_space(c)) {
                if (c == '\n') ++line_;
                ++pos_;
            } else {
                break;
            }
        }
    }

    // Reads an unsigned decimal number named `what`; it must end at a blank, a comment
    // or the end of the file.
    result<unsigned long> number(const char *what) {
        skip_blanks();
        if (pos_ >= b_.size()) return at_line(std::string("unexpected end of file: expected ") + what);
        if (!is_digit(b_[pos_]))
            return at_line(std::string("expected ") + what + ", found '" + printable(b_[pos_]) + "'");
        unsigned long v = 0;
        while (pos_ < b_.size() && is_digit(b_[pos_])) {
            v = v * 10 + unsigned(b_[pos_] - '0');
            if (v > kMaxHeaderNumber) return at_line(std::string(what) + " is too large");
            ++pos_;
        }
        if (pos_ < b_.size() && !is_space(b_[pos_]) && b_[pos_] != '#')
            return at_line(std::string("malformed ") + what + ": unexpected '" + printable(b_[pos_]) + "'");
        return v;
    }

    // After the header of a binary file: exactly one whitespace byte.
    status single_blank() {
        if (pos_ >= b_.size() || !is_space(b_[pos_]))
            return at_line("expected one whitespace byte after maxval before the binary data");
        ++pos_;
        return {};
    }

private:
    // The byte itself if printable ASCII, otherwise as C writes it (ESC as \x1b, 0x86 as \x86).
    static std::string printable(char c) {
        if (c >= 32 && c < 127) return std::string(1, c);
        static constexpr char digits[] = "0123456789abcdef";
        const unsigned byte = static_cast<unsigned char>(c);
        return std::string("\\x") + digits[byte >> 4] + digits[byte & 15];
    }
    const std::string &path_;
    const std::string &b_;
    std::size_t pos_ = 2;  // after the magic number
    long line_ = 1;
};

// The magic number, checked before the rest of the file is read.
status probe_magic(std::string_view b, const std::string &path) {
    if (b.size() >= 2 && b[0] == 'P' && (b[1] == '2' || b[1] == '3' || b[1] == '5' || b[1] == '6')) return {};
    return error{path, 1, -1, "not a PGM/PPM file: the magic number must be P2, P3, P5 or P6"};
}

}  // namespace

result<canvas_ptr> load_pgm(const std::string &path) {
    result<std::string> file = read_file_bytes(path, kMaxPnmBytes, probe_magic);
    if (!file) return file.err();
    const std::string &bytes = *file;
    const bool binary = bytes[1] == '5' || bytes[1] == '6';
    const int channels = (bytes[1] == '3' || bytes[1] == '6') ? 3 : 1;

    pnm_cursor in(path, bytes);
    const auto width = in.number("width");
    if (!width) return width.err();
    const auto height = in.number("height");
    if (!height) return height.err();
    if (status s = check_canvas_size(int(*width), int(*height)); !s) return in.at_line(s.err().reason);
    const auto maxval = in.number("maxval");
    if (!maxval) return maxval.err();
    if (*maxval < 1 || *maxval > kMaxMaxval) return in.at_line("maxval must be 1..65535, not " + std::to_string(*maxval));

    const std::size_t pixels = std::size_t(*width) * std::size_t(*height);
    const std::size_t samples = pixels * std::size_t(channels);
    const std::size_t sample_bytes = *maxval > 255 ? 2 : 1;
    // Is the file long enough for the size it claims? Checked before allocating.
    if (binary) {
        if (status s = in.single_blank(); !s) return s.err();
        if (in.remaining() < samples * sample_bytes)
            return in.at_byte(in.pos(), "truncated: " + std::to_string(*width) + "x" + std::to_string(*height) +
                                            " needs " + std::to_string(samples * sample_bytes) +
                                            " bytes of pixel data, the file has " + std::to_string(in.remaining()));
    } else if (in.remaining() + 1 < 2 * samples) {  // each ASCII sample takes ≥ 2 bytes
        return in.at_line("truncated: " + std::to_string(*width) + "x" + std::to_string(*height) + " needs " +
                          std::to_string(samples) + " samples, the file is too short to hold them");
    }

    result<canvas_ptr> made = make_canvas(int(*width), int(*height));
    if (!made) return error{path, 0, -1, made.err().reason};
    canvas_ptr canvas = std::move(made.value());
    const double scale = 1.0 / double(*maxval);
    std::size_t offset = in.pos();
    for (std::size_t i = 0; i < pixels; ++i) {
        double rgb[3] = {0, 0, 0};
        for (int ch = 0; ch < channels; ++ch) {
            unsigned long v;
            if (binary) {
                const auto *p = reinterpret_cast<const unsigned char *>(bytes.data() + offset);
                v = sample_bytes == 2 ? (unsigned long)(p[0]) << 8 | p[1] : p[0];
                if (v > *maxval)
                    return in.at_byte(offset, "sample " + std::to_string(v) + " exceeds maxval " + std::to_string(*maxval));
                offset += sample_bytes;
            } else {
                const auto n = in.number("a sample");
                if (!n) return n.err();
                if (*n > *maxval)
                    return in.at_line("sample " + std::to_string(*n) + " exceeds maxval " + std::to_string(*maxval));
                v = *n;
            }
            rgb[ch] = double(v) * scale;
        }
        const double grey = channels == 1 ? rgb[0] : kLumaR * rgb[0] + kLumaG * rgb[1] + kLumaB * rgb[2];
        canvas->data[i] = float(grey > 1.0 ? 1.0 : grey);
    }
    return canvas;
}

}  // namespace tiny3d
