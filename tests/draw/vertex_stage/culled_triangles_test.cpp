// The culling of draw()'s screen triangles before set-up (KernelTable::drop_culled_triangles):
// - every ISA keeps exactly the triangles the reference keeps, in the same order, and counts
//   the dropped ones as it does;
// - the culled ones are exactly those whose set-up status (the same ISA's coverage kernel, which
//   fills a status per triangle) is culled_zero_area or culled_winding: bad indices, non-finite
//   and out-of-band vertices stay for set-up to report;
// - the unseen ones are drawn by set-up and cover no sample of the window's rectangle, one per
//   pixel or in any standard multisample pattern (for a window that reaches half a pixel);
// on random lists that mix snapped and unsnapped vertices, both windings, zero areas (repeated
// and collinear corners), special and guard-band values, bad indices and triangles smaller than
// a pixel, of every length around the lane counts, under each cull mode and random windows;
// - for a binned draw, each kept triangle's bin is the reference's, and holds every sample the
//   triangle covers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "edgewise/coverage.hpp"
#include "edgewise/multisample.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "core/kernel_table.hpp"

namespace edgewise::test {
namespace {

constexpr CullMode kCullModes[] = {CullMode::none, CullMode::clockwise,
                                   CullMode::counter_clockwise};

// A coordinate around `centre`, snapped ones within `spread` pixels of it.
float coordinate(Random& random, double centre, double spread) {
  const double band = kGuardBand;
  switch (random.integer(0, 9)) {
    case 0:
      return std::numeric_limits<float>::quiet_NaN();
    case 1:
      return static_cast<float>(random.sign()) * std::numeric_limits<float>::infinity();
    case 2:  // at and around the guard band's edges
      return static_cast<float>(random.sign() * band + random.integer(-2, 2) / 512.0);
    case 3:  // unsnapped
      return static_cast<float>(centre + random.uniform(-spread, spread));
    default:  // snapped to 1/256 px, as draw()'s vertex stage leaves it
      return static_cast<float>(std::nearbyint((centre + random.uniform(-spread, spread)) * 256.0) /
                                256.0);
  }
}

struct TriangleList {
  std::vector<Vec2> vertices;
  std::vector<std::uint32_t> indices;
};

// Vertices within 64 px of (32, 32), or, for lists of triangles smaller than a pixel, within
// one or two pixels of a point of [-4, 68).
TriangleList random_list(Random& random, std::size_t triangles) {
  TriangleList list;
  const std::size_t vertex_count = static_cast<std::size_t>(random.integer(0, 24));
  const bool tiny = random.chance(0.5);
  const double spread = tiny ? random.uniform(0.3, 2.0) : 64.0;
  const double cx = tiny ? random.uniform(-4.0, 68.0) : 32.0;
  const double cy = tiny ? random.uniform(-4.0, 68.0) : 32.0;
  for (std::size_t v = 0; v < vertex_count; ++v)
    list.vertices.push_back({coordinate(random, cx, spread), coordinate(random, cy, spread)});
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

// A window of up to 64 x 64 pixels at a random place in [0, 64), sometimes empty, with samples
// at the pixel centres or within half a pixel of them.
detail::SampleWindow random_window(Random& random) {
  const auto x0 = static_cast<std::int32_t>(random.integer(0, 63));
  const auto y0 = static_cast<std::int32_t>(random.integer(0, 63));
  const auto x1 = static_cast<std::int32_t>(random.integer(x0, 64));
  const auto y1 = static_cast<std::int32_t>(random.integer(y0, 64));
  return {PixelRect{x0, y0, x1, y1}, random.chance(0.5) ? 128 : 0};
}

struct Dropped {
  std::vector<std::uint32_t> kept;  // the kept triangles' indices
  detail::DroppedTriangles counts;
};

Dropped dropped_by(const detail::KernelTable& kernels, const TriangleList& list, CullMode cull,
                   const detail::SampleWindow& window, const detail::BinGrid* grid = nullptr,
                   std::vector<std::uint32_t>* bins = nullptr) {
  Dropped dropped{list.indices, {}};
  detail::BinOutput output;
  if (grid != nullptr) {
    bins->assign(list.indices.size() / 3, 0xdead'beefu);
    output = {grid, bins->data()};
  }
  dropped.counts =
      kernels.drop_culled_triangles(list.vertices.data(), list.vertices.size(), dropped.kept.data(),
                                    list.indices.size() / 3, cull, window, output);
  dropped.kept.resize(3 * dropped.counts.kept);
  if (bins != nullptr) bins->resize(dropped.counts.kept);
  return dropped;
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

// The triangles in `all` but not in `kept` (a subsequence of it), three indices each.
std::vector<std::uint32_t> left_out(const std::vector<std::uint32_t>& all,
                                    const std::vector<std::uint32_t>& kept) {
  std::vector<std::uint32_t> out;
  std::size_t k = 0;
  for (std::size_t t = 0; t < all.size(); t += 3) {
    if (k < kept.size() && std::equal(all.begin() + t, all.begin() + t + 3, kept.begin() + k)) {
      k += 3;
    } else {
      out.insert(out.end(), all.begin() + t, all.begin() + t + 3);
    }
  }
  return out;
}

// The samples `triangles` cover in `window`: pixel centres, and when the window reaches half a
// pixel, the samples of every standard multisample pattern too.
std::uint64_t samples_covered(const TriangleList& list, const std::vector<std::uint32_t>& triangles,
                              const detail::SampleWindow& window) {
  std::uint64_t covered = 0;
  for (int samples : {1, 2, 4, 8, 16}) {
    if (samples > 1 && window.reach == 0) break;
    RasterOptions options;
    options.samples = samples;
    options.threads = 1;
    covered +=
        count_coverage(list.vertices, triangles, RasterTarget{64, 64, window.clip}, options).pixels;
  }
  return covered;
}

class CulledTriangles : public IsaTest {};

TEST_P(CulledTriangles, KeepsWhatSetUpKeepsAsTheReferenceDoes) {
  const detail::KernelTable& kernels = detail::kernel_table(isa());
  const detail::KernelTable& reference = detail::kernel_table(Isa::reference);
  Random random(0x5eed'c011);
  std::size_t culled = 0, unseen = 0, kept = 0;
  for (int round = 0; round < 600; ++round) {
    const std::size_t triangles = round < 40 ? static_cast<std::size_t>(round)
                                             : static_cast<std::size_t>(random.integer(0, 300));
    const TriangleList list = random_list(random, triangles);
    for (CullMode cull : kCullModes) {
      const detail::SampleWindow window = random_window(random);
      const std::string where =
          "round " + std::to_string(round) + ", cull " + std::to_string(static_cast<int>(cull)) +
          ", window " + std::to_string(window.clip.x0) + " " + std::to_string(window.clip.y0) +
          " " + std::to_string(window.clip.x1) + " " + std::to_string(window.clip.y1) + ", reach " +
          std::to_string(window.reach);
      const Dropped ours = dropped_by(kernels, list, cull, window);
      const Dropped theirs = dropped_by(reference, list, cull, window);
      ASSERT_EQ(ours.kept, theirs.kept) << where;
      ASSERT_EQ(ours.counts.culled, theirs.counts.culled) << where;
      ASSERT_EQ(ours.counts.unseen, theirs.counts.unseen) << where;
      ASSERT_EQ(ours.counts.kept + ours.counts.culled + ours.counts.unseen, triangles) << where;
      // Without a sample in the window nothing is culled that set-up keeps: the window's
      // drops are the others.
      const std::vector<std::uint32_t> drawn = kept_by_set_up(kernels, list, cull);
      ASSERT_EQ(drawn.size() / 3, triangles - ours.counts.culled) << where;
      const std::vector<std::uint32_t> unseen_triangles = left_out(drawn, ours.kept);
      ASSERT_EQ(unseen_triangles.size() / 3, ours.counts.unseen) << where;
      ASSERT_EQ(left_out(list.indices, drawn).size() / 3, ours.counts.culled) << where;
      if (!unseen_triangles.empty()) {
        ASSERT_EQ(samples_covered(list, unseen_triangles, window), 0u) << where;
      }
      culled += ours.counts.culled;
      unseen += ours.counts.unseen;
      kept += ours.counts.kept;
    }
  }
  // The lists hold every outcome in number (a test that only ever kept would prove nothing).
  EXPECT_GT(culled, 10'000u);
  EXPECT_GT(unseen, 10'000u);
  EXPECT_GT(kept, 10'000u);
}

// The bins of the kept triangles (BinOutput, for a binned draw): the reference's, and a
// triangle given a bin covers no sample outside it (every sample it covers in the window it
// covers in the bin's rectangle too); grids of 8 to 64 px bins, so that boxes often span several.
TEST_P(CulledTriangles, KeptTrianglesGetTheReferenceBinsWhichHoldTheirSamples) {
  const detail::KernelTable& kernels = detail::kernel_table(isa());
  const detail::KernelTable& reference = detail::kernel_table(Isa::reference);
  Random random(0xb175'0001);
  std::size_t single = 0, several = 0;
  for (int round = 0; round < 2000; ++round) {
    const TriangleList list = random_list(random, static_cast<std::size_t>(random.integer(0, 120)));
    const CullMode cull = kCullModes[random.integer(0, 2)];
    const detail::SampleWindow window = random_window(random);
    const detail::BinGrid grid(window.clip, static_cast<int>(random.integer(3, 6)),
                               static_cast<int>(random.integer(3, 6)));
    const std::string where = "round " + std::to_string(round) + ", bins " +
                              std::to_string(grid.width_shift) + " " +
                              std::to_string(grid.height_shift);
    std::vector<std::uint32_t> ours_bins, theirs_bins;
    const Dropped ours = dropped_by(kernels, list, cull, window, &grid, &ours_bins);
    const Dropped theirs = dropped_by(reference, list, cull, window, &grid, &theirs_bins);
    ASSERT_EQ(ours.kept, theirs.kept) << where;
    ASSERT_EQ(ours_bins, theirs_bins) << where;
    // Without a grid, the same triangles are kept.
    ASSERT_EQ(dropped_by(kernels, list, cull, window).kept, ours.kept) << where;
    for (std::size_t k = 0; k < ours_bins.size(); ++k) {
      if (ours_bins[k] == detail::kSeveralBins) {
        ++several;
        continue;
      }
      ++single;
      ASSERT_LT(ours_bins[k], grid.count()) << where;
      const std::vector<std::uint32_t> triangle(ours.kept.begin() + 3 * k,
                                                ours.kept.begin() + 3 * k + 3);
      detail::SampleWindow in_bin = window;
      in_bin.clip = grid.rect(ours_bins[k]);
      ASSERT_EQ(samples_covered(list, triangle, in_bin), samples_covered(list, triangle, window))
          << where << ", kept triangle " << k;
    }
  }
  EXPECT_GT(single, 500u);
  EXPECT_GT(several, 5'000u);
}

EDGEWISE_INSTANTIATE_PER_ISA(CulledTriangles, every_isa());

}  // namespace
}  // namespace edgewise::test
