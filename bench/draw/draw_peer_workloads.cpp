#include "draw_peer_workloads.hpp"

#include <algorithm>
#include <charconv>
#include <functional>
#include <map>
#include <memory>
#include <vector>

#include "shading_scene.hpp"
#if defined(EDGEWISE_BENCH_SAMPLING)
#include "../texture/bench_texture.hpp"
#endif
#if defined(EDGEWISE_BENCH_MESHES)
#include "mesh_scenes.hpp"
#endif

namespace edgewise::bench {
namespace {

constexpr std::string_view kFixedNames[] = {
    "area:8",
    "area:64",
    "area:1000",
    "area:200000",
    "area:8/samples:4",
    "area:8/samples:8",
    "area:64/samples:4",
    "area:64/samples:8",
    "area:1000/samples:4",
    "area:1000/samples:8",
#if defined(EDGEWISE_BENCH_SAMPLING)
    "ground_plane/trilinear",
    "ground_plane/anisotropic16",
#endif
};

std::unique_ptr<PeerWorkload> build(std::string_view name) {
  auto w = std::make_unique<PeerWorkload>();
  w->name = name;
  for (const ShadingCase& c : kShadingCases) {
    const std::string area = "area:" + std::to_string(c.area);
    if (name.substr(0, name.find('/')) != area) continue;
    if (name != area) {  // area:<px>/samples:<n>
      constexpr std::string_view kSamples = "/samples:";
      const std::string_view count = name.substr(area.size());
      if (count.rfind(kSamples, 0) != 0) return nullptr;
      const auto [end, status] =
          std::from_chars(count.data() + kSamples.size(), count.data() + count.size(), w->samples);
      if (status != std::errc() || end != count.data() + count.size()) return nullptr;
    }
    const ShadingScene& scene = shading_scene(Camera::orthographic, c);
    w->mesh.positions = scene.positions;
    w->mesh.colors = scene.colors;
    w->options = shading_options(active_isa(), Camera::orthographic);
    w->clear_color = kShadingClearColor;
    w->clear_depth = kShadingClearDepth;
    w->triangles = c.triangles;
    return w;
  }
#if defined(EDGEWISE_BENCH_SAMPLING)
  if (name == "ground_plane/trilinear" || name == "ground_plane/anisotropic16") {
    const TextureFilter filter =
        name == "ground_plane/trilinear" ? TextureFilter::trilinear : TextureFilter::anisotropic;
    w->mesh = ground_plane_mesh().mesh();
    w->options = ground_plane_options(active_isa(), filter, TextureDerivatives::quad);
    w->options.texture->sampler.max_anisotropy = 16;
    w->clear_color = kGroundPlaneClearColor;
    w->clear_depth = kGroundPlaneClearDepth;
    w->triangles = w->mesh.positions.size() / 3;
    return w;
  }
#endif
#if defined(EDGEWISE_BENCH_MESHES)
  for (const MeshScene& scene : mesh_scenes()) {
    if (name != "mesh/" + scene.name) continue;
    w->mesh = draw_mesh(scene);
    w->options = mesh_options(active_isa(), scene);
    w->clear_color = kMeshClearColor;
    w->clear_depth = kMeshClearDepth;
    w->triangles = scene.mesh.indices.size() / 3;
    return w;
  }
#endif
  return nullptr;
}

std::vector<std::string> all_names() {
  std::vector<std::string> names(std::begin(kFixedNames), std::end(kFixedNames));
#if defined(EDGEWISE_BENCH_MESHES)
  for (const MeshScene& scene : mesh_scenes())
    names.push_back("mesh/" + scene.name);
#endif
  return names;
}

}  // namespace

std::span<const std::string_view> peer_workload_names() {
  static const std::vector<std::string> names = all_names();
  static const std::vector<std::string_view> views(names.begin(), names.end());
  return views;
}

const PeerWorkload* find_peer_workload(std::string_view name) {
  const auto names = peer_workload_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) return nullptr;
  static std::map<std::string, std::unique_ptr<PeerWorkload>, std::less<>> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(std::string(name), build(name)).first;
  return it->second.get();
}

}  // namespace edgewise::bench
