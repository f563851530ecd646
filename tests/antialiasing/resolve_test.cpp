// resolve() (resolve.hpp): filters against their definitions, averages computed here by hand,
// sRGB encoding against the transfer function, and the errors it reports.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "edgewise/draw.hpp"
#include "edgewise/framebuffer.hpp"
#include "edgewise/multisample.hpp"
#include "edgewise/resolve.hpp"
#include "edgewise/texture.hpp"
#include "random.hpp"

namespace edgewise::test {
namespace {

std::vector<std::uint8_t> resolved(const Framebuffer& source, const ResolveOptions& options) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(source.width() / options.supersampling) *
                                 static_cast<std::size_t>(source.height() / options.supersampling) *
                                 4);
  resolve(source, rgba, options);
  return rgba;
}

// Writes `color` to sample k of pixel (x, y) through the tiled storage (framebuffer.hpp).
void set_sample(Framebuffer& target, std::int32_t x, std::int32_t y, int k, std::uint32_t color) {
  const std::size_t tile = static_cast<std::size_t>(y / 8) * target.tiles_x() + x / 8;
  target.color_tiles()[(tile * target.samples() + k) * 64 + (y % 8) * 8 + x % 8] = color;
}

std::uint32_t random_colour(Random& random) {
  return static_cast<std::uint32_t>(random.uniform(0.0, 4294967295.0));
}

std::uint8_t channel(std::uint32_t c, int k) {
  return static_cast<std::uint8_t>(c >> (8 * k));
}

TEST(Resolve, UniformImagesKeepTheirColourUnderEveryFilter) {
  for (int samples : {1, 2, 4, 8, 16}) {
    for (ResolveFilter filter : values_of<ResolveFilter>()) {
      for (int factor : {1, 3}) {
        Framebuffer target(21 * factor, 10 * factor, samples);
        target.clear({0.2f, 0.6f, 1.0f, 0.4f}, 1.0f);
        ResolveOptions options;
        options.filter = filter;
        options.supersampling = factor;
        const std::vector<std::uint8_t> rgba = resolved(target, options);
        const std::uint32_t expected = pack_rgba8({0.2f, 0.6f, 1.0f, 0.4f});
        for (std::size_t p = 0; p < rgba.size() / 4; ++p) {
          for (int k = 0; k < 4; ++k)
            ASSERT_EQ(rgba[4 * p + k], channel(expected, k)) << name_of(filter) << " " << samples;
        }
      }
    }
  }
}

// The box filter is the mean of the pixel's own samples (every standard offset lies in
// [-8, 7] / 16 px: inside the pixel), rounded to nearest.
TEST(Resolve, BoxIsTheMeanOfThePixelsSamples) {
  Random random(3);
  for (int samples : {2, 4, 8, 16}) {
    Framebuffer target(13, 9, samples);
    for (std::int32_t y = 0; y < 9; ++y) {
      for (std::int32_t x = 0; x < 13; ++x) {
        for (int k = 0; k < samples; ++k)
          set_sample(target, x, y, k, random_colour(random));
      }
    }
    const std::vector<std::uint8_t> rgba = resolved(target, {});
    for (std::int32_t y = 0; y < 9; ++y) {
      for (std::int32_t x = 0; x < 13; ++x) {
        for (int c = 0; c < 4; ++c) {
          int sum = 0;
          for (int k = 0; k < samples; ++k)
            sum += channel(target.color(x, y, k), c);
          const double mean = static_cast<double>(sum) / samples;
          const int got = rgba[(static_cast<std::size_t>(y) * 13 + x) * 4 + c];
          // Rounded to nearest; a mean of exactly c + 1/2 may round either way after float sums.
          EXPECT_LE(std::abs(got - mean), 0.5 + 1e-9) << x << "," << y << " " << samples;
        }
      }
    }
  }
}

// Supersampling by f with the box filter averages f x f blocks of source pixels.
TEST(Resolve, SupersamplingBoxAveragesBlocks) {
  Random random(4);
  for (int factor : {2, 3, 4}) {
    Framebuffer target(7 * factor, 5 * factor);
    for (std::int32_t y = 0; y < target.height(); ++y) {
      for (std::int32_t x = 0; x < target.width(); ++x)
        set_sample(target, x, y, 0, random_colour(random));
    }
    ResolveOptions options;
    options.supersampling = factor;
    const std::vector<std::uint8_t> rgba = resolved(target, options);
    for (std::int32_t y = 0; y < 5; ++y) {
      for (std::int32_t x = 0; x < 7; ++x) {
        for (int c = 0; c < 4; ++c) {
          int sum = 0;
          for (int j = 0; j < factor; ++j) {
            for (int i = 0; i < factor; ++i)
              sum += channel(target.color(x * factor + i, y * factor + j), c);
          }
          const double mean = static_cast<double>(sum) / (factor * factor);
          const int got = rgba[(static_cast<std::size_t>(y) * 7 + x) * 4 + c];
          EXPECT_LE(std::abs(got - mean), 0.5 + 1e-9) << x << "," << y << " factor " << factor;
        }
      }
    }
  }
}

// Tent and Mitchell-Netravali are partitions of unity: their integer shifts sum to 1 at every
// offset, the property that keeps a flat image flat under a regular grid of samples.
TEST(Resolve, FiltersArePartitionsOfUnity) {
  for (ResolveFilter filter : values_of<ResolveFilter>()) {
    for (double d = -0.5; d < 0.5; d += 1.0 / 64) {
      double sum = 0.0;
      for (int n = -3; n <= 3; ++n)
        sum += filter_weight(filter, d + n);
      EXPECT_NEAR(sum, 1.0, 1e-12) << name_of(filter) << " at " << d;
    }
    EXPECT_EQ(filter_weight(filter, filter_radius(filter)), 0.0);
    EXPECT_GT(filter_weight(filter, filter_radius(filter) - 0.01), -0.01);
  }
  // Mitchell's values at the integers (B = C = 1/3): (6 - 2B) / 6 = 8/9 at 0, B / 6 = 1/18 at 1.
  EXPECT_NEAR(filter_weight(ResolveFilter::mitchell, 0.0), 8.0 / 9.0, 1e-15);
  EXPECT_NEAR(filter_weight(ResolveFilter::mitchell, 1.0), 1.0 / 18.0, 1e-15);
  EXPECT_LT(filter_weight(ResolveFilter::mitchell, 1.5), 0.0);  // the negative lobe
}

// A tent resolve reaches the neighbours: a single bright pixel spreads to them with the weights
// of the filter at the samples' distances.
TEST(Resolve, TentSpreadsToTheNeighboursByItsWeights) {
  Framebuffer target(5, 5, 4);
  target.clear({0.0f, 0.0f, 0.0f, 0.0f}, 1.0f);
  for (int k = 0; k < 4; ++k)
    set_sample(target, 2, 2, k, 0xFFFFFFFFu);
  ResolveOptions options;
  options.filter = ResolveFilter::tent;
  const std::vector<std::uint8_t> rgba = resolved(target, options);
  // Expected: the weights of the bright pixel's samples over the sum of all weights.
  const std::span<const SampleOffset> pattern = standard_sample_pattern(4);
  for (std::int32_t y = 0; y < 5; ++y) {
    for (std::int32_t x = 0; x < 5; ++x) {
      double bright = 0.0, total = 0.0;
      for (int j = -2; j <= 2; ++j) {
        for (int i = -2; i <= 2; ++i) {
          for (const SampleOffset& s : pattern) {
            const double w = filter_weight(ResolveFilter::tent, i + s.x / 16.0) *
                             filter_weight(ResolveFilter::tent, j + s.y / 16.0);
            total += w;
            if (x + i == 2 && y + j == 2) bright += w;
          }
        }
      }
      const int got = rgba[(static_cast<std::size_t>(y) * 5 + x) * 4];
      EXPECT_LE(std::abs(got - 255.0 * bright / total), 0.5 + 1e-6) << x << "," << y;
    }
  }
  EXPECT_GT(rgba[(2 * 5 + 3) * 4], 0);  // the neighbour got some
}

TEST(Resolve, SrgbEncodesTheLinearMean) {
  Framebuffer target(16, 16);
  for (std::int32_t y = 0; y < 16; ++y) {
    for (std::int32_t x = 0; x < 16; ++x) {
      const std::uint32_t code = static_cast<std::uint32_t>(y * 16 + x);
      set_sample(target, x, y, 0, code | code << 8 | code << 16 | code << 24);
    }
  }
  ResolveOptions options;
  options.srgb = true;
  const std::vector<std::uint8_t> rgba = resolved(target, options);
  for (std::uint32_t code = 0; code < 256; ++code) {
    const long expected = std::lround(255.0 * linear_to_srgb(code / 255.0));
    EXPECT_EQ(rgba[4 * code], expected) << code;
    EXPECT_EQ(rgba[4 * code + 3], code);  // alpha stays linear
  }
}

// Drawn and resolved: a vertical edge at x = 10.5 splits pixel column 10's 4x samples two and
// two (offsets -2/16 and -6/16 px left of the centre are inside): the box resolve is the mean.
TEST(Resolve, HalfCoveredPixelsOfADrawnEdgeAreTheMean) {
  Framebuffer target(24, 16, 4);
  target.clear({0.0f, 0.0f, 0.0f, 1.0f}, 1.0f);
  // Clip space x = -1 .. 1 maps to 0 .. 24 px: x = 10.5 px is -1 + 21 / 24.
  const float edge = -1.0f + 21.0f / 24.0f;
  const Vec3 positions[] = {{-1.0f, -1.0f, 0.5f}, {edge, -1.0f, 0.5f}, {edge, 1.0f, 0.5f},
                            {-1.0f, -1.0f, 0.5f}, {edge, 1.0f, 0.5f},  {-1.0f, 1.0f, 0.5f}};
  DrawMesh mesh;
  mesh.positions = positions;
  DrawOptions options;
  options.shading = Shading::flat;
  draw(target, mesh, options);
  const std::vector<std::uint8_t> rgba = resolved(target, {});
  for (std::int32_t y = 0; y < 16; ++y) {
    EXPECT_EQ(rgba[(static_cast<std::size_t>(y) * 24 + 9) * 4], 255);
    EXPECT_EQ(rgba[(static_cast<std::size_t>(y) * 24 + 10) * 4], 128);  // 127.5 rounded up
    EXPECT_EQ(rgba[(static_cast<std::size_t>(y) * 24 + 11) * 4], 0);
  }
}

TEST(Resolve, RefusesBadFactorsAndSpans) {
  const Framebuffer target(12, 8, 4);
  std::vector<std::uint8_t> rgba(12 * 8 * 4);
  ResolveOptions options;
  options.supersampling = 0;
  EXPECT_THROW(resolve(target, rgba, options), std::invalid_argument);
  options.supersampling = 5;  // divides neither side
  EXPECT_THROW(resolve(target, rgba, options), std::invalid_argument);
  options.supersampling = 1;
  std::vector<std::uint8_t> short_span(12 * 8 * 4 - 1);
  EXPECT_THROW(resolve(target, short_span, options), std::invalid_argument);
  EXPECT_NO_THROW(resolve(target, rgba, options));
  const Framebuffer empty(0, 0, 4);
  EXPECT_NO_THROW(resolve(empty, std::span<std::uint8_t>{}, options));
}

TEST(Framebuffer, RefusesNonStandardSampleCountsAndSamples) {
  EXPECT_THROW(Framebuffer(8, 8, 3), std::invalid_argument);
  EXPECT_THROW(Framebuffer(8, 8, 0), std::invalid_argument);
  EXPECT_THROW(Framebuffer(8, 8, 32), std::invalid_argument);
  const Framebuffer target(8, 8, 8);
  EXPECT_EQ(target.samples(), 8);
  std::vector<std::uint8_t> rgba(8 * 8 * 4);
  std::vector<float> depth(8 * 8);
  EXPECT_NO_THROW(target.read_rgba8(rgba, 7));
  EXPECT_THROW(target.read_rgba8(rgba, 8), std::invalid_argument);
  EXPECT_THROW(target.read_depth(depth, -1), std::invalid_argument);
}

}  // namespace
}  // namespace edgewise::test
