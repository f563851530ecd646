// Differential tests: random triangles from every generator of triangle_sources.cpp, drawn by
// each fast ISA and by the reference, must give bit-identical tile masks, statuses and report
// counts.
//
// Budget: EDGEWISE_FUZZ_ITERS triangles per ISA over all generators (default 1,000,000), split
// by each generator's share; each generator is its own test so `ctest -j` runs them side by
// side. Under qemu (the AArch64/NEON run) everything is ~10x slower, so that run may set a
// smaller EDGEWISE_FUZZ_ITERS; a longer local soak sets a larger one.
// Seed: EDGEWISE_FUZZ_SEED (default fixed, so runs are reproducible); a failure prints the seed,
// the command line that replays it, and the first differing triangle with its tiles.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "coverage_result.hpp"
#include "env_number.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "triangle_sources.hpp"

namespace edgewise::test {
namespace {

constexpr std::uint64_t kDefaultBudget = 1'000'000;
constexpr std::uint64_t kDefaultSeed = 0x5eed'ed9e'0001ull;
constexpr std::size_t kBatchSize = 512;
constexpr int kMaxReportedMismatches = 3;

// FNV-1a: a stream per generator name, the same on every platform.
std::uint64_t name_hash(std::string_view name) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (char c : name)
    h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
  return h;
}

const TriangleSource& source_named(std::string_view name) {
  for (const TriangleSource& source : triangle_sources()) {
    if (source.name == name) return source;
  }
  throw std::logic_error("no triangle source named " + std::string(name));
}

// A scissor for one batch: a small window (sources of huge triangles, so the reference stays
// cheap), or sometimes a random one, possibly empty or reaching outside the target.
std::optional<PixelRect> batch_scissor(Random& random, const TriangleSource& source) {
  const RasterTarget& t = source.target;
  if (source.window > 0) {
    const std::int32_t w = static_cast<std::int32_t>(random.integer(1, source.window));
    const std::int32_t h = static_cast<std::int32_t>(random.integer(1, source.window));
    const std::int32_t x = static_cast<std::int32_t>(random.integer(0, t.width - w));
    const std::int32_t y = static_cast<std::int32_t>(random.integer(0, t.height - h));
    return PixelRect{x, y, x + w, y + h};
  }
  if (!random.chance(0.3)) return std::nullopt;
  const auto span = [&random](std::int32_t size) {
    const std::int32_t lo = static_cast<std::int32_t>(random.integer(-8, size));
    return std::pair{lo, static_cast<std::int32_t>(random.integer(lo, lo + size))};
  };
  const auto [x0, x1] = span(t.width);
  const auto [y0, y1] = span(t.height);
  return PixelRect{x0, y0, x1, y1};
}

// count_coverage() on one thread against the reference's masks (of every sample, with
// samples): the whole call's count, and with `per_triangle` each triangle's count from a call of
// its own.
::testing::AssertionResult same_counts(const RasterCall& call, const RasterRun& expected, Isa isa,
                                       bool per_triangle) {
  RasterOptions options;
  options.isa = isa;
  options.threads = 1;
  options.cull = call.cull;
  options.samples = call.samples;
  std::vector<std::uint64_t> pixels(expected.statuses.size());
  std::uint64_t total = 0;
  for (const TileCoverage& tile : expected.tiles) {
    pixels[tile.triangle] += static_cast<std::uint64_t>(std::popcount(tile.mask));
    total += static_cast<std::uint64_t>(std::popcount(tile.mask));
  }
  const std::uint64_t counted =
      count_coverage(call.vertices, call.indices, call.target, options).pixels;
  if (counted != total) {
    return ::testing::AssertionFailure()
           << "count_coverage: " << counted << " pixels, reference " << total << "\n";
  }
  if (!per_triangle) return ::testing::AssertionSuccess();
  for (std::size_t t = 0; t < pixels.size(); ++t) {
    const std::uint64_t one =
        call.indices.empty()
            ? count_coverage(call.vertices.subspan(3 * t, 3), {}, call.target, options).pixels
            : count_coverage(call.vertices, call.indices.subspan(3 * t, 3), call.target, options)
                  .pixels;
    if (one != pixels[t]) {
      return ::testing::AssertionFailure() << "count_coverage of triangle " << t << ": " << one
                                           << " pixels, reference " << pixels[t] << "\n";
    }
  }
  return ::testing::AssertionSuccess();
}

// `samples` per pixel (RasterOptions::samples) on a `fraction` of the source's share of the
// budget.
void run_differential(Isa isa, std::string_view source_name, int samples = 1,
                      double fraction = 1.0) {
  const TriangleSource& source = source_named(source_name);
  const std::uint64_t budget = env_number("EDGEWISE_FUZZ_ITERS", kDefaultBudget);
  const std::uint64_t seed = env_number("EDGEWISE_FUZZ_SEED", kDefaultSeed);
  const std::uint64_t count =
      static_cast<std::uint64_t>(static_cast<double>(budget) * source.share * fraction);
  const std::string replay = "EDGEWISE_FUZZ_SEED=" + std::to_string(seed) +
                             " EDGEWISE_FUZZ_ITERS=" + std::to_string(budget) +
                             " edgewise_coverage_tests --gtest_filter=Differential." +
                             ::testing::UnitTest::GetInstance()->current_test_info()->name();
  // Each generator has its own stream, independent of the others' shares.
  Random random(seed ^ name_hash(source.name) ^ static_cast<std::uint64_t>(samples - 1));

  std::vector<Vec2> vertices;
  std::vector<std::uint32_t> indices;
  std::uint64_t drawn = 0, covered = 0, mismatches = 0;
  for (std::uint64_t done = 0; done < count;) {
    const std::size_t n =
        static_cast<std::size_t>(std::min<std::uint64_t>(kBatchSize, count - done));
    RasterTarget target = source.target;
    target.scissor = batch_scissor(random, source);
    const PixelRect aim = clip_rect(target).empty() ? clip_rect(source.target) : clip_rect(target);
    vertices.resize(3 * n);
    for (std::size_t t = 0; t < n; ++t) {
      Vec2 tri[3];
      source.make(random, aim, tri);
      std::copy(tri, tri + 3, vertices.begin() + static_cast<std::ptrdiff_t>(3 * t));
    }
    // Half the batches are indexed, through a reversed copy of the vertex array.
    indices.clear();
    if (random.chance(0.5)) {
      std::reverse(vertices.begin(), vertices.end());
      for (std::size_t i = 0; i < 3 * n; ++i)
        indices.push_back(static_cast<std::uint32_t>(3 * n - 1 - i));
    }
    const CullMode culls[] = {CullMode::none, CullMode::none, CullMode::clockwise,
                              CullMode::counter_clockwise};
    const RasterCall call{vertices, indices, target, culls[random.integer(0, 3)], samples};

    const RasterRun expected = run_raster(Isa::reference, call);
    const RasterRun actual = run_raster(isa, call);
    const ::testing::AssertionResult same = same_coverage(call, expected, actual);
    const ::testing::AssertionResult sane = well_formed(call, actual);
    // count_coverage() takes paths of its own (the span walk's counts, without masks): its
    // count must be the reference's, for the batch and, in every 16th batch, per triangle.
    const ::testing::AssertionResult counted =
        same_counts(call, expected, isa, done / kBatchSize % 16 == 0);
    if (!same || !sane || !counted) {
      ADD_FAILURE() << "seed " << seed << ", source " << source.name << ", triangles " << done
                    << ".." << done + n - 1 << "\nreplay: " << replay << "\n"
                    << (same ? "" : same.message()) << (sane ? "" : sane.message())
                    << (counted ? "" : counted.message());
      if (++mismatches == kMaxReportedMismatches) return;
    }
    drawn += expected.report.drawn;
    for (const TileCoverage& tile : expected.tiles)
      covered += static_cast<std::uint64_t>(std::popcount(tile.mask));
    done += n;
  }
  // Guard against a generator that silently stopped producing work.
  if (count >= 1000) {
    EXPECT_GT(drawn, count / 20) << "source " << source.name << " draws almost nothing";
    EXPECT_GT(covered, 0u) << "source " << source.name << " covers nothing";
  }
  std::printf("[ %-8s ] %s, %d sample(s): %" PRIu64 " triangles (%" PRIu64 " drawn, %" PRIu64
              " samples covered), seed %" PRIu64 "\n",
              std::string(name_of(isa)).c_str(), std::string(source.name).c_str(), samples, count,
              drawn, covered, seed);
}

// Every sample of the multisample patterns: the reference decides each sample pixel by pixel,
// so each pattern takes 1 / (10 n) of each source's budget (a fortieth at 4x): every pattern then
// costs the reference the same number of sample decisions.
void run_multisample_differential(Isa isa, int samples) {
  for (const TriangleSource& source : triangle_sources())
    run_differential(isa, source.name, samples, 1.0 / (10.0 * samples));
}

using Differential = IsaTest;

TEST_P(Differential, Uniform) {
  run_differential(isa(), "uniform");
}
TEST_P(Differential, Tiny) {
  run_differential(isa(), "tiny");
}
TEST_P(Differential, Huge) {
  run_differential(isa(), "huge");
}
TEST_P(Differential, Slivers) {
  run_differential(isa(), "slivers");
}
TEST_P(Differential, NearAxis) {
  run_differential(isa(), "near_axis");
}
TEST_P(Differential, Ties) {
  run_differential(isa(), "ties");
}
TEST_P(Differential, GuardBand) {
  run_differential(isa(), "guard_band");
}
TEST_P(Differential, Multisample2) {
  run_multisample_differential(isa(), 2);
}
TEST_P(Differential, Multisample4) {
  run_multisample_differential(isa(), 4);
}
TEST_P(Differential, Multisample8) {
  run_multisample_differential(isa(), 8);
}
TEST_P(Differential, Multisample16) {
  run_multisample_differential(isa(), 16);
}

// The span walk (boxes of 576 pixels or more) orders a triangle's edges by kind: two left and
// one right, one left and two right, or one of each and a horizontal edge. Triangles of each
// set, in both windings, with vertices on pixel centres, tile corners and random positions
// (so that edges pass exactly through samples and horizontal edges lie on sample rows), must
// give the reference's masks and pixel count.
TEST_P(Differential, SpanWalkEdgeSets) {
  Random random(0x5a4e'ed6e'5e75);
  const RasterTarget target{256, 256, std::nullopt};
  const auto coordinate = [&random](double lo, double hi) {
    switch (random.integer(0, 2)) {
      case 0:
        return std::floor(random.uniform(lo, hi)) + 0.5;  // a pixel centre
      case 1:
        return 8.0 * std::floor(random.uniform(lo, hi) / 8.0);  // a tile corner
      default:
        return random.uniform(lo, hi);
    }
  };
  std::vector<Vec2> vertices;
  for (int t = 0; t < 3000; ++t) {
    Vec2 tri[3];
    for (Vec2& v : tri)
      v = {static_cast<float>(coordinate(0, 256)), static_cast<float>(coordinate(0, 256))};
    if (t % 3 == 0) tri[1].y = tri[0].y;  // a horizontal edge
    if (t % 2 == 0) std::swap(tri[1], tri[2]);
    vertices.insert(vertices.end(), tri, tri + 3);
  }
  const RasterCall call{vertices, {}, target, CullMode::none};
  const RasterRun expected = run_raster(Isa::reference, call);
  const RasterRun actual = run_raster(isa(), call);
  EXPECT_TRUE(same_coverage(call, expected, actual));
  EXPECT_TRUE(well_formed(call, actual));
  RasterOptions options;
  options.isa = isa();
  options.threads = 1;
  const std::uint64_t counted = count_coverage(vertices, {}, target, options).pixels;
  EXPECT_EQ(counted, covered_pixels(expected).size());
  // The set is meant for the span walk: most boxes are large enough for it.
  EXPECT_GT(expected.tiles.size(), 3000u * 8u);
}

// The span walk's integer edge stepping admits an edge while its first covered column stays
// within 2^29 of the origin on every row the walk visits, and needs |a| >= 4 (an edge rising
// 4/256 px or more) where the tile walk's int32 bound stands in for that check. Edges rising
// 1 to 8 steps over up to 16384 px, in boxes up to 8192 rows tall, with apexes on either side,
// straddle both limits; a window keeps the reference cheap. Masks and counts must match.
TEST_P(Differential, SpanWalkNearItsLimits) {
  Random random(0x5a4e'0111'0175);
  const float step = 1.0f / 256.0f;
  std::vector<Vec2> vertices;
  for (int t = 0; t < 600; ++t) {
    const float x0 = static_cast<float>(random.integer(0, 8192)) + step * random.integer(0, 255);
    const float y0 = static_cast<float>(random.integer(0, 8192)) + step * random.integer(0, 255);
    const float run = static_cast<float>(random.integer(16, 16384));
    const float rise = step * static_cast<float>(random.integer(1, 8));
    const float height =
        static_cast<float>(random.integer(8, 8192)) * (random.chance(0.5) ? 1 : -1);
    Vec2 tri[3] = {{x0, y0},
                   {x0 + run, y0 + rise},
                   {x0 + static_cast<float>(random.uniform(-run, 2 * run)), y0 + height}};
    if (random.chance(0.5)) std::swap(tri[1], tri[2]);
    vertices.insert(vertices.end(), tri, tri + 3);
  }
  for (int window = 0; window < 40; ++window) {
    RasterTarget target{kMaxTargetSize, kMaxTargetSize, std::nullopt};
    // Windows on the triangles' long edges and near their apexes.
    const Vec2& at = vertices[static_cast<std::size_t>(random.integer(0, 3 * 600 - 1))];
    const std::int32_t x = std::clamp(static_cast<std::int32_t>(at.x) - 32, 0, kMaxTargetSize - 96);
    const std::int32_t y = std::clamp(static_cast<std::int32_t>(at.y) - 32, 0, kMaxTargetSize - 96);
    target.scissor = PixelRect{x, y, x + 96, y + 96};
    const RasterCall call{vertices, {}, target, CullMode::none};
    const RasterRun expected = run_raster(Isa::reference, call);
    const RasterRun actual = run_raster(isa(), call);
    EXPECT_TRUE(same_coverage(call, expected, actual));
    EXPECT_TRUE(same_counts(call, expected, isa(), window % 4 == 0));
  }
}

TEST(DifferentialSources, SharesCoverTheBudget) {
  double total = 0;
  for (const TriangleSource& source : triangle_sources())
    total += source.share;
  EXPECT_NEAR(total, 1.0, 1e-9);
}

EDGEWISE_INSTANTIATE_PER_ISA(Differential, fast_isas());

}  // namespace
}  // namespace edgewise::test
