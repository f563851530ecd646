#include "texture_scene/builtin_views.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace edgewise::texture_scene {
namespace {

double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

bool all_finite(std::initializer_list<double> values) {
  for (double value : values) {
    if (!std::isfinite(value)) return false;
  }
  return true;
}

}  // namespace

TextureView ground_plane_view(std::int32_t width, std::int32_t height,
                              const GroundPlaneOptions& options) {
  const double fov = options.vertical_fov_degrees;
  const double below = options.top_below_horizon_degrees;
  if (!all_finite(
          {options.camera_height, options.texture_period, fov, below, options.yaw_degrees}) ||
      !(options.camera_height > 0.0) || !(options.texture_period > 0.0) || !(fov > 0.0) ||
      !(fov < 170.0) || !(below > 0.0) || !(below < 90.0 - fov / 2.0))
    throw std::invalid_argument("ground_plane_view: option out of range");

  // Camera at height h looking toward +Z, pitched down by theta so that the ray through the top
  // edge's centre is `below` degrees under the horizon. With F the focal length in pixels, the
  // ray through pixel position (x, y) meets the plane at
  //   X = h (x - W/2) / w,   Z = h (F cos(theta) - (y - H/2) sin(theta)) / w,
  //   w = F sin(theta) + (y - H/2) cos(theta)   (> 0 below the horizon, so on the whole screen).
  const double theta = radians(fov / 2.0 + below);
  const double focal = (height / 2.0) / std::tan(radians(fov / 2.0));
  const double sin_theta = std::sin(theta), cos_theta = std::cos(theta);
  const double half_width = width / 2.0, half_height = height / 2.0;
  // Z's numerator is z_slope y + z_offset.
  const double z_slope = -sin_theta;
  const double z_offset = focal * cos_theta + half_height * sin_theta;

  // Texture coordinates: (X, -Z) turned by the yaw, in texture periods (t grows toward the
  // camera, like screen y).
  const double yaw = radians(options.yaw_degrees);
  const double cos_yaw = std::cos(yaw), sin_yaw = std::sin(yaw);
  const double scale = options.camera_height / options.texture_period;
  // s = (cos X + sin Z) / period, t = (sin X - cos Z) / period.
  ProjectiveMap map{};
  map.s_row = {scale * cos_yaw, scale * sin_yaw * z_slope,
               scale * (-cos_yaw * half_width + sin_yaw * z_offset)};
  map.t_row = {scale * sin_yaw, -scale * cos_yaw * z_slope,
               scale * (-sin_yaw * half_width - cos_yaw * z_offset)};
  map.w_row = {0.0, cos_theta, focal * sin_theta - half_height * cos_theta};
  return TextureView(width, height, map);
}

TextureView magnification_view(std::int32_t width, std::int32_t height, std::int32_t texture_width,
                               std::int32_t texture_height, const MagnificationOptions& options) {
  constexpr std::int32_t kMaxSize = 1 << 15;
  if (texture_width < 1 || texture_height < 1 || texture_width > kMaxSize ||
      texture_height > kMaxSize)
    throw std::invalid_argument("magnification_view: texture size outside [1, 32768]");
  const double p = options.perspective;
  if (!all_finite({options.texels_across, options.centre_s, options.centre_t,
                   options.centre_offset_texels_u, options.centre_offset_texels_v,
                   options.rotation_degrees, p}) ||
      !(options.texels_across > 0.0) || !(p >= 0.0 && p <= 1.0))
    throw std::invalid_argument("magnification_view: option out of range");
  if (width < 1 || height < 1)  // before dividing by them; TextureView checks the rest
    throw std::invalid_argument("magnification_view: screen size below 1");

  // In texels, with X = (x - W/2) / W, Y = (y - H/2) / W (square pixels) and
  // w = 1 + p (y - H/2) / H:
  //   u = cu + S (cos(a) X - sin(a) Y) / w,   v = cv + S (sin(a) X + cos(a) Y) / w.
  const double cu = options.centre_s * texture_width + options.centre_offset_texels_u;
  const double cv = options.centre_t * texture_height + options.centre_offset_texels_v;
  const double across = options.texels_across;
  const double angle = radians(options.rotation_degrees);
  const double c = std::cos(angle), s = std::sin(angle);
  const double aspect = double(height) / width;
  ProjectiveMap map{};
  map.s_row = {across * c / width, cu * p / height - across * s / width,
               cu * (1.0 - p / 2.0) + across * (-c / 2.0 + s * aspect / 2.0)};
  map.t_row = {across * s / width, cv * p / height + across * c / width,
               cv * (1.0 - p / 2.0) + across * (-s / 2.0 - c * aspect / 2.0)};
  for (double& coefficient : map.s_row)
    coefficient /= texture_width;
  for (double& coefficient : map.t_row)
    coefficient /= texture_height;
  map.w_row = {0.0, p / height, 1.0 - p / 2.0};
  return TextureView(width, height, map);
}

}  // namespace edgewise::texture_scene
