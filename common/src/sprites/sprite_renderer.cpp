#include <kit/sprites/sprite_renderer.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

#include <kit/sprites/blend.hpp>

namespace kit {
namespace {
// Where a rasterized sprite's pixels go: blended straight into the image (3 floats a pixel)…
template <Blend mode>
struct ImageTarget {
  static constexpr int stride = 3;
  Image& image;
  float* row(int column, int row_index) { return image.pixel(column, row_index); }
  void put(float* pixel, Rgb c, float alpha) const { blend<mode>(pixel, c, alpha); }
};
// … or into a SpriteTile (4 floats a pixel: colour and opacity) for ex 5.3 to composite.
struct TileTarget {
  static constexpr int stride = 4;
  SpriteTile& tile;
  float* row(int column, int row_index) { return tile.at(column - tile.x0, row_index - tile.y0); }
  void put(float* pixel, Rgb c, float alpha) const {
    pixel[0] = c.r, pixel[1] = c.g, pixel[2] = c.b, pixel[3] = alpha;
  }
};
}  // namespace

SpriteRenderer::SpriteRenderer(const SpriteScene& scene, int width, int height)
    : camera_(scene.camera, width, height), background_(scene.background) {
  for (const Emitter& emitter : scene.emitters) {
    blend_of_emitter_.push_back(emitter.blend);
    // One copy of each texture, however many emitters share it.
    const auto [at, added] = texture_index_.try_emplace(emitter.texture, textures_.size());
    if (added) textures_.push_back(mip_levels(texture_for(emitter.texture)));
    texture_of_emitter_.push_back(at->second);
  }
  columns_.resize(static_cast<std::size_t>(width));
}

RenderStats SpriteRenderer::render(const Particles& particles, Image& out) {
  const int width = camera_.width(), height = camera_.height();
  if (out.width != width || out.height != height)
    out = Image(width, height, background_);
  else
    out.fill(background_);

  RenderStats stats;
  over_.clear();
  additive_.clear();
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const std::size_t e = particles.emitter[i];
    if (e >= blend_of_emitter_.size())
      throw std::out_of_range(fmt::format("particle {} names emitter {}, but the scene has {} emitters", i, e,
                                          blend_of_emitter_.size()));
    const auto at = camera_.project(particles.x[i], particles.y[i], particles.z[i]);
    // A diverged particle (non-finite position) is culled like one behind the camera.
    if (!at || !std::isfinite(at->px) || !std::isfinite(at->py) || !(particles.alpha[i] > 0) ||
        !(particles.size_m[i] > 0)) {
      ++stats.sprites_culled;
      continue;
    }
    const double edge = particles.size_m[i] * camera_.pixels_per_metre(at->depth);
    const double half = 0.5 * edge;
    if (!std::isfinite(edge) || at->px + half <= 0 || at->px - half >= width || at->py + half <= 0 ||
        at->py - half >= height) {
      ++stats.sprites_culled;
      continue;
    }
    const Sprite sprite{at->px, at->py, edge, at->depth, static_cast<std::uint32_t>(i)};
    (blend_of_emitter_[e] == Blend::over ? over_ : additive_).push_back(sprite);
  }
  // "over" depends on order: the farthest first, so nearer sprites cover it. Equal depths fall
  // back to the particle index, so the image does not depend on the sort algorithm.
  std::sort(over_.begin(), over_.end(), [](const Sprite& a, const Sprite& b) {
    return a.depth != b.depth ? a.depth > b.depth : a.index < b.index;
  });
  for (const Sprite& sprite : over_) {
    if (!composite_over_) {
      stats.pixels_blended += draw(sprite, particles, out, ImageTarget<Blend::over>{out});
      continue;
    }
    stats.pixels_blended += draw(sprite, particles, out, TileTarget{tile_});
    composite_over_(out, tile_);
  }
  for (const Sprite& sprite : additive_)
    stats.pixels_blended += draw(sprite, particles, out, ImageTarget<Blend::additive>{out});
  stats.sprites_drawn = static_cast<long>(over_.size() + additive_.size());
  return stats;
}

template <class Target>
long SpriteRenderer::draw(const Sprite& sprite, const Particles& particles, Image& out, Target target) {
  const std::size_t i = sprite.index;
  const std::vector<Texture>& mips = textures_[texture_of_emitter_[particles.emitter[i]]];
  // The mip level whose texels are about one pixel: log2(texels per pixel), rounded down, so a
  // sprite of a pixel or less shows the texture's average (its 1 × 1 level).
  const double texels_per_pixel = mips.front().width / sprite.edge;
  const auto level = static_cast<std::size_t>(std::clamp(
      std::floor(std::log2(std::max(1.0, texels_per_pixel))), 0.0, static_cast<double>(mips.size() - 1)));
  const Texture& texture = mips[level];

  // The square [x0, x1) × [y0, y1) in continuous pixel coordinates, clipped to the image.
  const double x0 = sprite.px - 0.5 * sprite.edge, x1 = sprite.px + 0.5 * sprite.edge;
  const double y0 = sprite.py - 0.5 * sprite.edge, y1 = sprite.py + 0.5 * sprite.edge;
  // Clamped as doubles first: a sprite next to the camera can span more pixels than an int holds.
  const auto inside = [](double v, int size) { return std::clamp(v, 0.0, double(size)); };
  const int column_begin = static_cast<int>(std::floor(inside(x0, out.width)));
  const int column_end = static_cast<int>(std::ceil(inside(x1, out.width)));
  const int row_begin = static_cast<int>(std::floor(inside(y0, out.height)));
  const int row_end = static_cast<int>(std::ceil(inside(y1, out.height)));
  if (column_begin >= column_end || row_begin >= row_end) return 0;
  if constexpr (std::is_same_v<Target, TileTarget>)
    target.tile.reset(column_begin, row_begin, column_end - column_begin, row_end - row_begin);

  // Bilinear filtering is separable: the texel columns and weights depend on the image column
  // only, the texel rows on the image row only, so both are found once per sprite and row, and
  // the per-pixel work is four texel reads and three interpolations. Texel centres sit at
  // (i + ½)/width of the square; outside them the edge texels extend (clamp to edge).
  const double texels_per_px_x = texture.width / sprite.edge, texels_per_px_y = texture.height / sprite.edge;
  const int columns = column_end - column_begin;
  for (int k = 0; k < columns; ++k) {
    const double left = column_begin + k;
    const double t = std::clamp((left + 0.5 - x0) * texels_per_px_x - 0.5, 0.0, texture.width - 1.0);
    const int t0 = static_cast<int>(t);
    columns_[static_cast<std::size_t>(k)] = {t0, std::min(t0 + 1, texture.width - 1),
                                             static_cast<float>(t - t0),
                                             static_cast<float>(std::min(left + 1, x1) - std::max(left, x0))};
  }
  const Rgb tint{particles.r[i], particles.g[i], particles.b[i]};
  const float opacity = particles.alpha[i];
  const ColumnSample* column = columns_.data();
  long blended = 0;
  for (int row = row_begin; row < row_end; ++row) {
    const double top = row;
    const float row_opacity = opacity * static_cast<float>(std::min(top + 1, y1) - std::max(top, y0));
    const double t = std::clamp((top + 0.5 - y0) * texels_per_px_y - 0.5, 0.0, texture.height - 1.0);
    const int t0 = static_cast<int>(t);
    const float down = static_cast<float>(t - t0);
    const float* upper = texture.texel(0, t0);
    const float* lower = texture.texel(0, std::min(t0 + 1, texture.height - 1));
    float* pixel = target.row(column_begin, row);
    for (int k = 0; k < columns; ++k, pixel += Target::stride) {
      const ColumnSample& c = column[k];
      const float* a = upper + 4 * c.left;
      const float* b = upper + 4 * c.right;
      const float* d = lower + 4 * c.left;
      const float* e = lower + 4 * c.right;
      float texel[4];
      for (int channel = 0; channel < 4; ++channel) {
        const float above = a[channel] + c.toward_right * (b[channel] - a[channel]);
        const float below = d[channel] + c.toward_right * (e[channel] - d[channel]);
        texel[channel] = above + down * (below - above);
      }
      const float alpha = texel[3] * row_opacity * c.coverage;
      if (!(alpha > 0)) continue;
      target.put(pixel, Rgb{texel[0] * tint.r, texel[1] * tint.g, texel[2] * tint.b}, alpha);
      ++blended;
    }
  }
  return blended;
}

}  // namespace kit
