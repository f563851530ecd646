// A procedural city for occlusion culling (docs/design/occlusion.md, "The city"): blocks of box
// buildings on a street grid over a ground plane, and props (trees: spheres on the pavements),
// each an object with its own bounds, seen from street level where buildings hide most of it.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/mesh.hpp"
#include "scene/procedural.hpp"

namespace edgewise::scene {

struct CityOptions {
  int blocks_per_side = 20;  // the city is blocks_per_side^2 blocks
  int props_per_block = 22;  // trees per block
  int prop_rings = 12;       // each tree's sphere: rings x segments
  int prop_segments = 24;
  std::uint64_t seed = 1;
};

struct CityObject {
  std::uint32_t first_index = 0;  // into City::mesh.indices
  std::uint32_t index_count = 0;
  std::uint32_t first_vertex = 0;  // its indices name only vertices [first, first + count)
  std::uint32_t vertex_count = 0;
  Box3 bounds;
};

struct City {
  // Every object's triangles in object order, with normals and colours: the buildings, the
  // ground, then the props.
  Mesh mesh;
  std::vector<CityObject> objects;
  std::size_t buildings = 0;  // objects [0, buildings) are buildings, object `buildings` the ground
  std::size_t first_prop() const { return buildings + 1; }
  // The occluders: the buildings and the ground, as drawn: mesh.indices[0, this), which name
  // only the vertices [0, occluder_vertex_count).
  std::size_t occluder_index_count = 0;
  std::size_t occluder_vertex_count = 0;
  // Standing in a street near the city's middle, looking along it.
  SceneCamera camera;
};

// Buildings never touch or overlap: each stands inside its quarter of its block's lot, with a gap.
City make_city(const CityOptions& options = {});

}  // namespace edgewise::scene
