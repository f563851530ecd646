// resolve() on every ISA against the scalar reference, byte for byte: random samples (every
// code, extremes included) under every filter, sample count, supersampling factor, encoding
// and thread count, at sizes that end inside tiles and SIMD batches.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "edgewise/framebuffer.hpp"
#include "edgewise/resolve.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "antialiasing/resolve_call.hpp"

namespace edgewise::test {
namespace {

// A target whose every sample (padding included) is random; a third of them take a channel's
// extreme, 0 or 255, where the rounding of sums and the clamping of Mitchell's lobes differ most.
Framebuffer random_samples(std::int32_t width, std::int32_t height, int samples,
                           std::uint64_t seed) {
  Framebuffer target(width, height, samples);
  Random random(seed);
  const std::size_t count =
      static_cast<std::size_t>(target.tiles_x()) * target.tiles_y() * 64 * samples;
  std::uint32_t* tiles = target.color_tiles();
  for (std::size_t i = 0; i < count; ++i) {
    std::uint32_t c = static_cast<std::uint32_t>(random.next());
    for (int k = 0; k < 4; ++k) {
      const std::int64_t pick = random.integer(0, 5);
      if (pick == 0) c &= ~(0xFFu << (8 * k));
      if (pick == 1) c |= 0xFFu << (8 * k);
    }
    tiles[i] = c;
  }
  return target;
}

std::vector<std::uint8_t> resolved_image(const Framebuffer& source, const ResolveOptions& options) {
  const int f = options.supersampling;
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(source.width() / f) *
                                 static_cast<std::size_t>(source.height() / f) * 4);
  resolve(source, rgba, options);
  return rgba;
}

// The first differing byte as "pixel (x, y) channel c: isa v, reference w", or "".
std::string first_different_byte(const std::vector<std::uint8_t>& fast,
                                 const std::vector<std::uint8_t>& reference, std::int32_t width) {
  for (std::size_t i = 0; i < fast.size(); ++i) {
    if (fast[i] == reference[i]) continue;
    const std::size_t pixel = i / 4;
    return "pixel (" + std::to_string(pixel % width) + ", " + std::to_string(pixel / width) +
           ") channel " + std::to_string(i % 4) + ": " + std::to_string(fast[i]) + ", reference " +
           std::to_string(reference[i]);
  }
  return "";
}

class ResolveIsa : public IsaTest {};

TEST_P(ResolveIsa, EveryFilterMatchesTheReferenceByteForByte) {
  // 21 x 11 output pixels: neither a whole tile nor a whole batch of any ISA.
  constexpr std::int32_t kOutputWidth = 21, kOutputHeight = 11;
  std::uint64_t seed = 1;
  for (ResolveFilter filter : values_of<ResolveFilter>()) {
    for (int samples : {1, 2, 4, 8, 16}) {
      for (int factor : {1, 2, 3}) {
        if (samples * factor * factor > 64) continue;  // the sums are covered by smaller ones
        const Framebuffer source =
            random_samples(kOutputWidth * factor, kOutputHeight * factor, samples, seed++);
        for (bool srgb : {false, true}) {
          for (std::size_t threads : {std::size_t{1}, std::size_t{3}}) {
            ResolveOptions options{filter, factor, srgb, isa(), threads, {}};
            const std::vector<std::uint8_t> fast = resolved_image(source, options);
            options.isa = Isa::reference;
            options.threads = 1;
            EXPECT_EQ(first_different_byte(fast, resolved_image(source, options), kOutputWidth), "")
                << name_of(filter) << ", " << samples << " samples, factor " << factor
                << (srgb ? ", sRGB" : ", linear") << ", " << threads << " threads";
          }
        }
      }
    }
  }
}

TEST_P(ResolveIsa, TallTargetsSplitIntoBandsMatchTheReference) {
  // 70 rows: three bands of rows, the last a partial tile row; 4 threads share them.
  const Framebuffer source = random_samples(13, 70, 4, 99);
  for (ResolveFilter filter : values_of<ResolveFilter>()) {
    ResolveOptions options{filter, 1, true, isa(), 4, {}};
    const std::vector<std::uint8_t> fast = resolved_image(source, options);
    options.isa = Isa::reference;
    options.threads = 1;
    EXPECT_EQ(first_different_byte(fast, resolved_image(source, options), 13), "")
        << name_of(filter);
  }
}

EDGEWISE_INSTANTIATE_PER_ISA(ResolveIsa, fast_isas());

// The constant-time sRGB codes equal the binary search's at every threshold, one float either
// side of it, and at random values.
TEST(ResolveCodes, SrgbCellsGiveTheReferenceCodes) {
  const detail::SrgbCodeCells& cells = detail::srgb_code_cells();
  const auto expect_same = [&](float v) {
    ASSERT_EQ(cells.code(v), detail::encode_resolved(v, true)) << "at " << v;
  };
  for (float threshold : detail::srgb_code_thresholds()) {
    expect_same(threshold);
    expect_same(std::nextafter(threshold, 0.0f));
    expect_same(std::nextafter(threshold, 1.0f));
  }
  for (int cell = 0; cell <= detail::SrgbCodeCells::kCells; ++cell) {
    const float low = static_cast<float>(cell) / detail::SrgbCodeCells::kCells;
    expect_same(low);
    if (cell > 0) expect_same(std::nextafter(low, 0.0f));
  }
  Random random(7);
  for (int i = 0; i < 100000; ++i)
    expect_same(static_cast<float>(random.uniform()));
}

}  // namespace
}  // namespace edgewise::test
