#include "render/camera_setup.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "common/usage_error.hpp"

namespace edgewise::render_tool {

using tools::UsageError;

namespace {

struct Vec3d {
  double x, y, z;
};

Vec3d widen(const Vec3& v) {
  return {v.x, v.y, v.z};
}
Vec3 narrow(const Vec3d& v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}
Vec3d operator-(const Vec3d& a, const Vec3d& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Vec3d operator+(const Vec3d& a, const Vec3d& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
Vec3d operator*(double s, const Vec3d& v) {
  return {s * v.x, s * v.y, s * v.z};
}
double dot(const Vec3d& a, const Vec3d& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
double length(const Vec3d& v) {
  return std::sqrt(dot(v, v));
}
Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

constexpr double kDefaultFovDegrees = 45.0;
constexpr Vec3d kFramingDirection{0.45, 0.35, 1.0};
constexpr double kFramingMargin = 1.05;
// Further apart, float32 depth (z/w) cannot tell the far half of the scene apart.
constexpr double kMaxFarOverNear = 1e4;

std::string text(float value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

// Depths along `forward` (from `eye`) of the box's nearest and farthest corners.
std::pair<double, double> depth_range(const scene::Box3& box, const Vec3d& eye,
                                      const Vec3d& forward) {
  double nearest = INFINITY, farthest = -INFINITY;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3d p{corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                  corner & 4 ? box.max.z : box.min.z};
    const double depth = dot(p - eye, forward);
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  return {nearest, farthest};
}

// The eye distance at which a sphere of `radius` fills the narrower field of view.
double framing_distance(double radius, double fov_radians, double aspect) {
  const double half_vertical = fov_radians / 2.0;
  const double half_horizontal = std::atan(std::tan(half_vertical) * aspect);
  return kFramingMargin * radius / std::sin(std::min(half_vertical, half_horizontal));
}

}  // namespace

ResolvedCamera resolve_camera(const CameraOverrides& overrides,
                              const std::optional<scene::SceneCamera>& scene_camera,
                              const scene::Box3& bounds, float aspect) {
  const Vec3d center = 0.5 * (widen(bounds.min) + widen(bounds.max));
  // A single point still gets a view volume of some size.
  double radius = 0.5 * length(widen(bounds.max) - widen(bounds.min));
  if (!(radius > 0.0)) radius = std::max(1.0, length(center) * 1e-3);

  scene::SceneCamera view;
  view.vertical_fov_degrees = overrides.fov_degrees.value_or(
      scene_camera ? scene_camera->vertical_fov_degrees : static_cast<float>(kDefaultFovDegrees));
  const double fov = radians(view.vertical_fov_degrees);
  view.up = overrides.up.value_or(scene_camera ? scene_camera->up : Vec3{0.0f, 1.0f, 0.0f});
  view.target = overrides.target.value_or(scene_camera ? scene_camera->target : narrow(center));
  if (overrides.eye) {
    view.eye = *overrides.eye;
  } else if (scene_camera) {
    view.eye = scene_camera->eye;
  } else {
    const Vec3d direction = (1.0 / length(kFramingDirection)) * kFramingDirection;
    view.eye = narrow(widen(view.target) + framing_distance(radius, fov, aspect) * direction);
  }

  if (!std::isfinite(view.eye.x) || !std::isfinite(view.eye.y) || !std::isfinite(view.eye.z)) {
    throw std::runtime_error(
        "the mesh is too large to frame: the eye would lie beyond the float range");
  }
  const Vec3d to_target = widen(view.target) - widen(view.eye);
  const double distance = length(to_target);
  if (!(distance > 0.0) || !std::isfinite(distance)) {
    throw UsageError("the eye and the target are at the same point");
  }
  const Vec3d forward = (1.0 / distance) * to_target;
  const Vec3d up = widen(view.up);
  // Below an angle of 1e-3 radians between up and the view direction, the camera's right axis
  // (their cross product) would be mostly rounding.
  if (!(length(cross(forward, up)) > 1e-3 * length(up))) {
    throw UsageError("--up is zero or parallel to the view direction");
  }

  ResolvedCamera camera;
  camera.orthographic = overrides.orthographic;
  const auto [nearest, farthest] = depth_range(bounds, widen(view.eye), forward);
  if (camera.orthographic) {
    const double pad = 0.01 * std::max(farthest - nearest, radius * 1e-3);
    view.near_plane = overrides.near_plane.value_or(static_cast<float>(nearest - pad));
    view.far_plane = overrides.far_plane.value_or(static_cast<float>(farthest + pad));
  } else if (scene_camera) {
    view.near_plane = overrides.near_plane.value_or(scene_camera->near_plane);
    view.far_plane = overrides.far_plane.value_or(scene_camera->far_plane);
  } else {
    // A box entirely behind the eye draws nothing whatever the range: any valid one will do.
    const double far = farthest > 0.0 ? farthest * 1.01 : 1.0;
    view.far_plane = overrides.far_plane.value_or(static_cast<float>(far));
    view.near_plane = overrides.near_plane.value_or(
        static_cast<float>(std::max(nearest * 0.99, double(view.far_plane) / kMaxFarOverNear)));
  }
  if (!camera.orthographic && !(view.near_plane > 0.0f)) {
    throw UsageError("--near " + text(view.near_plane) +
                     " must be greater than 0 for a perspective camera");
  }
  if (!(view.near_plane < view.far_plane)) {
    throw UsageError("the near plane (" + text(view.near_plane) +
                     ") must be nearer than the far plane (" + text(view.far_plane) + ")");
  }

  const Mat4 world_to_view = look_at(view.eye, view.target, view.up);
  Mat4 projection;
  if (camera.orthographic) {
    const double half_height = distance * std::tan(fov / 2.0);
    const double half_width = half_height * aspect;
    camera.ortho_half_height = static_cast<float>(half_height);
    projection = orthographic(static_cast<float>(-half_width), static_cast<float>(half_width),
                              static_cast<float>(-half_height), static_cast<float>(half_height),
                              view.near_plane, view.far_plane);
  } else {
    projection = perspective(static_cast<float>(fov), aspect, view.near_plane, view.far_plane);
  }
  camera.view = view;
  camera.transform = projection * world_to_view;
  return camera;
}

}  // namespace edgewise::render_tool
