// Random large triangles, clipped and mapped to the screen, never leave the rasterizer's guard
// band (so it never reports an error) and never cover a pixel outside the viewport, whatever the
// viewport size: the guard-band planes and their margin (clip.cpp) hold on every ISA.
#include <gtest/gtest.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "clipped_mesh.hpp"
#include "coverage_result.hpp"
#include "isa_params.hpp"
#include "random.hpp"

namespace edgewise::test {
namespace {

constexpr int kTrianglesPerViewport = 1000;
constexpr std::uint64_t kGuardBandSeed = 0x9a4d'b4d5'11a7ull;

// clip.cpp's bound: |screen coordinate| <= G + 0.0118 px with G = kGuardBand - kGuardBandMargin.
constexpr double kScreenBound = kGuardBand - double{kGuardBandMargin} + 0.0118;

struct TargetSetup {
  Viewport viewport;
  std::optional<PixelRect> scissor;  // where a full-size target would cost too much to walk
};

// Vertices up to 1e6 times their w off axis, w of both signs over twelve orders of magnitude.
Vec4 random_vertex(Random& random) {
  const double w = random.sign() * random.log_uniform(1e-4, 1e8);
  const auto lateral = [&] { return w * random.sign() * random.log_uniform(1e-3, 1e6); };
  return {static_cast<float>(lateral()), static_cast<float>(lateral()),
          static_cast<float>(w * random.uniform(-0.5, 1.5)), static_cast<float>(w)};
}

using ClipGuardBand = IsaTest;

TEST_P(ClipGuardBand, ClippedTrianglesStayInsideTheGuardBandAndViewport) {
  const TargetSetup setups[] = {
      {{96, 80}, {}},
      {{1, 1}, {}},
      {{7, 3000}, {}},
      // The largest target: the guard-band planes lie 1/16 px inside its right and bottom sides.
      {{kMaxTargetSize, kMaxTargetSize},
       PixelRect{kMaxTargetSize - 40, kMaxTargetSize - 40, kMaxTargetSize, kMaxTargetSize}},
      {{kMaxTargetSize, kMaxTargetSize}, PixelRect{0, 0, 40, 40}},
  };
  Random random(kGuardBandSeed);
  double largest = 0;
  std::uint64_t drawn = 0, pixels = 0;
  for (const TargetSetup& setup : setups) {
    const Viewport& vp = setup.viewport;
    std::vector<Vec4> vertices;
    for (int i = 0; i < 3 * kTrianglesPerViewport; ++i)
      vertices.push_back(random_vertex(random));
    std::vector<std::uint32_t> indices(vertices.size());
    for (std::uint32_t i = 0; i < indices.size(); ++i)
      indices[i] = i;
    const ClippedMesh mesh = clip_mesh(vertices, indices, vp);

    for (const ScreenVertex& v : mesh.screen) {
      largest = std::max({largest, std::fabs(double{v.x}), std::fabs(double{v.y})});
      ASSERT_LE(std::fabs(v.x), kScreenBound);
      ASSERT_LE(std::fabs(v.y), kScreenBound);
      ASSERT_TRUE(v.z >= 0.0f && v.z <= 1.0f) << v.z;
      ASSERT_TRUE(std::isfinite(v.inv_w) && v.inv_w > 0.0f) << v.inv_w;
    }

    const RasterCall call{mesh.positions, {}, RasterTarget{vp.width, vp.height, setup.scissor}};
    const RasterRun run = run_checked(isa(), call);  // well formed: no pixel outside the target
    ASSERT_FALSE(::testing::Test::HasFailure());
    for (std::size_t t = 0; t < run.statuses.size(); ++t) {
      ASSERT_FALSE(is_error(run.statuses[t])) << describe(run.statuses[t]) << "\n"
                                              << describe_triangle(call, t);
    }
    drawn += run.report.drawn;
    pixels += covered_pixels(run).size();
  }
  // The triangles must really reach the guard band and the screen.
  EXPECT_GT(largest, kGuardBand - 1.0);
  EXPECT_GT(pixels, 1000u);
  std::printf("[ %-8s ] %" PRIu64 " triangles drawn, %" PRIu64
              " pixels, largest |screen coordinate| %.6f (bound %.6f)\n",
              std::string(name_of(isa())).c_str(), drawn, pixels, largest, kScreenBound);
}

EDGEWISE_INSTANTIATE_PER_ISA(ClipGuardBand, every_isa());

}  // namespace
}  // namespace edgewise::test
