#include "scene/city.hpp"

#include <algorithm>
#include <cmath>

namespace edgewise::scene {
namespace {

constexpr float kBlock = 40.0f;   // a block's side, pavement included
constexpr float kStreet = 12.0f;  // between blocks
constexpr float kPavement = 3.0f;

// A fixed generator, so a seed gives the same city everywhere.
struct Lcg {
  std::uint64_t state;
  float uniform(float lo, float hi) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return lo + (hi - lo) * static_cast<float>(static_cast<double>(state >> 11) * 0x1.0p-53);
  }
};

// A box with a normal and colour per face (4 vertices each), counter-clockwise outside.
void append_box(Mesh& mesh, const Box3& b, const Vec4& colour) {
  const Vec3 lo = b.min, hi = b.max;
  struct Face {
    Vec3 normal;
    Vec3 corners[4];
  };
  const Face faces[6] = {
      {{-1, 0, 0},
       {{lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {lo.x, hi.y, lo.z}}},
      {{1, 0, 0}, {{hi.x, lo.y, hi.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}}},
      {{0, -1, 0},
       {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z}}},
      {{0, 1, 0}, {{lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}}},
      {{0, 0, -1},
       {{hi.x, lo.y, lo.z}, {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}}},
      {{0, 0, 1}, {{lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}}},
  };
  for (const Face& f : faces) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (const Vec3& c : f.corners) {
      mesh.positions.push_back(c);
      mesh.normals.push_back(f.normal);
      mesh.colors.push_back(colour);
    }
    for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
      mesh.indices.push_back(base + i);
  }
}

void add_object(City& city, const Mesh& part) {
  CityObject object;
  object.first_index = static_cast<std::uint32_t>(city.mesh.indices.size());
  object.index_count = static_cast<std::uint32_t>(part.indices.size());
  object.first_vertex = static_cast<std::uint32_t>(city.mesh.positions.size());
  object.vertex_count = static_cast<std::uint32_t>(part.positions.size());
  object.bounds = *bounding_box(part);
  append(city.mesh, part);
  city.objects.push_back(object);
}

}  // namespace

City make_city(const CityOptions& options) {
  City city;
  Lcg random{0xc17ull + options.seed};
  const int n = std::max(options.blocks_per_side, 1);
  const float pitch = kBlock + kStreet;
  const float origin = -0.5f * static_cast<float>(n) * pitch;
  const float lot = 0.5f * (kBlock - 2.0f * kPavement);
  // Buildings: four per block, one per quarter of its lot, each inset by a random gap.
  for (int bz = 0; bz < n; ++bz) {
    for (int bx = 0; bx < n; ++bx) {
      const float x0 = origin + static_cast<float>(bx) * pitch + kPavement;
      const float z0 = origin + static_cast<float>(bz) * pitch + kPavement;
      for (int q = 0; q < 4; ++q) {
        const float lx = x0 + static_cast<float>(q & 1) * lot;
        const float lz = z0 + static_cast<float>(q >> 1) * lot;
        const float gap = random.uniform(0.5f, 2.0f);
        const Box3 box{{lx + gap, 0.0f, lz + gap},
                       {lx + lot - gap, random.uniform(8.0f, 60.0f), lz + lot - gap}};
        const Vec4 colour{random.uniform(0.4f, 0.9f), random.uniform(0.4f, 0.9f),
                          random.uniform(0.4f, 0.9f), 1.0f};
        Mesh part;
        append_box(part, box, colour);
        add_object(city, part);
      }
    }
  }
  city.buildings = city.objects.size();
  // The ground under the whole city, a thin slab just below the streets.
  const float extent = 0.5f * static_cast<float>(n) * pitch + kStreet;
  Mesh ground;
  append_box(ground, {{-extent, -0.5f, -extent}, {extent, -0.01f, extent}},
             {0.35f, 0.35f, 0.38f, 1.0f});
  add_object(city, ground);
  city.occluder_index_count = city.mesh.indices.size();
  city.occluder_vertex_count = city.mesh.positions.size();
  // Props: trees on the pavements around each block, spread along its four sides.
  const int props = std::max(options.props_per_block, 0);
  for (int bz = 0; bz < n; ++bz) {
    for (int bx = 0; bx < n; ++bx) {
      const float x0 = origin + static_cast<float>(bx) * pitch;
      const float z0 = origin + static_cast<float>(bz) * pitch;
      for (int i = 0; i < props; ++i) {
        const int side = i % 4;
        const float along = random.uniform(2.0f, kBlock - 2.0f);
        const float across = 0.5f * kPavement;
        const Vec3 spot = side == 0   ? Vec3{x0 + along, 0.0f, z0 + across}
                          : side == 1 ? Vec3{x0 + along, 0.0f, z0 + kBlock - across}
                          : side == 2 ? Vec3{x0 + across, 0.0f, z0 + along}
                                      : Vec3{x0 + kBlock - across, 0.0f, z0 + along};
        SphereOptions tree;
        tree.radius = random.uniform(0.6f, 1.2f);
        tree.center = {spot.x, 1.5f + tree.radius, spot.z};
        tree.rings = options.prop_rings;
        tree.segments = options.prop_segments;
        tree.color_top = {0.2f, random.uniform(0.5f, 0.8f), 0.2f, 1.0f};
        tree.color_bottom = {0.1f, 0.3f, 0.1f, 1.0f};
        add_object(city, make_uv_sphere(tree));
      }
    }
  }
  // In the street along z just right of the middle column of blocks, looking down it.
  const float street_x = origin + static_cast<float>(n / 2) * pitch - 0.5f * kStreet;
  const float start_z = origin + 1.5f * pitch;
  city.camera = {{street_x, 1.7f, start_z},
                 {street_x, 1.7f, start_z + 100.0f},
                 {0.0f, 1.0f, 0.0f},
                 60.0f,
                 0.5f,
                 2.0f * static_cast<float>(n) * pitch};
  return city;
}

}  // namespace edgewise::scene
