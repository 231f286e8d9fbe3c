// The tile-class picture: palette, labels, tinting, outlines, legend and argument checks.
#include "tilelight/picture/tile_class_image.h"

#include "tilelight/base/error.h"
#include "tilelight/picture/bitmap_font.h"
#include "tilelight/picture/png.h"
#include "tilelight_testing/png_file.h"

#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>

namespace tilelight {
namespace {

RgbaImage uniform_frame(std::uint32_t width, std::uint32_t height, std::array<float, 4> colour) {
  RgbaImage image;
  image.width = width;
  image.height = height;
  image.pixels.resize(static_cast<std::size_t>(width) * height * 4);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = colour[i % 4];
  return image;
}

// The RGBA pixels of the PNG at `path`; empty (and a test failure) unless it is width x height.
std::vector<std::uint8_t> decode_png(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height) {
  int w = 0, h = 0, channels = 0;
  unsigned char* decoded = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (decoded == nullptr) {
    ADD_FAILURE() << path << ": not a PNG stb_image can read";
    return {};
  }
  std::vector<std::uint8_t> pixels(decoded, decoded + std::size_t{static_cast<std::uint32_t>(w)} * h * 4);
  stbi_image_free(decoded);
  if (w != static_cast<int>(width) || h != static_cast<int>(height)) {
    ADD_FAILURE() << path << ": " << w << "x" << h << ", expected " << width << "x" << height;
    return {};
  }
  return pixels;
}

std::uint32_t tiles_along(std::uint32_t pixels, std::uint32_t tile) { return (pixels + tile - 1) / tile; }

// The documented tint: per channel (frame + class + 1) / 2 of the 8-bit values, alpha 255.
Rgba8 expected_blend(Rgba8 frame8, std::uint32_t id) {
  const Rgba8 tint = class_colour(id);
  Rgba8 out{};
  for (std::size_t c = 0; c < 3; ++c) {
    out[c] = static_cast<std::uint8_t>((frame8[c] + tint[c] + 1) / 2);
  }
  out[3] = 255;
  return out;
}

Rgba8 darker(Rgba8 colour) {
  return {static_cast<std::uint8_t>(colour[0] / 2), static_cast<std::uint8_t>(colour[1] / 2),
          static_cast<std::uint8_t>(colour[2] / 2), 255};
}

template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const Error& error) {
    return error.what();
  }
  return "(no tilelight::Error thrown)";
}

TEST(TileClassPalette, ThirtyTwoDistinctOpaqueColours) {
  std::set<Rgba8> colours;
  for (std::uint32_t id = 0; id < kOptimisedClassCount; ++id) {
    const Rgba8 colour = class_colour(id);
    EXPECT_EQ(colour[3], 255) << id;
    colours.insert(colour);
    // Documented separation: every pair at least 39 apart in RGB.
    for (std::uint32_t other = 0; other < id; ++other) {
      const Rgba8 b = class_colour(other);
      const double distance = std::hypot(colour[0] - b[0], colour[1] - b[1], colour[2] - b[2]);
      EXPECT_GE(distance, 39.0) << id << " vs " << other;
    }
  }
  EXPECT_EQ(colours.size(), 32u);
}

TEST(TileClassPalette, SunShadowClassSetsTheHue) {
  // Every colour of a sun/shadow family has the same dominant channel as the family's base.
  const auto dominant = [](Rgba8 c) { return c[0] >= c[1] && c[0] >= c[2] ? 0 : (c[1] >= c[2] ? 1 : 2); };
  EXPECT_EQ(dominant(class_colour(0)), 2);   // solid shadow: blue
  EXPECT_EQ(dominant(class_colour(8)), 1);   // solid shadow+fade+sun: green
  EXPECT_EQ(dominant(class_colour(16)), 0);  // sun, no shadow: amber
  EXPECT_EQ(class_colour(16), (Rgba8{255, 170, 0, 255}));
  for (std::uint32_t id = 0; id < 24; ++id) {
    EXPECT_EQ(dominant(class_colour(id)), dominant(class_colour(id & ~7u))) << id;
  }
  // Soft shadow is magenta: red and blue well above green.
  for (std::uint32_t id = 24; id < 32; ++id) {
    const Rgba8 c = class_colour(id);
    EXPECT_GT(c[0], c[1]);
    EXPECT_GT(c[2], c[1]);
  }
}

TEST(TileClassPalette, OutOfRangeIdThrows) {
  EXPECT_EQ(error_of([] { class_colour(32); }), "class_colour: optimised ID 32 is out of range; IDs must be < 32");
}

TEST(TileClassLabels, BuiltFromTheIdBits) {
  EXPECT_EQ(default_class_label(0), "solid shadow");
  EXPECT_EQ(default_class_label(1), "solid shadow | scattering");
  EXPECT_EQ(default_class_label(2), "solid shadow | MSAA edge");
  EXPECT_EQ(default_class_label(4), "sky");
  EXPECT_EQ(default_class_label(5), "scattering | sky");
  EXPECT_EQ(default_class_label(8), "solid shadow+fade+sun");
  EXPECT_EQ(default_class_label(16), "sun, no shadow");
  EXPECT_EQ(default_class_label(20), "sun, no shadow | sky");
  EXPECT_EQ(default_class_label(24), "soft shadow+fade+sun");
  EXPECT_EQ(default_class_label(27), "soft shadow+fade+sun | scattering | MSAA edge");
  EXPECT_EQ(default_class_label(31), "soft shadow+fade+sun | scattering | MSAA edge | sky");
  std::set<std::string> labels;
  for (std::uint32_t id = 0; id < 32; ++id) labels.insert(default_class_label(id));
  EXPECT_EQ(labels.size(), 32u);
  EXPECT_EQ(error_of([] { default_class_label(40); }),
            "default_class_label: optimised ID 40 is out of range; IDs must be < 32");
}

TEST(TileClassImage, CanvasIsFramePlusLegendAndGrowsForTheLegend) {
  // 33 x 17 with 4 px tiles: 9 x 5 tiles, partial on the right and bottom.
  const RgbaImage frame = uniform_frame(33, 17, {0.5f, 0.5f, 0.5f, 1.0f});
  std::vector<std::uint8_t> ids(45, 0);
  ids[3] = 16;
  ids[44] = 31;
  const TileClassLegendLayout layout = tile_class_legend_layout(33, 17, 4, ids);
  const Rgba8Canvas canvas = compose_tile_class_image(frame, 4, ids);

  EXPECT_EQ(layout.panel_x, 33u);
  EXPECT_GT(layout.panel_width, 0u);
  EXPECT_EQ(canvas.width, 33u + layout.panel_width);
  EXPECT_EQ(canvas.width, layout.canvas_width);
  // Three legend rows do not fit in 17 px: the canvas grows to the legend's height.
  EXPECT_GT(layout.panel_height, 17u);
  EXPECT_EQ(canvas.height, layout.panel_height);
  EXPECT_EQ(canvas.height, layout.canvas_height);
  EXPECT_EQ(canvas.pixels.size(), std::size_t{canvas.width} * canvas.height * 4);
  EXPECT_EQ(layout.scale, 1);
  EXPECT_EQ(layout.title, "tile classes (45 tiles, tile size 4)");
  // Everything of the legend lies inside the canvas.
  EXPECT_LE(layout.title_x + static_cast<std::uint32_t>(text_width(layout.title)), canvas.width);
  for (const auto& row : layout.rows) {
    EXPECT_LE(row.text_x + static_cast<std::uint32_t>(text_width(row.text)), canvas.width);
    EXPECT_LE(row.text_y + static_cast<std::uint32_t>(text_height()), canvas.height);
    EXPECT_LE(row.swatch_y + row.swatch_size, canvas.height);
  }
  // Padding below the frame is the neutral background.
  EXPECT_EQ(canvas.pixel(0, 17), kLegendBackground);
  EXPECT_EQ(canvas.pixel(32, canvas.height - 1), kLegendBackground);

  // A tall frame keeps its height.
  const TileClassLegendLayout tall = tile_class_legend_layout(8, 400, 8, std::vector<std::uint8_t>(50, 2));
  EXPECT_EQ(tall.canvas_height, 400u);
  EXPECT_EQ(tall.canvas_width, 8u + tall.panel_width);
}

TEST(TileClassImage, UniformTileGetsExactHalfBlend) {
  const RgbaImage frame = uniform_frame(16, 16, {0.2f, 0.4f, 0.6f, 0.5f});
  const std::vector<std::uint8_t> ids(16, 16);  // sun, no shadow: (255, 170, 0)
  const Rgba8Canvas canvas = compose_tile_class_image(frame, 4, ids);
  // 0.2/0.4/0.6 -> 51/102/153; (51+255+1)/2 = 153, (102+170+1)/2 = 136, (153+0+1)/2 = 77.
  const Rgba8 expected{153, 136, 77, 255};
  EXPECT_EQ(expected_blend({51, 102, 153, 128}, 16), expected);
  for (std::uint32_t y = 0; y < 16; ++y) {
    for (std::uint32_t x = 0; x < 16; ++x) {
      ASSERT_EQ(canvas.pixel(x, y), expected) << x << "," << y;
    }
  }
}

TEST(TileClassImage, FrameConversionMatchesToRgba8) {
  // Values that round, clamp and NaN: the tint must start from what to_rgba8 gives.
  RgbaImage frame = uniform_frame(4, 1, {0, 0, 0, 1});
  frame.pixels = {0.5f,  0.00196f, 0.998f, 1.0f, -1.0f, 2.0f, NAN,     1.0f,
                  0.25f, 0.75f,    0.1f,   1.0f, 1.0f,  0.0f, 0.3333f, 1.0f};
  const std::vector<std::uint8_t> bytes = to_rgba8(frame);
  const Rgba8Canvas canvas = compose_tile_class_image(frame, 4, std::vector<std::uint8_t>{13});
  for (std::uint32_t x = 0; x < 4; ++x) {
    const Rgba8 frame8{bytes[x * 4], bytes[x * 4 + 1], bytes[x * 4 + 2], bytes[x * 4 + 3]};
    EXPECT_EQ(canvas.pixel(x, 0), expected_blend(frame8, 13)) << x;
  }
}

TEST(TileClassImage, PartialEdgeTilesAreTinted) {
  const RgbaImage frame = uniform_frame(33, 17, {1.0f, 1.0f, 1.0f, 1.0f});
  const std::vector<std::uint8_t> ids(45, 9);
  const Rgba8Canvas canvas = compose_tile_class_image(frame, 4, ids);
  const Rgba8 expected = expected_blend({255, 255, 255, 255}, 9);
  EXPECT_EQ(canvas.pixel(32, 0), expected);   // right column: 1 px wide tile
  EXPECT_EQ(canvas.pixel(0, 16), expected);   // bottom row: 1 px high tile
  EXPECT_EQ(canvas.pixel(32, 16), expected);  // 1 x 1 corner tile
  EXPECT_EQ(canvas.pixel(31, 15), expected);
}

TEST(TileClassImage, OutlinesOnlyWhereTheClassChanges) {
  // 16 x 8, 4 px tiles: 4 x 2 tiles. Top row: 0 0 16 16; bottom row: 8 8 8 8.
  const RgbaImage frame = uniform_frame(16, 8, {0.0f, 0.0f, 0.0f, 1.0f});
  const std::vector<std::uint8_t> ids{0, 0, 16, 16, 8, 8, 8, 8};
  const Rgba8Canvas canvas = compose_tile_class_image(frame, 4, ids);
  const Rgba8 black{0, 0, 0, 255};
  const Rgba8 c0 = expected_blend(black, 0);
  const Rgba8 c16 = expected_blend(black, 16);
  const Rgba8 c8 = expected_blend(black, 8);

  for (std::uint32_t y = 1; y < 4; ++y) {
    EXPECT_EQ(canvas.pixel(8, y), darker(c16)) << y;  // vertical line: 0 | 16
    EXPECT_EQ(canvas.pixel(7, y), c0) << y;           // one pixel wide
    EXPECT_EQ(canvas.pixel(9, y), c16) << y;
    EXPECT_EQ(canvas.pixel(4, y), c0) << y;  // border between two class-0 tiles: none
    EXPECT_EQ(canvas.pixel(12, y), c16) << y;
  }
  for (std::uint32_t x = 0; x < 16; ++x) {
    EXPECT_EQ(canvas.pixel(x, 4), darker(c8)) << x;  // horizontal line: top | bottom
    EXPECT_EQ(canvas.pixel(x, 5), c8) << x;
    // Frame edge: no horizontal line (the vertical 0 | 16 line still runs to the top).
    EXPECT_EQ(canvas.pixel(x, 0), x < 8 ? c0 : (x == 8 ? darker(c16) : c16)) << x;
  }
  // Inside the uniform bottom row, tile borders get no vertical lines.
  for (std::uint32_t x : {4u, 8u, 12u}) EXPECT_EQ(canvas.pixel(x, 6), c8) << x;
}

TEST(TileClassImage, LegendListsExactlyThePresentClassesInIdOrder) {
  const RgbaImage frame = uniform_frame(64, 64, {0.3f, 0.3f, 0.3f, 1.0f});
  std::vector<std::uint8_t> ids(16 * 16, 24);
  for (std::size_t i = 0; i < 30; ++i) ids[i] = 31;
  for (std::size_t i = 100; i < 110; ++i) ids[i] = 3;
  ids[200] = 16;
  const TileClassLegendLayout layout = tile_class_legend_layout(64, 64, 4, ids);
  const Rgba8Canvas canvas = compose_tile_class_image(frame, 4, ids);

  ASSERT_EQ(layout.rows.size(), 4u);
  const std::uint32_t expected_ids[] = {3, 16, 24, 31};
  const std::uint32_t expected_tiles[] = {10, 1, 256 - 41, 30};
  std::uint32_t previous_y = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& row = layout.rows[i];
    EXPECT_EQ(row.entry.optimised_id, expected_ids[i]);
    EXPECT_EQ(row.entry.tiles, expected_tiles[i]);
    EXPECT_EQ(row.entry.label, default_class_label(expected_ids[i]));
    EXPECT_GE(row.swatch_x, 64u);  // in the panel, right of the frame
    if (i > 0) {
      EXPECT_GT(row.swatch_y, previous_y);
    }
    previous_y = row.swatch_y;
    const std::uint32_t centre = row.swatch_size / 2;
    EXPECT_EQ(canvas.pixel(row.swatch_x + centre, row.swatch_y + centre), class_colour(expected_ids[i]));
    EXPECT_EQ(canvas.pixel(row.swatch_x, row.swatch_y), class_colour(expected_ids[i]));
    // The row's text is drawn: some ink within its first cell ('#').
    bool ink = false;
    for (std::uint32_t y = row.text_y; y < row.text_y + 9; ++y) {
      for (std::uint32_t x = row.text_x; x < row.text_x + 6; ++x) {
        ink = ink || canvas.pixel(x, y) == kLegendText;
      }
    }
    EXPECT_TRUE(ink) << i;
  }
  EXPECT_EQ(layout.rows[0].text.substr(0, 5), "#3   ");
  EXPECT_NE(layout.rows[3].text.find("(11.7%)"), std::string::npos) << layout.rows[3].text;
  EXPECT_NE(layout.rows[1].text.find("  1   (0.4%)"), std::string::npos) << layout.rows[1].text;

  // Swatch colours of absent classes appear nowhere in the panel.
  for (std::uint32_t y = 0; y < canvas.height; ++y) {
    for (std::uint32_t x = 64; x < canvas.width; ++x) {
      const Rgba8 pixel = canvas.pixel(x, y);
      ASSERT_NE(pixel, class_colour(0));
      ASSERT_NE(pixel, class_colour(8));
    }
  }
}

TEST(TileClassImage, LegendUsesCustomLabels) {
  const RgbaImage frame = uniform_frame(4, 4, {0, 0, 0, 1});
  const std::vector<std::uint8_t> ids{7};
  const ClassLabelFn label = [](std::uint32_t id) { return "class " + std::to_string(id); };
  const auto entries = tile_class_legend_entries(ids, label);
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].label, "class 7");
  const Rgba8Canvas canvas = compose_tile_class_image(frame, 4, ids, label);
  EXPECT_EQ(canvas.width, 4u + tile_class_legend_layout(4, 4, 4, ids, label).panel_width);
}

TEST(TileClassImage, TextScaleFollowsFrameHeight) {
  EXPECT_EQ(tile_class_legend_layout(8, 599, 8, std::vector<std::uint8_t>(75, 0)).scale, 1);
  const auto big = tile_class_legend_layout(8, 600, 8, std::vector<std::uint8_t>(75, 0));
  EXPECT_EQ(big.scale, 2);
  EXPECT_EQ(big.rows[0].swatch_size, 20u);
}

TEST(TileClassImage, WorksForTinyAndLargeFrames) {
  {
    const Rgba8Canvas canvas =
        compose_tile_class_image(uniform_frame(1, 1, {1, 0, 0, 1}), 8, std::vector<std::uint8_t>{20});
    EXPECT_EQ(canvas.pixel(0, 0), expected_blend({255, 0, 0, 255}, 20));
    EXPECT_GT(canvas.height, 1u);
  }
  {
    const Rgba8Canvas canvas = compose_tile_class_image(uniform_frame(0, 0, {0, 0, 0, 0}), 4, {});
    EXPECT_GT(canvas.width, 0u);
    EXPECT_EQ(canvas.pixel(0, 0), kLegendBackground);
  }
  for (const auto& [width, height, tile] :
       {std::array<std::uint32_t, 3>{1280, 720, 8}, std::array<std::uint32_t, 3>{3840, 2160, 4}}) {
    const std::uint32_t tiles_x = tiles_along(width, tile);
    const std::uint32_t tiles_y = tiles_along(height, tile);
    std::vector<std::uint8_t> ids(std::size_t{tiles_x} * tiles_y);
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<std::uint8_t>((i / tiles_x / 8) % 32);
    const Rgba8Canvas canvas = compose_tile_class_image(uniform_frame(width, height, {0, 0, 0, 1}), tile, ids);
    EXPECT_EQ(canvas.height, height);
    EXPECT_GT(canvas.width, width);
    // Tile row 8 (class 1) starts at y = 8 * tile: outlined; one row further down: plain.
    EXPECT_EQ(canvas.pixel(width - 1, 8 * tile), darker(expected_blend({0, 0, 0, 255}, 1)));
    EXPECT_EQ(canvas.pixel(width - 1, 8 * tile + 1), expected_blend({0, 0, 0, 255}, 1));
    EXPECT_EQ(canvas.pixel(width - 1, height - 1), expected_blend({0, 0, 0, 255}, ids.back()));
  }
}

TEST(TileClassImage, RejectsBadArguments) {
  const RgbaImage frame = uniform_frame(33, 17, {0, 0, 0, 1});
  std::vector<std::uint8_t> ids(45, 0);
  EXPECT_EQ(error_of([&] { compose_tile_class_image(frame, 4, std::span(ids).first(44)); }),
            "tile class image: expected 45 tile IDs (9x5 tiles of 4 px for a 33x17 frame), got 44");
  ids[12] = 32;
  EXPECT_EQ(error_of([&] { compose_tile_class_image(frame, 4, ids); }),
            "tile class image: tile (3, 1) has optimised ID 32; IDs must be < 32");
  EXPECT_EQ(error_of([&] { tile_class_legend_entries(ids); }),
            "tile class image: tile 12 has optimised ID 32; IDs must be < 32");
  ids[12] = 0;
  EXPECT_EQ(error_of([&] { compose_tile_class_image(frame, 0, ids); }), "tile class image: tile size must be > 0");
  RgbaImage short_frame = frame;
  short_frame.pixels.pop_back();
  EXPECT_EQ(error_of([&] { compose_tile_class_image(short_frame, 4, ids); }),
            "tile class image: frame has 2243 floats, expected 33x17x4 = 2244");
}

// A synthetic scene with every kind of region, written for people to look at; only its
// existence is checked.
RgbaImage example_scene(std::uint32_t width, std::uint32_t height) {
  RgbaImage image = uniform_frame(width, height, {0, 0, 0, 1});
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const float u = static_cast<float>(x) / static_cast<float>(width);
      const float v = static_cast<float>(y) / static_cast<float>(height);
      float* p = &image.pixels[(std::size_t{y} * width + x) * 4];
      if (v < 0.35f) {  // sky gradient
        p[0] = 0.45f + 0.3f * v;
        p[1] = 0.6f + 0.3f * v;
        p[2] = 0.95f;
      } else {  // ground with a checker texture
        const bool check = ((x / 12) + (y / 12)) % 2 == 0;
        p[0] = check ? 0.55f : 0.4f;
        p[1] = check ? 0.5f : 0.38f;
        p[2] = 0.3f + 0.2f * u;
      }
    }
  }
  return image;
}

std::vector<std::uint8_t> example_ids(std::uint32_t tiles_x, std::uint32_t tiles_y) {
  std::vector<std::uint8_t> ids(std::size_t{tiles_x} * tiles_y);
  for (std::uint32_t ty = 0; ty < tiles_y; ++ty) {
    for (std::uint32_t tx = 0; tx < tiles_x; ++tx) {
      const float u = (static_cast<float>(tx) + 0.5f) / static_cast<float>(tiles_x);
      const float v = (static_cast<float>(ty) + 0.5f) / static_cast<float>(tiles_y);
      std::uint32_t id = 0;
      if (v < 0.35f) {
        id = 4;                         // sky
        if (v > 0.3f) id = 16 | 4 | 2;  // horizon: sky + sunlit geometry, MSAA edge
      } else {
        const float d1 = std::hypot(u - 0.3f, v - 0.65f);  // a shadowed blob
        const float d2 = std::hypot(u - 0.72f, v - 0.7f);  // a soft-shadowed blob
        if (d1 < 0.12f)
          id = 0;
        else if (d1 < 0.17f)
          id = 8;
        else if (d2 < 0.15f)
          id = 24;
        else
          id = 16;
        if ((d1 > 0.115f && d1 < 0.125f) || (d2 > 0.145f && d2 < 0.155f)) id |= 2;
      }
      if (u > 0.45f && u < 0.6f) id |= 1;  // a shaft of scattering light
      ids[std::size_t{ty} * tiles_x + tx] = static_cast<std::uint8_t>(id);
    }
  }
  return ids;
}

// The example pictures (kept in the build folder for a human to look at) are what the demo
// writes for such a frame: the legend lists exactly the classes present, the PNG decodes to the
// composed canvas pixel for pixel, and the frame part is the tinted frame.
TEST(TileClassImage, WritesExamplePictures) {
  const std::filesystem::path out = TILELIGHT_PICTURE_OUT;
  std::filesystem::create_directories(out);
  for (const auto& [name, width, height, tile] :
       {std::tuple<const char*, std::uint32_t, std::uint32_t, std::uint32_t>{"example.png", 320, 180, 4},
        std::tuple<const char*, std::uint32_t, std::uint32_t, std::uint32_t>{"example_720p.png", 1280, 720, 8}}) {
    SCOPED_TRACE(name);
    const std::uint32_t tiles_x = tiles_along(width, tile);
    const auto ids = example_ids(tiles_x, tiles_along(height, tile));
    const RgbaImage frame = example_scene(width, height);
    const Rgba8Canvas canvas = compose_tile_class_image(frame, tile, ids);
    const TileClassLegendLayout layout = tile_class_legend_layout(width, height, tile, ids);
    // Sky, horizon, ground, two shadows, their edges and the light shaft across them: the
    // legend has a row for each class present, in ID order, and no other.
    const std::set<std::uint8_t> present(ids.begin(), ids.end());
    std::vector<std::uint32_t> listed;
    for (const TileClassLegendLayout::Row& row : layout.rows) listed.push_back(row.entry.optimised_id);
    EXPECT_EQ(listed, std::vector<std::uint32_t>(present.begin(), present.end()));
    EXPECT_EQ(listed.size(), 17u);
    ASSERT_EQ(canvas.width, layout.canvas_width);
    ASSERT_EQ(canvas.height, layout.canvas_height);
    // Inside a tile, away from its outline: the documented tint of the frame and its class.
    const std::uint32_t x = 5 * tile + tile / 2, y = 3 * tile + tile / 2;
    const std::vector<std::uint8_t> frame8 = to_rgba8(frame);
    const std::size_t i = (std::size_t{y} * width + x) * 4;
    EXPECT_EQ(canvas.pixel(x, y), expected_blend({frame8[i], frame8[i + 1], frame8[i + 2], 255}, ids[3 * tiles_x + 5]));

    test::write_png_rgba8(out / name, canvas.width, canvas.height, canvas.pixels);
    const std::vector<std::uint8_t> decoded = decode_png(out / name, canvas.width, canvas.height);
    EXPECT_TRUE(decoded == canvas.pixels) << "the PNG does not hold the composed picture";
  }
}

}  // namespace
}  // namespace tilelight
