#include <kit/sprites/sprite_texture.hpp>

#include <cctype>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <kit/base/usage.hpp>
#include <kit/render/image.hpp>

namespace kit {
namespace {

constexpr int size = 64;

std::string builtin_list() { return fmt::format("{}", fmt::join(builtin_texture_names, ", ")); }

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

// A white texture whose alpha is shape(x, y), with x, y in [−1, 1] at texel centres (y up).
template <class Shape>
Texture white_texture(Shape shape) {
  Texture t{size, size, std::vector<float>(4 * size * size)};
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const double x = (i + 0.5) / size * 2 - 1, y = 1 - (j + 0.5) / size * 2;
      float* p = t.rgba.data() + 4 * (j * size + i);
      p[0] = p[1] = p[2] = 1;
      p[3] = static_cast<float>(std::clamp(shape(x, y), 0.0, 1.0));
    }
  return t;
}

// Goes from 1 at the centre to exactly 0 at radius 1 and beyond, so no texture shows its square.
double edge_window(double r) { return 1 - smoothstep(0.7, 1.0, r); }

double soft(double x, double y) {
  const double r2 = x * x + y * y;
  return std::exp(-r2 / (2 * 0.35 * 0.35)) * edge_window(std::sqrt(r2));
}

// A glowing point: a narrow Gaussian core, a faint halo, and four thin rays along x and y that
// taper to nothing at the border.
double spark(double x, double y) {
  const double r = std::hypot(x, y);
  const double core = std::exp(-r * r / (2 * 0.08 * 0.08));
  const double halo = 0.25 * std::exp(-r * r / (2 * 0.3 * 0.3));
  auto ray = [](double along, double across) {
    const double taper = std::max(0.0, 1 - std::abs(along));
    return std::exp(-across * across / (2 * 0.025 * 0.025)) * taper * taper;
  };
  const double star = std::max(ray(x, y), ray(y, x));
  return (core + halo + 0.9 * star) * edge_window(r);
}

// Distance from (x, y) to the segment from a to b.
double segment_distance(double x, double y, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay;
  const double t = std::clamp(((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(x - ax - t * dx, y - ay - t * dy);
}

// Six arms 60° apart, each with two side branches at 30° from it, plus a small bright hub.
double flake(double x, double y) {
  constexpr double arm = 0.85, half_width = 0.045;
  double nearest = 1e9;
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3;
    const double ux = std::cos(a), uy = std::sin(a);
    nearest = std::min(nearest, segment_distance(x, y, 0, 0, arm * ux, arm * uy));
    for (double at : {0.45, 0.65}) {  // branch roots along the arm, shorter further out
      const double length = at < 0.5 ? 0.25 : 0.17;
      const double bx = at * ux, by = at * uy;
      for (double side : {-1.0, 1.0}) {
        const double b = a + side * std::numbers::pi / 6;
        nearest = std::min(
            nearest, segment_distance(x, y, bx, by, bx + length * std::cos(b), by + length * std::sin(b)));
      }
    }
  }
  const double line = 1 - smoothstep(half_width * 0.5, half_width * 1.5, nearest);
  const double hub = std::exp(-(x * x + y * y) / (2 * 0.1 * 0.1));
  return std::max(line, hub) * edge_window(std::hypot(x, y));
}

// Value noise on an integer lattice: a fixed integer hash (no rand(), no seed), so every run
// and every machine draws the same smoke.
double lattice_value(int i, int j, std::uint32_t octave) {
  std::uint32_t h = static_cast<std::uint32_t>(i) * 0x8da6b343u ^
                    static_cast<std::uint32_t>(j) * 0xd8163841u ^ octave * 0xcb1ab31fu;
  h ^= h >> 16, h *= 0x7feb352du, h ^= h >> 15, h *= 0x846ca68bu, h ^= h >> 16;
  return static_cast<double>(h) / 4294967295.0;
}

double value_noise(double x, double y, std::uint32_t octave) {
  const double fx = std::floor(x), fy = std::floor(y);
  const int i = static_cast<int>(fx), j = static_cast<int>(fy);
  const double sx = smoothstep(0, 1, x - fx), sy = smoothstep(0, 1, y - fy);
  const double top = std::lerp(lattice_value(i, j, octave), lattice_value(i + 1, j, octave), sx);
  const double bottom = std::lerp(lattice_value(i, j + 1, octave), lattice_value(i + 1, j + 1, octave), sx);
  return std::lerp(top, bottom, sy);
}

// A puff: a broad radial falloff modulated by three octaves of noise (fractal sum, in [0, 1]).
double smoke(double x, double y) {
  double noise = 0, amplitude = 0.5, frequency = 3, total = 0;
  for (std::uint32_t octave = 0; octave < 3; ++octave, amplitude *= 0.5, frequency *= 2) {
    noise += amplitude * value_noise((x + 1) * frequency, (y + 1) * frequency, octave);
    total += amplitude;
  }
  noise /= total;
  const double r = std::hypot(x, y);
  const double puff = std::exp(-r * r / (2 * 0.4 * 0.4));
  return puff * (0.55 + 0.45 * noise) * edge_window(r);
}

}  // namespace

Texture builtin_texture(std::string_view name) {
  if (name == "soft") return white_texture(soft);
  if (name == "spark") return white_texture(spark);
  if (name == "flake") return white_texture(flake);
  if (name == "smoke") return white_texture(smoke);
  throw UsageError(fmt::format(
      "unknown texture '{}': the built-in textures are {}, or give a PNG file's path", name, builtin_list()));
}

Texture texture_for(const std::string& name_or_png_path) {
  for (std::string_view builtin : builtin_texture_names)
    if (name_or_png_path == builtin) return builtin_texture(builtin);
  const std::filesystem::path path(name_or_png_path);
  std::string extension = path.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".png")
    throw UsageError(
        fmt::format("unknown texture '{}': the built-in textures are {}, or give a PNG file's path",
                    name_or_png_path, builtin_list()));
  try {
    const Rgba8 png = read_png(path);
    Texture t{png.width, png.height, std::vector<float>(png.rgba.size())};
    for (std::size_t k = 0; k < png.rgba.size(); ++k) t.rgba[k] = static_cast<float>(png.rgba[k]) / 255.0f;
    return t;
  } catch (const std::runtime_error& error) {
    throw UsageError(fmt::format("texture '{}' is not a readable PNG ({}); the built-in textures are {}",
                                 name_or_png_path, error.what(), builtin_list()));
  }
}

std::vector<Texture> mip_levels(const Texture& texture) {
  std::vector<Texture> levels{texture};
  while (levels.back().width > 1 || levels.back().height > 1) {
    const Texture& fine = levels.back();
    Texture coarse{(fine.width + 1) / 2, (fine.height + 1) / 2, {}};
    coarse.rgba.resize(4 * static_cast<std::size_t>(coarse.width) * static_cast<std::size_t>(coarse.height));
    for (int j = 0; j < coarse.height; ++j)
      for (int i = 0; i < coarse.width; ++i) {
        // The 2 × 2 block under this texel; an odd edge repeats its last row or column.
        double premultiplied[3] = {0, 0, 0}, alpha = 0;
        for (int dj = 0; dj < 2; ++dj)
          for (int di = 0; di < 2; ++di) {
            const float* p =
                fine.texel(std::min(2 * i + di, fine.width - 1), std::min(2 * j + dj, fine.height - 1));
            for (int k = 0; k < 3; ++k) premultiplied[k] += static_cast<double>(p[k]) * p[3];
            alpha += p[3];
          }
        float* q =
            coarse.rgba.data() + 4 * (static_cast<std::size_t>(j) * static_cast<std::size_t>(coarse.width) +
                                      static_cast<std::size_t>(i));
        for (int k = 0; k < 3; ++k) q[k] = alpha > 0 ? static_cast<float>(premultiplied[k] / alpha) : 0.0f;
        q[3] = static_cast<float>(alpha / 4);
      }
    levels.push_back(std::move(coarse));
  }
  return levels;
}

}  // namespace kit
