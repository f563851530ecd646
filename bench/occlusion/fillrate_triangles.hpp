// The occluder workload of Masked Occlusion Culling's fill-rate test (its FillrateTest protocol),
// generated here: right triangles whose legs are `size` pixels at 1920x1080, turned by a random
// angle about a random point, kept only when wholly on screen, nearest last (each triangle is drawn
// in front of every earlier one, so every covered pixel is written).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgewise/vector.hpp"

namespace edgewise::bench {

// A fixed generator (a 64-bit linear congruential one), so that the occlusion workloads are the
// same on every machine and standard library.
struct BenchRandom {
  std::uint64_t state;
  double uniform() {  // in [0, 1)
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  }
};

struct FillrateTriangles {
  int size = 0;               // legs in pixels
  std::vector<Vec3> ndc;      // three vertices per triangle: x/w, y/w (y up), z/w in (0, 1]
  std::vector<float> clip_w;  // per vertex: the w that gives the same order in 1/w
  std::size_t triangles() const { return ndc.size() / 3; }
};

// The sizes of the protocol, in pixels.
inline constexpr int kFillrateSizes[] = {10, 25, 50, 75, 100, 250, 500};

// `count` triangles of one size, the same for every call with the same arguments.
const FillrateTriangles& fillrate_triangles(int size, std::size_t count);

// Triangles per benchmark run: about 2^25 covered pixels, between 4096 and 2^20 triangles, so a
// run takes some milliseconds at every size.
std::size_t fillrate_count(int size);

}  // namespace edgewise::bench
