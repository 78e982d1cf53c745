// Images: PNG/EXR round trips through OpenImageIO, differences, masked MSE, atomic writes.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/image.h"
#include "io/temp_dir.h"

using namespace sn::io;
namespace fs = std::filesystem;

static fs::path tmpdir() {
  static const sn::io::TempDir dir("test_image");  // removed at exit
  return dir.path();
}

TEST(Image, ExrRoundTripIsExact) {
  Image a(5, 3, 4);
  for (size_t i = 0; i < a.pixels.size(); ++i) a.pixels[i] = float(i) * 0.37f - 2.f;
  auto path = (tmpdir() / "a.exr").string();
  save_image(a, path);
  Image b = load_image(path);
  ASSERT_EQ(b.width, 5);
  ASSERT_EQ(b.height, 3);
  ASSERT_EQ(b.channels, 4);
  EXPECT_EQ(a.pixels, b.pixels);
}

TEST(Image, PngRoundTripQuantisesTo8Bits) {
  Image a(4, 4, 3);
  for (size_t i = 0; i < a.pixels.size(); ++i) a.pixels[i] = float(i) / float(a.pixels.size());
  a.pixels[0] = 7.f;  // clamped to 1
  auto path = (tmpdir() / "a.png").string();
  save_image(a, path);
  Image b = load_image(path);
  EXPECT_FLOAT_EQ(b.pixels[0], 1.f);
  for (size_t i = 1; i < a.pixels.size(); ++i) EXPECT_NEAR(a.pixels[i], b.pixels[i], 0.5 / 255 + 1e-6);
}

TEST(Image, TopRowStaysOnTop) {
  Image a(2, 2, 1);
  a.at(0, 0, 0) = 1.f;  // top-left
  auto path = (tmpdir() / "corner.png").string();
  save_image(a, path);
  Image b = load_image(path);
  EXPECT_EQ(b.at(0, 0, 0), 1.f);
  EXPECT_EQ(b.at(0, 1, 0), 0.f);
}

TEST(Image, DifferenceAndMaskedMse) {
  Image a(2, 1, 4), b(2, 1, 4), mask(2, 1, 4);
  a.at(0, 0, 0) = 1.f;  // differs by 1 in one channel of pixel 0
  a.at(1, 0, 1) = 3.f;  // differs by 3 in pixel 1
  mask.at(0, 0, 3) = 1.f;
  EXPECT_FLOAT_EQ(difference(a, b).at(1, 0, 1), 3.f);
  EXPECT_DOUBLE_EQ(mse(a, b, 3), (1.0 + 9.0) / 6.0);
  EXPECT_DOUBLE_EQ(mse(a, b, 3, &mask, 3), 1.0 / 3.0);
  EXPECT_THROW(mse(a, Image(3, 1, 4)), std::invalid_argument);
}

TEST(Image, FailedSaveLeavesNothing) {
  Image a(2, 2, 3);
  auto path = (tmpdir() / "x.unknownext").string();
  EXPECT_THROW(save_image(a, path), std::runtime_error);
  EXPECT_FALSE(fs::exists(path));
  for (auto& e : fs::directory_iterator(tmpdir())) EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos);
}

TEST(Image, MissingAndCorruptFilesAreClearErrors) {
  EXPECT_THROW(load_image("tests/data/no_such_image.png"), std::runtime_error);
  try {
    load_image("tests/data/corrupt.png");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("tests/data/corrupt.png"), std::string::npos);
  }
}
