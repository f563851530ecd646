#include "scene/city_frame.hpp"

#include <chrono>
#include <cmath>

namespace edgewise::scene {
namespace {

using Clock = std::chrono::steady_clock;

// Front faces are counter-clockwise in the world (mesh.hpp), so clockwise on screen, y down.
constexpr CullMode kBackFaces = CullMode::counter_clockwise;
constexpr Vec4 kSky{0.55f, 0.7f, 0.9f, 1.0f};

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

DrawOptions draw_options(const Mat4& view, const CityFrameOptions& options) {
  DrawOptions draw;
  draw.transform = view;
  draw.shading = Shading::diffuse;
  draw.light_direction = {0.4f, 1.0f, -0.6f};
  draw.ambient = 0.35f;
  draw.cull = kBackFaces;
  draw.isa = options.isa;
  draw.threads = options.threads;
  return draw;
}

DrawMesh city_mesh(const City& city, std::span<const std::uint32_t> indices) {
  return {city.mesh.positions, city.mesh.colors, city.mesh.normals, indices};
}

}  // namespace

Mat4 city_view(const City& city, float aspect) {
  const SceneCamera& c = city.camera;
  const float fov = c.vertical_fov_degrees * 3.14159265358979f / 180.0f;
  return perspective(fov, aspect, c.near_plane, c.far_plane) * look_at(c.eye, c.target, c.up);
}

CityFrame draw_city(Framebuffer& target, const City& city, const Mat4& view,
                    const CityFrameOptions& options) {
  CityFrame frame;
  const Clock::time_point start = Clock::now();
  target.clear(kSky, 1.0f);
  draw(target, city_mesh(city, city.mesh.indices), draw_options(view, options));
  frame.draw_seconds = seconds_since(start);
  frame.objects_drawn = city.objects.size();
  frame.triangles_drawn = city.mesh.indices.size() / 3;
  return frame;
}

CityFrame draw_city_culled(Framebuffer& target, OcclusionBuffer& occlusion, const City& city,
                           const Mat4& view, const CityFrameOptions& options, Mesh& visible) {
  CityFrame frame;
  Clock::time_point start = Clock::now();
  target.clear(kSky, 1.0f);
  const DrawMesh occluders{std::span(city.mesh.positions).first(city.occluder_vertex_count),
                           std::span(city.mesh.colors).first(city.occluder_vertex_count),
                           std::span(city.mesh.normals).first(city.occluder_vertex_count),
                           std::span(city.mesh.indices).first(city.occluder_index_count)};
  draw(target, occluders, draw_options(view, options));
  OcclusionOptions copy;
  copy.isa = options.isa;
  copy.threads = options.threads;
  occlusion.copy_depth(target, copy);
  frame.occluder_seconds = seconds_since(start);

  start = Clock::now();
  const std::size_t first = city.first_prop();
  std::vector<OcclusionBox> boxes(city.objects.size() - first);
  for (std::size_t i = 0; i < boxes.size(); ++i)
    boxes[i] = {city.objects[first + i].bounds.min, city.objects[first + i].bounds.max};
  std::vector<Visibility> answers(boxes.size());
  OcclusionOptions queries = copy;
  queries.transform = view;
  occlusion.test_boxes(boxes, answers, queries);
  visible.positions.clear();
  visible.normals.clear();
  visible.colors.clear();
  visible.indices.clear();
  frame.objects_drawn = first;
  for (std::size_t i = 0; i < answers.size(); ++i) {
    if (answers[i] != Visibility::visible) continue;
    const CityObject& object = city.objects[first + i];
    const auto offset = static_cast<std::uint32_t>(visible.positions.size()) - object.first_vertex;
    const auto copy_vertices = [&](const auto& from, auto& to) {
      to.insert(to.end(), from.begin() + object.first_vertex,
                from.begin() + object.first_vertex + object.vertex_count);
    };
    copy_vertices(city.mesh.positions, visible.positions);
    copy_vertices(city.mesh.normals, visible.normals);
    copy_vertices(city.mesh.colors, visible.colors);
    for (std::uint32_t k = 0; k < object.index_count; ++k)
      visible.indices.push_back(city.mesh.indices[object.first_index + k] + offset);
    ++frame.objects_drawn;
  }
  frame.query_seconds = seconds_since(start);

  start = Clock::now();
  // Empty indices would mean a mesh without indices: with no visible prop, nothing to draw.
  if (!visible.indices.empty()) {
    draw(target, {visible.positions, visible.colors, visible.normals, visible.indices},
         draw_options(view, options));
  }
  frame.draw_seconds = seconds_since(start);
  frame.triangles_drawn = (city.occluder_index_count + visible.indices.size()) / 3;
  return frame;
}

}  // namespace edgewise::scene
