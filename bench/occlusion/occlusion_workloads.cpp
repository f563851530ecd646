#include "occlusion_workloads.hpp"

#include <map>
#include <memory>
#include <mutex>
#include <tuple>

#include "../benchmarks.hpp"
#include "fillrate_triangles.hpp"

namespace edgewise::bench {

const OcclusionBuffer& query_scene(Isa isa, std::int32_t reduction, PartialCoverage partial) {
  static std::mutex mutex;
  static std::map<std::tuple<Isa, std::int32_t, PartialCoverage>, std::unique_ptr<OcclusionBuffer>>
      scenes;
  const std::lock_guard lock(mutex);
  std::unique_ptr<OcclusionBuffer>& scene = scenes[{isa, reduction, partial}];
  if (!scene) {
    scene = std::make_unique<OcclusionBuffer>(kWidth, kHeight, reduction, partial);
    OcclusionOptions options;
    options.isa = isa;
    const FillrateTriangles& t = fillrate_triangles(kQuerySceneSize, kQuerySceneTriangles);
    scene->draw_occluders({t.ndc, {}}, options);
  }
  return *scene;
}

const std::vector<OcclusionRect>& query_rects() {
  static const std::vector<OcclusionRect> rects = [] {
    std::vector<OcclusionRect> out;
    BenchRandom random{0x9ec7ull};
    const auto uniform = [&] { return random.uniform(); };
    for (int i = 0; i < 65536; ++i) {
      const double w = 4.0 * std::exp2(5.0 * uniform()), h = 4.0 * std::exp2(5.0 * uniform());
      const double x = uniform() * (kWidth - w), y = uniform() * (kHeight - h);
      // Depths across the occluders' (0, 1]: the later triangles are the nearer.
      out.push_back({static_cast<float>(x), static_cast<float>(y), static_cast<float>(x + w),
                     static_cast<float>(y + h), static_cast<float>(uniform())});
    }
    return out;
  }();
  return rects;
}

}  // namespace edgewise::bench
