#pragma once
// A software renderer for the cloth of chapters 6 and 7: the sheet as z-buffered, smoothly lit
// triangles, the sphere colliders as shaded balls and the ground as a checkerboard, seen
// through the scene's camera (the pinhole camera of chapter 5, y up). Written to PNG frames with
// FrameWriter (frame_writer.hpp).
#include <kit/cloth/cloth.hpp>
#include <kit/cloth/cloth_scene.hpp>
#include <kit/render/image.hpp>
#include <kit/render/raster.hpp>  // the scene's palette: sky, key light, ambient

namespace kit {

/// The sheet's two sides, linear RGB before lighting: warm on the side u×v points to (front),
/// cool on the other, so that a fold shows where the sheet turns over.
inline constexpr Colour cloth_front_colour{0.92, 0.46, 0.30};
inline constexpr Colour cloth_back_colour{0.36, 0.55, 0.86};

/// What render_cloth drew.
struct ClothRenderStats {
  long triangles_drawn = 0;    ///< at least partly inside the image and in front of the camera
  long triangles_skipped = 0;  ///< non-finite, crossing the near plane, degenerate or off-image
};

/// Renders the sheet at positions x (row i = node i [m]) in `scene` as a width × height image:
/// the sky (cloth_sky), the ground (when the scene has one) as a checkerboard of 0.25 m
/// squares fading into the horizon, each sphere collider (ray cast per pixel), then the cloth's
/// triangles (split as in write_cloth_obj) depth-tested, lit by the key light (Lambert) plus
/// ambient with per-vertex normals (vertex_normals), two-sided: each side its own colour.
/// A triangle with a non-finite vertex, a vertex nearer than Pinhole::near_depth, or one
/// beyond a million pixels from the image (a diverged sheet) is skipped, never drawn in part;
/// the others are clipped to the image. Throws as Pinhole for a bad camera or size and as
/// vertex_normals for positions that do not fit the grid.
Image render_cloth(const ClothGrid& grid, const NodeArray& x, const ClothScene& scene, int width, int height,
                   ClothRenderStats* stats = nullptr);

}  // namespace kit
