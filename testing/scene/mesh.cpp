#include "scene/mesh.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace edgewise::scene {
namespace {

bool is_finite(Vec2 v) {
  return std::isfinite(v.x) && std::isfinite(v.y);
}
bool is_finite(Vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool is_finite(Vec4 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

template <typename T>
std::optional<std::string> check_attribute(const std::vector<T>& values, std::size_t vertex_count,
                                           const char* name) {
  if (values.empty()) return std::nullopt;
  if (values.size() != vertex_count) {
    return std::string(name) + ": " + std::to_string(values.size()) + " values for " +
           std::to_string(vertex_count) + " vertices";
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!is_finite(values[i])) {
      return std::string(name) + " of vertex " + std::to_string(i) + " is not finite";
    }
  }
  return std::nullopt;
}

// The key under which vertices at the same position share a normal: the coordinates' bits, with
// -0 folded into +0 so that both signs of zero meet.
struct PositionKey {
  std::uint32_t x, y, z;
  bool operator==(const PositionKey&) const = default;
};

PositionKey position_key(Vec3 p) {
  return {std::bit_cast<std::uint32_t>(p.x + 0.0f), std::bit_cast<std::uint32_t>(p.y + 0.0f),
          std::bit_cast<std::uint32_t>(p.z + 0.0f)};
}

struct PositionKeyHash {
  std::size_t operator()(const PositionKey& key) const {
    std::uint64_t h = key.x;
    h = h * 0x9e3779b97f4a7c15ull ^ key.y;
    h = h * 0x9e3779b97f4a7c15ull ^ key.z;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

}  // namespace

std::optional<Box3> bounding_box(const Mesh& mesh) {
  std::optional<Box3> box;
  for (const Vec3& p : mesh.positions) {
    if (!is_finite(p)) continue;
    if (!box) {
      box = Box3{p, p};
      continue;
    }
    box->min = {std::min(box->min.x, p.x), std::min(box->min.y, p.y), std::min(box->min.z, p.z)};
    box->max = {std::max(box->max.x, p.x), std::max(box->max.y, p.y), std::max(box->max.z, p.z)};
  }
  return box;
}

std::optional<std::string> validate(const Mesh& mesh) {
  const std::size_t vertex_count = mesh.positions.size();
  if (vertex_count > std::numeric_limits<std::uint32_t>::max()) {
    return std::to_string(vertex_count) + " vertices: more than a 32-bit index can address";
  }
  if (mesh.indices.size() % 3 != 0) {
    return std::to_string(mesh.indices.size()) + " indices: not a multiple of 3";
  }
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
    if (mesh.indices[i] >= vertex_count) {
      return "index " + std::to_string(i) + " is " + std::to_string(mesh.indices[i]) +
             ", past the last of " + std::to_string(vertex_count) + " vertices";
    }
  }
  if (auto problem = check_attribute(mesh.positions, vertex_count, "position")) return problem;
  if (auto problem = check_attribute(mesh.normals, vertex_count, "normal")) return problem;
  if (auto problem = check_attribute(mesh.uvs, vertex_count, "uv")) return problem;
  if (auto problem = check_attribute(mesh.colors, vertex_count, "colour")) return problem;
  return std::nullopt;
}

void compute_smooth_normals(Mesh& mesh) {
  const std::size_t vertex_count = mesh.positions.size();
  // One accumulator per distinct position, in double.
  std::unordered_map<PositionKey, std::uint32_t, PositionKeyHash> slot_of_position;
  std::vector<std::uint32_t> slot(vertex_count);
  for (std::size_t i = 0; i < vertex_count; ++i) {
    const auto [it, inserted] = slot_of_position.try_emplace(
        position_key(mesh.positions[i]), static_cast<std::uint32_t>(slot_of_position.size()));
    slot[i] = it->second;
  }
  struct Vec3d {
    double x = 0, y = 0, z = 0;
  };
  std::vector<Vec3d> sums(slot_of_position.size());

  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t corners[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    if (corners[0] >= vertex_count || corners[1] >= vertex_count || corners[2] >= vertex_count) {
      continue;
    }
    Vec3d p[3];
    for (int k = 0; k < 3; ++k) {
      const Vec3 position = mesh.positions[corners[k]];
      p[k] = {position.x, position.y, position.z};
    }
    const auto edge = [&](int from, int to) {
      return Vec3d{p[to].x - p[from].x, p[to].y - p[from].y, p[to].z - p[from].z};
    };
    const Vec3d a = edge(0, 1), b = edge(0, 2);
    const Vec3d n{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    const double twice_area = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    // Also rejects NaN and infinite corners, whose products are not finite.
    if (!(twice_area > 0) || !std::isfinite(twice_area)) continue;
    for (int k = 0; k < 3; ++k) {
      const Vec3d u = edge(k, (k + 1) % 3), v = edge(k, (k + 2) % 3);
      const double cosine =
          (u.x * v.x + u.y * v.y + u.z * v.z) /
          std::sqrt((u.x * u.x + u.y * u.y + u.z * u.z) * (v.x * v.x + v.y * v.y + v.z * v.z));
      const double weight = std::acos(std::clamp(cosine, -1.0, 1.0)) / twice_area;
      Vec3d& sum = sums[slot[corners[k]]];
      sum.x += weight * n.x;
      sum.y += weight * n.y;
      sum.z += weight * n.z;
    }
  }

  mesh.normals.resize(vertex_count);
  for (std::size_t i = 0; i < vertex_count; ++i) {
    const Vec3d& sum = sums[slot[i]];
    const double length = std::sqrt(sum.x * sum.x + sum.y * sum.y + sum.z * sum.z);
    mesh.normals[i] =
        (length > 0 && std::isfinite(length))
            ? Vec3{static_cast<float>(sum.x / length), static_cast<float>(sum.y / length),
                   static_cast<float>(sum.z / length)}
            : kFallbackNormal;
  }
}

void append(Mesh& mesh, const Mesh& part) {
  const std::size_t old_count = mesh.positions.size();
  const std::size_t part_count = part.positions.size();
  const bool had_vertices = old_count > 0;

  // Normals: the side that lacks them gets smooth normals computed over its own triangles.
  std::vector<Vec3> part_normals = part.normals;
  if (!mesh.normals.empty() || !part.normals.empty()) {
    if (mesh.normals.empty() && had_vertices) compute_smooth_normals(mesh);
    if (part_normals.empty()) {
      Mesh copy = part;
      compute_smooth_normals(copy);
      part_normals = std::move(copy.normals);
    }
  }

  const auto merge = [&](auto& into, const auto& from, auto fill) {
    if (into.empty() && from.empty()) return;
    if (had_vertices && into.empty()) into.assign(old_count, fill);
    if (from.empty()) {
      into.insert(into.end(), part_count, fill);
    } else {
      into.insert(into.end(), from.begin(), from.end());
    }
  };
  merge(mesh.normals, part_normals, kFallbackNormal);
  merge(mesh.uvs, part.uvs, Vec2{0.0f, 0.0f});
  merge(mesh.colors, part.colors, Vec4{1.0f, 1.0f, 1.0f, 1.0f});

  mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
  const auto offset = static_cast<std::uint32_t>(old_count);
  for (const std::uint32_t index : part.indices)
    mesh.indices.push_back(index + offset);
}

}  // namespace edgewise::scene
