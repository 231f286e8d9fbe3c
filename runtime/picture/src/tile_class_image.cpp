#include "tilelight/picture/tile_class_image.h"

#include "tilelight/base/error.h"
#include "tilelight/picture/bitmap_font.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace tilelight {
namespace {

// The palette described in tile_class_image.h, precomputed (HSV hue per sun/shadow class;
// scattering: saturation x0.4, MSAA edge: value x0.6, sky: 40% towards white) so that the
// colours are exact bytes that tests and people comparing pictures can rely on.
// clang-format off
constexpr std::array<Rgba8, kOptimisedClassCount> kPalette{{
    {  0,  85, 255, 255},  //  0 solid shadow
    {153, 187, 255, 255},  //  1 solid shadow | scattering
    {  0,  51, 153, 255},  //  2 solid shadow | MSAA edge
    { 92, 112, 153, 255},  //  3 solid shadow | scattering | MSAA edge
    {102, 153, 255, 255},  //  4 sky
    {194, 214, 255, 255},  //  5 scattering | sky
    {102, 133, 194, 255},  //  6 MSAA edge | sky
    {157, 169, 194, 255},  //  7 scattering | MSAA edge | sky
    {  0, 255,  42, 255},  //  8 solid shadow+fade+sun
    {153, 255, 170, 255},  //  9 ... | scattering
    {  0, 153,  25, 255},  // 10 ... | MSAA edge
    { 92, 153, 102, 255},  // 11 ... | scattering | MSAA edge
    {102, 255, 127, 255},  // 12 ... | sky
    {194, 255, 204, 255},  // 13 ... | scattering | sky
    {102, 194, 117, 255},  // 14 ... | MSAA edge | sky
    {157, 194, 163, 255},  // 15 ... | scattering | MSAA edge | sky
    {255, 170,   0, 255},  // 16 sun, no shadow
    {255, 221, 153, 255},  // 17 ... | scattering
    {153, 102,   0, 255},  // 18 ... | MSAA edge
    {153, 133,  92, 255},  // 19 ... | scattering | MSAA edge
    {255, 204, 102, 255},  // 20 ... | sky
    {255, 235, 194, 255},  // 21 ... | scattering | sky
    {194, 163, 102, 255},  // 22 ... | MSAA edge | sky
    {194, 182, 157, 255},  // 23 ... | scattering | MSAA edge | sky
    {255,   0, 212, 255},  // 24 soft shadow+fade+sun
    {255, 153, 238, 255},  // 25 ... | scattering
    {153,   0, 127, 255},  // 26 ... | MSAA edge
    {153,  92, 143, 255},  // 27 ... | scattering | MSAA edge
    {255, 102, 229, 255},  // 28 ... | sky
    {255, 194, 245, 255},  // 29 ... | scattering | sky
    {194, 102, 178, 255},  // 30 ... | MSAA edge | sky
    {194, 157, 188, 255},  // 31 ... | scattering | MSAA edge | sky
}};
// clang-format on

constexpr std::uint32_t kScatteringBit = 1u << 0;
constexpr std::uint32_t kMsaaEdgeBit = 1u << 1;
constexpr std::uint32_t kSkyBit = 1u << 2;
constexpr std::uint32_t kSunShadowShift = 3;

void check_id(std::uint32_t optimised_id, const char* function) {
  if (optimised_id >= kOptimisedClassCount) {
    throw Error(fmt::format("{}: optimised ID {} is out of range; IDs must be < {}", function, optimised_id,
                            kOptimisedClassCount));
  }
}

std::uint32_t tiles_along(std::uint32_t pixels, std::uint32_t tile_size) {
  return pixels / tile_size + (pixels % tile_size != 0 ? 1u : 0u);
}

// Checks the tile grid and every ID, naming the first bad tile by its coordinates.
void check_tiles(std::uint32_t frame_width, std::uint32_t frame_height, std::uint32_t tile_size,
                 std::span<const std::uint8_t> tile_ids) {
  if (tile_size == 0) throw Error("tile class image: tile size must be > 0");
  const std::uint32_t tiles_x = tiles_along(frame_width, tile_size);
  const std::uint32_t tiles_y = tiles_along(frame_height, tile_size);
  const std::size_t expected = static_cast<std::size_t>(tiles_x) * tiles_y;
  if (tile_ids.size() != expected) {
    throw Error(fmt::format("tile class image: expected {} tile IDs ({}x{} tiles of {} px for a {}x{} frame), got {}",
                            expected, tiles_x, tiles_y, tile_size, frame_width, frame_height, tile_ids.size()));
  }
  for (std::size_t i = 0; i < tile_ids.size(); ++i) {
    if (tile_ids[i] >= kOptimisedClassCount) {
      throw Error(fmt::format("tile class image: tile ({}, {}) has optimised ID {}; IDs must be < {}", i % tiles_x,
                              i / tiles_x, tile_ids[i], kOptimisedClassCount));
    }
  }
}

std::uint32_t to_u32(int v) { return static_cast<std::uint32_t>(v); }

}  // namespace

std::array<std::uint8_t, 4> class_colour(std::uint32_t optimised_id) {
  check_id(optimised_id, "class_colour");
  return kPalette[optimised_id];
}

std::string default_class_label(std::uint32_t optimised_id) {
  check_id(optimised_id, "default_class_label");
  static constexpr const char* kSunShadow[] = {"solid shadow", "solid shadow+fade+sun", "sun, no shadow",
                                               "soft shadow+fade+sun"};
  const std::uint32_t sun_shadow = optimised_id >> kSunShadowShift;
  const bool sky = (optimised_id & kSkyBit) != 0;
  std::string label;
  const auto add = [&label](const char* part) {
    if (!label.empty()) label += " | ";
    label += part;
  };
  // See the header: on sky, class 00 means "no sun term", which is not worth a word.
  if (sun_shadow != 0 || !sky) add(kSunShadow[sun_shadow]);
  if ((optimised_id & kScatteringBit) != 0) add("scattering");
  if ((optimised_id & kMsaaEdgeBit) != 0) add("MSAA edge");
  if (sky) add("sky");
  return label;
}

std::vector<TileClassLegendEntry> tile_class_legend_entries(std::span<const std::uint8_t> tile_ids,
                                                            const ClassLabelFn& class_label) {
  std::array<std::uint32_t, kOptimisedClassCount> counts{};
  for (std::size_t i = 0; i < tile_ids.size(); ++i) {
    if (tile_ids[i] >= kOptimisedClassCount) {
      throw Error(fmt::format("tile class image: tile {} has optimised ID {}; IDs must be < {}", i, tile_ids[i],
                              kOptimisedClassCount));
    }
    ++counts[tile_ids[i]];
  }
  std::vector<TileClassLegendEntry> entries;
  for (std::uint32_t id = 0; id < kOptimisedClassCount; ++id) {
    if (counts[id] != 0) entries.push_back({id, class_label(id), counts[id]});
  }
  return entries;
}

TileClassLegendLayout tile_class_legend_layout(std::uint32_t frame_width, std::uint32_t frame_height,
                                               std::uint32_t tile_size, std::span<const std::uint8_t> tile_ids,
                                               const ClassLabelFn& class_label) {
  check_tiles(frame_width, frame_height, tile_size, tile_ids);

  TileClassLegendLayout layout;
  // Scale 1 text is hard to read once a 1080p or 4K picture is viewed scaled down.
  const int s = frame_height >= 600 ? 2 : 1;
  layout.scale = s;
  layout.panel_x = frame_width;
  layout.title = fmt::format("tile classes ({} tiles, tile size {})", tile_ids.size(), tile_size);

  const int pad = 8 * s;
  const int swatch = 10 * s;
  const int row_height = 13 * s;
  const int swatch_gap = 5 * s;
  const int rows_top = pad + text_height(s) + 6 * s;

  const std::vector<TileClassLegendEntry> entries = tile_class_legend_entries(tile_ids, class_label);
  // Monospaced columns: pad labels and counts to the widest one so counts line up.
  std::size_t label_chars = 0;
  std::size_t count_chars = 0;
  for (const TileClassLegendEntry& entry : entries) {
    label_chars = std::max(label_chars, entry.label.size());
    count_chars = std::max(count_chars, fmt::formatted_size("{}", entry.tiles));
  }

  int content_width = text_width(layout.title, s);
  const double total = static_cast<double>(tile_ids.size());
  int row_y = rows_top;
  for (const TileClassLegendEntry& entry : entries) {
    TileClassLegendLayout::Row row;
    row.entry = entry;
    // Right-aligned to the width of "(100.0%)" so the percentages line up too.
    const std::string percent = fmt::format("({:.1f}%)", 100.0 * static_cast<double>(entry.tiles) / total);
    row.text = fmt::format("#{:<2}  {:<{}}  {:>{}} {:>8}", entry.optimised_id, entry.label, label_chars, entry.tiles,
                           count_chars, percent);
    row.swatch_x = frame_width + to_u32(pad);
    row.swatch_y = to_u32(row_y);
    row.swatch_size = to_u32(swatch);
    row.text_x = row.swatch_x + to_u32(swatch + swatch_gap);
    // Centre the 7-row ink of the capitals on the swatch.
    row.text_y = to_u32(row_y + (swatch - 7 * s) / 2);
    content_width = std::max(content_width, swatch + swatch_gap + text_width(row.text, s));
    layout.rows.push_back(std::move(row));
    row_y += row_height;
  }

  layout.title_x = frame_width + to_u32(pad);
  layout.title_y = to_u32(pad);
  layout.panel_width = to_u32(pad + content_width + pad);
  layout.panel_height = to_u32(row_y + pad);
  layout.canvas_width = frame_width + layout.panel_width;
  layout.canvas_height = std::max(frame_height, layout.panel_height);
  return layout;
}

Rgba8Canvas compose_tile_class_image(const RgbaImage& frame, std::uint32_t tile_size,
                                     std::span<const std::uint8_t> tile_ids) {
  return compose_tile_class_image(frame, tile_size, tile_ids, default_class_label);
}

Rgba8Canvas compose_tile_class_image(const RgbaImage& frame, std::uint32_t tile_size,
                                     std::span<const std::uint8_t> tile_ids, const ClassLabelFn& class_label) {
  const std::size_t expected_floats = static_cast<std::size_t>(frame.width) * frame.height * 4;
  if (frame.pixels.size() != expected_floats) {
    throw Error(fmt::format("tile class image: frame has {} floats, expected {}x{}x4 = {}", frame.pixels.size(),
                            frame.width, frame.height, expected_floats));
  }
  const TileClassLegendLayout layout =
      tile_class_legend_layout(frame.width, frame.height, tile_size, tile_ids, class_label);
  Rgba8Canvas canvas = Rgba8Canvas::filled(layout.canvas_width, layout.canvas_height, kLegendBackground);

  // Frame: one pass, walking tile spans within each row so the tile lookup and the
  // neighbour comparisons happen once per tile span, not per pixel.
  const std::uint32_t tiles_x = tiles_along(frame.width, tile_size);
  for (std::uint32_t y = 0; y < frame.height; ++y) {
    const std::uint32_t tile_y = y / tile_size;
    const std::uint8_t* ids = tile_ids.data() + static_cast<std::size_t>(tile_y) * tiles_x;
    // Only the first pixel row of a tile can carry a top outline.
    const std::uint8_t* ids_above = (tile_y > 0 && y % tile_size == 0) ? ids - tiles_x : nullptr;
    const float* src = frame.pixels.data() + static_cast<std::size_t>(y) * frame.width * 4;
    std::uint8_t* dst = canvas.pixels.data() + static_cast<std::size_t>(y) * canvas.width * 4;
    for (std::uint32_t tile_x = 0; tile_x < tiles_x; ++tile_x) {
      const std::uint8_t id = ids[tile_x];
      const Rgba8& tint = kPalette[id];
      const bool top_outline = ids_above != nullptr && ids_above[tile_x] != id;
      const bool left_outline = tile_x > 0 && ids[tile_x - 1] != id;
      const std::uint32_t x0 = tile_x * tile_size;
      const std::uint32_t x1 = std::min(x0 + tile_size, frame.width);
      for (std::uint32_t x = x0; x < x1; ++x) {
        const bool outline = top_outline || (left_outline && x == x0);
        for (std::size_t c = 0; c < 3; ++c) {
          const unsigned blend = (to_unorm8(src[std::size_t{x} * 4 + c]) + unsigned{tint[c]} + 1u) / 2u;
          dst[std::size_t{x} * 4 + c] = static_cast<std::uint8_t>(outline ? blend / 2u : blend);
        }
        dst[x * 4 + 3] = 255;
      }
    }
  }

  // Legend.
  const int s = layout.scale;
  draw_text(canvas, static_cast<int>(layout.title_x), static_cast<int>(layout.title_y), layout.title, kLegendText, s);
  for (const TileClassLegendLayout::Row& row : layout.rows) {
    const int size = static_cast<int>(row.swatch_size);
    canvas.fill_rect(static_cast<int>(row.swatch_x), static_cast<int>(row.swatch_y), size, size,
                     kPalette[row.entry.optimised_id]);
    draw_text(canvas, static_cast<int>(row.text_x), static_cast<int>(row.text_y), row.text, kLegendText, s);
  }
  return canvas;
}

}  // namespace tilelight
