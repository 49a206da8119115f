// ex 5.3: one sprite composited "over" the image, clipped to it (sprite_over.hpp).
#include <vector>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "sprite_over.hpp"

namespace {
// A w × h tile at (x0, y0) of one colour and opacity.
kit::SpriteTile uniform_tile(int x0, int y0, int w, int h, float r, float g, float b, float alpha) {
  kit::SpriteTile tile;
  tile.reset(x0, y0, w, h);
  for (int row = 0; row < h; ++row)
    for (int column = 0; column < w; ++column) {
      float* p = tile.at(column, row);
      p[0] = r, p[1] = g, p[2] = b, p[3] = alpha;
    }
  return tile;
}
}  // namespace

TEST_CASE(
    "ex 5.3: over gives alpha·c + (1 − alpha)·dst exactly, for colours and alphas that floats hold exactly",
    "[grade][05-sprites][ex5.3]") {
  kit::Image image(4, 3, {0.5, 0.25, 1.0});
  kit::composite_over(image, uniform_tile(1, 1, 2, 1, 1.0f, 0.5f, 0.0f, 0.25f));
  // 0.25·(1, 0.5, 0) + 0.75·(0.5, 0.25, 1) = (0.625, 0.3125, 0.75)
  for (int x : {1, 2}) {
    CHECK(image.pixel(x, 1)[0] == 0.625f);
    CHECK(image.pixel(x, 1)[1] == 0.3125f);
    CHECK(image.pixel(x, 1)[2] == 0.75f);
  }
  for (int y = 0; y < 3; ++y)  // untouched around it
    for (int x = 0; x < 4; ++x)
      if (y != 1 || x == 0 || x == 3) CHECK(image.pixel(x, y)[0] == 0.5f);
  // Over again with alpha 1: the sprite's colour replaces the pixel; alpha 0 changes nothing.
  kit::composite_over(image, uniform_tile(1, 1, 1, 1, 0.125f, 0.0f, 1.0f, 1.0f));
  CHECK(image.pixel(1, 1)[0] == 0.125f);
  CHECK(image.pixel(1, 1)[2] == 1.0f);
  kit::composite_over(image, uniform_tile(0, 0, 4, 3, 0.9f, 0.9f, 0.9f, 0.0f));
  CHECK(image.pixel(2, 1)[0] == 0.625f);
  CHECK(image.pixel(0, 0)[1] == 0.25f);
}

TEST_CASE("ex 5.3: each pixel uses its own colour and alpha, and two sprites compose in order",
          "[grade][05-sprites][ex5.3]") {
  auto rng = kit::test::random_engine();
  kit::Image image(5, 5, {0.2, 0.4, 0.6});
  kit::SpriteTile tile;
  tile.reset(0, 0, 5, 5);
  for (float& v : tile.rgba) v = float(kit::test::uniform(rng, 0, 1));
  std::vector<float> expected = image.rgb;
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 5; ++x)
      for (int c = 0; c < 3; ++c) {
        const float a = tile.at(x, y)[3];
        float& e = expected[std::size_t(3 * (5 * y + x) + c)];
        e = a * tile.at(x, y)[c] + (1 - a) * e;
      }
  kit::composite_over(image, tile);
  // Any correct form (α·c + (1 − α)·dst, dst + α·(c − dst), fused or not) is within a few ulps.
  for (std::size_t i = 0; i < expected.size(); ++i)
    CHECK(image.rgb[i] == Approx(expected[i]).epsilon(1e-6).margin(1e-6));
  // Red at alpha 1/2 over blue at alpha 1/2 over black: (1/2, 0, 1/4); the other order differs.
  kit::Image first(1, 1, {0, 0, 0}), second(1, 1, {0, 0, 0});
  kit::composite_over(first, uniform_tile(0, 0, 1, 1, 0, 0, 1, 0.5f));
  kit::composite_over(first, uniform_tile(0, 0, 1, 1, 1, 0, 0, 0.5f));
  CHECK(first.pixel(0, 0)[0] == 0.5f);
  CHECK(first.pixel(0, 0)[2] == 0.25f);
  kit::composite_over(second, uniform_tile(0, 0, 1, 1, 1, 0, 0, 0.5f));
  kit::composite_over(second, uniform_tile(0, 0, 1, 1, 0, 0, 1, 0.5f));
  CHECK(second.pixel(0, 0)[0] == 0.25f);
}

TEST_CASE("ex 5.3: a sprite hanging over any border is clipped: only the pixels inside change",
          "[grade][05-sprites][ex5.3]") {
  struct Case {
    int x0, y0, w, h;
  };
  // Over the left, top, right and bottom borders, a corner, wholly outside, and larger than the image.
  for (const Case c : {Case{-2, 1, 4, 2}, Case{1, -3, 2, 5}, Case{5, 2, 6, 1}, Case{2, 3, 1, 9},
                       Case{-1, -1, 2, 2}, Case{7, 0, 3, 3}, Case{-5, -5, 20, 20}}) {
    INFO("tile at (" << c.x0 << ", " << c.y0 << "), " << c.w << " x " << c.h);
    kit::Image image(6, 4, {0.5, 0.5, 0.5});
    // A guard around the pixels: the image's own buffer must not grow or change size.
    const std::size_t size = image.rgb.size();
    kit::composite_over(image, uniform_tile(c.x0, c.y0, c.w, c.h, 1.0f, 1.0f, 1.0f, 0.5f));
    REQUIRE(image.rgb.size() == size);
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 6; ++x) {
        const bool inside = x >= c.x0 && x < c.x0 + c.w && y >= c.y0 && y < c.y0 + c.h;
        CHECK(image.pixel(x, y)[1] == (inside ? 0.75f : 0.5f));
      }
  }
}
