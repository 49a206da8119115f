// Chapter 7's scene run as a 3D page (cloth_implicit_page.hpp).
#include "cloth_implicit_page.hpp"

#include <fmt/format.h>

#include "cloth_page.hpp"

namespace kit {

PageWritten write_implicit_scene_page(ChapterApp& app, const ClothScene& scene, const Springs& springs,
                                      ClothKernels kernels, const ClothRunOptions& run,
                                      const ClothRecording& rec, const std::filesystem::path& out_dir) {
  if (app.options().no_viewer || app.options().no_plot) return {};  // and no explicit run either
  std::vector<PagePane> panes{cloth_pane(scene, rec, run, cloth_run_label(run))};
  if (run.implicit) {
    ClothRunOptions explicit_run = run;
    explicit_run.implicit.reset();
    explicit_run.integrator = ClothIntegrator::symplectic_euler;
    const ClothRecording exploded = run_cloth(scene, springs, kernels, explicit_run);
    panes.push_back(cloth_pane(scene, exploded, explicit_run, cloth_run_label(explicit_run)));
  }
  const std::string title =
      panes.size() > 1 ? fmt::format("Chapter 7: '{}', implicit and explicit at one step", scene.name)
                       : fmt::format("Chapter 7: '{}'", scene.name);
  return write_page(app, cloth_page(title, scene, run, std::move(panes)), out_dir / "cloth.html");
}

}  // namespace kit
