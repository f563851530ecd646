// Geometry the scene tests measure meshes with, in double precision: vector arithmetic, welding
// vertices by position, the surface's edges, and how far from unit length a normal may be.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include "scene/mesh.hpp"

namespace edgewise::scene::test {

// How far from 1 the length of a normal may be: normals are unit vectors in double precision
// whose components are each rounded once to float32 (relative error at most u = 2^-24), so their
// length is within u of 1; the double-precision arithmetic they come from (sums, sin and cos)
// adds ~1e-15.
inline constexpr double kUnitLengthTolerance = 0x1.0p-24 + 1e-12;

struct Vec3d {
  double x, y, z;
};

inline Vec3d to_double(Vec3 v) {
  return {v.x, v.y, v.z};
}
inline Vec3d operator-(Vec3d a, Vec3d b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3d operator+(Vec3d a, Vec3d b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3d operator*(double s, Vec3d a) {
  return {s * a.x, s * a.y, s * a.z};
}
inline double dot(Vec3d a, Vec3d b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3d cross(Vec3d a, Vec3d b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3d a) {
  return std::sqrt(dot(a, a));
}

// Twice the vector area of triangle t: points to the side it is counter-clockwise from.
inline Vec3d triangle_normal(const Mesh& mesh, std::size_t t) {
  const Vec3d a = to_double(mesh.positions[mesh.indices[3 * t]]);
  const Vec3d b = to_double(mesh.positions[mesh.indices[3 * t + 1]]);
  const Vec3d c = to_double(mesh.positions[mesh.indices[3 * t + 2]]);
  return cross(b - a, c - a);
}

inline Vec3d triangle_centroid(const Mesh& mesh, std::size_t t) {
  Vec3d sum{0, 0, 0};
  for (int k = 0; k < 3; ++k)
    sum = sum + to_double(mesh.positions[mesh.indices[3 * t + k]]);
  return (1.0 / 3.0) * sum;
}

// One id per distinct position (bit-identical coordinates), for each vertex.
inline std::vector<std::uint32_t> weld_by_position(const Mesh& mesh) {
  std::map<std::tuple<float, float, float>, std::uint32_t> id_of;
  std::vector<std::uint32_t> ids;
  for (const Vec3& p : mesh.positions) {
    const auto [it, inserted] =
        id_of.try_emplace({p.x, p.y, p.z}, static_cast<std::uint32_t>(id_of.size()));
    ids.push_back(it->second);
  }
  return ids;
}

inline std::size_t distinct_ids(const std::vector<std::uint32_t>& ids) {
  std::uint32_t largest = 0;
  for (const std::uint32_t id : ids)
    largest = std::max(largest, id + 1);
  return largest;
}

// How many triangles use each directed edge (from, to) of the welded surface.
inline std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed_edges(
    const Mesh& mesh, const std::vector<std::uint32_t>& welded) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (std::size_t t = 0; t < triangle_count(mesh); ++t) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t from = welded[mesh.indices[3 * t + k]];
      const std::uint32_t to = welded[mesh.indices[3 * t + (k + 1) % 3]];
      ++count[{from, to}];
    }
  }
  return count;
}

}  // namespace edgewise::scene::test
