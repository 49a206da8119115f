// The 3D page's storage (page_blob.hpp, web_page.hpp): what a page holds decodes back to the run
// within the rounding it states, blobs are real zlib and base64, a page over its limit keeps
// fewer frames and says so, and inconsistent pages are refused.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <stb_image.h>
#include <kit_catch.hpp>
#include <nlohmann/json.hpp>

#include <kit/render/page_blob.hpp>
#include <kit/render/web_page.hpp>

#include "process.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Inverse of kit::base64, written apart from it.
std::string from_base64(const std::string& text) {
  std::string out;
  int bits = 0, value = 0;
  for (const char c : text) {
    const auto at = std::string("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/").find(c);
    if (at == std::string::npos) continue;  // '=' padding
    value = value << 6 | int(at), bits += 6;
    if (bits >= 8) out.push_back(char((value >> (bits - 8)) & 0xff)), bits -= 8;
  }
  return out;
}

// A blob's bytes: base64, then zlib (stb_image's inflate, not the deflate that wrote it).
std::string unblob(const std::string& blob) {
  const std::string packed = from_base64(blob);
  int size = 0;
  char* bytes = stbi_zlib_decode_malloc(packed.data(), int(packed.size()), &size);
  REQUIRE(bytes != nullptr);
  std::string out(bytes, std::size_t(size));
  free(bytes);
  return out;
}

std::vector<std::uint16_t> as_u16(const std::string& bytes) {
  std::vector<std::uint16_t> v(bytes.size() / 2);
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = std::uint16_t(std::uint8_t(bytes[2 * i]) | std::uint8_t(bytes[2 * i + 1]) << 8);
  return v;
}

json page_header(const fs::path& page) {
  std::ifstream in(page);
  std::stringstream text;
  text << in.rdbuf();
  const std::string html = text.str();
  const std::string open = "<script id=\"kit-data\" type=\"application/json\">";
  const auto from = html.find(open) + open.size();
  return json::parse(html.substr(from, html.find("</script>", from) - from));
}

// A waving sheet of n × n vertices over `frames` frames, with its triangles.
kit::PageMesh waving_sheet(int n, int frames) {
  kit::PageMesh mesh;
  mesh.name = "cloth";
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const std::uint32_t a = std::uint32_t(j * n + i), b = a + 1, c = a + std::uint32_t(n), d = c + 1;
      mesh.triangles.push_back({a, b, d}), mesh.triangles.push_back({a, d, c});
    }
  for (int f = 0; f < frames; ++f) {
    std::vector<kit::Vec3> frame;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        frame.emplace_back(i / double(n - 1), 1 - 0.3 * std::sin(0.1 * f + 0.2 * i), j / double(n - 1));
    mesh.frames.push_back(frame);
  }
  mesh.pins = {0, n - 1};
  return mesh;
}

kit::WebPage sheet_page(int n, int frames) {
  kit::WebPage page;
  page.title = "a waving sheet </script> & co";
  for (int f = 0; f < frames; ++f) page.times.push_back(f / 30.0);
  kit::PagePane pane;
  pane.label = "test";
  pane.meshes.push_back(waving_sheet(n, frames));
  kit::PageReadout energy{"energy", "J", {}};
  for (int f = 0; f < frames; ++f) energy.values.push_back(f == 3 ? NAN : 1.0 / (f + 1));
  pane.readouts.push_back(energy);
  page.panes.push_back(pane);
  return page;
}

}  // namespace

TEST_CASE("page blobs: base64 as RFC 4648 gives it, and deflate read back by another inflate", "[web]") {
  CHECK(kit::base64("") == "");
  CHECK(kit::base64("f") == "Zg==");
  CHECK(kit::base64("fo") == "Zm8=");
  CHECK(kit::base64("foobar") == "Zm9vYmFy");
  std::string bytes;
  for (int i = 0; i < 100000; ++i)
    bytes.push_back(char(std::int64_t(i) * i % 251));  // i * i overflows an int past 46340
  CHECK(unblob(kit::base64(kit::deflate_bytes(bytes))) == bytes);
}

TEST_CASE("page blobs: 16-bit positions over the box, delta-coded, round within the stated error", "[web]") {
  const kit::PageMesh mesh = waving_sheet(9, 20);
  const kit::Box box = kit::bounding_box(mesh.frames);
  const std::vector<std::uint16_t> q = kit::quantise(mesh.frames, box, true);
  REQUIRE(q.size() == 20u * 81 * 3);
  std::vector<std::uint16_t> last(81 * 3, 0);
  double worst = 0;
  for (int f = 0; f < 20; ++f)
    for (int v = 0; v < 81; ++v) {
      kit::Vec3 back;
      for (int axis = 0; axis < 3; ++axis) {
        const std::size_t at = std::size_t(3 * v + axis);
        last[at] = std::uint16_t(last[at] + q[std::size_t(f) * 243 + at]);  // mod 2^16, as the player
        back[axis] = box.min[axis] + last[at] / 65535.0 * (box.max[axis] - box.min[axis]);
      }
      worst = std::max(worst, (back - mesh.frames[std::size_t(f)][std::size_t(v)]).norm());
    }
  CHECK(worst <= box.rounding_error() * (1 + 1e-12));
  CHECK(worst > 0.1 * box.rounding_error());  // the bound is not loose by orders of magnitude
}

TEST_CASE("a 3D page holds the run: the header, the positions and the readouts decode back", "[web]") {
  REQUIRE(fs::exists(kit::three_js_folder() / "three.min.js"));  // libjs-three: ./kit deps
  kit::test::TempDir dir("web-page");
  const kit::PageWritten made = kit::write_web_page(sheet_page(9, 20), dir.path() / "sheet.html");
  REQUIRE(made.path == dir.path() / "sheet.html");
  CHECK(made.bytes == fs::file_size(made.path));
  CHECK(made.frames == 20);
  CHECK_THAT(made.note, ContainsSubstring("sheet.html") && ContainsSubstring("20 frames"));
  const json header = page_header(made.path);
  CHECK(header["title"] == "a waving sheet </script> & co");  // escaped in the page, whole again here
  CHECK(header["times"].size() == 20);
  const json& mesh = header["panes"][0]["objects"][0];
  CHECK(mesh["vertices"] == 81);
  CHECK(mesh["triangles"] == 128);
  CHECK(as_u16(unblob(mesh["positions"])).size() == 20u * 243);
  CHECK(unblob(mesh["indices"]).size() == 128u * 3 * 4);
  const json& energy = header["panes"][0]["readouts"][0];
  CHECK(energy["values"][1].get<double>() == 0.5);  // every digit kept
  CHECK(energy["values"][3].is_null());             // NaN: not known
}

TEST_CASE("a 3D page over its limit keeps 1 frame in k, the smallest k that fits, and says so", "[web]") {
  REQUIRE(fs::exists(kit::three_js_folder() / "three.min.js"));  // libjs-three: ./kit deps
  kit::test::TempDir dir("web-page-limit");
  const kit::WebPage page = sheet_page(41, 120);
  const kit::PageWritten whole = kit::write_web_page(page, dir.path() / "whole.html");
  CHECK(whole.frames == 120);
  const std::size_t limit = whole.bytes - (whole.bytes - 900000) / 3;  // three.js alone is ~0.9 MB
  const kit::PageWritten cut = kit::write_web_page(page, dir.path() / "cut.html", limit);
  CHECK(cut.bytes <= limit);
  CHECK(cut.frames < 120);
  CHECK(cut.frames > 2);
  // The smallest k: a limit a byte under this page's size takes fewer frames still.
  const kit::PageWritten tighter = kit::write_web_page(page, dir.path() / "tighter.html", cut.bytes - 1);
  CHECK(tighter.frames < cut.frames);
  CHECK_THAT(cut.note, ContainsSubstring("of the run's 120") && ContainsSubstring("page limit"));
  CHECK(page_header(cut.path)["fps"].get<double>() < 30);  // still plays at the run's pace
}

TEST_CASE("a 3D page refuses a pane whose parts disagree, and writes nothing", "[web]") {
  kit::test::TempDir dir("web-page-bad");
  kit::WebPage page = sheet_page(5, 10);
  page.panes[0].readouts[0].values.pop_back();
  CHECK_THROWS_WITH(kit::write_web_page(page, dir.path() / "bad.html"),
                    ContainsSubstring("'energy' has 9 values for 10 frames"));
  page = sheet_page(5, 10);
  page.times.resize(5);
  CHECK_THROWS_WITH(kit::write_web_page(page, dir.path() / "bad.html"), ContainsSubstring("only 5 times"));
  page = sheet_page(5, 10);
  page.panes[0].meshes.push_back(waving_sheet(3, 4));
  CHECK_THROWS_WITH(kit::write_web_page(page, dir.path() / "bad.html"),
                    ContainsSubstring("has 4 frames where the others have 10"));
  CHECK_FALSE(fs::exists(dir.path() / "bad.html"));
}
