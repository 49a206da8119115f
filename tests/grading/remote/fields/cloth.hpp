#pragma once
// How kit/cloth/cloth.hpp's and kit/cloth/cloth_scene.hpp's types cross the link (wire.hpp).
#include <tuple>

#include <kit/cloth/cloth.hpp>

#include "../wire.hpp"

namespace kit {
inline auto fields(SpringFamily& f) { return std::tie(f.stiffness, f.damping); }
inline auto fields(SpringLayout& l) { return std::tie(l.structural, l.shear, l.bend, l.bend_layout); }
inline auto fields(ClothGrid& g) {
  return std::tie(g.nx, g.ny, g.width, g.height, g.origin, g.u, g.v, g.areal_density);
}
}  // namespace kit

namespace kit::remote {
/// A spring list whose arrays all have one length (a test indexes them together).
template <>
struct Codec<Springs> {
  static void put(Writer& w, const Springs& s) {
    remote::put(w, s.a), remote::put(w, s.b), remote::put(w, s.rest), remote::put(w, s.stiffness);
    remote::put(w, s.damping), remote::put(w, s.kind);
  }
  static void get(Reader& r, Springs& s) {
    remote::get(r, s.a), remote::get(r, s.b), remote::get(r, s.rest), remote::get(r, s.stiffness);
    remote::get(r, s.damping), remote::get(r, s.kind);
    const std::size_t n = s.a.size();
    if (s.b.size() != n || s.rest.size() != n || s.stiffness.size() != n || s.damping.size() != n ||
        s.kind.size() != n)
      throw ProtocolError("a spring list whose arrays differ in length");
  }
};
}  // namespace kit::remote
