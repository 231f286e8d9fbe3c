// The legend font: glyph table sanity, placement inside the cell, clipping and scaling.
#include "tilelight/picture/bitmap_font.h"
#include "tilelight/base/error.h"
#include "tilelight/picture/rgba8_canvas.h"

#include <gtest/gtest.h>

#include <set>

namespace tilelight {
namespace {

constexpr Rgba8 kBlack{0, 0, 0, 255};
constexpr Rgba8 kInk{255, 255, 0, 255};

// Bounding box of the pixels equal to `colour`; empty (count 0) when there are none.
struct InkBox {
  int count = 0;
  int min_x = 1 << 30, min_y = 1 << 30, max_x = -1, max_y = -1;
};

InkBox ink_box(const Rgba8Canvas& canvas, Rgba8 colour) {
  InkBox box;
  for (std::uint32_t y = 0; y < canvas.height; ++y) {
    for (std::uint32_t x = 0; x < canvas.width; ++x) {
      if (canvas.pixel(x, y) != colour) continue;
      ++box.count;
      box.min_x = std::min(box.min_x, static_cast<int>(x));
      box.min_y = std::min(box.min_y, static_cast<int>(y));
      box.max_x = std::max(box.max_x, static_cast<int>(x));
      box.max_y = std::max(box.max_y, static_cast<int>(y));
    }
  }
  return box;
}

TEST(BitmapFont, DrawsAInsideItsCellOnly) {
  Rgba8Canvas canvas = Rgba8Canvas::filled(20, 20, kBlack);
  draw_text(canvas, 3, 4, "A", kInk);
  const InkBox box = ink_box(canvas, kInk);
  EXPECT_GT(box.count, 10);
  // Cell [3, 9) x [4, 13); the ink itself never uses the spacing column or row.
  EXPECT_GE(box.min_x, 3);
  EXPECT_GE(box.min_y, 4);
  EXPECT_LT(box.max_x, 3 + kGlyphWidth);
  EXPECT_LT(box.max_y, 4 + kGlyphHeight);
  // 'A' spans the full glyph width and the capital height.
  EXPECT_EQ(box.min_x, 3);
  EXPECT_EQ(box.max_x, 7);
  EXPECT_EQ(box.min_y, 4);
  EXPECT_EQ(box.max_y, 10);
  // Only ink is written: the background elsewhere is untouched.
  EXPECT_EQ(canvas.pixel(0, 0), kBlack);
  EXPECT_EQ(canvas.pixel(4, 4 + 1), kBlack);  // inside the counter of the 'A'
}

TEST(BitmapFont, ScaleMultipliesEveryFontPixel) {
  Rgba8Canvas one = Rgba8Canvas::filled(12, 12, kBlack);
  Rgba8Canvas two = Rgba8Canvas::filled(24, 24, kBlack);
  draw_text(one, 0, 0, "A", kInk, 1);
  draw_text(two, 0, 0, "A", kInk, 2);
  EXPECT_EQ(ink_box(two, kInk).count, 4 * ink_box(one, kInk).count);
  for (std::uint32_t y = 0; y < 24; ++y) {
    for (std::uint32_t x = 0; x < 24; ++x) {
      EXPECT_EQ(two.pixel(x, y), one.pixel(x / 2, y / 2)) << x << "," << y;
    }
  }
}

TEST(BitmapFont, TextWidthAndHeight) {
  EXPECT_EQ(text_width("A"), 6);
  EXPECT_EQ(text_width("A", 2), 12);
  EXPECT_EQ(text_width("hello", 2), 60);
  EXPECT_EQ(text_width(""), 0);
  EXPECT_EQ(text_height(1), 9);
  EXPECT_EQ(text_height(2), 18);

  // Consecutive characters advance by one cell: the ink of "II" is the ink of "I" twice,
  // kFontCellWidth apart.
  Rgba8Canvas canvas = Rgba8Canvas::filled(static_cast<std::uint32_t>(text_width("II")), 9, kBlack);
  draw_text(canvas, 0, 0, "II", kInk);
  for (std::uint32_t y = 0; y < 9; ++y) {
    for (std::uint32_t x = 0; x < 6; ++x) {
      EXPECT_EQ(canvas.pixel(x, y), canvas.pixel(x + 6, y));
    }
  }
  const InkBox box = ink_box(canvas, kInk);
  EXPECT_LT(box.max_x, text_width("II"));
}

TEST(BitmapFont, EveryPrintableCharacterHasItsOwnGlyph) {
  std::set<std::array<std::uint8_t, kGlyphHeight>> seen;
  for (int c = 32; c <= 126; ++c) {
    const auto glyph = glyph_rows(static_cast<char>(c));
    int ink = 0;
    for (const std::uint8_t row : glyph) {
      EXPECT_EQ(row & ~0x1Fu, 0u) << "glyph wider than 5 columns: " << static_cast<char>(c);
      ink += row != 0;
    }
    if (c == ' ') {
      EXPECT_EQ(ink, 0);
    } else {
      EXPECT_GT(ink, 0) << static_cast<char>(c);
    }
    EXPECT_TRUE(seen.insert(glyph).second) << "duplicate glyph for " << static_cast<char>(c);
  }
}

TEST(BitmapFont, UnknownCharactersDrawAsABox) {
  const auto box = glyph_rows('\x01');
  EXPECT_EQ(glyph_rows('\x7f'), box);
  EXPECT_EQ(glyph_rows('\n'), box);
  EXPECT_EQ(glyph_rows(static_cast<char>(0xC3)), box);
  EXPECT_FALSE(has_glyph('\x7f'));
  EXPECT_TRUE(has_glyph('~'));
  EXPECT_EQ(box[0], 0x1F);
  EXPECT_EQ(box[3], 0x11);
  EXPECT_EQ(box[6], 0x1F);

  Rgba8Canvas canvas = Rgba8Canvas::filled(6, 9, kBlack);
  draw_text(canvas, 0, 0, "\t", kInk);
  EXPECT_EQ(canvas.pixel(0, 0), kInk);
  EXPECT_EQ(canvas.pixel(4, 6), kInk);
  EXPECT_EQ(canvas.pixel(2, 3), kBlack);
}

TEST(BitmapFont, ClipsAtEveryEdge) {
  Rgba8Canvas canvas = Rgba8Canvas::filled(4, 4, kBlack);
  draw_text(canvas, -2, -3, "W", kInk);
  draw_text(canvas, 2, 2, "W", kInk, 3);
  draw_text(canvas, -1000, 1000, "overflow", kInk, 2);
  EXPECT_GT(ink_box(canvas, kInk).count, 0);
  EXPECT_EQ(canvas.pixels.size(), 4u * 4u * 4u);
}

TEST(BitmapFont, RejectsScaleBelowOne) {
  Rgba8Canvas canvas = Rgba8Canvas::filled(4, 4, kBlack);
  try {
    draw_text(canvas, 0, 0, "A", kInk, 0);
    FAIL() << "expected tilelight::Error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "draw_text: scale must be >= 1, got 0");
  }
}

}  // namespace
}  // namespace tilelight
