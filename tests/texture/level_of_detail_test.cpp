// Pins the isotropic level of detail, lambda = log2(rho) - log2(3) / 2 + lod_bias
// (kernels/texture/level_of_detail.hpp), on every ISA and the reference, through sample() only: if
// the formula moves, the trilinear values below move with it.
//
// The texture is a float checkerboard of one-texel squares (0 and 1). Every box level above 0 is
// the constant 1/2, and at the centre of a texel of value 1 level 0's bilinear read is exactly 1,
// so trilinear there gives (1 - f) * 1 + f * 1/2 = 1 - f / 2 for lambda = f in [0, 1): the blend
// weight, and through it lambda, can be read off the result.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "isa_params.hpp"

namespace edgewise {
namespace {

constexpr std::int32_t kSize = 64;

Texture one_texel_checkerboard() {
  std::vector<float> texels(4 * kSize * kSize);
  for (std::int32_t y = 0; y < kSize; ++y) {
    for (std::int32_t x = 0; x < kSize; ++x) {
      const float v = static_cast<float>((x + y) % 2);
      for (int c = 0; c < 4; ++c)
        texels[4 * static_cast<std::size_t>(y * kSize + x) + static_cast<std::size_t>(c)] = v;
    }
  }
  return Texture::from_rgba32f(kSize, kSize, texels);
}

// The trilinear value expected at a footprint of rho x rho texels, from the formula written out
// here (not the library's constant).
double expected_trilinear(double rho, double bias) {
  const double lambda = std::log2(rho) - std::log2(3.0) / 2 + bias;
  const double f = std::fmin(std::fmax(lambda, 0.0), 1.0);
  return 1 - f / 2;
}

// Error analysis of the tolerance. The fast paths' lambda is within 2^-13 of the exact one
// (sample_bounds.hpp, "level of detail"; the reference's within a few ulps), so f is, and the
// result, 1 - f / 2, within 2^-14. The float blend rounds the two weights, two products and a sum
// of terms at most 1: 5 roundings of 2^-24. The squares' positions are exact (texel centres of a
// power-of-two texture), and every level above 0 holds exactly 1/2.
constexpr double kTolerance = 0x1p-14 + 5 * 0x1p-24;

class LevelOfDetail : public test::IsaTest {};

TEST_P(LevelOfDetail, TrilinearBlendsAtTheVarianceMatchedLevel) {
  const Texture texture = one_texel_checkerboard();
  // Texel (5, 4) holds 1; its centre.
  const float s = 5.5f / kSize, t = 4.5f / kSize;
  struct Case {
    double rho;  // texels, along both axes
    float bias;
  };
  const double root3 = std::sqrt(3.0);
  const Case cases[] = {
      {1.0, 0},                           // magnified: level 0 alone (log2(rho) alone gives 0)
      {1.5, 0},                           // still level 0 (log2(rho) alone gives 0.58)
      {root3, 0},                         // the edge of magnification
      {root3 * std::exp2(0.25), 0},       // lambda 0.25
      {root3 * std::exp2(0.5), 0},        // lambda 0.5
      {2.0, 0},                           // lambda 1 - log2(3) / 2 = 0.21
      {3.0, 0},                           // lambda log2(3) / 2 = 0.79
      {root3 * std::exp2(0.75), -0.25f},  // bias: lambda 0.5
      {1.0, 0.5f},                        // lambda 0.5 - 0.79: magnified
  };
  for (const Case& c : cases) {
    SamplerOptions options;  // the defaults: trilinear, exact, repeat
    options.lod_bias = c.bias;
    for (LodFormula lod : {LodFormula::exact, LodFormula::max_axis}) {
      options.lod = lod;  // an axis-aligned square footprint: both formulas give rho
      const float d = static_cast<float>(c.rho / kSize);
      const std::vector<TextureQuery> queries(8, TextureQuery{s, t, d, 0, 0, d});
      std::vector<Vec4> out(queries.size());
      sample(texture, {options, isa()}, queries, out);
      const double expected = expected_trilinear(double{d} * kSize, c.bias);
      for (const Vec4& v : out) {
        EXPECT_NEAR(v.x, expected, kTolerance)
            << "rho " << c.rho << ", bias " << c.bias << ", " << name_of(lod);
      }
    }
  }
}

EDGEWISE_INSTANTIATE_PER_ISA(LevelOfDetail, test::every_isa());

}  // namespace
}  // namespace edgewise
