#pragma once
// The tile-classification picture (tile_classes.png): the lit frame with every tile tinted by
// its optimised lighting class, outlines where the class changes, and a legend panel to the
// right, in the style of GPU Pro 2, "Screen-Space Classification for Efficient Deferred
// Shading", figures 4.1/4.2. Pure CPU: it works from a read-back frame and the tile IDs, so it
// can be tested and drawn without a device.
//
// Optimised class ID bits (5 bits, 32 classes):
//   bit 0  light scattering
//   bit 1  MSAA edge
//   bit 2  sky
//   bits 3-4 sun/shadow class, (bit4, bit3):
//     00 solid shadow (no sun)        01 solid shadow + fade + sun
//     10 sun, no shadow               11 soft shadow + fade + sun
//
// Palette (class_colour): the sun/shadow class picks the hue, 90 degrees apart, so the four
// big lighting regions read at a glance: 00 blue (220), 01 green (130), 10 amber (40),
// 11 magenta (310). The other bits only change saturation and lightness of that hue:
// scattering desaturates (HSV saturation 1 -> 0.4), MSAA edge darkens (value 1 -> 0.6), sky
// lightens (mixed 40% towards white). All 32 colours differ by at least 39 in RGB distance.
//
// Picture layout (compose_tile_class_image):
//   - columns [0, frame.width) hold the frame: every pixel is the 50/50 blend, per channel
//     (a + b + 1) / 2, of the frame pixel converted like to_rgba8() and its tile's class colour;
//     alpha is 255.
//   - outline: the first pixel column of a tile whose left neighbour has a different class,
//     and the first pixel row of a tile whose upper neighbour has a different class, are drawn
//     darker (each channel of the blend halved, rounding down). Borders between tiles of the
//     same class and the frame edges get no outline, so the lines trace class regions.
//   - columns [frame.width, canvas width) hold the legend panel on a neutral dark grey
//     (kLegendBackground); rows below a frame shorter than the legend get the same grey.
//     Its geometry is given by tile_class_legend_layout().
//   - text scale is 2 when frame.height >= 600, otherwise 1 (see bitmap_font.h).

#include "tilelight/picture/rgba8_canvas.h"
#include "tilelight/picture/rgba_image.h"

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace tilelight {

inline constexpr std::uint32_t kOptimisedClassCount = 32;

// One legend row: a class that occurs in the frame and how many tiles have it.
struct TileClassLegendEntry {
  std::uint32_t optimised_id = 0;
  std::string label;
  std::uint32_t tiles = 0;
};

// Where the legend puts things, in canvas pixels. The panel starts at x = frame width.
struct TileClassLegendLayout {
  struct Row {
    TileClassLegendEntry entry;
    std::uint32_t swatch_x = 0, swatch_y = 0;  // top-left of the swatch
    std::uint32_t swatch_size = 0;             // the swatch is a square of class_colour
    std::uint32_t text_x = 0, text_y = 0;      // top-left of the row's text
    std::string text;                          // "#<id>  <label>  <tiles> (<pct>%)"
  };

  std::uint32_t canvas_width = 0;   // frame width + panel_width
  std::uint32_t canvas_height = 0;  // max(frame height, panel_height)
  std::uint32_t panel_x = 0;        // = frame width
  std::uint32_t panel_width = 0;
  std::uint32_t panel_height = 0;  // height the legend content needs
  int scale = 1;                   // text scale: 2 when frame height >= 600
  std::uint32_t title_x = 0, title_y = 0;
  std::string title;      // "tile classes (<N> tiles, tile size <T>)"
  std::vector<Row> rows;  // classes that occur, sorted by ID
};

// Neutral dark grey behind the legend and below a short frame, and the legend's text colour.
inline constexpr Rgba8 kLegendBackground{40, 40, 44, 255};
inline constexpr Rgba8 kLegendText{235, 235, 235, 255};

// A fixed colour per optimised class (see the palette above); alpha 255.
// Throws tilelight::Error if optimised_id >= 32.
std::array<std::uint8_t, 4> class_colour(std::uint32_t optimised_id);

// A readable name built from the ID bits: the sun/shadow part ("solid shadow",
// "solid shadow+fade+sun", "sun, no shadow", "soft shadow+fade+sun"), then "scattering",
// "MSAA edge" and "sky" for the bits that are set, joined by " | ". A sky tile of class 00
// drops "solid shadow": the sky is not lit by the sun, so 00 there means "no sun term", not
// a shadow. Examples: 0 "solid shadow", 4 "sky", 5 "scattering | sky",
// 27 "soft shadow+fade+sun | scattering | MSAA edge",
// 31 "soft shadow+fade+sun | scattering | MSAA edge | sky".
// Throws tilelight::Error if optimised_id >= 32.
std::string default_class_label(std::uint32_t optimised_id);

// Maps an optimised ID to the label the legend shows.
using ClassLabelFn = std::function<std::string(std::uint32_t optimised_id)>;

// Counts the classes in `tile_ids`, giving one entry per class present, sorted by ID.
// Throws tilelight::Error if an ID is >= 32:
//   "tile class image: tile <index> has optimised ID <v>; IDs must be < 32".
std::vector<TileClassLegendEntry> tile_class_legend_entries(std::span<const std::uint8_t> tile_ids,
                                                            const ClassLabelFn& class_label = default_class_label);

// The layout compose_tile_class_image() uses for this frame size and these tile IDs. Checks
// its arguments like compose_tile_class_image() (except the frame's pixel count).
TileClassLegendLayout tile_class_legend_layout(std::uint32_t frame_width, std::uint32_t frame_height,
                                               std::uint32_t tile_size, std::span<const std::uint8_t> tile_ids,
                                               const ClassLabelFn& class_label = default_class_label);

// Builds the picture described at the top of this file.
// frame: the lit frame as rendered (float RGBA, rows top to bottom); any size, even 0 x 0.
// tile_size: tile edge in pixels, > 0 (the renderer uses 4, 8 or 16).
// tile_ids: ROW-MAJOR optimised ID per tile, tiles_x * tiles_y entries with
//   tiles_x = ceil(frame.width / tile_size), tiles_y = ceil(frame.height / tile_size); tiles
//   on the right and bottom edges may be partial.
// Throws tilelight::Error, messages exactly:
//   "tile class image: tile size must be > 0"
//   "tile class image: frame has <n> floats, expected <W>x<H>x4 = <m>"
//   "tile class image: expected <n> tile IDs (<tx>x<ty> tiles of <T> px for a <W>x<H> frame),
//    got <m>"   (one line)
//   "tile class image: tile (<tx>, <ty>) has optimised ID <v>; IDs must be < 32"
// Cost: one pass over the frame pixels plus the legend; no per-pixel allocation.
Rgba8Canvas compose_tile_class_image(const RgbaImage& frame, std::uint32_t tile_size,
                                     std::span<const std::uint8_t> tile_ids);

// As above, with legend labels from `class_label` instead of default_class_label().
Rgba8Canvas compose_tile_class_image(const RgbaImage& frame, std::uint32_t tile_size,
                                     std::span<const std::uint8_t> tile_ids, const ClassLabelFn& class_label);

}  // namespace tilelight
