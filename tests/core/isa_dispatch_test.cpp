// ISA dispatch: the lists of compiled and supported ISAs agree with each other and with the
// build's, every compiled ISA has a complete kernel table, and a forced ISA (ScopedIsa,
// force_isa, RasterOptions::isa) is the one whose kernels run, as each kernel table reports the
// ISA it was compiled for.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "edgewise/edgewise.hpp"
#include "../isa_params.hpp"
#include "core/kernel_table.hpp"

namespace edgewise::test {
namespace {

const std::vector<Isa> kEveryIsa = every_isa_value();

class NullSink final : public CoverageSink {
 public:
  void consume(std::span<const TileCoverage>) override {}
};

class NullAreaSink final : public AreaSink {
 public:
  void consume(std::span<const AreaTile>) override {}
};

const std::vector<Vec2> kTriangle = {{0.5f, 0.5f}, {12.0f, 1.0f}, {3.0f, 9.0f}};
const RasterTarget kTarget{16, 16, {}};

// The ISA that ran a default-options call, as both entry points report it.
Isa isa_that_runs() {
  NullSink sink;
  const Isa rasterized = rasterize(kTriangle, {}, kTarget, {}, sink).isa;
  EXPECT_EQ(count_coverage(kTriangle, {}, kTarget, {}).report.isa, rasterized);
  return rasterized;
}

TEST(IsaDispatch, CompiledAndSupportedListsAgree) {
  const std::span<const Isa> compiled = compiled_isas();
  ASSERT_FALSE(compiled.empty());
  EXPECT_EQ(compiled.front(), Isa::reference);
  EXPECT_TRUE(std::is_sorted(compiled.begin(), compiled.end()));  // worst first
  EXPECT_EQ(std::adjacent_find(compiled.begin(), compiled.end()), compiled.end());
  // The build's list (cmake/isas.cmake) and the code's (kernels/core/isa_list.hpp) agree.
  std::string names = "reference";
  for (Isa isa : compiled.subspan(1))
    names += "," + std::string(name_of(isa));
  EXPECT_EQ(names, "reference," EDGEWISE_CMAKE_ISAS);

  const std::vector<Isa> supported = supported_isas();
  ASSERT_FALSE(supported.empty());
  EXPECT_EQ(supported.front(), Isa::reference);
  EXPECT_TRUE(std::includes(compiled.begin(), compiled.end(), supported.begin(), supported.end()));
  for (Isa isa : kEveryIsa) {
    const bool listed = std::find(supported.begin(), supported.end(), isa) != supported.end();
    EXPECT_EQ(isa_supported(isa), listed) << name_of(isa);
  }
  EXPECT_EQ(best_isa(), supported.back());
}

TEST(IsaDispatch, NamesRoundTrip) {
  EXPECT_GE(kEveryIsa.size(), compiled_isas().size());
  for (Isa isa : kEveryIsa)
    EXPECT_EQ(parse_name<Isa>(name_of(isa)), isa) << name_of(isa);
  EXPECT_EQ(parse_name<Isa>("sse4.1"), std::nullopt);
  EXPECT_EQ(parse_name<Isa>(""), std::nullopt);
  EXPECT_EQ(parse_name<Isa>("avx512f"), std::nullopt);
}

TEST(IsaDispatch, ParseSupportedIsaExplainsWhatIsAvailable) {
  for (Isa isa : supported_isas())
    EXPECT_EQ(parse_supported_isa(name_of(isa)), isa);
  try {
    parse_supported_isa("avx9");
    FAIL() << "an unknown name was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(
        std::string(error.what()).rfind("unknown ISA 'avx9'; this machine supports reference", 0),
        0u)
        << error.what();
  }
  for (Isa isa : compiled_isas()) {
    if (!isa_supported(isa)) {
      EXPECT_THROW(parse_supported_isa(name_of(isa)), std::invalid_argument);
    }
  }
  EXPECT_THROW(parse_supported_isa("neon_or_not"), std::invalid_argument);
}

TEST(IsaDispatch, DefaultIsTheBestIsaWithoutTheEnvironmentVariable) {
  const char* forced = std::getenv("EDGEWISE_ISA");
  if (forced != nullptr && *forced != '\0') GTEST_SKIP() << "EDGEWISE_ISA=" << forced << " is set";
  EXPECT_EQ(active_isa(), best_isa());
  EXPECT_EQ(isa_that_runs(), best_isa());
}

TEST(IsaDispatch, UnsupportedIsaCannotBeForced) {
  const Isa before = active_isa();
  int unsupported = 0;
  for (Isa isa : kEveryIsa) {
    if (isa_supported(isa)) continue;
    ++unsupported;
    EXPECT_THROW(force_isa(isa), std::invalid_argument) << name_of(isa);
    EXPECT_THROW(ScopedIsa{isa}, std::invalid_argument) << name_of(isa);
    EXPECT_EQ(active_isa(), before);
  }
  EXPECT_GT(unsupported, 0);  // no build has both x86 and AArch64 kernels
}

// rasterize(), count_coverage(), draw(), sample(), force_isa() and parse_supported_isa() refuse
// an ISA this machine lacks in the same words.
TEST(IsaDispatch, EveryEntryPointRefusesAnUnsupportedIsaAlike) {
  std::string supported;
  for (Isa isa : supported_isas())
    supported += (supported.empty() ? "" : ", ") + std::string(name_of(isa));
  int unsupported = 0;
  for (Isa isa : kEveryIsa) {
    if (isa_supported(isa)) continue;
    ++unsupported;
    const std::string expected = "ISA " + std::string(name_of(isa)) +
                                 " is not supported on this machine; it supports " + supported;
    const auto expect_refusal = [&](const char* entry_point, auto&& call) {
      try {
        call();
        ADD_FAILURE() << entry_point << " accepted " << name_of(isa);
      } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find(expected), std::string::npos)
            << entry_point << ": " << error.what();
      }
    };
    RasterOptions raster;
    raster.isa = isa;
    NullSink sink;
    expect_refusal("rasterize", [&] { rasterize(kTriangle, {}, kTarget, raster, sink); });
    expect_refusal("count_coverage", [&] { count_coverage(kTriangle, {}, kTarget, raster); });
    Framebuffer target(16, 16);
    const std::vector<Vec3> positions = {{-1, -1, 0.5f}, {1, -1, 0.5f}, {0, 1, 0.5f}};
    DrawOptions draw_options;
    draw_options.isa = isa;
    expect_refusal("draw", [&] { draw(target, DrawMesh{positions, {}, {}, {}}, draw_options); });
    const std::vector<std::uint8_t> texels(4, 255);
    const Texture texture = Texture::from_rgba8(1, 1, texels, ColorEncoding::linear);
    const std::vector<TextureQuery> queries(1, TextureQuery{0.5f, 0.5f, 0, 0, 0, 0});
    std::vector<Vec4> results(1);
    expect_refusal("sample", [&] { edgewise::sample(texture, {{}, isa}, queries, results); });
    expect_refusal("force_isa", [&] { force_isa(isa); });
    expect_refusal("parse_supported_isa", [&] { parse_supported_isa(name_of(isa)); });
  }
  EXPECT_GT(unsupported, 0);  // no build has both x86 and AArch64 kernels
}

using IsaForcing = IsaTest;

TEST_P(IsaForcing, ScopedIsaChoosesTheKernelsThatRun) {
  const Isa before = active_isa();
  {
    const ScopedIsa scoped(isa());
    EXPECT_EQ(active_isa(), isa());
    EXPECT_EQ(isa_that_runs(), isa());
    {
      const ScopedIsa inner(Isa::reference);
      EXPECT_EQ(isa_that_runs(), Isa::reference);
    }
    EXPECT_EQ(isa_that_runs(), isa());  // the outer choice is restored
  }
  EXPECT_EQ(active_isa(), before);
}

TEST_P(IsaForcing, ForceIsaUntilCleared) {
  const Isa before = active_isa();
  force_isa(isa());
  EXPECT_EQ(isa_that_runs(), isa());
  force_isa(std::nullopt);
  EXPECT_EQ(active_isa(), before);
}

TEST_P(IsaForcing, OptionOverridesTheActiveIsa) {
  for (Isa active : supported_isas()) {
    const ScopedIsa scoped(active);
    RasterOptions options;
    options.isa = isa();
    NullSink sink;
    EXPECT_EQ(rasterize(kTriangle, {}, kTarget, options, sink).isa, isa());
    EXPECT_EQ(count_coverage(kTriangle, {}, kTarget, options).report.isa, isa());
    NullAreaSink area_sink;
    EXPECT_EQ(rasterize_areas(kTriangle, {}, kTarget, options, area_sink).isa, isa());
  }
}

// Every kernel of every table is there, and the table's objects were compiled for its ISA.
TEST_P(IsaForcing, KernelTableIsComplete) {
  const detail::KernelTable& table = detail::kernel_table(isa());
  EXPECT_EQ(table.isa, isa());
  EXPECT_NE(table.rasterize, nullptr);
  EXPECT_NE(table.count_coverage, nullptr);
  EXPECT_NE(table.transform_vertices, nullptr);
  EXPECT_NE(table.map_vertices, nullptr);
  EXPECT_NE(table.assemble_triangles, nullptr);
  EXPECT_NE(table.drop_culled_triangles, nullptr);
  EXPECT_NE(table.shade, nullptr);
  EXPECT_NE(table.resolve_box, nullptr);
  EXPECT_NE(table.resolve_taps, nullptr);
  EXPECT_NE(table.sample, nullptr);
  EXPECT_NE(table.sample_fields, nullptr);
  EXPECT_NE(table.rasterize_areas, nullptr);
  EXPECT_NE(table.rect_sample_ranges, nullptr);
  EXPECT_NE(table.box_sample_ranges, nullptr);
  EXPECT_NE(table.test_sample_rects, nullptr);
  EXPECT_NE(table.occlusion_tile_maxima, nullptr);
  EXPECT_NE(table.resolve_plane_tiles, nullptr);
  static_assert(sizeof(detail::KernelTable) == sizeof(void*) * 18,
                "a kernel was added to KernelTable: check it here");
}

EDGEWISE_INSTANTIATE_PER_ISA(IsaForcing, every_isa());

}  // namespace
}  // namespace edgewise::test
