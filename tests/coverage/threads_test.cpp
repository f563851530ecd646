// count_coverage() on several threads, and rasterize(), which stays on the calling thread
// (coverage.hpp): for 1, 2, 3 and 8 threads, on every ISA, the same pixels, report and statuses,
// on triangles of every status (bad indices, non-finite and out-of-band vertices, zero area,
// culled windings) in a target with a scissor.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "edgewise/coverage.hpp"
#include "isa_params.hpp"
#include "random.hpp"

namespace edgewise::test {
namespace {

constexpr std::int32_t kWidth = 1000, kHeight = 600;

struct Triangles {
  std::vector<Vec2> vertices;
  std::vector<std::uint32_t> indices;
};

// Random triangles of sizes from below a pixel to `max_size`, a few of them bad.
Triangles random_triangles(std::uint64_t seed, int count, double max_size) {
  Random random(seed);
  Triangles out;
  for (int t = 0; t < count; ++t) {
    const double cx = random.uniform(-100.0, kWidth + 100.0);
    const double cy = random.uniform(-100.0, kHeight + 100.0);
    const double size = random.log_uniform(0.3, max_size);
    for (int i = 0; i < 3; ++i) {
      out.vertices.push_back({static_cast<float>(cx + random.uniform(-size, size)),
                              static_cast<float>(cy + random.uniform(-size, size))});
    }
    Vec2* v = &out.vertices[out.vertices.size() - 3];
    if (random.chance(0.01)) v[1].x = std::numeric_limits<float>::quiet_NaN();
    if (random.chance(0.01)) v[2].y = 40000.0f;  // outside the guard band
    if (random.chance(0.02)) v[2] = v[0];        // zero area
  }
  const std::uint32_t n = static_cast<std::uint32_t>(out.vertices.size());
  for (std::uint32_t c = 0; c < n; ++c)
    out.indices.push_back(random.chance(0.005) ? n + 7 : n - 1 - c);  // reversed, a few bad
  return out;
}

struct Counted {
  CoverageCount count;
  std::vector<TriangleStatus> statuses;
};

Counted count(Isa isa, const Triangles& triangles, bool indexed, CullMode cull, std::size_t threads,
              const TaskExecutor& executor = {}, int samples = 1) {
  Counted out;
  out.statuses.resize((indexed ? triangles.indices.size() : triangles.vertices.size()) / 3);
  RasterOptions options;
  options.isa = isa;
  options.cull = cull;
  options.statuses = out.statuses;
  options.threads = threads;
  options.executor = executor;
  options.samples = samples;
  const RasterTarget target{kWidth, kHeight, PixelRect{5, 3, 990, 597}};
  out.count = count_coverage(triangles.vertices,
                             indexed ? std::span<const std::uint32_t>(triangles.indices)
                                     : std::span<const std::uint32_t>(),
                             target, options);
  return out;
}

void expect_same(const Counted& one, const Counted& many, const std::string& what) {
  EXPECT_EQ(one.count.pixels, many.count.pixels) << what;
  const RasterReport& a = one.count.report;
  const RasterReport& b = many.count.report;
  EXPECT_EQ(a.triangles, b.triangles) << what;
  EXPECT_EQ(a.drawn, b.drawn) << what;
  EXPECT_EQ(a.culled, b.culled) << what;
  EXPECT_EQ(a.errors, b.errors) << what;
  EXPECT_EQ(a.first_error_triangle, b.first_error_triangle) << what;
  EXPECT_EQ(a.first_error, b.first_error) << what;
  EXPECT_EQ(a.isa, b.isa) << what;
  EXPECT_TRUE(one.statuses == many.statuses) << what << ": statuses differ";
}

using CoverageThreads = IsaTest;

// Enough triangles for several binning ranges (over 2048 each,
// kernels/coverage/triangle_binning.hpp); smaller ones for the reference, which evaluates every
// pixel of a triangle's box (the tsan stage of tools/check runs these tests about 20 times slower).
Triangles triangles_for(Isa isa, std::uint64_t seed) {
  return isa == Isa::reference ? random_triangles(seed, 6000, 150.0)
                               : random_triangles(seed, 12000, 400.0);
}

TEST_P(CoverageThreads, CountCoverageIsTheSameForEveryThreadCount) {
  const Triangles triangles = triangles_for(isa(), 21);
  for (bool indexed : {false, true}) {
    for (CullMode cull : {CullMode::none, CullMode::counter_clockwise}) {
      const Counted one = count(isa(), triangles, indexed, cull, 1);
      EXPECT_GT(one.count.report.errors, 0u);
      if (!indexed || cull != CullMode::none) {
        EXPECT_GT(one.count.report.culled, 0u);
      }
      for (std::size_t threads : {2, 3, 8}) {
        expect_same(one, count(isa(), triangles, indexed, cull, threads),
                    std::to_string(threads) + " threads, indexed " + std::to_string(indexed) +
                        ", cull " + std::string(name_of(cull)));
      }
    }
  }
}

// Binning widens a multisampled triangle's box by the samples' reach: a triangle whose centres
// miss a bin may still cover samples in it.
TEST_P(CoverageThreads, MultisampleCountIsTheSameForEveryThreadCount) {
  const Triangles triangles = isa() == Isa::reference ? random_triangles(23, 2500, 40.0)
                                                      : random_triangles(23, 5000, 150.0);
  for (int samples : {4, 16}) {
    const Counted one = count(isa(), triangles, false, CullMode::none, 1, {}, samples);
    EXPECT_GT(one.count.pixels, 0u);
    for (std::size_t threads : {2, 3, 8}) {
      expect_same(one, count(isa(), triangles, false, CullMode::none, threads, {}, samples),
                  std::to_string(threads) + " threads, " + std::to_string(samples) + " samples");
    }
  }
}

TEST_P(CoverageThreads, CallersExecutorCountsTheSame) {
  const Triangles triangles = triangles_for(isa(), 22);
  std::size_t runs = 0;
  const TaskExecutor reversed = [&](std::size_t n, const std::function<void(std::size_t)>& task) {
    ++runs;
    for (std::size_t i = n; i-- > 0;)
      task(i);
  };
  const Counted one = count(isa(), triangles, true, CullMode::none, 1, reversed);
  EXPECT_EQ(runs, 0u);
  expect_same(one, count(isa(), triangles, true, CullMode::none, 5, reversed), "reversed");
  EXPECT_EQ(runs, 2u);
}

// rasterize() ignores the thread count: one thread delivers every tile, the caller's, in order.
class RecordingSink : public CoverageSink {
 public:
  std::vector<TileCoverage> tiles;
  bool other_thread = false;
  void consume(std::span<const TileCoverage> batch) override {
    other_thread = other_thread || std::this_thread::get_id() != caller_;
    tiles.insert(tiles.end(), batch.begin(), batch.end());
  }

 private:
  std::thread::id caller_ = std::this_thread::get_id();
};

TEST_P(CoverageThreads, RasterizeDeliversOnTheCallingThreadInOrder) {
  const Triangles triangles = random_triangles(23, 2000, 100.0);
  const RasterTarget target{kWidth, kHeight, {}};
  RasterOptions options;
  options.isa = isa();
  options.threads = 1;
  RecordingSink one;
  rasterize(triangles.vertices, {}, target, options, one);
  options.threads = 8;
  RecordingSink eight;
  rasterize(triangles.vertices, {}, target, options, eight);
  EXPECT_FALSE(eight.other_thread);
  ASSERT_EQ(one.tiles.size(), eight.tiles.size());
  for (std::size_t i = 0; i < one.tiles.size(); ++i) {
    EXPECT_TRUE(one.tiles[i].triangle == eight.tiles[i].triangle &&
                one.tiles[i].tile_x == eight.tiles[i].tile_x &&
                one.tiles[i].tile_y == eight.tiles[i].tile_y &&
                one.tiles[i].mask == eight.tiles[i].mask)
        << "tile " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Isas, CoverageThreads, ::testing::ValuesIn(every_isa()), isa_test_name);

}  // namespace
}  // namespace edgewise::test
