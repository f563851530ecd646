// The scored settings: every filter (or those asked for), the denser supersampling grid, the
// anisotropy, level-of-detail formula and bias asked for, each named.
#include "texture_quality/filter_methods.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "edgewise/texture.hpp"

namespace edgewise::texture_quality {
namespace {

MethodSettings settings_with(int max_anisotropy, LodFormula lod = LodFormula::exact,
                             float lod_bias = 0.0f) {
  MethodSettings settings;
  settings.max_anisotropy = max_anisotropy;
  settings.lod = lod;
  settings.lod_bias = lod_bias;
  return settings;
}

TEST(FilterMethods, EveryFilterWithUniqueNames) {
  const std::vector<FilterMethod> methods = filter_methods(MethodSettings{});
  std::set<std::string> names;
  for (const FilterMethod& method : methods)
    names.insert(method.name);
  EXPECT_EQ(names.size(), methods.size());
  for (int f = 0; f <= static_cast<int>(TextureFilter::ewa); ++f) {
    const auto filter = static_cast<TextureFilter>(f);
    int count = 0;
    for (const FilterMethod& method : methods) {
      if (method.options.filter != filter) continue;
      ++count;
      // Names start with the filter's own name, so a reader of the scores can tell it.
      EXPECT_EQ(method.name.rfind(std::string(name_of(filter)), 0), 0u) << method.name;
    }
    // Both precisions of the filters made of bilinear taps; supersample at two grids.
    const int precisions = reads_bilinear_taps(filter) ? 2 : 1;
    EXPECT_EQ(count, (filter == TextureFilter::supersample ? 2 : 1) * precisions)
        << name_of(filter);
  }
}

TEST(FilterMethods, FixedPointVariantsNamedAndNeverAutomatic) {
  for (const FilterMethod& method : filter_methods(MethodSettings{})) {
    EXPECT_NE(method.options.precision, FilterPrecision::automatic) << method.name;
    const bool suffixed =
        method.name.size() > 8 && method.name.compare(method.name.size() - 8, 8, "_fixed16") == 0;
    EXPECT_EQ(suffixed, method.options.precision == FilterPrecision::fixed16) << method.name;
    if (!reads_bilinear_taps(method.options.filter)) {
      EXPECT_EQ(method.options.precision, FilterPrecision::float32) << method.name;
    }
  }
  MethodSettings only_fixed;
  only_fixed.precisions = {FilterPrecision::fixed16};
  only_fixed.filters = {TextureFilter::trilinear, TextureFilter::ewa};
  const std::vector<FilterMethod> methods = filter_methods(only_fixed);
  ASSERT_EQ(methods.size(), 2u);
  EXPECT_EQ(methods[0].name, "trilinear_fixed16");
  EXPECT_EQ(methods[1].name, "ewa_16x");  // no taps: float32 whatever is asked
}

TEST(FilterMethods, SupersampleAtTheDefaultAndTheDenseGrid) {
  std::set<int> taps;
  for (const FilterMethod& method : filter_methods(MethodSettings{})) {
    if (method.options.filter == TextureFilter::supersample) {
      taps.insert(method.options.supersample_taps);
      const std::string grid = "supersample_" + std::to_string(method.options.supersample_taps) +
                               "x" + std::to_string(method.options.supersample_taps);
      EXPECT_EQ(method.name,
                method.options.precision == FilterPrecision::fixed16 ? grid + "_fixed16" : grid);
    }
  }
  EXPECT_EQ(taps, (std::set<int>{SamplerOptions{}.supersample_taps, kDenseSupersampleTaps}));
}

TEST(FilterMethods, AnisotropyGoesIntoTheOptionsAndTheNames) {
  for (const FilterMethod& method : filter_methods(settings_with(8))) {
    EXPECT_EQ(method.options.max_anisotropy, 8);
    EXPECT_EQ(method.options.wrap_s, WrapMode::repeat);
    EXPECT_EQ(method.options.wrap_t, WrapMode::repeat);
    if (method.options.filter == TextureFilter::anisotropic) {
      EXPECT_EQ(method.name, method.options.precision == FilterPrecision::fixed16
                                 ? "anisotropic_8x_fixed16"
                                 : "anisotropic_8x");
    }
    if (method.options.filter == TextureFilter::ewa) {
      EXPECT_EQ(method.name, "ewa_8x");
    }
  }
}

TEST(FilterMethods, OnlyTheFiltersAskedFor) {
  MethodSettings settings;
  settings.filters = {TextureFilter::ewa, TextureFilter::supersample};
  const std::vector<FilterMethod> methods = filter_methods(settings);
  // In TextureFilter order, supersample at both grids in both precisions.
  ASSERT_EQ(methods.size(), 5u);
  EXPECT_EQ(methods[0].name, "supersample_4x4");
  EXPECT_EQ(methods[1].name, "supersample_4x4_fixed16");
  EXPECT_EQ(methods[2].name, "supersample_8x8");
  EXPECT_EQ(methods[3].name, "supersample_8x8_fixed16");
  EXPECT_EQ(methods[4].name, "ewa_16x");
}

// Every method carries the formula and bias; only those whose results depend on them say so in
// their names, so that a scores file with several settings keeps its rows apart.
TEST(FilterMethods, LevelOfDetailSettingsInTheOptionsAndTheNamesOfTheFiltersReadingThem) {
  const std::vector<FilterMethod> methods =
      filter_methods(settings_with(16, LodFormula::max_axis, -0.5f));
  std::set<std::string> names;
  for (const FilterMethod& method : methods) {
    names.insert(method.name);
    EXPECT_EQ(method.options.lod, LodFormula::max_axis);
    EXPECT_EQ(method.options.lod_bias, -0.5f);
  }
  EXPECT_EQ(names.size(), methods.size());
  for (const char* name :
       {"nearest", "bilinear", "supersample_8x8", "summed_area", "mip_nearest_max_axis_bias-0.5",
        "trilinear_max_axis_bias-0.5", "ripmap_bias-0.5", "anisotropic_16x_max_axis_bias-0.5",
        "ewa_16x_bias-0.5"}) {
    EXPECT_EQ(names.count(name), 1u) << name;
  }
  const std::vector<FilterMethod> biased =
      filter_methods(settings_with(16, LodFormula::exact, 0.25f));
  EXPECT_EQ(std::count_if(biased.begin(), biased.end(),
                          [](const FilterMethod& m) { return m.name == "trilinear_bias0.25"; }),
            1);
}

// Whether a filter reads the settings, checked against the sampler itself: a bias of 2 changes
// a minified query's result exactly for the filters said to read it, and the max-of-axes formula
// (sqrt(2) lower on a diagonal footprint) exactly for those said to read the formula.
TEST(FilterMethods, ReadsLevelOfDetailAgreesWithTheSampler) {
  constexpr int kSide = 64;
  std::vector<std::uint8_t> texels(kSide * kSide * 4);
  for (int i = 0; i < kSide * kSide; ++i) {
    const std::uint8_t value = static_cast<std::uint8_t>((i * 37 + (i / kSide) * 11) % 256);
    for (int k = 0; k < 4; ++k)
      texels[4 * i + k] = static_cast<std::uint8_t>(value + 50 * k);
  }
  const Texture texture = Texture::from_rgba8(
      kSide, kSide, texels, ColorEncoding::linear,
      TextureBuild{PyramidFilter::box, /*ripmaps=*/true, /*summed_area_table=*/true});
  // A diagonal footprint of 4 x 7 texels: a fractional level, anisotropy below 2, and rho
  // 7 sqrt(2) (exact) against 7 (max_axis) puts lambda at 2.52 and 2.02
  // (log2(rho) - log2(3) / 2), so that even mip_nearest's levels (3 and 2) differ.
  const TextureQuery query{0.3f, 0.6f, 4.0f / kSide, 4.0f / kSide, -7.0f / kSide, 7.0f / kSide};
  const auto result = [&](const SamplerOptions& options) {
    Vec4 out;
    sample(texture, {options, Isa::reference}, std::span(&query, 1), std::span(&out, 1));
    return out;
  };
  for (int f = 0; f <= static_cast<int>(TextureFilter::ewa); ++f) {
    SamplerOptions options;
    options.filter = static_cast<TextureFilter>(f);
    const Vec4 plain = result(options);
    SamplerOptions biased = options;
    biased.lod_bias = 2.0f;
    SamplerOptions max_axis = options;
    max_axis.lod = LodFormula::max_axis;
    const auto differs = [](const Vec4& a, const Vec4& b) {
      return a.x != b.x || a.y != b.y || a.z != b.z || a.w != b.w;
    };
    EXPECT_EQ(differs(result(biased), plain), reads_lod_bias(options.filter))
        << name_of(options.filter);
    EXPECT_EQ(differs(result(max_axis), plain), reads_lod_formula(options.filter))
        << name_of(options.filter);
  }
}

}  // namespace
}  // namespace edgewise::texture_quality
