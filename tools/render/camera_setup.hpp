// The camera a render uses: the values given on the command line, the rest from the scene's own
// camera or, for a mesh without one (an OBJ file), from a camera that frames its bounding box.
#pragma once

#include <optional>

#include "edgewise/camera.hpp"
#include "render/command_line.hpp"
#include "scene/mesh.hpp"
#include "scene/procedural.hpp"

namespace edgewise::render_tool {

struct WorldPoint {
  double x, y, z;
};

// The camera as used, in world units: in double, as a mesh near float's limits is framed from a
// distance beyond them.
struct WorldCamera {
  WorldPoint eye, target;
  Vec3 up;
  float vertical_fov_degrees;
  double near_plane, far_plane;
};

struct ResolvedCamera {
  WorldCamera view;  // eye, target, up, field of view, near and far as used
  bool orthographic = false;
  double ortho_half_height = 0.0;  // of the orthographic view volume, world units
  Mat4 transform;                  // world space to clip space
};

// Without a scene camera: the target is the box's centre, the eye looks at it from the front,
// a little from above and the right (direction (0.45, 0.35, 1)), far enough that the box's
// bounding sphere fits the narrower field of view with 5% to spare; the field of view is 45
// degrees. Near and far, unless given, hold the whole box: for a perspective camera the nearest
// box corner's depth (at least far / 10^4) to the farthest's, for an orthographic one the same
// range with 1% of its length added at both ends (an orthographic near plane may lie behind the
// eye). The orthographic view's half height is what the perspective camera sees at the target's
// distance: distance * tan(fov / 2).
//
// Any box whose extent float can hold is framed, from 1e-45 to 1e38: the camera is worked out in
// units of a power of two near the scene's size, and the transform scaled by powers of two so
// that clip-space coordinates stay within the range draw() projects and interpolates
// perspective-correct (camera_setup.cpp says how). Powers of two change no rounding: a mesh
// scaled by one gives the same image, and for a scene between 2^-20 and 2^20 the transform is
// the one world units give, bit for bit.
//
// Throws UsageError (common/usage_error.hpp) for a camera that cannot be built: eye at the
// target, up parallel to the view direction, near not below far, or a perspective near plane not
// in front of the eye; std::runtime_error for a box whose extent along an axis is beyond the
// float range.
ResolvedCamera resolve_camera(const CameraOverrides& overrides,
                              const std::optional<scene::SceneCamera>& scene_camera,
                              const scene::Box3& bounds, float aspect);

}  // namespace edgewise::render_tool
