#include "fem_output.hpp"

#include <map>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include <kit/base/atomic_file.hpp>

namespace kit {

void write_fem_obj(const std::filesystem::path& path, const FemBody& body) {
  std::string text = fmt::format("# A {} sheet, {} nodes, {} triangles; positions in metres.\n"
                                 "# Written by the physics-for-animation kit; opens in Blender and MeshLab.\n"
                                 "o sheet\n",
                                 model_name(body.model()), body.nodes(), body.elements());
  text.reserve(text.size() + std::size_t(body.nodes()) * 50 + std::size_t(body.elements()) * 20);
  for (long k = 0; k < body.nodes(); ++k)
    text += fmt::format("v {:.9g} {:.9g} {:.9g}\n", body.x(k, 0), body.x(k, 1), body.x(k, 2));
  for (const auto& t : body.mesh().triangles)
    text += fmt::format("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
  write_file_atomic(path, text);
}

std::vector<int> boundary_loop(const TriangleMesh& mesh) {
  // A counter-clockwise triangle walks its boundary edges in the domain's counter-clockwise sense;
  // an inner edge is walked once each way and drops out.
  std::map<std::pair<int, int>, int> walked;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++walked[{t[k], t[(k + 1) % 3]}];
  std::map<int, int> next;
  for (const auto& [edge, count] : walked)
    if (!walked.contains({edge.second, edge.first})) next[edge.first] = edge.second;
  if (next.empty()) throw std::invalid_argument("boundary_loop: a mesh without a boundary");
  std::vector<int> loop{next.begin()->first};
  while (loop.size() <= next.size()) {
    loop.push_back(next.at(loop.back()));
    if (loop.back() == loop.front()) return loop;
  }
  throw std::invalid_argument("boundary_loop: the boundary is not one loop");
}

}  // namespace kit
