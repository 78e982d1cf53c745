// Live mode's overlays: text boxes that never run off the picture, a progress bar filled by its
// fraction, and the GPU blend that puts them over a copy of the picture.
#include <gtest/gtest.h>

#include "gl/context.h"
#include "gl/overlay.h"
#include "io/overlay.h"

using namespace sn;

TEST(Overlay, LongLinesAreCutToTheBox) {
  std::string longline(400, 'x');
  std::string cut = io::fit_text(longline, 200, 14);
  ASSERT_LT(cut.size(), longline.size());
  EXPECT_EQ(cut.substr(cut.size() - 3), "...");
  EXPECT_LE(io::text_size(cut, 14)[0], 200);
  EXPECT_EQ(io::fit_text("short", 200, 14), "short");
  io::Image box = io::text_box({{longline}, {"second"}}, 240);
  EXPECT_EQ(box.width, 240);
  EXPECT_EQ(box.channels, 4);
  EXPECT_FLOAT_EQ(box.at(0, 0, 3), 0.75f);  // the translucent background
}

TEST(Overlay, ProgressBarIsFilledByItsFraction) {
  io::Image bar = io::progress_bar(0.25, "", 200, {1, 0, 0});
  EXPECT_FLOAT_EQ(bar.at(49, 1, 0), 1.f);  // 50 pixels filled
  EXPECT_FLOAT_EQ(bar.at(50, 1, 0), 0.f);
  EXPECT_FLOAT_EQ(bar.at(49, 1, 3), 1.f);
  EXPECT_FLOAT_EQ(io::progress_bar(2.0, "", 10, {1, 0, 0}).at(9, 0, 0), 1.f);  // clamped
}

TEST(Overlay, BlendOverACopyLeavesThePicture) {
  gl::current();  // a headless context
  gl::RenderTarget picture(8, 6), shown(8, 6);
  picture.clear({0.2f, 0.4f, 0.6f, 1});
  gl::copy_color(picture, shown);
  io::Image o(2, 1, 4);
  for (int x = 0; x < 2; ++x) o.at(x, 0, 0) = 1, o.at(x, 0, 1) = 0, o.at(x, 0, 2) = 0, o.at(x, 0, 3) = 0.5f;
  gl::blend_over(shown, o, 3, 1);  // top-left origin: row 1 from the top, columns 3 and 4
  io::Image out = shown.read(), kept = picture.read();
  EXPECT_NEAR(out.at(3, 1, 0), 0.6, 1e-6);
  EXPECT_NEAR(out.at(4, 1, 1), 0.2, 1e-6);
  EXPECT_NEAR(out.at(5, 1, 0), 0.2, 1e-6);  // outside the overlay
  EXPECT_NEAR(out.at(3, 2, 0), 0.2, 1e-6);
  EXPECT_NEAR(kept.at(3, 1, 0), 0.2, 1e-6);  // the picture underneath is untouched
  EXPECT_THROW(gl::copy_color(picture, *std::make_unique<gl::RenderTarget>(4, 4)), std::invalid_argument);
}
