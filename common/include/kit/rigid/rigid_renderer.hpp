#pragma once
// The software renderer for chapter 8's rigid bodies: the body's boxes as flat-shaded, z-buffered
// triangles over the cloth's sky and checkerboard ground (y = 0, raster.hpp), seen through a
// pinhole camera (chapter 5's, y up); and a default camera that keeps a run's body in view.
#include <cstddef>
#include <vector>

#include <kit/render/camera.hpp>
#include <kit/render/image.hpp>
#include <kit/rigid/rigid_body.hpp>

namespace kit {

/// The colour of part k of a body, linear RGB before lighting: warm for part 0 (a box, the
/// T-handle's bar), cool for part 1 (the T-handle's stem), then green and grey, cycling.
Colour rigid_part_colour(std::size_t part);

/// Renders the body `shape` at `state` as a width × height image: the sky, the ground y = 0 with
/// the body's shadow (the key light blocked by a part), then each part's faces that turn towards
/// the camera, two triangles each, depth-tested and flat-shaded: rigid_part_colour(part) times
/// light_intensity(face normal) (raster.hpp). A face with a corner that cannot be projected (not
/// finite, nearer than Pinhole::near_depth, far off the image) is skipped: a diverged body
/// leaves the picture, not the run. Throws as Pinhole for a bad camera or size.
Image render_rigid(const RigidShape& shape, const RigidState& state, const Camera& camera, int width,
                   int height);

/// The view rigid runs are seen in: from the front (+z), right and 20° above, at the middle of
/// the region the body can cover over `frames` (a sphere of the shape's bounding radius about each
/// x [m]), with `with_ground` that region reaching down to the ground y = 0 so that it shows
/// under the body; far enough that the region's bounding sphere fits a 40° vertical field of view
/// and the horizontal one of an image of this aspect (width/height). Throws std::invalid_argument
/// when frames is empty, aspect is not positive, or a centre is not finite.
Camera rigid_camera(const RigidShape& shape, const std::vector<RigidState>& frames, bool with_ground,
                    double aspect = 4.0 / 3.0);

}  // namespace kit
