#include "render/camera_setup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "common/usage_error.hpp"

namespace edgewise::render_tool {

using tools::UsageError;

namespace {

using Vec3d = WorldPoint;

Vec3d widen(const Vec3& v) {
  return {v.x, v.y, v.z};
}
// v * 2^exponent: exact in double for every value here.
Vec3d scaled(const Vec3d& v, int exponent) {
  return {std::ldexp(v.x, exponent), std::ldexp(v.y, exponent), std::ldexp(v.z, exponent)};
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
// The transform's homogeneous scale is 2^j with |j| <= kMaxClipExponent where it can be: the
// scene's clip-space w, about 2^j, then stays in the range draw() interpolates perspective-
// correct, [2^-32, 2^32] (kernels/interpolation/screen_triangle.hpp), with room for near and far
// planes given on the command line, and far inside the range it projects, [2^-125, 2^64].
constexpr int kMaxClipExponent = 20;
// And the columns that multiply x, y and z are 2^(j - e) times entries of about 1 (e the scene's
// exponent), with |j - e| <= kMaxColumnExponent: normal floats, well within float's range.
constexpr int kMaxColumnExponent = 100;

std::string text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

// Depths along `forward` (from `eye`) of the nearest and farthest corners of the box [lo, hi].
std::pair<double, double> depth_range(const Vec3d& lo, const Vec3d& hi, const Vec3d& eye,
                                      const Vec3d& forward) {
  double nearest = INFINITY, farthest = -INFINITY;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3d p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
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

// Refuses a box that float cannot measure: the difference of two of its coordinates would
// overflow.
void check_extent(const Vec3d& lo, const Vec3d& hi) {
  const double extent[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
  for (int axis = 0; axis < 3; ++axis) {
    if (extent[axis] > static_cast<double>(std::numeric_limits<float>::max())) {
      throw std::runtime_error(std::string("the mesh is too large to frame: its extent along ") +
                               "xyz"[axis] + ", " + text(extent[axis]) +
                               ", is beyond the float range (" +
                               text(std::numeric_limits<float>::max()) + ")");
    }
  }
}

// The camera's transform from its matrices in scene units of 2^e, m = projection * view: the
// world-to-clip transform 2^j m diag(2^-e, 2^-e, 2^-e, 1). Powers of two change no rounding, so
// this is exactly the transform world units would give, times 2^j: the same image (draw()
// divides by w). j is what world units give (e for a perspective camera, whose clip coordinates
// grow with the scene; 0 for an orthographic one, whose w is 1), limited as kMaxClipExponent
// and kMaxColumnExponent say. The second limit only binds for scenes below 2^-120, whose w
// falls below 2^-20 (below 2^-32, from 2^-132 on, they are drawn without perspective
// correction), and orthographic ones beyond 2^100 or below 2^-100 (whose w are all equal, so
// that affine interpolation is exact).
Mat4 world_transform(const Mat4& m, int e, bool orthographic) {
  const int j = std::clamp(std::clamp(orthographic ? 0 : e, -kMaxClipExponent, kMaxClipExponent),
                           e - kMaxColumnExponent, e + kMaxColumnExponent);
  Mat4 out = m;
  for (auto& row : out.m) {
    for (int c = 0; c < 4; ++c)
      row[c] = std::ldexp(row[c], c < 3 ? j - e : j);
  }
  return out;
}

}  // namespace

ResolvedCamera resolve_camera(const CameraOverrides& overrides,
                              const std::optional<scene::SceneCamera>& scene_camera,
                              const scene::Box3& bounds, float aspect) {
  const Vec3d lo = widen(bounds.min), hi = widen(bounds.max);
  check_extent(lo, hi);
  const Vec3d center = 0.5 * (lo + hi);
  // A single point still gets a view volume of some size.
  double radius = 0.5 * length(hi - lo);
  if (!(radius > 0.0)) radius = std::max(1.0, length(center) * 1e-3);

  const float fov_degrees = overrides.fov_degrees.value_or(
      scene_camera ? scene_camera->vertical_fov_degrees : static_cast<float>(kDefaultFovDegrees));
  const double fov = radians(fov_degrees);
  const Vec3 up_vector =
      overrides.up.value_or(scene_camera ? scene_camera->up : Vec3{0.0f, 1.0f, 0.0f});
  const std::optional<Vec3> given_target =
      overrides.target ? overrides.target
                       : (scene_camera ? std::optional(scene_camera->target) : std::nullopt);
  const std::optional<Vec3> given_eye =
      overrides.eye ? overrides.eye
                    : (scene_camera ? std::optional(scene_camera->eye) : std::nullopt);
  const Vec3d direction = (1.0 / length(kFramingDirection)) * kFramingDirection;
  const double framing = framing_distance(radius, fov, aspect);

  // The scene's unit 2^e: its size, or the eye's distance where that is larger. Every length
  // from here on is in that unit (multiplied by 2^-e, exactly), so it is near 1 whatever the
  // scene's size; rounded to float, each is 2^-e times what world units would give.
  const Vec3d world_target = given_target ? widen(*given_target) : center;
  const Vec3d world_eye = given_eye ? widen(*given_eye) : world_target + framing * direction;
  const double world_distance = length(world_target - world_eye);
  if (!(world_distance > 0.0)) throw UsageError("the eye and the target are at the same point");
  const int e = std::ilogb(std::max(radius, world_distance));
  const Vec3 target = narrow(scaled(world_target, -e));
  const Vec3 eye = given_eye ? narrow(scaled(widen(*given_eye), -e))
                             : narrow(widen(target) + std::ldexp(framing, -e) * direction);

  const Vec3d to_target = widen(target) - widen(eye);
  const double distance = length(to_target);
  if (!(distance > 0.0) || !std::isfinite(distance)) {
    throw UsageError("the eye and the target are at the same point");
  }
  const Vec3d forward = (1.0 / distance) * to_target;
  const Vec3d up = widen(up_vector);
  // Below an angle of 1e-3 radians between up and the view direction, the camera's right axis
  // (their cross product) would be mostly rounding.
  if (!(length(cross(forward, up)) > 1e-3 * length(up))) {
    throw UsageError("--up is zero or parallel to the view direction");
  }

  ResolvedCamera camera;
  camera.orthographic = overrides.orthographic;
  const auto in_units = [e](float world) { return static_cast<float>(std::ldexp(world, -e)); };
  const auto in_world = [e](double units) { return std::ldexp(units, e); };
  const auto [nearest, farthest] = depth_range(scaled(lo, -e), scaled(hi, -e), widen(eye), forward);
  // Each plane from the command line, else the scene's, else made to hold the box.
  const auto plane = [&](const std::optional<float>& option, float scene_value, double automatic) {
    if (option) return in_units(*option);
    return scene_camera && !camera.orthographic ? in_units(scene_value)
                                                : static_cast<float>(automatic);
  };
  float near_plane = 0.0f, far_plane = 0.0f;
  if (camera.orthographic) {
    const double pad = 0.01 * std::max(farthest - nearest, std::ldexp(radius, -e) * 1e-3);
    near_plane = plane(overrides.near_plane, 0.0f, nearest - pad);
    far_plane = plane(overrides.far_plane, 0.0f, farthest + pad);
  } else {
    // A box entirely behind the eye draws nothing whatever the range: any valid one will do.
    const double far = farthest > 0.0 ? farthest * 1.01 : 1.0;
    far_plane = plane(overrides.far_plane, scene_camera ? scene_camera->far_plane : 0.0f, far);
    near_plane = plane(overrides.near_plane, scene_camera ? scene_camera->near_plane : 0.0f,
                       std::max(nearest * 0.99, double(far_plane) / kMaxFarOverNear));
  }
  if (!camera.orthographic && !(near_plane > 0.0f)) {
    throw UsageError("--near " + text(overrides.near_plane.value_or(in_world(near_plane))) +
                     " must be greater than 0 for a perspective camera");
  }
  if (!(near_plane < far_plane)) {
    throw UsageError("the near plane (" + text(in_world(near_plane)) +
                     ") must be nearer than the far plane (" + text(in_world(far_plane)) + ")");
  }

  const Mat4 view_matrix = look_at(eye, target, up_vector);
  Mat4 projection;
  if (camera.orthographic) {
    const double half_height = distance * std::tan(fov / 2.0);
    const double half_width = half_height * aspect;
    camera.ortho_half_height = in_world(static_cast<float>(half_height));
    projection = orthographic(static_cast<float>(-half_width), static_cast<float>(half_width),
                              static_cast<float>(-half_height), static_cast<float>(half_height),
                              near_plane, far_plane);
  } else {
    projection = perspective(static_cast<float>(fov), aspect, near_plane, far_plane);
  }
  camera.view = {scaled(widen(eye), e), scaled(widen(target), e), up_vector,
                 fov_degrees,           in_world(near_plane),     in_world(far_plane)};
  camera.transform = world_transform(projection * view_matrix, e, camera.orthographic);
  return camera;
}

}  // namespace edgewise::render_tool
