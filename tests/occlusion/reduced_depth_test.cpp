// Reduced occlusion buffers (a depth per block of 2x2 or 4x4 pixels of the view): the blocks
// against their definition (each triangle drawn alone at full resolution), every ISA's blocks
// against the reference's bit for bit, and every answer against the full-resolution oracles:
// never above the full-resolution depth, never occluded where a sample shows.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "edgewise/draw.hpp"
#include "edgewise/occlusion.hpp"
#include "env_number.hpp"
#include "isa_params.hpp"
#include "occlusion/occlusion_scenes.hpp"
#include "random.hpp"

namespace edgewise::test {
namespace {

constexpr std::int32_t kReductions[] = {2, 4};
constexpr PartialCoverage kPartials[] = {PartialCoverage::ignored, PartialCoverage::merged};

std::string mode(std::int32_t k, PartialCoverage partial) {
  return "reduction " + std::to_string(k) + ", partial coverage " + std::string(name_of(partial));
}

std::vector<float> depth_of(const OcclusionBuffer& buffer) {
  std::vector<float> depth(static_cast<std::size_t>(buffer.depth_width()) * buffer.depth_height());
  buffer.read_depth(depth);
  return depth;
}

// Block (x, y)'s value must be at least every full-resolution depth of its pixels in the view.
void expect_at_least_full_depth(const OcclusionBuffer& reduced, const std::vector<float>& full,
                                const std::string& what) {
  const std::int32_t k = reduced.reduction();
  const std::vector<float> blocks = depth_of(reduced);
  for (std::int32_t y = 0; y < reduced.height(); ++y) {
    for (std::int32_t x = 0; x < reduced.width(); ++x) {
      const float block = blocks[static_cast<std::size_t>(y / k) * reduced.depth_width() + x / k];
      const float pixel = full[static_cast<std::size_t>(y) * reduced.width() + x];
      ASSERT_GE(block, pixel) << what << ": pixel (" << x << ", " << y << ")";
    }
  }
}

class ReducedDepth : public IsaTest {};

// The definition, from draw() alone: each triangle drawn by itself (depth test always) shows
// which samples it covers and their depths. In submission order, a block covered whole by a
// triangle takes the largest of its depths over the block where that is below the block's value;
// a block covered in part, with a largest depth over those samples below its value, adds them
// to its layer
// at the larger of the two depths (or starts the layer, when it is empty or no nearer than the
// block's value), and the block takes the layer's depth once the layer holds all its samples
// (with partial coverage merged).
// Views whose sides are multiples of the reduction, so that every sample of a block is drawn.
TEST_P(ReducedDepth, BlocksEqualTheirDefinition) {
  constexpr std::int32_t kViewWidth = 96, kViewHeight = 64;
  Random random(0x7ed0);
  for (const std::int32_t k : kReductions) {
    for (int scene = 0; scene < 12; ++scene) {
      const PartialCoverage partial = kPartials[scene % 2];
      const OccluderSoup soup = random_occluders(random, 4 + 3 * scene);
      const std::string what = mode(k, partial) + ", scene " + std::to_string(scene);
      OcclusionBuffer buffer(kViewWidth, kViewHeight, k, partial);
      OcclusionOptions options;
      options.isa = isa();
      options.threads = 1 + static_cast<std::size_t>(scene % 3);
      const DrawReport report = buffer.draw_occluders(soup.mesh(), options);

      std::vector<float> want(static_cast<std::size_t>(kViewWidth / k) * (kViewHeight / k), 1.0f);
      struct Layer {
        float depth = 1.0f;
        std::uint32_t samples = 0;
      };
      std::vector<Layer> layers(want.size());
      const std::uint32_t all = (1u << (k * k)) - 1u;
      std::uint64_t fragments = 0, passed = 0;
      Framebuffer alone(kViewWidth, kViewHeight);
      DrawOptions draw_options;
      draw_options.isa = Isa::reference;
      draw_options.depth_test = DepthTest::always;
      const std::vector<Vec4> white(3, Vec4{1.0f, 1.0f, 1.0f, 1.0f});
      for (std::size_t t = 0; t < soup.positions.size() / 3; ++t) {
        alone.clear({0.0f, 0.0f, 0.0f, 1.0f}, 1.0f);
        draw(alone, {std::span<const Vec3>(soup.positions.data() + 3 * t, 3), white, {}, {}},
             draw_options);
        for (std::int32_t by = 0; by < kViewHeight / k; ++by) {
          for (std::int32_t bx = 0; bx < kViewWidth / k; ++bx) {
            std::uint32_t samples = 0;
            float farthest = 0.0f;
            for (std::int32_t j = 0; j < k; ++j) {
              for (std::int32_t i = 0; i < k; ++i) {
                if (alone.color(k * bx + i, k * by + j) != 0xFFFFFFFFu) continue;
                samples |= 1u << (j * k + i);
                farthest = std::max(farthest, alone.depth(k * bx + i, k * by + j));
              }
            }
            const std::size_t block = static_cast<std::size_t>(by) * (kViewWidth / k) + bx;
            float& stored = want[block];
            if (samples == 0) continue;
            if (samples != all) {
              if (partial == PartialCoverage::ignored) continue;
              Layer& layer = layers[block];
              if (!(farthest < stored)) continue;
              if (layer.samples == 0 || !(layer.depth < stored)) {
                layer = {farthest, samples};
              } else if ((layer.samples | samples) == all) {
                stored = std::max(layer.depth, farthest);
                layer = {};
              } else {
                layer = {std::max(layer.depth, farthest), layer.samples | samples};
              }
              continue;
            }
            ++fragments;
            if (farthest < stored) {
              stored = farthest;
              ++passed;
            }
          }
        }
      }
      const std::vector<float> got = depth_of(buffer);
      for (std::size_t i = 0; i < want.size(); ++i) {
        ASSERT_EQ(std::bit_cast<std::uint32_t>(got[i]), std::bit_cast<std::uint32_t>(want[i]))
            << what << ": block (" << i % (kViewWidth / k) << ", " << i / (kViewWidth / k) << ")";
      }
      EXPECT_EQ(report.fragments, fragments) << what;
      EXPECT_EQ(report.fragments_passed, passed) << what;
      // Some blocks must be covered by the soup's triangles, not only by its backdrop.
      EXPECT_GT(passed, 2u) << what;
    }
  }
}

// Every ISA's blocks are the reference's, bit for bit, on views whose sides are not multiples of
// the reduction (the last blocks' samples reach past the view), on one thread and in bins, over
// several calls, with the counts of each call.
TEST_P(ReducedDepth, KernelsEqualReference) {
  if (isa() == Isa::reference) GTEST_SKIP() << "the reference is what the kernels are tested by";
  Random random(0x7ed1);
  const std::int32_t sizes[][2] = {{101, 77}, {203, 150}, {37, 300}};
  for (const std::int32_t k : kReductions) {
    for (int scene = 0; scene < 12; ++scene) {
      const PartialCoverage partial = kPartials[(scene / 3) % 2];
      const std::int32_t width = sizes[scene % 3][0], height = sizes[scene % 3][1];
      const OccluderSoup soup = random_occluders(random, 10 + 25 * scene);
      const std::string what = mode(k, partial) + ", scene " + std::to_string(scene);
      OcclusionBuffer got(width, height, k, partial), want(width, height, k, partial);
      OcclusionOptions options, reference;
      options.isa = isa();
      options.threads = 1 + static_cast<std::size_t>(scene % 4);
      reference.isa = Isa::reference;
      const std::size_t triangles = soup.positions.size() / 3;
      const std::size_t calls = 1 + static_cast<std::size_t>(scene % 3);
      for (std::size_t c = 0; c < calls; ++c) {
        const std::size_t first = 3 * (triangles * c / calls);
        const std::size_t last = 3 * (triangles * (c + 1) / calls);
        const OcclusionMesh part{std::span<const Vec3>(soup.positions.data() + first, last - first),
                                 {}};
        const DrawReport a = got.draw_occluders(part, options);
        const DrawReport b = want.draw_occluders(part, reference);
        EXPECT_EQ(a.fragments, b.fragments) << what << ", call " << c;
        EXPECT_EQ(a.fragments_passed, b.fragments_passed) << what << ", call " << c;
        EXPECT_EQ(a.rasterized, b.rasterized) << what << ", call " << c;
      }
      const std::vector<float> a = depth_of(got), b = depth_of(want);
      for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(std::bit_cast<std::uint32_t>(a[i]), std::bit_cast<std::uint32_t>(b[i]))
            << what << ": block (" << i % got.depth_width() << ", " << i / got.depth_width() << ")";
      }
    }
  }
}

// Triangles thousands of views across (clipped to the guard band), whose edge steps on blocks of
// 4 reach 2^26: the tile walk's per-tile clamp must keep each edge's sign over a tile.
TEST_P(ReducedDepth, HugeTrianglesEqualReference) {
  if (isa() == Isa::reference) GTEST_SKIP() << "the reference is what the kernels are tested by";
  Random random(0x7ed5);
  for (int scene = 0; scene < 40; ++scene) {
    const std::int32_t width = 9 + scene, height = 20 + 3 * scene;
    std::vector<Vec3> positions;
    for (int t = 0; t < 6; ++t) {
      // Long slivers through the view: one corner near it, two far out on either side.
      const double far = random.log_uniform(100.0, 5000.0);
      const double angle = random.uniform(0.0, 6.2832);
      const double cx = random.uniform(-1.0, 1.0), cy = random.uniform(-1.0, 1.0);
      const double dx = far * std::cos(angle), dy = far * std::sin(angle);
      positions.push_back(
          {static_cast<float>(cx), static_cast<float>(cy), static_cast<float>(random.uniform())});
      positions.push_back({static_cast<float>(cx + dx), static_cast<float>(cy + dy),
                           static_cast<float>(random.uniform())});
      positions.push_back({static_cast<float>(cx - dx + random.uniform(-0.5, 0.5)),
                           static_cast<float>(cy - dy + random.uniform(-0.5, 0.5)),
                           static_cast<float>(random.uniform())});
    }
    for (const std::int32_t k : kReductions) {
      const PartialCoverage partial = kPartials[scene % 2];
      OcclusionBuffer got(width, height, k, partial), want(width, height, k, partial);
      OcclusionOptions options, reference;
      options.isa = isa();
      reference.isa = Isa::reference;
      got.draw_occluders({positions, {}}, options);
      want.draw_occluders({positions, {}}, reference);
      const std::vector<float> a = depth_of(got), b = depth_of(want);
      for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(std::bit_cast<std::uint32_t>(a[i]), std::bit_cast<std::uint32_t>(b[i]))
            << mode(k, partial) << ", scene " << scene << ": block (" << i % got.depth_width()
            << ", " << i / got.depth_width() << ")";
      }
    }
  }
}

// Conservative: every block holds at least the full-resolution depth of each of its pixels,
// drawn or copied, and a copied frame gives each block exactly its pixels' largest depth.
TEST_P(ReducedDepth, NeverBelowFullResolution) {
  Random random(0x7ed2);
  for (const std::int32_t k : kReductions) {
    for (int scene = 0; scene < 8; ++scene) {
      const PartialCoverage partial = kPartials[scene % 2];
      const std::int32_t width = 61 + 17 * scene, height = 47 + 9 * scene;
      const OccluderSoup soup = random_occluders(random, 5 + 20 * scene);
      const std::string what = mode(k, partial) + ", scene " + std::to_string(scene);
      OcclusionOptions options;
      options.isa = isa();
      OcclusionBuffer full(width, height), reduced(width, height, k, partial);
      full.draw_occluders(soup.mesh(), options);
      reduced.draw_occluders(soup.mesh(), options);
      const std::vector<float> full_depth = depth_of(full);
      expect_at_least_full_depth(reduced, full_depth, what + ", drawn");

      Framebuffer frame(width, height);
      frame.clear({0.0f, 0.0f, 0.0f, 1.0f}, 1.0f);
      DrawOptions draw_options;
      draw_options.isa = isa();
      draw(frame, {soup.positions, {}, {}, {}}, draw_options);
      reduced.copy_depth(frame, options);
      const std::vector<float> blocks = depth_of(reduced);
      for (std::int32_t by = 0; by < reduced.depth_height(); ++by) {
        for (std::int32_t bx = 0; bx < reduced.depth_width(); ++bx) {
          float farthest = 0.0f;
          for (std::int32_t y = k * by; y < std::min(k * by + k, height); ++y) {
            for (std::int32_t x = k * bx; x < std::min(k * bx + k, width); ++x)
              farthest = std::max(farthest, frame.depth(x, y));
          }
          ASSERT_EQ(blocks[static_cast<std::size_t>(by) * reduced.depth_width() + bx], farthest)
              << what << ", copied: block (" << bx << ", " << by << ")";
        }
      }
    }
  }
}

// Rectangles: outside exactly when the full-resolution oracle says so, and never occluded when
// a sample whose centre lies in the rectangle holds a depth above the rectangle's.
// EDGEWISE_FUZZ_ITERS sets the rectangles per ISA (default 1,000,000, shared by the reductions).
TEST_P(ReducedDepth, RectanglesNeverOccludedWhereSamplesShow) {
  constexpr std::int32_t kViewWidth = 160, kViewHeight = 120;
  const std::uint64_t seed = env_number("EDGEWISE_FUZZ_SEED", 0x7ed3);
  const int count = static_cast<int>(env_number("EDGEWISE_FUZZ_ITERS", 1000000));
  Random random(seed);
  std::uint64_t occluded = 0, oracle_occluded = 0;
  const int scenes = 20;
  for (int scene = 0; scene < scenes; ++scene) {
    const std::int32_t k = kReductions[scene % 2];
    const PartialCoverage partial = kPartials[(scene / 2) % 2];
    const OccluderSoup soup = random_occluders(random, 1 + scene * 4);
    OcclusionOptions options;
    options.isa = isa();
    OcclusionBuffer full(kViewWidth, kViewHeight), reduced(kViewWidth, kViewHeight, k, partial);
    full.draw_occluders(soup.mesh(), options);
    reduced.draw_occluders(soup.mesh(), options);
    const std::vector<OcclusionRect> rects =
        random_rects(random, count / scenes, kViewWidth, kViewHeight);
    // The full-resolution answers are exact (occlusion_oracle_test.cpp proves them so).
    std::vector<Visibility> want(rects.size()), got(rects.size());
    full.test_rects(rects, want, isa());
    reduced.test_rects(rects, got, isa());
    for (std::size_t i = 0; i < rects.size(); ++i) {
      const bool wrong = (got[i] == Visibility::outside) != (want[i] == Visibility::outside) ||
                         (got[i] == Visibility::occluded && want[i] != Visibility::occluded);
      ASSERT_FALSE(wrong) << mode(k, partial) << ", scene " << scene << " rectangle " << i << " ["
                          << rects[i].x0 << ", " << rects[i].x1 << "] x [" << rects[i].y0 << ", "
                          << rects[i].y1 << "] depth " << rects[i].depth << ": " << name_of(got[i])
                          << " against " << name_of(want[i]) << ", seed " << seed;
      occluded += got[i] == Visibility::occluded;
      oracle_occluded += want[i] == Visibility::occluded;
    }
  }
  // A buffer that occluded nothing would pass the test above: most of what the oracle finds
  // occluded is found occluded here too.
  EXPECT_GT(occluded, oracle_occluded / 2) << occluded << " of " << oracle_occluded;
}

// Triangles and boxes: a box's faces that show a sample at full resolution are never found
// occluded on a reduced buffer, by test_triangles() or by test_boxes(); outside agrees.
TEST_P(ReducedDepth, FacesAndBoxesNeverOccludedWhereFacesShow) {
  constexpr std::int32_t kViewWidth = 160, kViewHeight = 120;
  Random random(0x7ed4);
  std::uint64_t occluded = 0, oracle_occluded = 0;
  for (int scene = 0; scene < 8; ++scene) {
    const std::int32_t k = kReductions[scene % 2];
    const PartialCoverage partial = kPartials[(scene / 2) % 2];
    OcclusionOptions options;
    options.isa = isa();
    options.transform = random_camera(random, static_cast<float>(kViewWidth) / kViewHeight);
    std::vector<Vec3> walls;
    for (const OcclusionBox& wall : random_boxes(random, 6)) {
      const std::vector<Vec3> faces = box_faces(wall);
      walls.insert(walls.end(), faces.begin(), faces.end());
    }
    OcclusionBuffer full(kViewWidth, kViewHeight), reduced(kViewWidth, kViewHeight, k, partial);
    full.draw_occluders({walls, {}}, options);
    reduced.draw_occluders({walls, {}}, options);
    const std::vector<OcclusionBox> boxes = random_boxes(random, 300);
    std::vector<Visibility> answers(boxes.size());
    reduced.test_boxes(boxes, options.transform, answers, isa());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const std::vector<Vec3> faces = box_faces(boxes[i]);
      const Visibility oracle = full.test_triangles({faces, {}}, options);
      const Visibility triangles = reduced.test_triangles({faces, {}}, options);
      const std::string what =
          mode(k, partial) + ", scene " + std::to_string(scene) + " box " + std::to_string(i);
      EXPECT_EQ(triangles == Visibility::outside, oracle == Visibility::outside) << what;
      if (oracle == Visibility::visible) {
        ASSERT_EQ(triangles, Visibility::visible) << what;
        ASSERT_EQ(answers[i], Visibility::visible) << what;
      }
      occluded += triangles == Visibility::occluded;
      oracle_occluded += oracle == Visibility::occluded;
    }
  }
  EXPECT_GT(occluded, oracle_occluded / 2) << occluded << " of " << oracle_occluded;
}

EDGEWISE_INSTANTIATE_PER_ISA(ReducedDepth, every_isa());

TEST(ReducedDepthApi, SizesAndBadReductions) {
  const OcclusionBuffer buffer(101, 77, 4);
  EXPECT_EQ(buffer.width(), 101);
  EXPECT_EQ(buffer.height(), 77);
  EXPECT_EQ(buffer.reduction(), 4);
  EXPECT_EQ(buffer.depth_width(), 26);
  EXPECT_EQ(buffer.depth_height(), 20);
  for (const std::int32_t bad : {0, 3, 8, -2}) {
    try {
      const OcclusionBuffer rejected(64, 64, bad);
      ADD_FAILURE() << "reduction " << bad << " accepted";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find(std::to_string(bad)), std::string::npos)
          << error.what();
    }
  }
  EXPECT_THROW(OcclusionBuffer(64, 64, 2, static_cast<PartialCoverage>(7)), std::invalid_argument);
  EXPECT_EQ(OcclusionBuffer(64, 64, 2).partial_coverage(), PartialCoverage::ignored);
  Framebuffer wrong(25, 19);
  OcclusionBuffer reduced(101, 77, 4);
  EXPECT_THROW(reduced.copy_depth(wrong), std::invalid_argument);
}

}  // namespace
}  // namespace edgewise::test
