// A run as a page a browser plays in 3D (web_page.hpp).
#include <kit/render/web_page.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <kit/base/atomic_file.hpp>
#include <kit/base/stopwatch.hpp>
#include <kit/render/page_blob.hpp>

#include "web_assets.hpp"

#ifndef KIT_THREE_JS_DIR
#define KIT_THREE_JS_DIR "/usr/share/javascript/three"
#endif

namespace kit {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

template <class Frames>
Frames every_kth(const Frames& frames, long k) {
  Frames kept;
  for (std::size_t f = 0; f < frames.size(); f += std::size_t(k)) kept.push_back(frames[f]);
  return kept;
}

// A number for JSON: NaN and infinities, which JSON has not, become null.
json number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json array3(const Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }

json box_json(const Box& box) {
  return json::array({box.min.x(), box.min.y(), box.min.z(), box.max.x(), box.max.y(), box.max.z()});
}

// The largest rounding error of the positions this pane stores [m].
struct PaneJson {
  json value;
  double rounding = 0;
};

PaneJson pane_json(const PagePane& pane, long k) {
  PaneJson out;
  json& p = out.value;
  p["label"] = pane.label;
  if (!pane.cost.empty()) p["cost"] = pane.cost;
  if (!pane.ended.empty()) p["ended"] = pane.ended;
  p["facts"] = json::array();
  for (const auto& [name, value] : pane.facts) p["facts"].push_back({name, value});
  const long frames = (pane.frames() + k - 1) / k;
  p["frames"] = frames;
  p["readouts"] = json::array();
  for (const PageReadout& r : pane.readouts) {
    json values = json::array();
    for (const double v : every_kth(r.values, k)) values.push_back(number(v));
    p["readouts"].push_back({{"name", r.name}, {"unit", r.unit}, {"digits", r.digits}, {"values", values}});
  }
  json& objects = p["objects"] = json::array();
  for (const PageMesh& mesh : pane.meshes) {
    const auto kept = every_kth(mesh.frames, k);
    const Box box = bounding_box(kept);
    out.rounding = std::max(out.rounding, box.rounding_error());
    std::vector<std::uint32_t> indices;
    for (const auto& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
    json m = {{"type", "mesh"},
              {"name", mesh.name},
              {"color", mesh.color},
              {"vertices", kept.empty() ? 0 : kept.front().size()},
              {"triangles", mesh.triangles.size()},
              {"indices", page_blob(indices)},
              {"box", box_json(box)},
              {"frames", kept.size()},
              {"positions", page_blob(quantise(kept, box, true))},
              {"flat", mesh.flat}};
    if (!mesh.pins.empty()) m["pins"] = mesh.pins;
    if (!mesh.scalar.empty()) {
      const auto values = every_kth(mesh.scalar, k);
      double lo = INFINITY, hi = -INFINITY;
      for (const auto& frame : values)
        for (const double v : frame)
          if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
      if (!(lo <= hi)) lo = 0, hi = 1;
      if (hi - lo < 1e-300) hi = lo + 1;
      std::vector<std::uint8_t> bytes;
      for (const auto& frame : values)
        for (const double v : frame)
          bytes.push_back(std::isfinite(v) ? std::uint8_t(std::lround(255 * (v - lo) / (hi - lo))) : 0);
      m["scalar"] = {{"name", mesh.scalar_name},
                     {"unit", mesh.scalar_unit},
                     {"min", lo},
                     {"max", hi},
                     {"values", page_blob(bytes)}};
    }
    objects.push_back(std::move(m));
  }
  for (const PagePoints& points : pane.points) {
    const auto kept = every_kth(points.frames, k);
    const Box box = bounding_box(kept);
    out.rounding = std::max(out.rounding, box.rounding_error());
    std::vector<long> counts;
    std::vector<std::uint8_t> rgba;
    for (const auto& frame : every_kth(points.rgba, k)) {
      counts.push_back(long(frame.size()));
      for (const auto& c : frame) rgba.insert(rgba.end(), c.begin(), c.end());
    }
    objects.push_back({{"type", "points"},
                       {"name", points.name},
                       {"frames", kept.size()},
                       {"counts", counts},
                       {"box", box_json(box)},
                       {"positions", page_blob(quantise(kept, box, false))},
                       {"colors", page_blob(rgba)},
                       {"size", points.size}});
  }
  for (const PageSphere& s : pane.spheres)
    objects.push_back({{"type", "sphere"},
                       {"name", s.name},
                       {"center", array3(s.center)},
                       {"radius", s.radius},
                       {"color", s.color}});
  if (pane.ground)
    objects.push_back({{"type", "ground"},
                       {"y", pane.ground->y},
                       {"size", pane.ground->size},
                       {"color", pane.ground->color}});
  return out;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// JSON inside a <script> element: "</" would end the element early; "<\/" is the same JSON.
std::string script_safe(std::string text) {
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
    text.replace(at, 2, "<\\/");
  return text;
}

std::string escape_html(const std::string& text) {
  std::string out;
  for (const char c : text)
    out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return out;
}

void check_page(const WebPage& page) {
  if (page.panes.empty() || page.panes.size() > 4)
    throw std::invalid_argument(fmt::format("a page shows 1 to 4 panes, not {}", page.panes.size()));
  if (!(page.fps > 0)) throw std::invalid_argument(fmt::format("a page's fps must be > 0, not {}", page.fps));
  for (const PagePane& pane : page.panes) {
    const long frames = pane.frames();
    if (frames > long(page.times.size()))
      throw std::invalid_argument(fmt::format("pane '{}' has {} frames but the page's clock only {} times",
                                              pane.label, frames, page.times.size()));
    for (const PageReadout& r : pane.readouts)
      if (long(r.values.size()) != frames)
        throw std::invalid_argument(fmt::format("pane '{}': readout '{}' has {} values for {} frames",
                                                pane.label, r.name, r.values.size(), frames));
  }
}

}  // namespace

long PagePane::frames() const {
  long count = -1;
  const auto agree = [&](long n, const std::string& name) {
    if (count >= 0 && n != count)
      throw std::invalid_argument(
          fmt::format("pane '{}': '{}' has {} frames where the others have {}", label, name, n, count));
    count = n;
  };
  for (const PageMesh& m : meshes) agree(long(m.frames.size()), m.name);
  for (const PagePoints& p : points) {
    agree(long(p.frames.size()), p.name);
    if (p.rgba.size() != p.frames.size())
      throw std::invalid_argument(fmt::format("pane '{}': '{}' has {} colour frames for {} frames", label,
                                              p.name, p.rgba.size(), p.frames.size()));
  }
  return std::max(count, 0L);
}

fs::path three_js_folder() { return KIT_THREE_JS_DIR; }

PageWritten write_web_page(const WebPage& page, const fs::path& path, std::size_t limit) {
  const Stopwatch clock;
  check_page(page);
  PageWritten written;
  written.frames_given = long(page.times.size());
  const fs::path three = three_js_folder() / "three.min.js",
                 orbit = three_js_folder() / "examples/js/controls/OrbitControls.js";
  if (!fs::exists(three) || !fs::exists(orbit)) {
    written.note = fmt::format("no 3D page: three.js is not installed ({} missing; `./kit deps --for run` "
                               "installs Debian's libjs-three)",
                               (fs::exists(three) ? orbit : three).string());
    return written;
  }
  const std::string head_scripts = "<script>" + read_file(three) + "</script>\n<script>" + read_file(orbit) +
                                   "</script>\n<script>" + std::string(web_player_js) + "</script>\n";
  // Every k-th frame, the smallest k whose page fits the limit.
  std::string html;
  for (long k = 1;; ++k) {
    json header = {{"format", 1},
                   {"title", page.title},
                   {"subtitle", page.subtitle},
                   {"fps", page.fps / k},
                   {"up", {0, 1, 0}}};
    json times = json::array();
    for (const double t : every_kth(page.times, k)) times.push_back(t);
    header["times"] = times;
    if (!page.background.empty()) header["background"] = page.background;
    header["panes"] = json::array();
    double rounding = 0;
    for (const PagePane& pane : page.panes) {
      PaneJson p = pane_json(pane, k);
      rounding = std::max(rounding, p.rounding);
      header["panes"].push_back(std::move(p.value));
    }
    header["precision"] =
        fmt::format("positions stored in 16 bits over each object's box: rounded by at most "
                    "{:.2g} mm",
                    1e3 * rounding);
    html = fmt::format(
        "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{}</title>\n"
        "<style>{}</style>\n</head>\n<body>\n<script id=\"kit-data\" type=\"application/json\">{}</script>\n"
        "{}</body>\n</html>\n",
        escape_html(page.title), web_player_css, script_safe(header.dump()), head_scripts);
    written.frames = long(times.size());
    written.position_error = rounding;
    if (html.size() <= limit || written.frames <= 2) {
      if (k > 1)
        written.note =
            fmt::format(", 1 in {} of the run's {}: all of them would pass the page limit of {:.0f} MB", k,
                        written.frames_given, double(limit) / 1e6);
      break;
    }
  }
  write_file_atomic(path, html);
  written.path = path;
  written.bytes = html.size();
  written.seconds = clock.seconds();
  written.note = fmt::format("3D page: {} ({:.1f} MB, {} frames{}; open it in a browser, or ./kit view)",
                             path.string(), double(written.bytes) / 1e6, written.frames, written.note);
  return written;
}

}  // namespace kit
