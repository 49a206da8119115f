// What the browser test reads off a screenshot (tests/browser/pages.py): within a rectangle of a
// PNG, how much of it is not its most common colour (a blank canvas is one colour), the share of
// pixels of a few colour classes, and how much of it differs from the same rectangle of another
// PNG. Prints one JSON object.
//
// Usage: png_probe FILE X Y W H [OTHER]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include <stb_image.h>

namespace {

struct Png {
  int width = 0, height = 0;
  unsigned char* rgb = nullptr;
  explicit Png(const char* path) {
    int channels = 0;
    rgb = stbi_load(path, &width, &height, &channels, 3);
  }
  ~Png() { stbi_image_free(rgb); }
  Png(const Png&) = delete;
  Png& operator=(const Png&) = delete;
  const unsigned char* at(int x, int y) const {
    return rgb + 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6 && argc != 7) {
    std::fprintf(stderr, "usage: png_probe FILE X Y W H [OTHER]\n");
    return 2;
  }
  const Png png(argv[1]);
  if (!png.rgb) {
    std::fprintf(stderr, "png_probe: cannot read %s: %s\n", argv[1], stbi_failure_reason());
    return 2;
  }
  const int x0 = std::clamp(std::atoi(argv[2]), 0, png.width),
            y0 = std::clamp(std::atoi(argv[3]), 0, png.height);
  const int x1 = std::clamp(x0 + std::atoi(argv[4]), x0, png.width),
            y1 = std::clamp(y0 + std::atoi(argv[5]), y0, png.height);
  const long pixels = long(x1 - x0) * (y1 - y0);
  if (pixels == 0) {
    std::fprintf(stderr, "png_probe: the rectangle holds no pixel\n");
    return 2;
  }
  std::map<long, long> counts;  // colour → pixels
  long red = 0, blue = 0, green = 0, bright = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const unsigned char* p = png.at(x, y);
      const int r = p[0], g = p[1], b = p[2];
      ++counts[long(r) << 16 | long(g) << 8 | b];
      red += r > g + 40 && r > b + 40;
      blue += b > r + 40 && b > g + 10;
      green += g > r + 30;
      bright += r > 170 && g > 170 && b > 170;
    }
  long common = 0, background = 0;
  for (const auto& [colour, n] : counts)
    if (n > common) common = n, background = colour;
  long other = 0;  // pixels further than 16 from the most common colour in some channel
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const unsigned char* p = png.at(x, y);
      const int d[] = {std::abs(p[0] - int(background >> 16)), std::abs(p[1] - int((background >> 8) & 255)),
                       std::abs(p[2] - int(background & 255))};
      other += *std::max_element(d, d + 3) > 16;
    }
  double differs = -1;
  if (argc == 7) {
    const Png second(argv[6]);
    if (!second.rgb || second.width != png.width || second.height != png.height) {
      std::fprintf(stderr, "png_probe: %s cannot be read or is not %d x %d\n", argv[6], png.width,
                   png.height);
      return 2;
    }
    long changed = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const unsigned char *a = png.at(x, y), *b = second.at(x, y);
        changed += std::abs(a[0] - b[0]) > 16 || std::abs(a[1] - b[1]) > 16 || std::abs(a[2] - b[2]) > 16;
      }
    differs = double(changed) / double(pixels);
  }
  std::printf("{\"width\": %d, \"height\": %d, \"not_background\": %.6f, \"red\": %.6f, \"blue\": %.6f, "
              "\"green\": %.6f, \"bright\": %.6f, \"differs\": %.6f}\n",
              png.width, png.height, double(other) / double(pixels), double(red) / double(pixels),
              double(blue) / double(pixels), double(green) / double(pixels), double(bright) / double(pixels),
              differs);
  return 0;
}
