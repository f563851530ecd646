// Watertightness on random meshes whose triangles share edges: every sample inside the mesh's
// outline is covered exactly once, every sample outside never, whatever the windings, slivers,
// target border or scissor; and each ISA's masks equal the reference's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "coverage_result.hpp"
#include "isa_params.hpp"
#include "meshes.hpp"
#include "random.hpp"

namespace edgewise::test {
namespace {

constexpr int kMeshesPerTest = 1000;
constexpr std::uint64_t kSeed = 0x3a7e'27f1'9447ull;

using Watertight = IsaTest;

// A target whose sides are not multiples of 8, sometimes with a scissor cutting the mesh.
RasterTarget random_target(Random& random) {
  RasterTarget target{72, 61, {}};
  if (random.chance(0.4)) {
    const std::int32_t x0 = static_cast<std::int32_t>(random.integer(-4, 40));
    const std::int32_t y0 = static_cast<std::int32_t>(random.integer(-4, 40));
    target.scissor = PixelRect{x0, y0, x0 + static_cast<std::int32_t>(random.integer(1, 50)),
                               y0 + static_cast<std::int32_t>(random.integer(1, 50))};
  }
  return target;
}

std::string describe_mesh(const RasterCall& call) {
  std::ostringstream out;
  out << describe_call(call);
  for (std::size_t t = 0; t < call.triangle_count(); ++t)
    out << "\n" << describe_triangle(call, t);
  return out.str();
}

// Checks one mesh; false (with a failure recorded) when a sample is covered the wrong number
// of times. Counts the samples found inside the outline.
bool check_mesh(Isa isa, const Mesh& mesh, const RasterTarget& target, const std::string& where,
                std::uint64_t& inside) {
  const RasterCall call{mesh.vertices, mesh.indices, target};
  const RasterRun run = run_checked(isa, call);
  if (::testing::Test::HasFailure()) {
    ADD_FAILURE() << where;
    return false;
  }
  const PixelRect clip = clip_rect(target);
  const std::int32_t width = clip.x1 - clip.x0;
  std::vector<int> counts(static_cast<std::size_t>(width) * std::max(0, clip.y1 - clip.y0), 0);
  for (const Pixel& p : covered_pixels(run))
    ++counts[static_cast<std::size_t>((p.y - clip.y0) * width + (p.x - clip.x0))];
  for (std::int32_t y = clip.y0; y < clip.y1; ++y) {
    for (std::int32_t x = clip.x0; x < clip.x1; ++x) {
      const int count = counts[static_cast<std::size_t>((y - clip.y0) * width + (x - clip.x0))];
      bool on_outline = false;
      const int winding =
          std::abs(outline_winding(mesh, {256 * x + 128, 256 * y + 128}, on_outline));
      if (winding > 1) {
        ADD_FAILURE() << "the mesh generator folded a mesh over itself; " << where;
        return false;
      }
      if (!on_outline) inside += static_cast<std::uint64_t>(winding);
      const bool wrong = on_outline ? count > 1 : count != winding;
      if (wrong) {
        ADD_FAILURE() << "sample (" << x << ".5, " << y << ".5) covered " << count
                      << " times; expected " << (on_outline ? "at most 1 (on the outline)" : "")
                      << (on_outline ? "" : std::to_string(winding)) << "\n"
                      << where << "\n"
                      << describe_mesh(call);
        return false;
      }
    }
  }
  return true;
}

void check_meshes(Isa isa, Mesh (*make)(Random&, const PixelRect&), std::uint64_t stream) {
  Random random(kSeed ^ stream);
  std::uint64_t triangles = 0, inside = 0;
  for (int m = 0; m < kMeshesPerTest; ++m) {
    const RasterTarget target = random_target(random);
    const Mesh mesh = make(random, PixelRect{0, 0, target.width, target.height});
    triangles += mesh.indices.size() / 3;
    std::ostringstream where;
    where << "mesh " << m << " of seed " << kSeed << " (stream " << stream << ")";
    if (!check_mesh(isa, mesh, target, where.str(), inside)) return;
  }
  // The meshes must really land on the targets for the test to mean anything.
  EXPECT_GT(inside, 100u * kMeshesPerTest);
  std::printf("[ %-8s ] %d meshes, %" PRIu64 " triangles, %" PRIu64 " samples inside\n",
              std::string(name_of(isa)).c_str(), kMeshesPerTest, triangles, inside);
}

TEST_P(Watertight, JitteredGrids) {
  check_meshes(isa(), &jittered_grid, 1);
}

TEST_P(Watertight, Fans) {
  check_meshes(isa(), &triangle_fan, 2);
}

EDGEWISE_INSTANTIATE_PER_ISA(Watertight, every_isa());

}  // namespace
}  // namespace edgewise::test
