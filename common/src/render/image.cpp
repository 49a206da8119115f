#include <kit/render/image.hpp>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <stb_image.h>
#include <stb_image_write.h>

#include <kit/base/atomic_file.hpp>

namespace kit {

Image::Image(int w, int h, Colour colour) : width(w), height(h) {
  if (w < 1 || h < 1)
    throw std::invalid_argument(fmt::format("an image needs at least 1 x 1 pixels, not {} x {}", w, h));
  rgb.resize(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  fill(colour);
}

void Image::fill(Colour colour) {
  const float r = static_cast<float>(colour[0]), g = static_cast<float>(colour[1]),
              b = static_cast<float>(colour[2]);
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) rgb[i] = r, rgb[i + 1] = g, rgb[i + 2] = b;
}

std::uint8_t to_byte(float v) {
  if (!(v > 0)) return 0;  // also NaN
  if (v >= 1) return 255;
  return static_cast<std::uint8_t>(std::lround(255.0f * v));
}

namespace {
// stb_image_write hands the encoded PNG over in pieces; they are collected in memory so that
// the file itself is written once, atomically.
extern "C" void append_to_string(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}
}  // namespace

void write_png(const Image& image, const std::filesystem::path& path) {
  if (image.width < 1 || image.height < 1 ||
      image.rgb.size() != 3 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    throw std::invalid_argument(fmt::format("cannot write {}: the image is {} x {} with {} values",
                                            path.string(), image.width, image.height, image.rgb.size()));
  std::vector<std::uint8_t> bytes(image.rgb.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = to_byte(image.rgb[i]);
  std::string encoded;
  if (!stbi_write_png_to_func(append_to_string, &encoded, image.width, image.height, 3, bytes.data(),
                              3 * image.width))
    throw std::runtime_error(fmt::format("cannot encode {} as PNG", path.string()));
  write_file_atomic(path, encoded);
}

Rgba8 read_png(const std::filesystem::path& path) {
  int w = 0, h = 0, channels_in_file = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load(path.c_str(), &w, &h, &channels_in_file, 4), stbi_image_free);
  if (!pixels) {
    const char* reason = stbi_failure_reason();
    throw std::runtime_error(
        fmt::format("cannot read PNG {}: {}", path.string(), reason ? reason : "unknown reason"));
  }
  Rgba8 image{w, h, {}};
  image.rgba.assign(pixels.get(),
                    pixels.get() + 4 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  return image;
}

}  // namespace kit
