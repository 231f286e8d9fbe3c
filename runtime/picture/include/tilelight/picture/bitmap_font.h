#pragma once
// A tiny fixed-width bitmap font for labelling debug pictures (the tile-class legend) without
// a font library or font files: pictures stay reproducible byte for byte on every machine.
//
// Glyphs are 5 columns x 8 rows: rows 0..6 hold capitals, digits and the x-height body
// (baseline under row 6), row 7 is the descender of g, j, p, q, y, ',' and ';' and holds '_'.
// Each glyph sits at the top-left of a 6 x 9 cell, so one blank column separates characters
// and one blank row separates lines. Every character is one byte: printable ASCII 32..126 has
// a glyph; any other byte (control characters, each byte of a UTF-8 sequence) draws as a box.

#include "tilelight/picture/rgba8_canvas.h"

#include <array>
#include <cstdint>
#include <string_view>

namespace tilelight {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 8;
inline constexpr int kFontCellWidth = 6;
inline constexpr int kFontCellHeight = 9;

// The glyph of `c`: kGlyphHeight rows, top first; bit (kGlyphWidth - 1 - column) of a row is
// set where the glyph has ink, so bit 4 is the left column. Characters outside 32..126 give
// the box glyph.
std::array<std::uint8_t, kGlyphHeight> glyph_rows(char c);

// Whether `c` has its own glyph (printable ASCII 32..126) rather than the box.
constexpr bool has_glyph(char c) { return static_cast<unsigned char>(c) >= 32 && static_cast<unsigned char>(c) <= 126; }

// Width in pixels of `text` drawn at `scale`: one cell per byte, including the blank column
// after the last character. Precondition: scale >= 1 (checked by draw_text, not here).
constexpr int text_width(std::string_view text, int scale = 1) {
  return static_cast<int>(text.size()) * kFontCellWidth * scale;
}

// Height in pixels of one line of text at `scale` (a full cell, blank row included).
constexpr int text_height(int scale = 1) { return kFontCellHeight * scale; }

// Draws `text` with the top-left of its first cell at (x, y), each font pixel a
// scale x scale block of `colour` (written as is, alpha included: no blending). Only ink
// pixels are written; the cell background is left untouched. Pixels outside the canvas are
// clipped, so x and y may be negative. No line breaks: '\n' draws as a box.
// Throws tilelight::Error if scale < 1.
void draw_text(Rgba8Canvas& canvas, int x, int y, std::string_view text, Rgba8 colour, int scale = 1);

}  // namespace tilelight
