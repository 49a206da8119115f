#pragma once
// Chapter 9's scene as a 3D page (web_page.hpp): the spinning plate's triangles coloured by
// Green's strain |E| (Frobenius, each node the mean of its triangles'), with at each frame the
// largest strain, the elastic and the kinetic energy.
#include <filesystem>
#include <string>

#include <kit/fem/fem_body.hpp>
#include <kit/render/page_output.hpp>

#include "continuum_flags.hpp"

namespace kit {

class PlatePage {
 public:
  /// `label` names the model, the integrator and the step.
  explicit PlatePage(std::string label) : label_(std::move(label)) {}
  /// Keeps the body as the next frame, at time t [s].
  void add(const FemBody& body, double t);
  /// Writes out_dir/plate.html (write_page); `ended` says where a diverged run stopped (empty: it
  /// did not), `seconds` is the run's wall time [s] over `simulated` seconds.
  PageWritten write(ChapterApp& app, const std::filesystem::path& path, const std::string& ended,
                    double seconds, double simulated) const;

 private:
  std::string label_;
  PageMesh mesh_;
  std::vector<double> times_;
  PageReadout strain_{"largest strain |E|", "", {}, 3}, elastic_{"elastic energy", "J", {}},
      kinetic_{"kinetic energy", "J", {}};
};

/// Section 6, the scene: the plate by --model and --integrator for --t-end, its --frames OBJ
/// meshes in out_dir/plate_meshes/ (the first at t = 0) and its page out_dir/plate.html.
void plate_scene(ChapterApp& app, const ContinuumSetup& s, const ContinuumKernels& kernels);

}  // namespace kit
