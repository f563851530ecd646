// The standard sample patterns (edgewise/multisample.hpp) and the per-sample coverage reference:
// the patterns against the fractional positions the standards print, watertightness per sample
// on meshes, and agreement with the pixel-centre rule and with the exact-area reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "edgewise/multisample.hpp"
#include "random.hpp"
#include "antialiasing/pixel_area_reference.hpp"

namespace edgewise::test {
namespace {

using reference::covers_sample;
using reference::SnappedTriangle;

constexpr int kCounts[] = {1, 2, 4, 8, 16};

TEST(SamplePattern, CountsWithAPattern) {
  for (int samples : kCounts) {
    EXPECT_TRUE(is_standard_sample_count(samples));
    EXPECT_EQ(standard_sample_pattern(samples).size(), static_cast<std::size_t>(samples));
  }
  for (int samples : {-1, 0, 3, 5, 6, 32, 64}) {
    EXPECT_FALSE(is_standard_sample_count(samples));
    EXPECT_THROW(standard_sample_pattern(samples), std::invalid_argument);
  }
}

// The positions as fractions of the pixel (x right, y down from its top-left corner), as
// Vulkan's table of standard sample locations prints them, in sample order.
TEST(SamplePattern, MatchesTheStandardPositionsInPixelFractions) {
  const std::vector<std::vector<std::pair<double, double>>> standard = {
      {{0.5, 0.5}},
      {{0.75, 0.75}, {0.25, 0.25}},
      {{0.375, 0.125}, {0.875, 0.375}, {0.125, 0.625}, {0.625, 0.875}},
      {{0.5625, 0.3125},
       {0.4375, 0.6875},
       {0.8125, 0.5625},
       {0.3125, 0.1875},
       {0.1875, 0.8125},
       {0.0625, 0.4375},
       {0.6875, 0.9375},
       {0.9375, 0.0625}},
      {{0.5625, 0.5625},
       {0.4375, 0.3125},
       {0.3125, 0.625},
       {0.75, 0.4375},
       {0.1875, 0.375},
       {0.625, 0.8125},
       {0.8125, 0.6875},
       {0.6875, 0.1875},
       {0.375, 0.875},
       {0.5, 0.0625},
       {0.25, 0.125},
       {0.125, 0.75},
       {0.0, 0.5},
       {0.9375, 0.25},
       {0.875, 0.9375},
       {0.0625, 0.0}}};
  for (std::size_t c = 0; c < standard.size(); ++c) {
    const auto pattern = standard_sample_pattern(kCounts[c]);
    ASSERT_EQ(pattern.size(), standard[c].size());
    std::set<std::pair<int, int>> distinct;
    for (std::size_t k = 0; k < pattern.size(); ++k) {
      EXPECT_EQ(0.5 + pattern[k].x / 16.0, standard[c][k].first) << kCounts[c] << "x sample " << k;
      EXPECT_EQ(0.5 + pattern[k].y / 16.0, standard[c][k].second) << kCounts[c] << "x sample " << k;
      distinct.insert({pattern[k].x, pattern[k].y});
    }
    EXPECT_EQ(distinct.size(), pattern.size());
  }
}

// A jittered grid of fixed-point vertices cut into triangles (each cell along a random
// diagonal, with random winding): every sample of every pixel inside the grid's interior is
// covered by exactly one triangle, for every pattern.
TEST(SampleCoverage, WatertightPerSampleOnJitteredGrids) {
  Random random(0x5a3b'0001);
  for (int trial = 0; trial < 40; ++trial) {
    constexpr int kCells = 6;
    const std::int64_t cell = random.integer(64, 700);  // fixed-point units
    const std::int64_t jitter = cell / 3;
    const std::int64_t origin_x = random.integer(-20000, 20000);
    const std::int64_t origin_y = random.integer(-20000, 20000);
    std::int64_t vx[kCells + 1][kCells + 1], vy[kCells + 1][kCells + 1];
    for (int j = 0; j <= kCells; ++j) {
      for (int i = 0; i <= kCells; ++i) {
        // Border vertices stay on the grid's straight outline.
        const bool border_x = i == 0 || i == kCells, border_y = j == 0 || j == kCells;
        vx[j][i] = origin_x + i * cell + (border_x ? 0 : random.integer(-jitter, jitter));
        vy[j][i] = origin_y + j * cell + (border_y ? 0 : random.integer(-jitter, jitter));
      }
    }
    std::vector<SnappedTriangle> mesh;
    const auto add = [&](int i0, int j0, int i1, int j1, int i2, int j2) {
      SnappedTriangle t{{vx[j0][i0], vx[j1][i1], vx[j2][i2]}, {vy[j0][i0], vy[j1][i1], vy[j2][i2]}};
      if (random.chance(0.5)) {
        std::swap(t.x[1], t.x[2]);
        std::swap(t.y[1], t.y[2]);
      }
      mesh.push_back(t);
    };
    for (int j = 0; j < kCells; ++j) {
      for (int i = 0; i < kCells; ++i) {
        if (random.chance(0.5)) {
          add(i, j, i + 1, j, i + 1, j + 1);
          add(i, j, i + 1, j + 1, i, j + 1);
        } else {
          add(i, j, i + 1, j, i, j + 1);
          add(i + 1, j, i + 1, j + 1, i, j + 1);
        }
      }
    }
    // Pixels whose square lies inside the grid's outline.
    const auto ceil_px = [](std::int64_t v) { return static_cast<std::int32_t>((v + 255) >> 8); };
    const auto floor_px = [](std::int64_t v) { return static_cast<std::int32_t>(v >> 8); };
    const PixelRect inner{ceil_px(origin_x), ceil_px(origin_y), floor_px(origin_x + kCells * cell),
                          floor_px(origin_y + kCells * cell)};
    for (int samples : kCounts) {
      const auto pattern = standard_sample_pattern(samples);
      for (std::int32_t py = inner.y0; py < inner.y1; ++py) {
        for (std::int32_t px = inner.x0; px < inner.x1; ++px) {
          for (std::size_t k = 0; k < pattern.size(); ++k) {
            int hits = 0;
            for (const SnappedTriangle& t : mesh)
              hits += covers_sample(t, px, py, pattern[k]) ? 1 : 0;
            ASSERT_EQ(hits, 1) << "trial " << trial << " pixel " << px << "," << py << " sample "
                               << k << " of " << samples;
          }
        }
      }
    }
  }
}

SnappedTriangle random_triangle(Random& random) {
  const std::int64_t x = random.integer(-30000, 30000), y = random.integer(-30000, 30000);
  const double size = random.log_uniform(1.0, 8192.0);
  SnappedTriangle t;
  for (int i = 0; i < 3; ++i) {
    t.x[i] = x + static_cast<std::int64_t>(std::llround(random.uniform(-size, size)));
    t.y[i] = y + static_cast<std::int64_t>(std::llround(random.uniform(-size, size)));
  }
  return t;
}

// One sample is the pixel centre; a square the triangle fills has every sample covered, and a
// square it misses (zero area) none of those strictly inside it (16x puts two samples on the
// square's top and left sides, which the neighbour's triangle may cover).
TEST(SampleCoverage, AgreesWithTheCentreAndTheExactArea) {
  Random random(0x5a3b'0002);
  for (int trial = 0; trial < 1500; ++trial) {
    const SnappedTriangle t = random_triangle(random);
    if ((t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) == (t.y[1] - t.y[0]) * (t.x[2] - t.x[0])) continue;
    const auto [x0, x1] = std::minmax({t.x[0], t.x[1], t.x[2]});
    const auto [y0, y1] = std::minmax({t.y[0], t.y[1], t.y[2]});
    for (std::int32_t py = static_cast<std::int32_t>(y0 >> 8) - 1; py <= (y1 >> 8) + 1; ++py) {
      for (std::int32_t px = static_cast<std::int32_t>(x0 >> 8) - 1; px <= (x1 >> 8) + 1; ++px) {
        ASSERT_EQ(covers_sample(t, px, py, standard_sample_pattern(1)[0]),
                  reference::covers(t, px, py));
        const double area = reference::pixel_area(t, px, py);
        const bool full = area > 1.0 - reference::kPixelAreaErrorBound;
        const bool empty = area == 0.0;
        if (!full && !empty) continue;
        for (int samples : kCounts) {
          for (const SampleOffset offset : standard_sample_pattern(samples)) {
            const bool on_side = offset.x == -8 || offset.y == -8;
            if (empty && on_side) continue;
            ASSERT_EQ(covers_sample(t, px, py, offset), full)
                << "trial " << trial << " pixel " << px << "," << py << " area " << area;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace edgewise::test
