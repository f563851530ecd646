// Depth kept as planes (kernels/draw/shading/plane_tiles.hpp) against draw(): occluders in the
// orders that keep tiles as planes (nearest last, each wholly in front of the last), that break
// them (nearest first) and at random, flat and tilted, in several calls, with copied depth and
// the reference's draws in between; the buffer's every value and draw()'s counts bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "edgewise/draw.hpp"
#include "edgewise/occlusion.hpp"
#include "isa_params.hpp"
#include "occlusion/occlusion_scenes.hpp"
#include "random.hpp"

namespace edgewise::test {
namespace {

enum class Order { nearest_last, nearest_first, as_made };

// Triangles of `soup` (after its two backdrop triangles) reordered by their mean depth; flat ones
// (each vertex at the mean) with `flatten`.
std::vector<Vec3> ordered(const OccluderSoup& soup, Order order, bool flatten) {
  const std::size_t triangles = soup.positions.size() / 3;
  std::vector<std::size_t> sequence(triangles);
  std::iota(sequence.begin(), sequence.end(), std::size_t{0});
  const auto mean = [&](std::size_t t) {
    return (soup.positions[3 * t].z + soup.positions[3 * t + 1].z + soup.positions[3 * t + 2].z) /
           3.0f;
  };
  if (order != Order::as_made) {
    std::stable_sort(sequence.begin() + 2, sequence.end(), [&](std::size_t a, std::size_t b) {
      return order == Order::nearest_last ? mean(a) > mean(b) : mean(a) < mean(b);
    });
  }
  std::vector<Vec3> out;
  for (const std::size_t t : sequence) {
    for (int i = 0; i < 3; ++i) {
      Vec3 v = soup.positions[3 * t + i];
      if (flatten) v.z = mean(t);
      out.push_back(v);
    }
  }
  return out;
}

// The buffer's values and draw()'s depth, compared bit for bit.
void expect_same_depth(const OcclusionBuffer& buffer, const Framebuffer& drawn,
                       const std::string& what) {
  std::vector<float> want(static_cast<std::size_t>(drawn.width()) * drawn.height());
  std::vector<float> got(want.size());
  drawn.read_depth(want);
  buffer.read_depth(got);
  for (std::size_t i = 0; i < want.size(); ++i) {
    ASSERT_EQ(std::bit_cast<std::uint32_t>(got[i]), std::bit_cast<std::uint32_t>(want[i]))
        << what << ": pixel (" << i % drawn.width() << ", " << i / drawn.width() << ")";
  }
}

class PlaneDepth : public IsaTest {
 protected:
  // The occluders in `calls` draw_occluders() calls against as many draw() calls.
  void check(const std::vector<Vec3>& positions, std::int32_t width, std::int32_t height,
             std::size_t calls, std::size_t threads, const std::string& what) {
    OcclusionBuffer buffer(width, height);
    Framebuffer drawn(width, height);
    drawn.clear({0.0f, 0.0f, 0.0f, 1.0f}, 1.0f);
    OcclusionOptions options;
    options.isa = isa();
    options.threads = threads;
    DrawOptions draw_options;
    draw_options.isa = isa();
    draw_options.threads = 1;
    const std::size_t triangles = positions.size() / 3;
    for (std::size_t c = 0; c < calls; ++c) {
      const std::size_t first = 3 * (triangles * c / calls);
      const std::size_t last = 3 * (triangles * (c + 1) / calls);
      const std::span<const Vec3> part(positions.data() + first, last - first);
      const DrawReport got = buffer.draw_occluders({part, {}}, options);
      const DrawReport want = draw(drawn, {part, {}, {}, {}}, draw_options);
      EXPECT_EQ(got.fragments, want.fragments) << what << ", call " << c;
      EXPECT_EQ(got.fragments_passed, want.fragments_passed) << what << ", call " << c;
      EXPECT_EQ(got.rasterized, want.rasterized) << what << ", call " << c;
    }
    expect_same_depth(buffer, drawn, what);
  }
};

TEST_P(PlaneDepth, EveryOrderEqualsDraw) {
  Random random(2027);
  for (int scene = 0; scene < 24; ++scene) {
    const OccluderSoup soup = random_occluders(random, 20 + 40 * (scene % 6));
    const bool flatten = scene % 2 == 0;
    for (const Order order : {Order::nearest_last, Order::nearest_first, Order::as_made}) {
      const std::string what = "scene " + std::to_string(scene) + ", order " +
                               std::to_string(static_cast<int>(order)) +
                               (flatten ? ", flat" : ", tilted");
      const std::vector<Vec3> positions = ordered(soup, order, flatten);
      // Sides that are not multiples of the tile, so that the last tiles are partly outside.
      check(positions, 96, 64, 1 + scene % 4, 1, what);
      check(positions, 77, 45, 2, 3, what + ", 77x45, 3 threads");
    }
  }
}

// Nearest last at the fill-rate protocol's sizes: tiles whole and in part under each triangle,
// slots filling and freeing; larger than the other scenes, so that triangles cover many tiles.
TEST_P(PlaneDepth, NearestLastAtManySizesEqualsDraw) {
  Random random(31);
  std::vector<Vec3> positions;
  const int count = 400;
  for (int t = 0; t < count; ++t) {
    const double size = random.log_uniform(0.005, 0.6);
    const double cx = random.uniform(-1.0, 1.0), cy = random.uniform(-1.0, 1.0);
    const double z = 1.0 - (t + 1.0) / (count + 1.0);
    const double tilt = random.chance(0.5) ? 0.0 : random.uniform(-0.3, 0.3) / count;
    for (int i = 0; i < 3; ++i) {
      const double dx = size * random.uniform(-1.0, 1.0), dy = size * random.uniform(-1.0, 1.0);
      positions.push_back({static_cast<float>(cx + dx), static_cast<float>(cy + dy),
                           static_cast<float>(z + tilt * (dx + dy))});
    }
  }
  check(positions, 320, 200, 1, 1, "one call");
  check(positions, 320, 200, 3, 2, "three calls, two threads");
}

// A tilted triangle drawn over a flat one at depth d, its depths a few units in the last place
// from d or straddling it: whether each pixel passes is decided by the rounding of the depth
// formula, which the planes' bounds must allow for (shade_occluder-inl.hpp).
TEST_P(PlaneDepth, NearlyTouchingDepthsEqualDraw) {
  Random random(77);
  constexpr std::int32_t kSide = 40;
  for (int trial = 0; trial < 3000; ++trial) {
    const float d = static_cast<float>(random.uniform(0.05, 0.95));
    std::vector<Vec3> positions = {{-3.0f, -3.0f, d}, {3.0f, -3.0f, d}, {0.0f, 3.0f, d}};
    // Below d by 1 to 3 units in the last place at its nearest vertex, or straddling d.
    const bool straddles = random.chance(0.3);
    float top = d;
    for (int steps = static_cast<int>(random.integer(1, 3)); steps > 0; --steps)
      top = std::nextafter(top, 0.0f);
    const double spread = random.log_uniform(1e-7, straddles ? 1e-2 : d);
    const double cx = random.uniform(-0.5, 0.5), cy = random.uniform(-0.5, 0.5);
    const double size = random.log_uniform(0.05, 1.5);
    const std::int64_t nearest = random.integer(0, 2);
    // The nearest vertex on a pixel centre now and then: there the formula's rounding alone
    // decides against d.
    const bool centred = random.chance(0.5);
    for (int i = 0; i < 3; ++i) {
      const double below = i == nearest ? 0.0 : random.uniform(0.0, spread);
      const double z = straddles ? d + random.uniform(-spread, spread) : top - below;
      double x = cx + size * random.uniform(-1.0, 1.0), y = cy + size * random.uniform(-1.0, 1.0);
      if (centred && i == nearest) {
        const double half = kSide / 2.0;
        x = (std::floor((x + 1.0) * half) + 0.5) / half - 1.0;
        y = (std::floor((y + 1.0) * half) + 0.5) / half - 1.0;
      }
      positions.push_back({static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)});
    }
    check(positions, kSide, kSide, 1 + trial % 2, 1, "trial " + std::to_string(trial));
    if (HasFatalFailure() || HasNonfatalFailure()) return;
  }
}

// Depth from elsewhere (copied, or drawn by the reference) in between SIMD draws: tiles held as
// values and as planes side by side.
TEST_P(PlaneDepth, CopiedAndReferenceDepthInBetween) {
  Random random(5);
  const OccluderSoup first = random_occluders(random, 120);
  const OccluderSoup second = random_occluders(random, 120);
  const std::vector<Vec3> a = ordered(first, Order::nearest_last, true);
  const std::vector<Vec3> b = ordered(second, Order::nearest_last, false);
  constexpr std::int32_t kW = 96, kH = 64;
  Framebuffer drawn(kW, kH);
  drawn.clear({0.0f, 0.0f, 0.0f, 1.0f}, 1.0f);
  DrawOptions draw_options;
  draw_options.isa = isa();
  draw(drawn, {a, {}, {}, {}}, draw_options);

  OcclusionOptions options;
  options.isa = isa();
  OcclusionBuffer buffer(kW, kH);
  buffer.draw_occluders({b, {}}, options);  // planes, then replaced by the copy
  buffer.copy_depth(drawn, options);
  buffer.draw_occluders({b, {}}, options);
  draw(drawn, {b, {}, {}, {}}, draw_options);
  expect_same_depth(buffer, drawn, "after the copy");

  OcclusionOptions by_reference = options;
  by_reference.isa = Isa::reference;
  buffer.draw_occluders({a, {}}, by_reference);
  buffer.draw_occluders({b, {}}, options);
  draw(drawn, {a, {}, {}, {}}, draw_options);
  draw(drawn, {b, {}, {}, {}}, draw_options);
  expect_same_depth(buffer, drawn, "after the reference's draw");

  buffer.clear();
  drawn.clear({0.0f, 0.0f, 0.0f, 1.0f}, 1.0f);
  buffer.draw_occluders({b, {}}, options);
  draw(drawn, {b, {}, {}, {}}, draw_options);
  expect_same_depth(buffer, drawn, "after clear()");
}

EDGEWISE_INSTANTIATE_PER_ISA(PlaneDepth, every_isa());

}  // namespace
}  // namespace edgewise::test
