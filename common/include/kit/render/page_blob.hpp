#pragma once
// How a web page stores a run's numbers (web_page.hpp): positions rounded to 16 bits over a box,
// delta-coded from frame to frame, deflated (zlib format, which the browser's
// DecompressionStream("deflate") reads) and written as base64 text inside the page.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <kit/base/vec3.hpp>

namespace kit {

/// An axis-aligned box [m]; a side of zero length is widened so that every point maps.
struct Box {
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
  /// The largest distance a point moves when rounded to 16 bits in this box [m]: half a step
  /// along each axis, combined.
  double rounding_error() const;
};

/// The box around every finite point of every frame (the unit cube at 0 when there is none).
Box bounding_box(const std::vector<std::vector<Vec3>>& frames);

/// Each coordinate as round((p − min) / (max − min) · 65535), frame after frame; with `delta`,
/// frames after the first store the difference from the frame before, modulo 2^16. A coordinate
/// that is not finite is stored as the box's middle.
std::vector<std::uint16_t> quantise(const std::vector<std::vector<Vec3>>& frames, const Box& box, bool delta);

/// The bytes deflated into a zlib stream (RFC 1950).
std::string deflate_bytes(std::string_view bytes);

/// Standard base64 (RFC 4648, with '=' padding).
std::string base64(std::string_view bytes);

/// base64(deflate_bytes(the values' little-endian bytes)).
template <class T>
std::string page_blob(const std::vector<T>& values) {
  static_assert(std::is_integral_v<T>, "blobs hold integers");
  std::string bytes;
  bytes.reserve(values.size() * sizeof(T));
  for (const T value : values)
    for (std::size_t b = 0; b < sizeof(T); ++b)
      bytes.push_back(static_cast<char>((static_cast<std::uint64_t>(value) >> (8 * b)) & 0xff));
  return base64(deflate_bytes(bytes));
}

}  // namespace kit
