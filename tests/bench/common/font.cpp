// font.cpp — libtiny3d's built-in 5 × 7 bitmap font and text drawing.
//
// Each printable ASCII glyph (32..126) is drawn below as seven rows of five cells,
// top row first: '#' is ink, '.' is paper.
#include <algorithm>
#include <cstddef>

#include "chart.h"

namespace tiny3d {
namespace {

constexpr char32_t first_glyph = 32;
constexpr char32_t last_glyph = 126;
constexpr std::size_t glyph_cells = std::size_t(font_glyph_width) * font_glyph_height;

constexpr const char *glyph_art[] = {
    "....." "....." "....." "....." "....." "....." ".....",  // space
    "..#.." "..#.." "..#.." "..#.." "..#.." "....." "..#..",  // '!'
    ".#.#." ".#.#." "....." "....." "....." "....." ".....",  // '"'
    ".#.#." ".#.#." "#####" ".#.#." "#####" ".#.#." ".#.#.",  // '#'
    "..#.." ".####" "#.#.." ".###." "..#.#" "####." "..#..",  // '$'
    "##..." "##..#" "...#." "..#.." ".#..." "#..##" "...##",  // '%'
    ".##.." "#..#." "#.#.." ".#..." "#.#.#" "#..#." ".##.#",  // '&'
    "..#.." "..#.." "....." "....." "....." "....." ".....",  // '''
    "...#." "..#.." ".#..." ".#..." ".#..." "..#.." "...#.",  // '('
    ".#..." "..#.." "...#." "...#." "...#." "..#.." ".#...",  // ')'
    "....." "..#.." "#.#.#" ".###." "#.#.#" "..#.." ".....",  // '*'
    "....." "..#.." "..#.." "#####" "..#.." "..#.." ".....",  // '+'
    "....." "....." "....." "....." "..##." "..#.." ".#...",  // ','
    "....." "....." "....." "#####" "....." "....." ".....",  // '-'
    "....." "....." "....." "....." "....." ".##.." ".##..",  // '.'
    "....." "....#" "...#." "..#.." ".#..." "#...." ".....",  // '/'
    ".###." "#...#" "#..##" "#.#.#" "##..#" "#...#" ".###.",  // '0'
    "..#.." ".##.." "..#.." "..#.." "..#.." "..#.." ".###.",  // '1'
    ".###." "#...#" "....#" "...#." "..#.." ".#..." "#####",  // '2'
    "#####" "...#." "..#.." "...#." "....#" "#...#" ".###.",  // '3'
    "...#." "..##." ".#.#." "#..#." "#####" "...#." "...#.",  // '4'
    "#####" "#...." "####." "....#" "....#" "#...#" ".###.",  // '5'
    "..##." ".#..." "#...." "####." "#...#" "#...#" ".###.",  // '6'
    "#####" "....#" "...#." "..#.." ".#..." ".#..." ".#...",  // '7'
    ".###." "#...#" "#...#" ".###." "#...#" "#...#" ".###.",  // '8'
    ".###." "#...#" "#...#" ".####" "....#" "...#." ".##..",  // '9'
    "....." ".##.." ".##.." "....." ".##.." ".##.." ".....",  // ':'
    "....." ".##.." ".##.." "....." ".##.." "..#.." ".#...",  // ';'
    "...#." "..#.." ".#..." "#...." ".#..." "..#.." "...#.",  // '<'
    "....." "....." "#####" "....." "#####" "....." ".....",  // '='
    ".#..." "..#.." "...#." "....#" "...#." "..#.." ".#...",  // '>'
    ".###." "#...#" "....#" "...#." "..#.." "....." "..#..",  // '?'
    ".###." "#...#" "....#" ".##.#" "#.#.#" "#.#.#" ".###.",  // '@'
    ".###." "#...#" "#...#" "#####" "#...#" "#...#" "#...#",  // 'A'
    "####." "#...#" "#...#" "####." "#...#" "#...#" "####.",  // 'B'
    ".###." "#...#" "#...." "#...." "#...." "#...#" ".###.",  // 'C'
    "###.." "#..#." "#...#" "#...#" "#...#" "#..#." "###..",  // 'D'
    "#####" "#...." "#...." "####." "#...." "#...." "#####",  // 'E'
    "#####" "#...." "#...." "####." "#...." "#...." "#....",  // 'F'
    ".###." "#...#" "#...." "#.###" "#...#" "#...#" ".####",  // 'G'
    "#...#" "#...#" "#...#" "#####" "#...#" "#...#" "#...#",  // 'H'
    ".###." "..#.." "..#.." "..#.." "..#.." "..#.." ".###.",  // 'I'
    "..###" "...#." "...#." "...#." "...#." "#..#." ".##..",  // 'J'
    "#...#" "#..#." "#.#.." "##..." "#.#.." "#..#." "#...#",  // 'K'
    "#...." "#...." "#...." "#...." "#...." "#...." "#####",  // 'L'
    "#...#" "##.##" "#.#.#" "#.#.#" "#...#" "#...#" "#...#",  // 'M'
    "#...#" "#...#" "##..#" "#.#.#" "#..##" "#...#" "#...#",  // 'N'
    ".###." "#...#" "#...#" "#...#" "#...#" "#...#" ".###.",  // 'O'
    "####." "#...#" "#...#" "####." "#...." "#...." "#....",  // 'P'
    ".###." "#...#" "#...#" "#...#" "#.#.#" "#..#." ".##.#",  // 'Q'
    "####." "#...#" "#...#" "####." "#.#.." "#..#." "#...#",  // 'R'
    ".####" "#...." "#...." ".###." "....#" "....#" "####.",  // 'S'
    "#####" "..#.." "..#.." "..#.." "..#.." "..#.." "..#..",  // 'T'
    "#...#" "#...#" "#...#" "#...#" "#...#" "#...#" ".###.",  // 'U'
    "#...#" "#...#" "#...#" "#...#" "#...#" ".#.#." "..#..",  // 'V'
    "#...#" "#...#" "#...#" "#.#.#" "#.#.#" "#.#.#" ".#.#.",  // 'W'
    "#...#" "#...#" ".#.#." "..#.." ".#.#." "#...#" "#...#",  // 'X'
    "#...#" "#...#" ".#.#." "..#.." "..#.." "..#.." "..#..",  // 'Y'
    "#####" "....#" "...#." "..#.." ".#..." "#...." "#####",  // 'Z'
    ".###." ".#..." ".#..." ".#..." ".#..." ".#..." ".###.",  // '['
    "....." "#...." ".#..." "..#.." "...#." "....#" ".....",  // '\'
    ".###." "...#." "...#." "...#." "...#." "...#." ".###.",  // ']'
    "..#.." ".#.#." "#...#" "....." "....." "....." ".....",  // '^'
    "....." "....." "....." "....." "....." "....." "#####",  // '_'
    ".#..." "..#.." "....." "....." "....." "....." ".....",  // '`'
    "....." "....." ".###." "....#" ".####" "#...#" ".####",  // 'a'
    "#...." "#...." "#.##." "##..#" "#...#" "#...#" "####.",  // 'b'
    "....." "....." ".###." "#...." "#...." "#...#" ".###.",  // 'c'
    "....#" "....#" ".##.#" "#..##" "#...#" "#...#" ".####",  // 'd'
    "....." "....." ".###." "#...#" "#####" "#...." ".###.",  // 'e'
    "..##." ".#..#" ".#..." "###.." ".#..." ".#..." ".#...",  // 'f'
    "....." ".####" "#...#" "#...#" ".####" "....#" ".###.",  // 'g'
    "#...." "#...." "#.##." "##..#" "#...#" "#...#" "#...#",  // 'h'
    "..#.." "....." ".##.." "..#.." "..#.." "..#.." ".###.",  // 'i'
    "...#." "....." "..##." "...#." "...#." "#..#." ".##..",  // 'j'
    "#...." "#...." "#..#." "#.#.." "##..." "#.#.." "#..#.",  // 'k'
    ".##.." "..#.." "..#.." "..#.." "..#.." "..#.." ".###.",  // 'l'
    "....." "....." "##.#." "#.#.#" "#.#.#" "#...#" "#...#",  // 'm'
    "....." "....." "#.##." "##..#" "#...#" "#...#" "#...#",  // 'n'
    "....." "....." ".###." "#...#" "#...#" "#...#" ".###.",  // 'o'
    "....." "....." "####." "#...#" "####." "#...." "#....",  // 'p'
    "....." "....." ".##.#" "#..##" ".####" "....#" "....#",  // 'q'
    "....." "....." "#.##." "##..#" "#...." "#...." "#....",  // 'r'
    "....." "....." ".###." "#...." ".###." "....#" "####.",  // 's'
    ".#..." ".#..." "###.." ".#..." ".#..." ".#..#" "..##.",  // 't'
    "....." "....." "#...#" "#...#" "#...#" "#..##" ".##.#",  // 'u'
    "....." "....." "#...#" "#...#" "#...#" ".#.#." "..#..",  // 'v'
    "....." "....." "#...#" "#...#" "#.#.#" "#.#.#" ".#.#.",  // 'w'
    "....." "....." "#...#" ".#.#." "..#.." ".#.#." "#...#",  // 'x'
    "....." "....." "#...#" "#...#" ".####" "....#" ".###.",  // 'y'
    "....." "....." "#####" "...#." "..#.." ".#..." "#####",  // 'z'
    "...#." "..#.." "..#.." ".#..." "..#.." "..#.." "...#.",  // '{'
    "..#.." "..#.." "..#.." "..#.." "..#.." "..#.." "..#..",  // '|'
    ".#..." "..#.." "..#.." "...#." "..#.." "..#.." ".#...",  // '}'
    "....." "....." ".#..." "#.#.#" "...#." "....." ".....",  // '~'
};
static_assert(sizeof glyph_art / sizeof glyph_art[0] == last_glyph - first_glyph + 1);

// Every glyph has exactly 35 cells of '#' or '.' (checked when compiling).
constexpr bool glyph_art_is_well_formed() {
    for (const char *art : glyph_art) {
        std::size_t n = 0;
        for (; art[n] != '\0'; ++n)
            if (art[n] != '#' && art[n] != '.') return false;
        if (n != glyph_cells) return false;
    }
    return true;
}
static_assert(glyph_art_is_well_formed());

// A hollow box: the glyph of every character the font does not have.
constexpr bool missing_glyph_pixel(int column, int row) {
    return column == 0 || column == font_glyph_width - 1 || row == 0 || row == font_glyph_height - 1;
}

// Decodes the next UTF-8 code point of `text` at `pos` (advancing pos). Malformed bytes
// come out as one code point each, so every byte is consumed exactly once.
char32_t next_code_point(std::string_view text, std::size_t &pos) {
    const auto lead = static_cast<unsigned char>(text[pos++]);
    int continuation = lead >= 0xF0 ? 3 : lead >= 0xE0 ? 2 : lead >= 0xC0 ? 1 : 0;
    char32_t cp = continuation == 0 ? lead : char32_t(lead & (0x3F >> continuation));
    for (; continuation > 0 && pos < text.size(); --continuation) {
        const auto next = static_cast<unsigned char>(text[pos]);
        if ((next & 0xC0) != 0x80) break;
        cp = (cp << 6) | (next & 0x3F);
        ++pos;
    }
    return cp;
}

std::size_t code_point_count(std::string_view text) {
    std::size_t n = 0;
    for (std::size_t pos = 0; pos < text.size(); ++n) next_code_point(text, pos);
    return n;
}

// Calls ink(px, py) for every ink font pixel of `text`, in font-pixel units relative to
// the text's top-left corner (px along the text, py down the glyph).
template <class Ink>
void for_each_ink_pixel(std::string_view text, Ink &&ink) {
    int origin = 0;
    for (std::size_t pos = 0; pos < text.size(); origin += font_advance) {
        const char32_t c = next_code_point(text, pos);
        for (int row = 0; row < font_glyph_height; ++row)
            for (int column = 0; column < font_glyph_width; ++column)
                if (font_glyph_pixel(c, column, row)) ink(origin + column, row);
    }
}

void fill_block(canvas_t &canvas, int x, int y, int scale, float value) {
    const int x_end = std::min(x + scale, canvas.width), y_end = std::min(y + scale, canvas.height);
    for (int yy = std::max(y, 0); yy < y_end; ++yy)
        for (int xx = std::max(x, 0); xx < x_end; ++xx) canvas.pixels[yy][xx] = value;
}

}  // namespace

bool font_glyph_pixel(char32_t c, int column, int row) {
    if (column < 0 || column >= font_glyph_width || row < 0 || row >= font_glyph_height) return false;
    if (c < first_glyph || c > last_glyph) return missing_glyph_pixel(column, row);
    return glyph_art[c - first_glyph][row * font_glyph_width + column] == '#';
}

int text_width(std::string_view text, int scale) {
    const std::size_t n = code_point_count(text);
    if (n == 0 || scale < 1) return 0;
    return (int(n) * font_advance - (font_advance - font_glyph_width)) * scale;
}

int text_height(int scale) { return scale < 1 ? 0 : font_glyph_height * scale; }

void draw_text(canvas_t &canvas, int x, int y, std::string_view text, float intensity, int scale) {
    if (scale < 1) return;
    const float value = std::clamp(intensity, 0.0f, 1.0f);
    for_each_ink_pixel(text, [&](int px, int py) { fill_block(canvas, x + px * scale, y + py * scale, scale, value); });
}

void draw_text_vertical(canvas_t &canvas, int x, int y, std::string_view text, float intensity, int scale) {
    if (scale < 1) return;
    const float value = std::clamp(intensity, 0.0f, 1.0f);
    // Turned 90° counter-clockwise: text runs upwards from the box's bottom edge and
    // the glyphs' tops face left.
    const int bottom = y + text_width(text, scale);
    for_each_ink_pixel(text, [&](int px, int py) {
        fill_block(canvas, x + py * scale, bottom - (px + 1) * scale, scale, value);
    });
}

}  // namespace tiny3d
