// Every ISA's texture filters against the double-precision reference, on random textures (8-bit
// linear and sRGB, float with values outside [0, 1], odd and one-texel-wide sizes) and random
// queries from deep magnification to extreme anisotropy, far-out coordinates and bad input,
// within the per-query bounds of tests/texture/sample_bounds.hpp.
//
// Budget: EDGEWISE_SAMPLE_QUERIES random queries per texture, filter and wrap (default 203, not a
// multiple of any lane count, so that every run ends on a partial batch). Under qemu the
// double-precision reference is the slow part; that run may set fewer.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "env_number.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "texture/sample_reference.hpp"
#include "texture/sample_bounds.hpp"

namespace edgewise {
namespace {

using test::Random;

struct TestTexture {
  std::string name;
  Texture texture;
  test::TextureExtremes extremes;
};

TestTexture make_texture(std::string name, std::int32_t width, std::int32_t height,
                         TexelFormat format, ColorEncoding encoding, std::uint64_t seed) {
  Random random(seed);
  const TextureBuild build{PyramidFilter::box, true, true};
  const std::size_t values = 4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  Texture texture = [&] {
    if (format == TexelFormat::rgba8) {
      std::vector<std::uint8_t> texels(values);
      for (std::uint8_t& v : texels)
        v = static_cast<std::uint8_t>(random.integer(0, 255));
      return Texture::from_rgba8(width, height, texels, encoding, build);
    }
    std::vector<float> texels(values);
    for (float& v : texels)
      v = static_cast<float>(random.uniform(-2.0, 3.0));
    return Texture::from_rgba32f(width, height, texels, build);
  }();
  const test::TextureExtremes extremes = test::texture_extremes(texture);
  return {std::move(name), std::move(texture), extremes};
}

std::vector<TestTexture> test_textures() {
  std::vector<TestTexture> textures;
  textures.push_back(
      make_texture("rgba8 37x19", 37, 19, TexelFormat::rgba8, ColorEncoding::linear, 1));
  textures.push_back(
      make_texture("rgba8 64x64", 64, 64, TexelFormat::rgba8, ColorEncoding::linear, 2));
  textures.push_back(make_texture("rgba8 1x7", 1, 7, TexelFormat::rgba8, ColorEncoding::linear, 3));
  textures.push_back(
      make_texture("srgb 33x33", 33, 33, TexelFormat::rgba8, ColorEncoding::srgb, 4));
  textures.push_back(
      make_texture("float 20x13", 20, 13, TexelFormat::rgba32f, ColorEncoding::linear, 5));
  textures.push_back(
      make_texture("rgba8 256x3", 256, 3, TexelFormat::rgba8, ColorEncoding::linear, 6));
  return textures;
}

// A derivative pair of a footprint in level-0 texels: random size from deep magnification to far
// past the coarsest level, random anisotropy up to 1:200, random orientation; some degenerate.
void random_derivatives(Random& random, const Texture& texture, TextureQuery& q) {
  const double kind = random.uniform();
  if (kind < 0.04) {
    q.dsdx = q.dtdx = q.dsdy = q.dtdy = 0.0f;
    return;
  }
  const double size = std::exp2(random.uniform(-8.0, 12.0));
  const double ratio = kind < 0.5 ? 1.0 + random.uniform() : std::exp2(random.uniform(0.0, 7.6));
  const double angle = random.uniform(0.0, 6.283185307179586);
  const double major[2] = {size * std::cos(angle), size * std::sin(angle)};
  const double minor[2] = {-major[1] / ratio, major[0] / ratio};
  const bool swap = random.uniform() < 0.5;
  const double* x = swap ? minor : major;
  const double* y = swap ? major : minor;
  q.dsdx = static_cast<float>(x[0] / texture.width());
  q.dtdx = static_cast<float>(x[1] / texture.height());
  q.dsdy = static_cast<float>(y[0] / texture.width());
  q.dtdy = static_cast<float>(y[1] / texture.height());
  if (kind < 0.06) q.dsdy = q.dtdy = 0.0f;  // a line footprint
}

std::vector<TextureQuery> random_queries(Random& random, const Texture& texture,
                                         std::size_t count) {
  std::vector<TextureQuery> queries(count);
  const float bad[] = {std::numeric_limits<float>::quiet_NaN(),
                       std::numeric_limits<float>::infinity(),
                       -std::numeric_limits<float>::infinity(), 3.0e38f};
  for (TextureQuery& q : queries) {
    const double where = random.uniform();
    const double span = where < 0.8 ? 3.0 : (where < 0.95 ? 1.0e3 : 1.0e7);
    q.s = static_cast<float>(random.uniform(-span, span + 1.0));
    q.t = static_cast<float>(random.uniform(-span, span + 1.0));
    random_derivatives(random, texture, q);
    if (random.uniform() < 0.03) {  // bad input in one field
      float* fields[6] = {&q.s, &q.t, &q.dsdx, &q.dtdx, &q.dsdy, &q.dtdy};
      *fields[random.integer(0, 5)] = bad[random.integer(0, 3)];
    }
  }
  return queries;
}

struct FilterCase {
  TextureFilter filter;
  int supersample_taps = 4;
  int max_anisotropy = 16;
  LodFormula lod = LodFormula::exact;
  float lod_bias = 0.0f;
};

std::vector<FilterCase> filter_cases() {
  return {{TextureFilter::nearest},
          {TextureFilter::bilinear},
          {TextureFilter::bicubic_catmull_rom},
          {TextureFilter::bicubic_bspline},
          {TextureFilter::mip_nearest},
          {TextureFilter::mip_nearest, 4, 16, LodFormula::max_axis, 0.5f},
          {TextureFilter::trilinear},
          {TextureFilter::trilinear, 4, 16, LodFormula::max_axis, -0.75f},
          {TextureFilter::supersample, 1},
          {TextureFilter::supersample, 3},
          {TextureFilter::ripmap},
          {TextureFilter::anisotropic, 4, 1},
          {TextureFilter::anisotropic, 4, 4},
          {TextureFilter::anisotropic, 4, 16},
          {TextureFilter::anisotropic, 4, 16, LodFormula::max_axis, 0.25f},
          {TextureFilter::summed_area},
          {TextureFilter::ewa, 4, 4},
          {TextureFilter::ewa, 4, 16, LodFormula::exact, -0.5f},
          // A strongly negative bias: the work bound picks the levels on large footprints.
          {TextureFilter::ewa, 4, 2, LodFormula::exact, -8.0f},
          {TextureFilter::ewa, 4, 64, LodFormula::exact, -8.0f}};
}

class SampleDifferential : public test::IsaTest {};

TEST_P(SampleDifferential, EveryFilterWithinItsBoundOfTheReference) {
  const std::size_t per_case = test::env_number("EDGEWISE_SAMPLE_QUERIES", 203);
  ASSERT_GT(per_case, 0u) << "EDGEWISE_SAMPLE_QUERIES=0 would compare nothing";
  const std::vector<TestTexture> textures = test_textures();
  const WrapMode wraps[3] = {WrapMode::repeat, WrapMode::clamp_to_edge, WrapMode::mirror};
  std::size_t compared = 0;
  std::uint64_t seed = 100;
  for (const TestTexture& t : textures) {
    for (const FilterCase& c : filter_cases()) {
      for (int w = 0; w < 6; ++w) {
        SamplerOptions options;
        // Both precisions of the taps, on alternate wrap pairs.
        options.precision = w < 3 ? FilterPrecision::float32 : FilterPrecision::fixed16;
        options.filter = c.filter;
        options.supersample_taps = c.supersample_taps;
        options.max_anisotropy = c.max_anisotropy;
        options.lod = c.lod;
        options.lod_bias = c.lod_bias;
        options.wrap_s = wraps[w % 3];
        options.wrap_t = wraps[(w + 1 + w / 3) % 3];
        Random random(++seed);
        const std::vector<TextureQuery> queries = random_queries(random, t.texture, per_case);
        std::vector<Vec4> fast(queries.size());
        sample(t.texture, {options, isa()}, queries, fast);
        for (std::size_t i = 0; i < queries.size(); ++i) {
          const TextureQuery& q = queries[i];
          const float got[4] = {fast[i].x, fast[i].y, fast[i].z, fast[i].w};
          const double allowed = test::sample_bound(t.texture, t.extremes, options, q);
          const double best = test::distance_to_reference(t.texture, options, q, fast[i]);
          ASSERT_TRUE(std::isfinite(got[0]) && std::isfinite(got[1]) && std::isfinite(got[2]) &&
                      std::isfinite(got[3]))
              << t.name << " " << name_of(c.filter) << " query " << i << ": s " << q.s << " t "
              << q.t << " d " << q.dsdx << " " << q.dtdx << " " << q.dsdy << " " << q.dtdy;
          ASSERT_LE(best, allowed)
              << t.name << " " << name_of(c.filter) << " wrap " << name_of(options.wrap_s) << "/"
              << name_of(options.wrap_t) << " query " << i << ": s " << q.s << " t " << q.t << " d "
              << q.dsdx << " " << q.dtdx << " " << q.dsdy << " " << q.dtdy;
          ++compared;
        }
      }
    }
  }
  RecordProperty("compared", std::to_string(compared));
}

// The promised 8-bit accuracy: for textures up to 1024 texels a side, and positions and
// footprints within a few periods (|s| + |t| + the derivatives' magnitudes below 4), every bound
// above is within 1/255. Past that, float32 positions lose sub-texel bits in proportion to the
// texture's size (the reference keeps them): at 4096 texels the Catmull-Rom bound is about 2/255.
TEST(SampleBound, EightBitResultsWithinOneLevel) {
  const TestTexture t =
      make_texture("rgba8 1024x8", 1024, 8, TexelFormat::rgba8, ColorEncoding::linear, 7);
  for (const FilterCase& c : filter_cases()) {
    // EWA's bound (ewa_bound above) counts every texel of the ellipse's box as moved by the
    // whole position error: valid, but far looser than the error it bounds.
    if (c.filter == TextureFilter::ewa) continue;
    SamplerOptions options;
    options.filter = c.filter;
    options.supersample_taps = c.supersample_taps;
    options.max_anisotropy = c.max_anisotropy;
    const TextureQuery q{0.9f, -0.9f, 0.5f, 0.5f, -0.5f, 0.5f};
    EXPECT_LE(test::sample_bound(t.texture, t.extremes, options, q), 1.0 / 255.0)
        << name_of(c.filter);
  }
}

TEST_P(SampleDifferential, BadQueriesGiveTheirDefinedResults) {
  const TestTexture t =
      make_texture("rgba8 16x16", 16, 16, TexelFormat::rgba8, ColorEncoding::linear, 8);
  const reference::Rgba average = reference::coarsest_texel(t.texture);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<TextureQuery> queries = {{nan, 0.5f, 0, 0, 0, 0},
                                             {0.5f, inf, 0, 0, 0, 0},
                                             {0.5f, 0.5f, nan, 0, 0, 0},
                                             {0.5f, 0.5f, 0, 0, 0, -inf}};
  for (const FilterCase& c : filter_cases()) {
    SamplerOptions options;
    options.filter = c.filter;
    std::vector<Vec4> out(queries.size());
    sample(t.texture, {options, isa()}, queries, out);
    for (int i = 0; i < 2; ++i) {
      EXPECT_EQ(out[i].x, 0.0f);
      EXPECT_EQ(out[i].w, 0.0f);
    }
    const bool derivatives = c.filter != TextureFilter::nearest &&
                             c.filter != TextureFilter::bilinear &&
                             c.filter != TextureFilter::bicubic_catmull_rom &&
                             c.filter != TextureFilter::bicubic_bspline;
    for (int i = 2; i < 4; ++i) {
      ASSERT_TRUE(std::isfinite(out[i].x));
      // The coarsest texel is stored: float32 decoding is within 2^-24 of it.
      if (derivatives) {
        EXPECT_NEAR(out[i].x, average[0], 0x1p-23) << name_of(c.filter);
      }
    }
  }
}

// 8-bit taps load a tap row's two texels together where no lane of the batch wraps between them,
// one by one otherwise (docs/design/textures.md), and both must give the same bits: queries
// inside the texture with small footprints (levels at least 8 texels wide, where no tap wraps)
// are sampled, then again with the first query moved to where its tap rows wrap or clamp, which
// sends its whole batch down the other path. Every other query's result must stay the same.
TEST_P(SampleDifferential, TexelPairsAndSingleTexelsGiveTheSameBits) {
  for (ColorEncoding encoding : {ColorEncoding::linear, ColorEncoding::srgb}) {
    const TestTexture t = make_texture("rgba8 64x48", 64, 48, TexelFormat::rgba8, encoding, 9);
    for (TextureFilter filter :
         {TextureFilter::bilinear, TextureFilter::trilinear, TextureFilter::anisotropic}) {
      for (WrapMode wrap : {WrapMode::repeat, WrapMode::clamp_to_edge, WrapMode::mirror}) {
        for (FilterPrecision precision : {FilterPrecision::float32, FilterPrecision::fixed16}) {
          SamplerOptions options;
          options.precision = precision;
          options.filter = filter;
          options.wrap_s = options.wrap_t = wrap;
          Random random(static_cast<std::uint64_t>(filter) * 3 + static_cast<std::uint64_t>(wrap));
          std::vector<TextureQuery> queries(37);
          for (TextureQuery& q : queries) {
            q.s = static_cast<float>(random.uniform(0.25, 0.45));
            q.t = static_cast<float>(random.uniform(0.25, 0.45));
            // Up to 3 texels of level 0 per pixel: lambda below 2, levels of 16 x 12 texels or
            // more.
            q.dsdx = static_cast<float>(random.uniform(0.2, 3.0) / 64.0);
            q.dtdx = static_cast<float>(random.uniform(-0.5, 0.5) / 48.0);
            q.dsdy = static_cast<float>(random.uniform(-0.5, 0.5) / 64.0);
            q.dtdy = static_cast<float>(random.uniform(0.2, 3.0) / 48.0);
          }
          std::vector<Vec4> together(queries.size()), apart(queries.size());
          sample(t.texture, {options, isa()}, queries, together);
          queries[0].s = 0.999f;  // x0 = 63 in level 0: the row wraps (repeat) or clamps
          sample(t.texture, {options, isa()}, queries, apart);
          for (std::size_t i = 1; i < queries.size(); ++i) {
            const float a[4] = {together[i].x, together[i].y, together[i].z, together[i].w};
            const float b[4] = {apart[i].x, apart[i].y, apart[i].z, apart[i].w};
            for (int k = 0; k < 4; ++k) {
              ASSERT_EQ(a[k], b[k]) << name_of(filter) << " " << name_of(wrap) << " "
                                    << name_of(precision) << " query " << i << " channel " << k;
            }
          }
        }
      }
    }
  }
}

// AVX-512 runs the float filters made of taps 16 lanes at a time, AVX2 8: the same float
// operations per query, so the results are identical bit for bit, on every test texture and wrap
// pair, with bad queries among them and a last batch that is partial on both.
TEST(SampleWidth, Avx512TapsEqualAvx2BitForBit) {
  if (!isa_supported(Isa::avx512) || !isa_supported(Isa::avx2)) {
    GTEST_SKIP() << "this CPU lacks AVX-512 or AVX2";
  }
  const WrapMode wraps[3] = {WrapMode::repeat, WrapMode::clamp_to_edge, WrapMode::mirror};
  std::size_t compared = 0;
  std::uint64_t seed = 500;
  for (const TestTexture& t : test_textures()) {
    for (const FilterCase& c : filter_cases()) {
      if (!reads_bilinear_taps(c.filter)) continue;
      for (int w = 0; w < 3; ++w) {
        SamplerOptions options;
        options.precision = FilterPrecision::float32;
        options.filter = c.filter;
        options.supersample_taps = c.supersample_taps;
        options.max_anisotropy = c.max_anisotropy;
        options.lod = c.lod;
        options.lod_bias = c.lod_bias;
        options.wrap_s = wraps[w];
        options.wrap_t = wraps[(w + 1) % 3];
        Random random(++seed);
        const std::vector<TextureQuery> queries = random_queries(random, t.texture, 203);
        std::vector<Vec4> eight(queries.size()), sixteen(queries.size());
        sample(t.texture, {options, Isa::avx2}, queries, eight);
        sample(t.texture, {options, Isa::avx512}, queries, sixteen);
        for (std::size_t i = 0; i < queries.size(); ++i) {
          const float a[4] = {eight[i].x, eight[i].y, eight[i].z, eight[i].w};
          const float b[4] = {sixteen[i].x, sixteen[i].y, sixteen[i].z, sixteen[i].w};
          for (int k = 0; k < 4; ++k) {
            ASSERT_EQ(std::bit_cast<std::uint32_t>(a[k]), std::bit_cast<std::uint32_t>(b[k]))
                << t.name << " " << name_of(c.filter) << " wrap " << name_of(options.wrap_s) << "/"
                << name_of(options.wrap_t) << " query " << i << " channel " << k;
          }
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 10000u);
}

// fixed16 weighs a tap row's two texels by integers in units of 2^-15 and sums exactly: on a
// 2x1 texture of red codes 0 and 255, s = 0.4 puts the tap at u = 0.8f - 0.5f (exact), so the
// right texel's weight is round(u 2^15) = 9830 and red is 9830 * 255 / 2^15 codes, where float32
// gives u * 255. Alpha (255 on both) sums to exactly 255 in both.
TEST_P(SampleDifferential, FixedPointTapsWeighByFifteenBitIntegers) {
  const std::vector<std::uint8_t> texels = {0, 0, 0, 255, 255, 0, 0, 255};
  const Texture texture = Texture::from_rgba8(2, 1, texels, ColorEncoding::linear);
  const std::vector<TextureQuery> queries(5, TextureQuery{0.4f, 0.5f, 0, 0, 0, 0});
  const float u = 0.8f - 0.5f;
  for (FilterPrecision precision : {FilterPrecision::float32, FilterPrecision::fixed16}) {
    SamplerOptions options;
    options.filter = TextureFilter::bilinear;
    options.precision = precision;
    std::vector<Vec4> out(queries.size());
    sample(texture, {options, isa()}, queries, out);
    // One rounding of the sum's scaling and one of the code scale 1 / 255 apart from the exact.
    const double expected = precision == FilterPrecision::fixed16 ? 9830.0 / 32768.0 : double(u);
    for (const Vec4& v : out) {
      EXPECT_NEAR(v.x, expected, 0x1p-22) << name_of(precision);
      EXPECT_NEAR(v.w, 1.0, 0x1p-23) << name_of(precision);
    }
  }
  EXPECT_GT(double(u) - 9830.0 / 32768.0, 0x1p-20);  // the two expectations are told apart
}

TEST(SamplePrecision, FixedPointOnlyWhereItApplies) {
  const std::vector<std::uint8_t> texels(4 * 4 * 4, 128);
  const Texture linear = Texture::from_rgba8(4, 4, texels, ColorEncoding::linear);
  const Texture srgb = Texture::from_rgba8(4, 4, texels, ColorEncoding::srgb);
  const std::vector<float> floats(4 * 4 * 4, 0.5f);
  const Texture hdr = Texture::from_rgba32f(4, 4, floats);
  SamplerOptions options;
  options.filter = TextureFilter::trilinear;
  options.precision = FilterPrecision::fixed16;
  EXPECT_EQ(effective_precision(linear, options), FilterPrecision::fixed16);
  EXPECT_EQ(effective_precision(srgb, options), FilterPrecision::float32);
  EXPECT_EQ(effective_precision(hdr, options), FilterPrecision::float32);
  options.precision = FilterPrecision::automatic;
  EXPECT_EQ(effective_precision(linear, options), default_precision(TextureFilter::trilinear));
  for (TextureFilter filter : {TextureFilter::nearest, TextureFilter::bicubic_catmull_rom,
                               TextureFilter::summed_area, TextureFilter::ewa}) {
    options.filter = filter;
    options.precision = FilterPrecision::fixed16;
    EXPECT_EQ(effective_precision(linear, options), FilterPrecision::float32) << name_of(filter);
    EXPECT_EQ(default_precision(filter), FilterPrecision::float32) << name_of(filter);
  }
}

TEST(SampleArguments, RejectsMismatchedSpansAndOptionsOutOfRange) {
  const TestTexture t =
      make_texture("rgba8 4x4", 4, 4, TexelFormat::rgba8, ColorEncoding::linear, 9);
  std::vector<TextureQuery> queries(3, TextureQuery{0.5f, 0.5f, 0, 0, 0, 0});
  std::vector<Vec4> out(2);
  EXPECT_THROW(sample(t.texture, {}, queries, out), std::invalid_argument);
  out.resize(3);
  SamplerOptions options;
  options.max_anisotropy = 0;
  EXPECT_THROW(sample(t.texture, options, queries, out), std::invalid_argument);
  options = {};
  options.supersample_taps = 17;
  EXPECT_THROW(sample(t.texture, options, queries, out), std::invalid_argument);
  options = {};
  options.lod_bias = std::numeric_limits<float>::infinity();
  EXPECT_THROW(sample(t.texture, options, queries, out), std::invalid_argument);
  options = {};
  options.precision = static_cast<FilterPrecision>(3);
  EXPECT_THROW(sample(t.texture, options, queries, out), std::invalid_argument);
  const std::vector<std::uint8_t> texels(4 * 4 * 4, 128);
  const Texture bare = Texture::from_rgba8(4, 4, texels, ColorEncoding::linear);
  for (TextureFilter filter : {TextureFilter::summed_area, TextureFilter::ripmap}) {
    options = {};
    options.filter = filter;  // the texture was built without its table or ripmaps
    EXPECT_THROW(sample(bare, options, queries, out), std::invalid_argument);
  }
  EXPECT_NO_THROW(sample(t.texture, {}, std::span<const TextureQuery>(), std::span<Vec4>()));
}

TEST(SampleNames, RoundTrip) {
  for (int f = 0; f <= static_cast<int>(TextureFilter::ewa); ++f) {
    const auto filter = static_cast<TextureFilter>(f);
    EXPECT_EQ(parse_name<TextureFilter>(name_of(filter)), filter);
  }
  for (WrapMode wrap : {WrapMode::repeat, WrapMode::clamp_to_edge, WrapMode::mirror})
    EXPECT_EQ(parse_name<WrapMode>(name_of(wrap)), wrap);
  for (LodFormula lod : {LodFormula::exact, LodFormula::max_axis})
    EXPECT_EQ(parse_name<LodFormula>(name_of(lod)), lod);
  EXPECT_FALSE(parse_name<TextureFilter>("bogus"));
}

INSTANTIATE_TEST_SUITE_P(Isas, SampleDifferential, ::testing::ValuesIn(test::fast_isas()),
                         test::isa_test_name);

}  // namespace
}  // namespace edgewise
