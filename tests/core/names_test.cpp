// names.hpp's convention for every enum of the API: each value has a distinct name that parses
// back to it, values_of<>() lists every value once in the enum's order, and any other text
// parses to nothing.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <string_view>

#include "edgewise/edgewise.hpp"
#include "draw/vertex_stage/clip.hpp"

namespace edgewise {
namespace {

template <class Enum>
void expect_names_round_trip(int value_count) {
  const std::span<const Enum> values = values_of<Enum>();
  ASSERT_EQ(static_cast<int>(values.size()), value_count);
  std::set<std::string_view> names;
  for (int i = 0; i < value_count; ++i) {
    EXPECT_EQ(static_cast<int>(values[static_cast<std::size_t>(i)]), i);  // in the enum's order
    const std::string_view name = name_of(values[static_cast<std::size_t>(i)]);
    EXPECT_NE(name, "unknown");
    EXPECT_FALSE(name.empty());
    EXPECT_TRUE(names.insert(name).second) << "two values are named " << name;
    EXPECT_EQ(parse_name<Enum>(name), values[static_cast<std::size_t>(i)]) << name;
    EXPECT_EQ(parse_name<Enum>(std::string(name) + "_"), std::nullopt);
  }
  EXPECT_EQ(parse_name<Enum>(""), std::nullopt);
  EXPECT_EQ(parse_name<Enum>("unknown"), std::nullopt);
  EXPECT_EQ(name_of(static_cast<Enum>(value_count)), "unknown");  // past the last value
}

TEST(Names, EveryEnumRoundTrips) {
  expect_names_round_trip<Isa>(6);
  expect_names_round_trip<CullMode>(3);
  expect_names_round_trip<PartialCoverage>(2);
  expect_names_round_trip<TriangleStatus>(6);
  expect_names_round_trip<ClipStatus>(6);
  expect_names_round_trip<InterpolationMethod>(6);
  expect_names_round_trip<Perspective>(2);
  expect_names_round_trip<ResolveFilter>(3);
  expect_names_round_trip<LineCap>(3);
  expect_names_round_trip<LineJoin>(3);
  expect_names_round_trip<DepthTest>(5);
  expect_names_round_trip<Shading>(3);
  expect_names_round_trip<TextureDerivatives>(2);
  expect_names_round_trip<TextureFilter>(11);
  expect_names_round_trip<WrapMode>(3);
  expect_names_round_trip<LodFormula>(2);
  expect_names_round_trip<FilterPrecision>(3);
  expect_names_round_trip<TexelFormat>(2);
  expect_names_round_trip<ColorEncoding>(2);
  expect_names_round_trip<PyramidFilter>(2);
}

TEST(Names, ToolSpellingsStay) {
  // The names the tools' options and output files use.
  EXPECT_EQ(name_of(WrapMode::clamp_to_edge), "clamp");
  EXPECT_EQ(name_of(Isa::sse4_1), "sse4_1");
  EXPECT_EQ(name_of(Isa::avx512), "avx512");
  EXPECT_EQ(name_of(TextureFilter::bicubic_catmull_rom), "bicubic_catmull_rom");
  EXPECT_EQ(parse_name<WrapMode>("clamp_to_edge"), std::nullopt);
}

}  // namespace
}  // namespace edgewise
