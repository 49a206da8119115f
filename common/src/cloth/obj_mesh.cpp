#include <kit/cloth/obj_mesh.hpp>

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include <kit/base/atomic_file.hpp>

namespace kit {
namespace {

void check_shape(const ClothGrid& grid, const NodeArray& x) {
  if (grid.nx < 2 || grid.ny < 2)
    throw std::invalid_argument(
        fmt::format("a cloth grid needs at least 2 x 2 nodes, not {} x {}", grid.nx, grid.ny));
  if (x.rows() != long(grid.nx) * grid.ny)
    throw std::invalid_argument(
        fmt::format("{} node positions for a {} x {} grid", x.rows(), grid.nx, grid.ny));
}

// The sheet's own orientation: u×v, or world up when u and v are parallel or not finite.
Vec3 sheet_normal(const ClothGrid& grid) {
  const Vec3 n = grid.u.cross(grid.v);
  const double length = n.norm();
  return std::isfinite(length) && length > 0 ? Vec3(n / length) : Vec3(0, 1, 0);
}

std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t at = 0;
  while (at < line.size()) {
    const std::size_t start = line.find_first_not_of(" \t\r", at);
    if (start == std::string_view::npos) break;
    const std::size_t end = std::min(line.find_first_of(" \t\r", start), line.size());
    words.push_back(line.substr(start, end - start));
    at = end;
  }
  return words;
}

}  // namespace

NodeArray vertex_normals(const ClothGrid& grid, const NodeArray& x) {
  check_shape(grid, x);
  const int nx = grid.nx, ny = grid.ny;
  NodeArray sum = NodeArray::Zero(x.rows(), 3);
  auto add_triangle = [&](long a, long b, long c) {
    // |(b − a) × (c − a)| is twice the triangle's area: summing the raw products weights by area.
    const Vec3 pa = x.row(a), pb = x.row(b), pc = x.row(c);
    const Vec3 n = (pb - pa).cross(pc - pa);
    if (!n.allFinite()) return;  // a diverged node must not poison its neighbours' normals
    sum.row(a) += n.transpose(), sum.row(b) += n.transpose(), sum.row(c) += n.transpose();
  };
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const long a = long(j) * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
      add_triangle(a, b, c);
      add_triangle(a, c, d);
    }
  const Vec3 fallback = sheet_normal(grid);
  for (long k = 0; k < sum.rows(); ++k) {
    const double length = sum.row(k).norm();
    if (std::isfinite(length) && length > 1e-300)
      sum.row(k) /= length;
    else
      sum.row(k) = fallback.transpose();
  }
  return sum;
}

void write_cloth_obj(const std::filesystem::path& path, const ClothGrid& grid, const NodeArray& x) {
  const NodeArray normals = vertex_normals(grid, x);
  const int nx = grid.nx, ny = grid.ny;
  std::string text =
      fmt::format("# Cloth sheet, {} x {} nodes ({} x {} m at rest), {} triangles; positions in metres.\n"
                  "# Written by the physics-for-animation kit; opens in Blender and MeshLab.\n"
                  "o cloth\n",
                  nx, ny, grid.width, grid.height, 2L * (nx - 1) * (ny - 1));
  text.reserve(text.size() + std::size_t(x.rows()) * 110);
  for (long k = 0; k < x.rows(); ++k)
    text += fmt::format("v {:.9g} {:.9g} {:.9g}\n", x(k, 0), x(k, 1), x(k, 2));
  for (long k = 0; k < x.rows(); ++k)
    text += fmt::format("vn {:.9g} {:.9g} {:.9g}\n", normals(k, 0), normals(k, 1), normals(k, 2));
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const long a = long(j) * nx + i + 1, b = a + 1, c = a + nx + 1, d = a + nx;  // 1-based
      text += fmt::format("f {0}//{0} {1}//{1} {2}//{2}\nf {0}//{0} {2}//{2} {3}//{3}\n", a, b, c, d);
    }
  write_file_atomic(path, text);
}

ObjMesh read_obj(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot open the OBJ file", path.string()));
  ObjMesh mesh;
  std::string line;
  long line_number = 0;
  auto fail = [&](const std::string& why) {
    return std::runtime_error(fmt::format("{}:{}: {}: '{}'", path.string(), line_number, why, line));
  };
  auto number = [&](std::string_view word) {
    double value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size())
      throw fail(fmt::format("'{}' is not a number", word));
    return value;
  };
  auto index = [&](std::string_view word, std::size_t defined, const char* what) {
    int value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size())
      throw fail(fmt::format("'{}' is not a {} index", word, what));
    if (value < 1 || std::size_t(value) > defined)
      throw fail(fmt::format("{} index {} is outside 1 … {}", what, value, defined));
    return value - 1;
  };
  while (std::getline(in, line)) {
    ++line_number;
    const std::vector<std::string_view> words = words_of(line);
    if (words.empty() || words[0].starts_with('#')) continue;
    const std::string_view key = words[0];
    if (key == "o" || key == "g" || key == "s") continue;
    if (key == "v" || key == "vn") {
      if (words.size() != 4) throw fail(fmt::format("'{}' needs 3 numbers, not {}", key, words.size() - 1));
      const Vec3 value(number(words[1]), number(words[2]), number(words[3]));
      (key == "v" ? mesh.positions : mesh.normals).push_back(value);
    } else if (key == "f") {
      if (words.size() != 4) throw fail(fmt::format("a face needs 3 vertices, not {}", words.size() - 1));
      std::array<int, 3> face{};
      for (int k = 0; k < 3; ++k) {
        const std::string_view word = words[std::size_t(k) + 1];
        const std::size_t slashes = word.find("//");
        face[std::size_t(k)] = index(word.substr(0, slashes), mesh.positions.size(), "vertex");
        if (slashes == std::string_view::npos) continue;
        const int normal = index(word.substr(slashes + 2), mesh.normals.size(), "normal");
        if (normal != face[std::size_t(k)])
          throw fail(fmt::format("normal {} given to vertex {}: one normal per vertex, same index",
                                 normal + 1, face[std::size_t(k)] + 1));
      }
      mesh.faces.push_back(face);
    } else {
      throw fail(fmt::format("unknown keyword '{}'", key));
    }
  }
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
    throw std::runtime_error(fmt::format("{}: {} normals for {} vertices", path.string(), mesh.normals.size(),
                                         mesh.positions.size()));
  return mesh;
}

}  // namespace kit
