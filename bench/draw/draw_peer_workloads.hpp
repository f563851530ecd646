// The workloads DrawPeer/ measures: the draw() calls that Shading/ and TexturedDraw/ time, by
// name, for a peer renderer to draw from the same vertex arrays with the same settings:
// - area:<px>: Shading/<isa>/area:<px> (shading_scene.hpp);
// - area:<px>/samples:<n>: Multisample/<isa>/samples:<n>/area:<px>, the same triangles into a
//   target of n samples per pixel (the standard patterns), for 8, 64 and 1000 px and n = 4, 8;
// - ground_plane/trilinear: TexturedDraw/<isa>/trilinear/quad (bench_texture.hpp);
// - ground_plane/anisotropic16: TexturedDraw/<isa>/anisotropic/quad, max_anisotropy 16;
// - mesh/<name>: MeshDraw/<isa>/<name>, a real mesh (mesh_scenes.hpp), when built with the OBJ
//   loader and EDGEWISE_BENCH_MESHES names a folder of OBJ files.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "edgewise/edgewise.hpp"

namespace edgewise::bench {

// One draw() call into a kWidth x kHeight target of `samples` per pixel, cleared to clear_color
// and clear_depth.
struct PeerWorkload {
  std::string name;  // the last part of the benchmark's name
  int samples = 1;
  DrawMesh mesh;
  DrawOptions options;
  Vec4 clear_color;
  float clear_depth;
  std::uint64_t triangles;
};

// Every workload's name, in the order the benchmarks are registered.
std::span<const std::string_view> peer_workload_names();

// The workload called `name`, built on first use (the same in every process: fixed seeds);
// nullptr for an unknown name.
const PeerWorkload* find_peer_workload(std::string_view name);

}  // namespace edgewise::bench
