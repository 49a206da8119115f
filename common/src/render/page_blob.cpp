// How a web page stores a run's numbers (page_blob.hpp).
#include <kit/render/page_blob.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <stdexcept>

// Debian's libstb exports stb_image_write's deflate (it backs the PNG writer) without declaring
// it in the header's interface part.
extern "C" unsigned char* stbi_zlib_compress(unsigned char* data, int data_len, int* out_len, int quality);

namespace kit {

double Box::rounding_error() const { return 0.5 * (max - min).norm() / 65535; }

Box bounding_box(const std::vector<std::vector<Vec3>>& frames) {
  Box box{Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
  for (const auto& frame : frames)
    for (const Vec3& p : frame)
      if (p.allFinite()) box.min = box.min.cwiseMin(p), box.max = box.max.cwiseMax(p);
  if (!(box.min.array() <= box.max.array()).all()) return {Vec3::Zero(), Vec3::Ones()};
  for (int axis = 0; axis < 3; ++axis)  // a flat sheet: a side of zero length still maps
    if (box.max[axis] - box.min[axis] < 1e-9) box.max[axis] = box.min[axis] + 1e-9;
  return box;
}

std::vector<std::uint16_t> quantise(const std::vector<std::vector<Vec3>>& frames, const Box& box,
                                    bool delta) {
  std::vector<std::uint16_t> out;
  std::size_t total = 0;
  for (const auto& frame : frames) total += 3 * frame.size();
  out.reserve(total);
  const Vec3 scale = (box.max - box.min).cwiseInverse() * 65535.0;
  std::vector<std::uint16_t> previous;
  for (const auto& frame : frames) {
    std::vector<std::uint16_t> q;
    q.reserve(3 * frame.size());
    for (const Vec3& p : frame)
      for (int axis = 0; axis < 3; ++axis) {
        const double u = std::isfinite(p[axis]) ? (p[axis] - box.min[axis]) * scale[axis] : 32767.5;
        q.push_back(static_cast<std::uint16_t>(std::lround(std::clamp(u, 0.0, 65535.0))));
      }
    for (std::size_t i = 0; i < q.size(); ++i)
      out.push_back(delta && previous.size() == q.size() ? static_cast<std::uint16_t>(q[i] - previous[i])
                                                         : q[i]);
    previous = std::move(q);
  }
  return out;
}

std::string deflate_bytes(std::string_view bytes) {
  if (bytes.size() > std::size_t(std::numeric_limits<int>::max() / 2))
    throw std::invalid_argument("a page blob of over 1 GB");
  int size = 0;
  // Quality 5: stb's hash chain length; higher costs more time for a few percent.
  std::unique_ptr<unsigned char, decltype(&std::free)> packed(
      stbi_zlib_compress(reinterpret_cast<unsigned char*>(const_cast<char*>(bytes.data())), int(bytes.size()),
                         &size, 5),
      &std::free);
  if (!packed) throw std::runtime_error("deflate failed (out of memory)");
  return std::string(reinterpret_cast<const char*>(packed.get()), std::size_t(size));
}

std::string base64(std::string_view bytes) {
  static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = unsigned(std::uint8_t(bytes[i])) << 16 | unsigned(std::uint8_t(bytes[i + 1])) << 8 |
                       unsigned(std::uint8_t(bytes[i + 2]));
    out += {digits[v >> 18], digits[(v >> 12) & 63], digits[(v >> 6) & 63], digits[v & 63]};
  }
  if (const std::size_t left = bytes.size() - i; left > 0) {
    const unsigned v =
        unsigned(std::uint8_t(bytes[i])) << 16 | (left == 2 ? unsigned(std::uint8_t(bytes[i + 1])) << 8 : 0u);
    out += {digits[v >> 18], digits[(v >> 12) & 63], left == 2 ? digits[(v >> 6) & 63] : '=', '='};
  }
  return out;
}

}  // namespace kit
