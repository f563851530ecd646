// The culling of draw()'s screen triangles before set-up (KernelTable::drop_culled_triangles):
// - every ISA keeps exactly the triangles the reference keeps, in the same order;
// - those are exactly the triangles whose set-up status (the same ISA's coverage kernel, which
//   fills a status per triangle) is neither culled_zero_area nor culled_winding: bad indices,
//   non-finite and out-of-band vertices stay for set-up to report;
// on random lists that mix snapped and unsnapped vertices, both windings, zero areas (repeated
// and collinear corners), special and guard-band values and bad indices, of every length around
// the lane counts, under each cull mode.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "edgewise/coverage.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "src/kernel_table.hpp"

namespace edgewise::test {
namespace {

constexpr CullMode kCullModes[] = {CullMode::none, CullMode::clockwise,
                                   CullMode::counter_clockwise};

float coordinate(Random& random) {
  const double band = kGuardBand;
  switch (random.integer(0, 9)) {
    case 0:
      return std::numeric_limits<float>::quiet_NaN();
    case 1:
      return static_cast<float>(random.sign()) * std::numeric_limits<float>::infinity();
    case 2:  // at and around the guard band's edges
      return static_cast<float>(random.sign() * band + random.integer(-2, 2) / 512.0);
    case 3:  // unsnapped
      return static_cast<float>(random.uniform(-100.0, 100.0));
    default:  // snapped to 1/256 px, as draw()'s vertex stage leaves it
      return static_cast<float>(std::nearbyint(random.uniform(-64.0, 64.0) * 256.0) / 256.0);
  }
}

struct TriangleList {
  std::vector<Vec2> vertices;
  std::vector<std::uint32_t> indices;
};

TriangleList random_list(Random& random, std::size_t triangles) {
  TriangleList list;
  const std::size_t vertex_count = static_cast<std::size_t>(random.integer(0, 24));
  for (std::size_t v = 0; v < vertex_count; ++v)
    list.vertices.push_back({coordinate(random), coordinate(random)});
  // Collinear corners: a vertex halfway between two others, exactly on the 1/256 grid.
  if (vertex_count >= 3) list.vertices[2] = {list.vertices[0].x, list.vertices[1].y};
  for (std::size_t t = 0; t < triangles; ++t) {
    for (int i = 0; i < 3; ++i) {
      std::uint32_t index = vertex_count == 0
                                ? 0
                                : static_cast<std::uint32_t>(random.integer(
                                      0, static_cast<std::int64_t>(vertex_count) - 1));
      if (random.chance(0.03)) {
        index = random.chance(0.5) ? UINT32_MAX : static_cast<std::uint32_t>(vertex_count);
      }
      if (i > 0 && random.chance(0.05)) index = list.indices.back();  // a repeated corner
      list.indices.push_back(index);
    }
  }
  return list;
}

// The kept triangles' indices, and how many were kept.
std::vector<std::uint32_t> kept_by(const detail::KernelTable& kernels, const TriangleList& list,
                                   CullMode cull) {
  std::vector<std::uint32_t> indices = list.indices;
  const std::size_t kept = kernels.drop_culled_triangles(list.vertices.data(), list.vertices.size(),
                                                         indices.data(), indices.size() / 3, cull);
  indices.resize(3 * kept);
  return indices;
}

// The triangles set-up keeps: those whose status, by the kernels' coverage pass, is not culled.
std::vector<std::uint32_t> kept_by_set_up(const detail::KernelTable& kernels,
                                          const TriangleList& list, CullMode cull) {
  const std::size_t triangles = list.indices.size() / 3;
  std::vector<TriangleStatus> statuses(triangles);
  const detail::TriangleBatch batch{list.vertices.data(),    list.vertices.size(),
                                    list.indices.data(),     triangles,
                                    PixelRect{0, 0, 64, 64}, cull,
                                    statuses.data()};
  RasterReport report;
  std::uint64_t pixels = 0;
  kernels.count_coverage(batch, report, pixels);
  std::vector<std::uint32_t> kept;
  for (std::size_t t = 0; t < triangles; ++t) {
    if (statuses[t] == TriangleStatus::culled_zero_area ||
        statuses[t] == TriangleStatus::culled_winding) {
      continue;
    }
    kept.insert(kept.end(), list.indices.begin() + 3 * t, list.indices.begin() + 3 * t + 3);
  }
  return kept;
}

class CulledTriangles : public IsaTest {};

TEST_P(CulledTriangles, KeepsWhatSetUpKeepsAsTheReferenceDoes) {
  const detail::KernelTable& kernels = detail::kernel_table(isa());
  const detail::KernelTable& reference = detail::kernel_table(Isa::reference);
  Random random(0x5eed'c011);
  std::size_t dropped = 0, kept = 0;
  for (int round = 0; round < 600; ++round) {
    const std::size_t triangles = round < 40 ? static_cast<std::size_t>(round)
                                             : static_cast<std::size_t>(random.integer(0, 300));
    const TriangleList list = random_list(random, triangles);
    for (CullMode cull : kCullModes) {
      const std::vector<std::uint32_t> ours = kept_by(kernels, list, cull);
      ASSERT_EQ(ours, kept_by(reference, list, cull))
          << "round " << round << ", cull " << static_cast<int>(cull);
      ASSERT_EQ(ours, kept_by_set_up(kernels, list, cull))
          << "round " << round << ", cull " << static_cast<int>(cull);
      kept += ours.size() / 3;
      dropped += triangles - ours.size() / 3;
    }
  }
  // The lists hold both outcomes in number (a test that only ever kept would prove nothing).
  EXPECT_GT(dropped, 10'000u);
  EXPECT_GT(kept, 10'000u);
}

EDGEWISE_INSTANTIATE_PER_ISA(CulledTriangles, every_isa());

}  // namespace
}  // namespace edgewise::test
