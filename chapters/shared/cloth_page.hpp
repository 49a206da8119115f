#pragma once
// A cloth run as a pane of a 3D page (web_page.hpp), chapters 6 and 7: the sheet's mesh with its
// pins marked, the scene's spheres and ground, and at each frame the energy and the largest
// stretch the run measured.
#include <string>

#include <kit/cloth/cloth_run.hpp>
#include <kit/cloth/cloth_scene.hpp>
#include <kit/render/page_output.hpp>
#include <kit/render/web_page.hpp>

namespace kit {

/// The run's frames (k·t_end/frames, k = 0 … as long as the cloth held) as a pane. Each frame's
/// readouts are the run's sample nearest its time. `seconds` is the run's wall time [s], shown
/// as the cost per simulated second (rec.wall_seconds); `label` names the method and step.
PagePane cloth_pane(const ClothScene& scene, const ClothRecording& rec, const ClothRunOptions& run,
                    const std::string& label);
/// "symplectic Euler, Δt = 0.0001 s": the run's method and step.
std::string cloth_run_label(const ClothRunOptions& run);

/// The page's clock for a cloth run: frames + 1 times k·t_end/frames [s].
std::vector<double> cloth_page_times(const ClothRunOptions& run);

/// A page of panes of `scene` run as `run` says (its clock, and its frame rate: frames / t_end).
WebPage cloth_page(const std::string& title, const ClothScene& scene, const ClothRunOptions& run,
                   std::vector<PagePane> panes);

}  // namespace kit

namespace kit {
/// out_dir/cloth-stability.html (chapter 6): the scene under symplectic Euler just below and just
/// above its stable step 2/ω_max (0.9 and 1.1 times it; the springs undamped, no strain limit),
/// side by side on one clock: the one holds, the other explodes.
PageWritten write_stability_page(ChapterApp& app, const ClothScene& scene, ClothKernels kernels,
                                 const ClothRunOptions& run, const std::filesystem::path& out_dir);

/// out_dir/cloth.html: the run alone, titled "<chapter>: '<scene>'" (write_page).
PageWritten write_cloth_page(ChapterApp& app, const std::string& chapter, const ClothScene& scene,
                             const ClothRecording& rec, const ClothRunOptions& run,
                             const std::filesystem::path& out_dir);
}  // namespace kit
