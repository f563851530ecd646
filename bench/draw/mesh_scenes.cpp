#include "mesh_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <sstream>
#include <vector>

#include "../benchmarks.hpp"
#include "scene/obj_loader.hpp"
#include "scene/procedural.hpp"

namespace edgewise::bench {
namespace {

constexpr float kFovRadians = 45.0f * std::numbers::pi_v<float> / 180.0f;
// From above, the right and the front: every mesh shows sides that a view along an axis hides.
constexpr Vec3 kViewDirection{0.35f, 0.3f, 0.89f};
constexpr Vec3 kLightDirection{0.4f, 0.6f, 0.7f};

Vec3 normalized(Vec3 v) {
  const float length = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return {v.x / length, v.y / length, v.z / length};
}

// The view of the top of mesh_scenes.hpp for a mesh whose box is `box`.
Mat4 framing_transform(const scene::Box3& box) {
  const Vec3 centre{0.5f * (box.min.x + box.max.x), 0.5f * (box.min.y + box.max.y),
                    0.5f * (box.min.z + box.max.z)};
  const Vec3 half{0.5f * (box.max.x - box.min.x), 0.5f * (box.max.y - box.min.y),
                  0.5f * (box.max.z - box.min.z)};
  const float radius =
      std::max(std::sqrt(half.x * half.x + half.y * half.y + half.z * half.z), 1e-6f);
  const float distance = radius / std::sin(0.5f * kFovRadians);
  const Vec3 d = normalized(kViewDirection);
  const Vec3 eye{centre.x + distance * d.x, centre.y + distance * d.y, centre.z + distance * d.z};
  const float near_plane = std::max(distance - 1.05f * radius, 1e-3f * distance);
  const float far_plane = distance + 1.05f * radius;
  return perspective(kFovRadians, float(kWidth) / float(kHeight), near_plane, far_plane) *
         look_at(eye, centre, Vec3{0.0f, 1.0f, 0.0f});
}

// The built-in default scene (testing/scene/procedural.hpp, edgewise-render's scene), through
// its own camera.
MeshScene default_mesh_scene() {
  scene::Scene built_in = scene::default_scene();
  const scene::SceneCamera& camera = built_in.camera;
  MeshScene s;
  s.name = "default_scene";
  s.mesh = std::move(built_in.mesh);
  s.mesh.colors.clear();
  s.mesh.uvs.clear();
  s.transform = perspective(camera.vertical_fov_degrees * std::numbers::pi_v<float> / 180.0f,
                            float(kWidth) / float(kHeight), camera.near_plane, camera.far_plane) *
                look_at(camera.eye, camera.target, camera.up);
  return s;
}

std::vector<MeshScene> load_meshes() {
  std::vector<MeshScene> scenes = {default_mesh_scene()};
  const char* folder = std::getenv("EDGEWISE_BENCH_MESHES");
  if (folder == nullptr || *folder == '\0') return scenes;
  std::error_code error;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    if (entry.is_regular_file() && entry.path().extension() == ".obj")
      files.push_back(entry.path());
  }
  if (error) std::cerr << "EDGEWISE_BENCH_MESHES: " << folder << ": " << error.message() << "\n";
  std::sort(files.begin(), files.end());
  scene::ObjLoadOptions options;
  options.load_materials = false;  // white, diffuse: the colours do not change the work
  for (const auto& file : files) {
    scene::MeshResult result = scene::load_obj(file.string(), options);
    if (!result) {
      std::cerr << result.error() << " (left out of the mesh benchmarks)\n";
      continue;
    }
    MeshScene s;
    s.name = file.stem().string();
    s.mesh = std::move(result).mesh();
    s.mesh.colors.clear();
    s.mesh.uvs.clear();
    const std::optional<scene::Box3> box = scene::bounding_box(s.mesh);
    if (!box) continue;
    s.transform = framing_transform(*box);
    scenes.push_back(std::move(s));
  }
  return scenes;
}

// The names listed in EDGEWISE_BENCH_GRIDS, separated by commas.
std::vector<std::string> grid_names() {
  std::vector<std::string> names;
  const char* list = std::getenv("EDGEWISE_BENCH_GRIDS");
  if (list == nullptr) return names;
  std::istringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    if (!name.empty()) names.push_back(name);
  }
  return names;
}

// kGridSide^3 copies of `mesh` in a lattice, a fifth of the box's extent apart on each axis, as
// one indexed mesh.
scene::Mesh grid_of(const scene::Mesh& mesh, const scene::Box3& box) {
  const Vec3 step{1.2f * (box.max.x - box.min.x), 1.2f * (box.max.y - box.min.y),
                  1.2f * (box.max.z - box.min.z)};
  scene::Mesh grid;
  for (int i = 0; i < kGridSide; ++i) {
    for (int j = 0; j < kGridSide; ++j) {
      for (int k = 0; k < kGridSide; ++k) {
        scene::Mesh copy = mesh;
        for (Vec3& p : copy.positions) {
          p.x += static_cast<float>(i) * step.x;
          p.y += static_cast<float>(j) * step.y;
          p.z += static_cast<float>(k) * step.z;
        }
        scene::append(grid, copy);
      }
    }
  }
  return grid;
}

// The grids of the loaded meshes EDGEWISE_BENCH_GRIDS names, appended as grid27-<mesh>.
void add_grids(std::vector<MeshScene>& scenes) {
  for (const std::string& name : grid_names()) {
    const auto source = std::find_if(scenes.begin(), scenes.end(),
                                     [&](const MeshScene& s) { return s.name == name; });
    if (source == scenes.end()) {
      std::cerr << "EDGEWISE_BENCH_GRIDS: no mesh " << name << " among the loaded ones\n";
      continue;
    }
    const std::optional<scene::Box3> box = scene::bounding_box(source->mesh);
    if (!box) continue;
    MeshScene grid;
    grid.name = "grid" + std::to_string(kGridSide * kGridSide * kGridSide) + "-" + name;
    grid.mesh = grid_of(source->mesh, *box);
    const std::optional<scene::Box3> grid_box = scene::bounding_box(grid.mesh);
    if (!grid_box) continue;
    grid.transform = framing_transform(*grid_box);
    scenes.push_back(std::move(grid));
  }
}

}  // namespace

std::span<const MeshScene> mesh_scenes() {
  static const std::vector<MeshScene> scenes = [] {
    std::vector<MeshScene> loaded = load_meshes();
    add_grids(loaded);
    return loaded;
  }();
  return scenes;
}

DrawOptions mesh_options(Isa isa, const MeshScene& scene) {
  DrawOptions options;
  options.transform = scene.transform;
  options.cull = CullMode::clockwise;  // the back faces of counter-clockwise (OBJ) meshes
  options.depth_test = DepthTest::less;
  options.depth_write = true;
  options.shading = Shading::diffuse;
  options.light_direction = normalized(kLightDirection);
  options.isa = isa;
  options.threads = 1;
  return options;
}

DrawMesh draw_mesh(const MeshScene& scene) {
  DrawMesh mesh;
  mesh.positions = scene.mesh.positions;
  mesh.normals = scene.mesh.normals;
  mesh.indices = scene.mesh.indices;
  return mesh;
}

}  // namespace edgewise::bench
