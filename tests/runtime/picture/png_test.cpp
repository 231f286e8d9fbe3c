// PNG output: correct pixels, atomic replacement (encode_png's bytes written as the products
// write them, through tilelight/base/atomic_write.h), errors that name the path.
#include "tilelight/picture/png.h"
#include "tilelight/base/error.h"
#include "tilelight_testing/png_file.h"

#include <gtest/gtest.h>
#include <stb/stb_image.h>
#include <testsupport/scratch_dir.h>

#include <fstream>
#include <limits>

namespace tilelight {
namespace {

RgbaImage gradient(std::uint32_t width, std::uint32_t height) {
  RgbaImage image;
  image.width = width;
  image.height = height;
  image.pixels.resize(std::size_t{width} * height * 4);
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      float* p = &image.pixels[(std::size_t{y} * width + x) * 4];
      p[0] = static_cast<float>(x) / static_cast<float>(width - 1);
      p[1] = static_cast<float>(y) / static_cast<float>(height - 1);
      p[2] = 0.5f;
      p[3] = 1.0f;
    }
  }
  return image;
}

std::vector<std::filesystem::path> entries(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> out;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    out.push_back(entry.path().filename());
  }
  return out;
}

TEST(Png, ToRgba8ClampsAndRounds) {
  RgbaImage image;
  image.width = 2;
  image.height = 1;
  image.pixels = {-1.0f,           0.5f, 2.0f, std::numeric_limits<float>::quiet_NaN(), 1.0f / 255.0f, 0.499f / 255.0f,
                  254.5f / 255.0f, 1.0f};
  EXPECT_EQ(to_rgba8(image), (std::vector<std::uint8_t>{0, 128, 255, 0, 1, 0, 255, 255}));
}

TEST(Png, WritesDecodablePixelsAndNoTemporaryFile) {
  const std::filesystem::path dir = testsupport::scratch_dir(TILELIGHT_PICTURE_OUT);
  const std::filesystem::path path = dir / "lit.png";
  const RgbaImage image = gradient(17, 9);
  test::write_png(path, image);
  // Writing again replaces the file in one step.
  test::write_png(path, image);
  EXPECT_EQ(entries(dir), std::vector<std::filesystem::path>{"lit.png"});

  int width = 0;
  int height = 0;
  int channels = 0;
  unsigned char* decoded = stbi_load(path.c_str(), &width, &height, &channels, 4);
  ASSERT_NE(decoded, nullptr) << stbi_failure_reason();
  EXPECT_EQ(width, 17);
  EXPECT_EQ(height, 9);
  const std::vector<std::uint8_t> expected = to_rgba8(image);
  EXPECT_EQ(std::vector<std::uint8_t>(decoded, decoded + expected.size()), expected);
  stbi_image_free(decoded);
}

TEST(Png, UnwritableFolderNamesThePath) {
  const std::filesystem::path dir = testsupport::scratch_dir(TILELIGHT_PICTURE_OUT);
  // A regular file where a folder should be: fails even for root, unlike permission bits.
  std::ofstream(dir / "not-a-folder") << "x";
  const std::filesystem::path path = dir / "not-a-folder" / "out.png";
  try {
    test::write_png(path, gradient(2, 2));
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string text = e.what();
    EXPECT_EQ(text.rfind("cannot write PNG " + path.string() + ": ", 0), 0u) << text;
    EXPECT_NE(text.find("Not a directory"), std::string::npos) << text;
  }
  EXPECT_EQ(entries(dir), std::vector<std::filesystem::path>{"not-a-folder"});
}

TEST(Png, SizeMismatchIsAnError) {
  const std::filesystem::path dir = testsupport::scratch_dir(TILELIGHT_PICTURE_OUT);
  const std::vector<std::uint8_t> too_short(4 * 3);
  EXPECT_THROW(test::write_png_rgba8(dir / "x.png", 2, 2, too_short), Error);
  EXPECT_TRUE(entries(dir).empty());
}

}  // namespace
}  // namespace tilelight
