// The two views the filters are scored on, each for any screen size (the picture scales with
// the screen: halving the size doubles every footprint in texels).
#pragma once

#include <cstdint>

#include "texture_scene/texture_view.hpp"

namespace edgewise::texture_scene {

// A pinhole camera above an infinite textured plane, pitched down so that the screen's top edge
// lies just below the horizon: the whole screen is plane, with footprints from under a texel
// (bottom rows) to long thin ones (top rows). The texture repeats every texture_period metres
// (use WrapMode::repeat), its axes turned by yaw_degrees from the view direction so that the
// footprints' major axes are not aligned with the texture's.
//
// With the defaults and a 1024 x 1024 texture at 1920 x 1080, the footprint ellipses' axes grow
// from 0.2-0.4 texels (the bottom rows magnify) to 87-104 x 3.4-4.1 texels on the top row, the
// anisotropy (axis ratio) from 1.25 to 30 (21 to 30 on the top row), Pmax / Pmin up to 25, and
// lambda from -1.7 to 6.7; at 480 x 270 every footprint is 4 times longer (lambda 0.3 to 8.6).
// The builtin_views test prints these ranges.
// On the centre column the anisotropy is cos(b) / sin(a), with a the ray's angle below the
// horizon and b its angle from the optical axis: above 16 for a < 3.3 degrees near the top.
struct GroundPlaneOptions {
  double camera_height = 1.0;   // metres above the plane
  double texture_period = 4.0;  // metres per texture repeat, on both axes
  double vertical_fov_degrees = 45.0;
  double top_below_horizon_degrees = 2.5;  // the top edge's elevation below the horizon
  double yaw_degrees = 20.0;
};

// Throws std::invalid_argument for a size outside [1, 32768] or options out of range (height
// and period positive, field of view in (0, 170), the angle below the horizon in (0, 90 - fov/2),
// everything finite).
TextureView ground_plane_view(std::int32_t width, std::int32_t height,
                              const GroundPlaneOptions& options = {});

// A few texels of the texture enlarged over the whole screen, slightly rotated and with mild
// perspective, so that every pixel magnifies: with the defaults a 6-texel-wide region, so a
// footprint's major axis is at most about 8.3 / width texels (0.004 at 1920 wide, 0.26 at 32).
// The region is centred on texture point (centre_s, centre_t) shifted by centre_offset_texels;
// at (0.5, 0.5) a checkerboard with an even number of squares has a corner, which the small
// offset keeps off the texel grid. The mapping's denominator runs from 1 - perspective / 2 at
// the top to 1 + perspective / 2 at the bottom.
struct MagnificationOptions {
  double texels_across = 6.0;
  double centre_s = 0.5;
  double centre_t = 0.5;
  double centre_offset_texels_u = 0.3;
  double centre_offset_texels_v = -0.2;
  double rotation_degrees = 8.0;
  double perspective = 0.25;
};

// Throws std::invalid_argument for a screen or texture size outside [1, 32768], texels_across
// not positive, perspective outside [0, 1], or a non-finite option.
TextureView magnification_view(std::int32_t width, std::int32_t height, std::int32_t texture_width,
                               std::int32_t texture_height,
                               const MagnificationOptions& options = {});

}  // namespace edgewise::texture_scene
