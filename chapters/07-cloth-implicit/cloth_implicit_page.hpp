#pragma once
// Chapter 7's scene run as a 3D page (web_page.hpp): the implicit method beside symplectic Euler
// at the same large step, on one clock, each with what it cost, so that the trade is watched.
#include <kit/cloth/cloth_run.hpp>
#include <kit/render/page_output.hpp>

namespace kit {

/// out_dir/cloth.html (write_page): the scene run `rec`, made with `run`. When `run` is
/// implicit, a second pane runs the scene with symplectic Euler at the same step (it explodes
/// within a few steps at 1/30 s, so it costs little) and shows where it stopped.
PageWritten write_implicit_scene_page(ChapterApp& app, const ClothScene& scene, const Springs& springs,
                                      ClothKernels kernels, const ClothRunOptions& run,
                                      const ClothRecording& rec, const std::filesystem::path& out_dir);

}  // namespace kit
