// The scored settings: every filter, the denser supersampling grid, the anisotropy asked for.
#include "texture_quality/filter_methods.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace edgewise::texture_quality {
namespace {

TEST(FilterMethods, EveryFilterWithUniqueNames) {
  const std::vector<FilterMethod> methods = filter_methods(16);
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
      EXPECT_EQ(method.name.rfind(std::string(texture_filter_name(filter)), 0), 0u) << method.name;
    }
    EXPECT_EQ(count, filter == TextureFilter::supersample ? 2 : 1) << texture_filter_name(filter);
  }
}

TEST(FilterMethods, SupersampleAtTheDefaultAndTheDenseGrid) {
  std::set<int> taps;
  for (const FilterMethod& method : filter_methods(16)) {
    if (method.options.filter == TextureFilter::supersample) {
      taps.insert(method.options.supersample_taps);
      EXPECT_EQ(method.name, "supersample_" + std::to_string(method.options.supersample_taps) +
                                 "x" + std::to_string(method.options.supersample_taps));
    }
  }
  EXPECT_EQ(taps, (std::set<int>{SamplerOptions{}.supersample_taps, kDenseSupersampleTaps}));
}

TEST(FilterMethods, AnisotropyGoesIntoTheOptionsAndTheNames) {
  for (const FilterMethod& method : filter_methods(8)) {
    EXPECT_EQ(method.options.max_anisotropy, 8);
    EXPECT_EQ(method.options.wrap_s, WrapMode::repeat);
    EXPECT_EQ(method.options.wrap_t, WrapMode::repeat);
    if (method.options.filter == TextureFilter::anisotropic) {
      EXPECT_EQ(method.name, "anisotropic_8x");
    }
    if (method.options.filter == TextureFilter::ewa) {
      EXPECT_EQ(method.name, "ewa_8x");
    }
  }
}

}  // namespace
}  // namespace edgewise::texture_quality
