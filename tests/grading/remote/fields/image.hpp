#pragma once
// How kit/render/image.hpp's and kit/sprites/sprite_tile.hpp's types cross the link (wire.hpp): an image or a
// tile must hold exactly its pixels, since the judge indexes them.
#include <tuple>

#include <kit/render/image.hpp>
#include <kit/sprites/sprite_tile.hpp>

#include "../wire.hpp"

namespace kit::remote {
template <>
struct Codec<Image> {
  static void put(Writer& w, const Image& i) {
    remote::put(w, i.width), remote::put(w, i.height), remote::put(w, i.rgb);
  }
  static void get(Reader& r, Image& i) {
    remote::get(r, i.width), remote::get(r, i.height), remote::get(r, i.rgb);
    if (i.width < 0 || i.height < 0 || i.rgb.size() != 3 * std::size_t(i.width) * std::size_t(i.height))
      throw ProtocolError("an image whose pixels do not match its size");
  }
};
template <>
struct Codec<SpriteTile> {
  static void put(Writer& w, const SpriteTile& t) {
    remote::put(w, t.x0), remote::put(w, t.y0), remote::put(w, t.width), remote::put(w, t.height),
        remote::put(w, t.rgba);
  }
  static void get(Reader& r, SpriteTile& t) {
    remote::get(r, t.x0), remote::get(r, t.y0), remote::get(r, t.width), remote::get(r, t.height),
        remote::get(r, t.rgba);
    if (t.width < 0 || t.height < 0 || t.rgba.size() != 4 * std::size_t(t.width) * std::size_t(t.height))
      throw ProtocolError("a tile whose pixels do not match its size");
  }
};
}  // namespace kit::remote
