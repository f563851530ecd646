#include "scene/procedural.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace edgewise::scene {
namespace {

int clamp_count(int count, int min) {
  return std::clamp(count, min, kMaxSubdivisions);
}

Vec4 mix(Vec4 a, Vec4 b, double t) {
  const auto lerp = [t](float x, float y) { return static_cast<float>(x + (double(y) - x) * t); };
  return {lerp(a.x, b.x), lerp(a.y, b.y), lerp(a.z, b.z), lerp(a.w, b.w)};
}

// A unit direction in double precision; positions and normals are derived from it and rounded
// once, so a normal is unit length to within float32 rounding.
struct Direction {
  double x, y, z;
};

Vec3 to_float(Direction d) {
  return {static_cast<float>(d.x), static_cast<float>(d.y), static_cast<float>(d.z)};
}

Vec3 point_at(Vec3 center, Direction offset) {
  return {static_cast<float>(center.x + offset.x), static_cast<float>(center.y + offset.y),
          static_cast<float>(center.z + offset.z)};
}

// cos and sin of 2 pi k / n for k = 0 .. n, with k = n given k = 0's values exactly so that the
// seam's repeated vertices land on the same bits.
struct CircleTable {
  std::vector<double> cos, sin;
  explicit CircleTable(int n) : cos(static_cast<std::size_t>(n) + 1), sin(cos.size()) {
    for (int k = 0; k < n; ++k) {
      const double angle = 2 * std::numbers::pi * k / n;
      cos[static_cast<std::size_t>(k)] = std::cos(angle);
      sin[static_cast<std::size_t>(k)] = std::sin(angle);
    }
    cos.back() = cos.front();
    sin.back() = sin.front();
  }
};

void add_quad_triangles(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                        std::uint32_t d) {
  mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
}

}  // namespace

Mesh make_uv_sphere(const SphereOptions& options) {
  const int rings = clamp_count(options.rings, kMinSphereRings);
  const int segments = clamp_count(options.segments, kMinSegments);
  const CircleTable around(segments);
  const double radius = options.radius;
  Mesh mesh;

  // Longitude phi runs from +x towards -z, so that s grows to the right seen from outside.
  const auto add_vertex = [&](Direction d, double s, double t, double row) {
    mesh.positions.push_back(point_at(options.center, {radius * d.x, radius * d.y, radius * d.z}));
    mesh.normals.push_back(to_float(d));
    mesh.uvs.push_back({static_cast<float>(s), static_cast<float>(t)});
    mesh.colors.push_back(mix(options.color_top, options.color_bottom, row));
  };
  const auto add_pole = [&](double y, double t) {
    for (int j = 0; j < segments; ++j)
      add_vertex({0.0, y, 0.0}, (j + 0.5) / segments, t, t);
  };

  add_pole(1.0, 0.0);
  for (int i = 1; i < rings; ++i) {
    const double theta = std::numbers::pi * i / rings;  // from the +y pole
    const double t = static_cast<double>(i) / rings;
    const double ring_radius = std::sin(theta), y = std::cos(theta);
    for (int j = 0; j <= segments; ++j) {
      const auto k = static_cast<std::size_t>(j);
      add_vertex({ring_radius * around.cos[k], y, -ring_radius * around.sin[k]},
                 static_cast<double>(j) / segments, t, t);
    }
  }
  add_pole(-1.0, 1.0);

  const auto ring_vertex = [&](int i, int j) {
    return static_cast<std::uint32_t>(segments + (i - 1) * (segments + 1) + j);
  };
  const auto south_pole = static_cast<std::uint32_t>(segments + (rings - 1) * (segments + 1));
  // Corners in the order (down, then around) turn counter-clockwise seen from outside.
  for (int j = 0; j < segments; ++j) {
    mesh.indices.insert(mesh.indices.end(),
                        {static_cast<std::uint32_t>(j), ring_vertex(1, j), ring_vertex(1, j + 1)});
  }
  for (int i = 1; i + 1 < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      add_quad_triangles(mesh, ring_vertex(i, j), ring_vertex(i + 1, j), ring_vertex(i + 1, j + 1),
                         ring_vertex(i, j + 1));
    }
  }
  for (int j = 0; j < segments; ++j) {
    mesh.indices.insert(mesh.indices.end(),
                        {ring_vertex(rings - 1, j), south_pole + static_cast<std::uint32_t>(j),
                         ring_vertex(rings - 1, j + 1)});
  }
  return mesh;
}

Mesh make_torus(const TorusOptions& options) {
  const int major = clamp_count(options.major_segments, kMinSegments);
  const int minor = clamp_count(options.minor_segments, kMinSegments);
  const CircleTable around_axis(major), around_tube(minor);
  const double tilt_cos = std::cos(options.tilt_radians);
  const double tilt_sin = std::sin(options.tilt_radians);
  const auto tilt = [&](Direction d) {
    return Direction{d.x, d.y * tilt_cos - d.z * tilt_sin, d.y * tilt_sin + d.z * tilt_cos};
  };
  Mesh mesh;

  // Row i goes around the tube (psi), column j around the y axis (phi, from +x towards -z).
  for (int i = 0; i <= minor; ++i) {
    const auto ki = static_cast<std::size_t>(i);
    for (int j = 0; j <= major; ++j) {
      const auto kj = static_cast<std::size_t>(j);
      const double cos_phi = around_axis.cos[kj], sin_phi = around_axis.sin[kj];
      const double cos_psi = around_tube.cos[ki], sin_psi = around_tube.sin[ki];
      const Direction normal{cos_psi * cos_phi, sin_psi, -cos_psi * sin_phi};
      const double from_axis = options.major_radius + options.minor_radius * cos_psi;
      const Direction offset{from_axis * cos_phi, options.minor_radius * sin_psi,
                             -from_axis * sin_phi};
      mesh.positions.push_back(point_at(options.center, tilt(offset)));
      mesh.normals.push_back(to_float(tilt(normal)));
      mesh.uvs.push_back({static_cast<float>(static_cast<double>(j) / major),
                          static_cast<float>(static_cast<double>(i) / minor)});
      mesh.colors.push_back(mix(options.color_a, options.color_b, (1.0 - cos_phi) / 2));
    }
  }

  const auto vertex = [&](int i, int j) { return static_cast<std::uint32_t>(i * (major + 1) + j); };
  // Corners in the order (around the axis, then around the tube) turn counter-clockwise seen
  // from outside.
  for (int i = 0; i < minor; ++i) {
    for (int j = 0; j < major; ++j) {
      add_quad_triangles(mesh, vertex(i, j), vertex(i, j + 1), vertex(i + 1, j + 1),
                         vertex(i + 1, j));
    }
  }
  return mesh;
}

Mesh make_ground_plane(const GroundOptions& options) {
  const int cells = clamp_count(options.cells_per_side, 1);
  const double half = options.half_extent;
  const double cell_size = 2 * half / cells;
  // One formula per grid line, so that neighbouring cells' corners land on the same bits.
  const auto line = [&](int k) { return static_cast<float>(-half + k * cell_size); };
  const double tile = options.texture_tile;
  const float y = options.height;
  Mesh mesh;

  for (int row = 0; row < cells; ++row) {
    for (int column = 0; column < cells; ++column) {
      const auto first = static_cast<std::uint32_t>(mesh.positions.size());
      const Vec4 color = (row + column) % 2 == 0 ? options.color_a : options.color_b;
      // Corners (x0 z0), (x0 z1), (x1 z1), (x1 z0): counter-clockwise seen from above.
      for (const auto& [dx, dz] : {std::pair{0, 0}, {0, 1}, {1, 1}, {1, 0}}) {
        const float x = line(column + dx), z = line(row + dz);
        mesh.positions.push_back({x, y, z});
        mesh.normals.push_back({0.0f, 1.0f, 0.0f});
        mesh.uvs.push_back({static_cast<float>(x / tile), static_cast<float>(z / tile)});
        mesh.colors.push_back(color);
      }
      add_quad_triangles(mesh, first, first + 1, first + 2, first + 3);
    }
  }
  return mesh;
}

Scene default_scene() {
  // Mid-grey and charcoal squares of 4 world units, one texture repeat each.
  Mesh mesh = make_ground_plane({.height = 0.0f,
                                 .half_extent = 250.0f,
                                 .cells_per_side = 125,
                                 .texture_tile = 4.0f,
                                 .color_a = {0.8f, 0.8f, 0.75f, 1.0f},
                                 .color_b = {0.25f, 0.25f, 0.3f, 1.0f}});
  const Vec3 center{0.0f, 1.3f, 0.0f};
  append(mesh, make_uv_sphere({.center = center,
                               .radius = 1.0f,
                               .rings = 32,
                               .segments = 64,
                               .color_top = {1.0f, 0.75f, 0.3f, 1.0f},
                               .color_bottom = {0.75f, 0.2f, 0.1f, 1.0f}}));
  // Inner edge 1.35 from the centre: clear of the sphere (radius 1). Seen from the eye, the
  // sphere spans 8.7 degrees around its centre; tilted by 15 degrees, the ring's front middle
  // lies 7.4 degrees below the centre (in front of the sphere's lower half) and its back middle
  // 4.7 degrees above it (hidden behind the sphere's upper half). Lowest point: y = 0.64.
  append(mesh, make_torus({.center = center,
                           .major_radius = 1.6f,
                           .minor_radius = 0.25f,
                           .major_segments = 96,
                           .minor_segments = 24,
                           .tilt_radians = static_cast<float>(std::numbers::pi / 12),
                           .color_a = {0.2f, 0.5f, 0.95f, 1.0f},
                           .color_b = {0.2f, 0.9f, 0.55f, 1.0f}}));
  const SceneCamera camera{.eye = {0.0f, 2.4f, 6.5f},
                           .target = {0.0f, 1.1f, 0.0f},
                           .up = {0.0f, 1.0f, 0.0f},
                           .vertical_fov_degrees = 45.0f,
                           .near_plane = 0.1f,
                           .far_plane = 500.0f};
  return {std::move(mesh), camera};
}

Scene ground_scene() {
  return {make_ground_plane(
              {.color_a = {0.8f, 0.8f, 0.75f, 1.0f}, .color_b = {0.25f, 0.25f, 0.3f, 1.0f}}),
          {.eye = {0.0f, 1.7f, 6.0f},
           .target = {0.0f, 0.6f, -10.0f},
           .up = {0.0f, 1.0f, 0.0f},
           .vertical_fov_degrees = 60.0f,
           .near_plane = 0.1f,
           .far_plane = 500.0f}};
}

}  // namespace edgewise::scene
