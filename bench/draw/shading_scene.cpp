#include "shading_scene.hpp"

#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <tuple>

#include "../benchmarks.hpp"
#include "exact_area_triangles.hpp"

namespace edgewise::bench {
namespace {

constexpr std::uint64_t kShadingSceneSeed = 0x5eed'ed6e'0000'0003;

// View-space distances of the vertices, inside the cameras' near and far planes. Triangles are
// never clipped (the benchmarks check it).
constexpr float kNear = 1.0f, kFar = 100.0f;
constexpr double kMinDistance = 2.0, kMaxDistance = 50.0;
constexpr float kFovy = 1.0f;  // radians, for the perspective camera

// A view-space point that `camera` maps to screen pixel (sx, sy) at distance `distance`.
Vec3 unproject(Camera camera, double sx, double sy, double distance) {
  if (camera == Camera::orthographic) return {float(sx), float(sy), float(-distance)};
  // Inverse of perspective() and to_screen(): NDC times distance over the focal scale.
  const double focal = 1.0 / std::tan(0.5 * double(kFovy));
  const double aspect = double(kWidth) / double(kHeight);
  const double ndc_x = 2.0 * sx / kWidth - 1.0, ndc_y = 1.0 - 2.0 * sy / kHeight;
  return {float(ndc_x * distance * aspect / focal), float(ndc_y * distance / focal),
          float(-distance)};
}

}  // namespace

Mat4 camera_transform(Camera camera) {
  if (camera == Camera::orthographic) {
    // x, y in pixels with y down; z in view space gives depth.
    return orthographic(0.0f, float(kWidth), float(kHeight), 0.0f, kNear, kFar);
  }
  return perspective(kFovy, float(kWidth) / float(kHeight), kNear, kFar);
}

const ShadingScene& shading_scene(Camera camera, const ShadingCase& c) {
  static std::map<std::tuple<Camera, int>, ShadingScene> cache;
  auto [it, inserted] = cache.try_emplace({camera, c.area});
  if (!inserted) return it->second;
  ShadingScene& s = it->second;
  const std::vector<Vec2> pixels =
      workload::exact_area_triangles(c.triangles, c.area, kWidth, kHeight, kShadingSceneSeed);
  std::mt19937_64 rng(kShadingSceneSeed + static_cast<std::uint64_t>(c.area));
  std::uniform_real_distribution<double> distance(kMinDistance, kMaxDistance);
  std::uniform_real_distribution<float> channel(0.0f, 1.0f);
  s.positions.reserve(pixels.size());
  s.colors.reserve(pixels.size());
  for (const Vec2& p : pixels) {
    s.positions.push_back(unproject(camera, p.x, p.y, distance(rng)));
    s.colors.push_back({channel(rng), channel(rng), channel(rng), 1.0f});
  }
  return s;
}

DrawOptions shading_options(Isa isa, Camera camera) {
  DrawOptions options;
  options.transform = camera_transform(camera);
  options.depth_test = DepthTest::less;
  options.depth_write = true;
  options.shading = Shading::gouraud;
  options.isa = isa;
  options.threads = 1;  // one core; Shading/<isa>/threads:all/ sets its own
  return options;
}

}  // namespace edgewise::bench
