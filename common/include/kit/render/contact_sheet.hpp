#pragma once
// Several frames of an animation side by side in one picture, for slides and for a glance at a
// run without a video player (chapter 5).
#include <vector>

#include <kit/render/image.hpp>

namespace kit {

/// The background between and around the frames: a dark grey, linear RGB.
inline constexpr Colour contact_sheet_background{0.12, 0.12, 0.12};

/// Tiles `frames` left to right, top to bottom, in min(columns, frames.size()) columns, each
/// cell as large as the largest frame (a smaller frame sits in its cell's top-left corner), with
/// `gap_px` pixels of background between cells and around the edge:
/// width = c·cell_w + (c + 1)·gap, height = rows·cell_h + (rows + 1)·gap.
/// Throws std::invalid_argument for no frames, columns < 1 or gap_px < 0.
Image contact_sheet(const std::vector<Image>& frames, int columns, int gap_px);

}  // namespace kit
