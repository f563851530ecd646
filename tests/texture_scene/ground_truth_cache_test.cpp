// The ground-truth file: a round trip is bit-exact, and any mismatch (another fingerprint,
// another file, a truncated one) makes the reader decline rather than return stale data.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "scene/temp_directory.hpp"
#include "texture_scene/builtin_views.hpp"
#include "texture_scene/ground_truth_cache.hpp"
#include "texture_scene/procedural_textures.hpp"
#include "texture_scene/same_ground_truth.hpp"

namespace edgewise::texture_scene {
namespace {

using edgewise::scene::test::TempDirectory;

struct Inputs {
  LinearImage texture = checkerboard(64, 8);
  TextureView view = ground_plane_view(96, 54);
  ScreenRegion region{40, 0, 5, 3};
  GroundTruthOptions options;
  std::uint64_t fingerprint() const {
    return ground_truth_fingerprint(texture, WrapMode::repeat, WrapMode::repeat, view, region,
                                    options);
  }
  GroundTruth compute() const {
    return ground_truth(texture, WrapMode::repeat, WrapMode::repeat, view, region, options);
  }
};

// The file keeps the time the computation took, too.
void expect_same(const GroundTruth& a, const GroundTruth& b) {
  expect_same_result(a, b);
  EXPECT_EQ(a.report.seconds, b.report.seconds);
}

TEST(GroundTruthCache, RoundTripIsExact) {
  const TempDirectory directory;
  const Inputs inputs;
  const GroundTruth truth = inputs.compute();
  const std::filesystem::path path = directory.path() / "truth.bin";
  write_ground_truth(path, truth, inputs.fingerprint());
  const std::optional<GroundTruth> read = read_ground_truth(path, inputs.fingerprint());
  ASSERT_TRUE(read.has_value());
  expect_same(*read, truth);
  // Header (8 + 4 + 8 + 16 + 52 bytes), then 4 floats and one int32 per pixel.
  EXPECT_EQ(std::filesystem::file_size(path), 88u + 15u * (16u + 4u));
  EXPECT_FALSE(std::filesystem::exists(directory.path() / "truth.bin.partial"));
}

TEST(GroundTruthCache, DeclinesMismatchedOrDamagedFiles) {
  const TempDirectory directory;
  const Inputs inputs;
  const std::filesystem::path path = directory.path() / "truth.bin";
  EXPECT_FALSE(read_ground_truth(path, inputs.fingerprint()).has_value());  // missing
  write_ground_truth(path, inputs.compute(), inputs.fingerprint());
  EXPECT_FALSE(read_ground_truth(path, inputs.fingerprint() + 1).has_value());
  // Truncated by one byte, or one byte too long.
  const auto size = std::filesystem::file_size(path);
  std::filesystem::resize_file(path, size - 1);
  EXPECT_FALSE(read_ground_truth(path, inputs.fingerprint()).has_value());
  write_ground_truth(path, inputs.compute(), inputs.fingerprint());
  std::ofstream(path, std::ios::binary | std::ios::app).put('x');
  EXPECT_FALSE(read_ground_truth(path, inputs.fingerprint()).has_value());
  // Not a ground-truth file.
  const std::string other = directory.write("other.bin", "P6\n2 2\n255\n");
  EXPECT_FALSE(read_ground_truth(other, inputs.fingerprint()).has_value());
}

TEST(GroundTruthCache, FingerprintCoversEveryInput) {
  const Inputs base;
  const std::uint64_t reference = base.fingerprint();
  Inputs changed = base;
  changed.texture.rgba[17] = 0.5f;
  EXPECT_NE(changed.fingerprint(), reference);
  changed = base;
  changed.region.x0 = 41;
  EXPECT_NE(changed.fingerprint(), reference);
  changed = base;
  changed.view = ground_plane_view(96, 55);
  EXPECT_NE(changed.fingerprint(), reference);
  changed = base;
  changed.options.tolerance = 2e-4;
  EXPECT_NE(changed.fingerprint(), reference);
  changed = base;
  changed.options.max_grid = 1024;
  EXPECT_NE(changed.fingerprint(), reference);
  EXPECT_NE(ground_truth_fingerprint(base.texture, WrapMode::repeat, WrapMode::mirror, base.view,
                                     base.region, base.options),
            reference);
  // Threads change nothing in the result, so not the fingerprint either.
  changed = base;
  changed.options.threads = 1;
  EXPECT_EQ(changed.fingerprint(), reference);
}

TEST(GroundTruthCache, CachedComputesOnceThenReads) {
  const TempDirectory directory;
  const Inputs inputs;
  const std::filesystem::path path = directory.path() / "cached.bin";
  const GroundTruth first = cached_ground_truth(path, inputs.texture, WrapMode::repeat,
                                                WrapMode::repeat, inputs.view, inputs.region);
  ASSERT_TRUE(std::filesystem::exists(path));
  // The second call returns the stored result, including the first run's recorded time.
  const GroundTruth second = cached_ground_truth(path, inputs.texture, WrapMode::repeat,
                                                 WrapMode::repeat, inputs.view, inputs.region);
  expect_same(second, first);
  // A different input recomputes and replaces the file.
  const GroundTruth other = cached_ground_truth(path, inputs.texture, WrapMode::mirror,
                                                WrapMode::repeat, inputs.view, inputs.region);
  EXPECT_TRUE(read_ground_truth(
                  path, ground_truth_fingerprint(inputs.texture, WrapMode::mirror, WrapMode::repeat,
                                                 inputs.view, inputs.region, {}))
                  .has_value());
  (void)other;
}

TEST(GroundTruthCache, WriteFailsLoudly) {
  const TempDirectory directory;
  const Inputs inputs;
  EXPECT_THROW(write_ground_truth(directory.path() / "missing" / "truth.bin", inputs.compute(),
                                  inputs.fingerprint()),
               std::runtime_error);
}

}  // namespace
}  // namespace edgewise::texture_scene
