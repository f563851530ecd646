#include "render/builtin_scenes.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

namespace edgewise::render_tool {
namespace {

// The default scene's palette, so that each part looks the same alone and together.
constexpr Vec4 kWarmTop{1.0f, 0.75f, 0.3f, 1.0f}, kWarmBottom{0.75f, 0.2f, 0.1f, 1.0f};
constexpr Vec4 kCoolA{0.2f, 0.5f, 0.95f, 1.0f}, kCoolB{0.2f, 0.9f, 0.55f, 1.0f};

scene::Scene sphere_scene() {
  return {scene::make_uv_sphere({.center = {0.0f, 0.0f, 0.0f},
                                 .radius = 1.0f,
                                 .rings = 48,
                                 .segments = 96,
                                 .color_top = kWarmTop,
                                 .color_bottom = kWarmBottom}),
          {.eye = {0.0f, 1.2f, 3.0f},
           .target = {0.0f, 0.0f, 0.0f},
           .up = {0.0f, 1.0f, 0.0f},
           .vertical_fov_degrees = 45.0f,
           .near_plane = 0.1f,
           .far_plane = 100.0f}};
}

scene::Scene torus_scene() {
  return {scene::make_torus({.center = {0.0f, 0.0f, 0.0f},
                             .major_radius = 1.0f,
                             .minor_radius = 0.35f,
                             .major_segments = 96,
                             .minor_segments = 48,
                             .tilt_radians = static_cast<float>(std::numbers::pi / 6),
                             .color_a = kCoolA,
                             .color_b = kCoolB}),
          {.eye = {0.0f, 1.6f, 3.2f},
           .target = {0.0f, 0.0f, 0.0f},
           .up = {0.0f, 1.0f, 0.0f},
           .vertical_fov_degrees = 45.0f,
           .near_plane = 0.1f,
           .far_plane = 100.0f}};
}

}  // namespace

scene::Scene make_builtin_scene(std::string_view name) {
  if (name == "default") return scene::default_scene();
  if (name == "sphere") return sphere_scene();
  if (name == "torus") return torus_scene();
  if (name == "ground") return scene::ground_scene();
  throw std::invalid_argument("no built-in scene '" + std::string(name) + "'");
}

}  // namespace edgewise::render_tool
