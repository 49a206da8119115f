#pragma once
// A run as a page a browser plays in 3D (chapters 5-9): one self-contained HTML file beside the
// frames, opened from the file system with no server and no network. It holds three.js (Debian's
// libjs-three, inlined), the kit's player (common/web/player.js) and the run: meshes, points,
// spheres and the ground, frame by frame, with what the chapter measures at each frame. Panes
// side by side share one clock, so methods compared on one scene play together.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <kit/base/vec3.hpp>

namespace kit {

/// A triangle mesh whose vertices move: the cloth, a rigid body's faces, chapter 9's sheet.
struct PageMesh {
  std::string name;
  std::string color = "#c8553d";                        ///< CSS colour
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< vertex indices, counter-clockwise outside
  std::vector<std::vector<Vec3>> frames;                ///< positions per frame [m], all the same size
  std::vector<int> pins;                                ///< vertices drawn as pins
  bool flat = false;                                    ///< flat shading (boxes) rather than smooth
  /// A value per vertex and frame drawn as colour (chapter 9's strain); empty: none.
  std::string scalar_name, scalar_unit;
  std::vector<std::vector<double>> scalar;
};

/// Particles: any number per frame, each with its colour and opacity (chapter 5's sprites).
struct PagePoints {
  std::string name;
  double size = 0.05;                                          ///< drawn diameter [m]
  std::vector<std::vector<Vec3>> frames;                       ///< positions per frame [m]
  std::vector<std::vector<std::array<std::uint8_t, 4>>> rgba;  ///< colour and opacity, as frames
};

struct PageSphere {
  std::string name;
  Vec3 center = Vec3::Zero();  ///< [m]
  double radius = 1;           ///< [m]
  std::string color = "#8a8f99";
};

struct PageGround {
  double y = 0;      ///< height of the plane [m]
  double size = 10;  ///< side of the drawn square [m]
  std::string color = "#e4e4e4";
};

/// A number per frame shown beside the view (NaN: not known at that frame).
struct PageReadout {
  std::string name, unit;
  std::vector<double> values;
  int digits = 4;  ///< significant digits shown (the page keeps every digit)
};

/// One view: a method on a scene, with its label, its cost and what it measures.
struct PagePane {
  std::string label;  ///< "implicit Euler, h = 1/30 s"
  std::string cost;   ///< "0.21 s per simulated second"; empty: not shown
  std::string ended;  ///< shown past its last frame ("diverged at t = 0.43 s"); empty: none
  std::vector<std::pair<std::string, std::string>> facts;  ///< fixed lines: integrator, step
  std::vector<PageReadout> readouts;
  std::vector<PageMesh> meshes;
  std::vector<PagePoints> points;
  std::vector<PageSphere> spheres;
  std::optional<PageGround> ground;
  /// Frames this pane holds: its meshes' and points' frame count (they must agree).
  long frames() const;
};

struct WebPage {
  std::string title, subtitle;
  double fps = 30;              ///< playback rate at 1× [frames/s]
  std::vector<double> times;    ///< the clock: simulated time of each page frame [s]
  std::vector<PagePane> panes;  ///< 1 to 4, side by side
  std::string background;       ///< CSS colour of the 3D views; empty: the player's light grey
};

/// The largest page a run writes by default [bytes]: 120 frames of an 81 × 81 sheet take about
/// 4 MB. A bigger page keeps every k-th frame (the smallest k that fits) and says so.
inline constexpr std::size_t default_page_limit = 16u << 20;

struct PageWritten {
  std::filesystem::path path;  ///< empty when no page was written (note says why)
  std::size_t bytes = 0;
  long frames = 0, frames_given = 0;  ///< in the page, and in the run
  double position_error = 0;          ///< the largest rounding of a stored position [m]
  double seconds = 0;                 ///< the time it took to write [s]
  std::string note;                   ///< one line: where, how large, and what was left out
};

/// Where three.js comes from: Debian's libjs-three (three.min.js and
/// examples/js/controls/OrbitControls.js under this folder).
std::filesystem::path three_js_folder();

/// Writes `page` to `path` atomically, inlining three.js and the player. Frames are stored at
/// 16 bits per coordinate over each object's bounding box (error at most half a step: box side
/// / 131070), delta-coded between frames and deflated. Without three.js nothing is written and
/// the note says how to install it. Throws std::invalid_argument for a page that is not
/// consistent (no pane, a pane whose objects disagree on their frame count, more frames than
/// times), std::runtime_error when the file cannot be written.
PageWritten write_web_page(const WebPage& page, const std::filesystem::path& path,
                           std::size_t limit = default_page_limit);

}  // namespace kit
