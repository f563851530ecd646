// edgewise-sample against the library: images written here, queries written here, the tool's
// result file compared bit for bit with sample() on a Texture built from the same texels, on the
// same ISA. Also: what each option changes, every channel layout and pixel type the loader
// expands, sRGB decoding, files of more than one chunk, a piped query stream and an empty one.
#include <gtest/gtest.h>

#include <OpenImageIO/typedesc.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "bitwise_compare.hpp"
#include "edgewise/isa.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "isa_params.hpp"
#include "query_mix.hpp"
#include "random.hpp"
#include "scene/temp_directory.hpp"
#include "test_files.hpp"
#include "tool_run.hpp"

namespace edgewise::sample_cli_test {
namespace {

using scene::test::TempDirectory;

constexpr TextureFilter kEveryFilter[] = {
    TextureFilter::nearest,         TextureFilter::bilinear,    TextureFilter::bicubic_catmull_rom,
    TextureFilter::bicubic_bspline, TextureFilter::mip_nearest, TextureFilter::trilinear,
    TextureFilter::supersample,     TextureFilter::ripmap,      TextureFilter::summed_area,
    TextureFilter::anisotropic,     TextureFilter::ewa};

// Odd sizes: every pyramid level but the last has an odd side somewhere.
constexpr int kWidth = 37, kHeight = 23;
constexpr std::size_t kQueryCount = 2000;

template <class T>
std::vector<T> random_values(std::size_t count, std::uint64_t seed, T lo, T hi) {
  test::Random random(seed);
  std::vector<T> values(count);
  for (T& v : values) {
    if constexpr (std::is_integral_v<T>) {
      v = static_cast<T>(random.integer(lo, hi));
    } else {
      v = static_cast<T>(random.uniform(lo, hi));
    }
  }
  return values;
}

// Every texel channel random, alpha included: a loader that premultiplied alpha, or dropped or
// swapped a channel, would change results.
std::vector<std::uint8_t> random_rgba8(int width, int height, std::uint64_t seed) {
  return random_values<std::uint8_t>(4 * static_cast<std::size_t>(width) * height, seed, 0, 255);
}

TextureBuild build_for(TextureFilter filter) {
  return {PyramidFilter::box, filter == TextureFilter::ripmap,
          filter == TextureFilter::summed_area};
}

std::vector<Vec4> library_sample(const Texture& texture, const SamplerOptions& options,
                                 const std::vector<TextureQuery>& queries,
                                 std::optional<Isa> isa = std::nullopt) {
  std::vector<Vec4> out(queries.size());
  sample(texture, {options, isa}, queries, out);
  return out;
}

// The tool's arguments for the usual files, then `extra`.
std::vector<std::string> tool_args(const std::string& texture, TextureFilter filter,
                                   const std::string& queries, const std::string& out,
                                   std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"--texture", texture, "--filter", std::string(name_of(filter)),
                                   "--queries", queries, "--out",    out};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

struct RoundTripFiles {
  std::string image, queries, out, scratch;
};

RoundTripFiles files_in(const TempDirectory& dir, const std::string& image_name) {
  const std::string d = dir.path().string();
  return {d + "/" + image_name, d + "/queries.bin", d + "/results.bin", d};
}

// Runs the tool on a random texture and random queries with `filter` (and `isa_args`), and
// expects its results to be sample()'s on `isa` bit for bit, and its summary to name what was
// built and the ISA.
void expect_round_trip(const RoundTripFiles& f, TextureFilter filter,
                       const std::vector<std::string>& isa_args, Isa isa) {
  SCOPED_TRACE(std::string(name_of(filter)) + " on " + std::string(name_of(isa)));
  const std::vector<std::uint8_t> texels = random_rgba8(kWidth, kHeight, 41);
  write_image(f.image, kWidth, kHeight, 4, OIIO::TypeDesc::UINT8, texels.data());
  const std::vector<TextureQuery> queries = mixed_queries(42, kQueryCount, kWidth, kHeight);
  write_queries(f.queries, queries);
  const ToolRun run =
      run_sample_tool(tool_args(f.image, filter, f.queries, f.out, isa_args), f.scratch);
  ASSERT_EQ(run.status, 0) << run.summary();
  const Texture texture =
      Texture::from_rgba8(kWidth, kHeight, texels, ColorEncoding::linear, build_for(filter));
  SamplerOptions options;
  options.filter = filter;
  EXPECT_TRUE(bitwise_equal(read_results(f.out), library_sample(texture, options, queries, isa)));

  EXPECT_TRUE(contains(run.out, std::to_string(kQueryCount) + " queries")) << run.out;
  EXPECT_TRUE(contains(run.out, "37x23, 4 channels uint8 -> rgba8 linear, 6 mip levels"))
      << run.out;
  EXPECT_TRUE(contains(run.out, "ISA " + std::string(name_of(isa)))) << run.out;
  EXPECT_EQ(contains(run.out, "ripmaps"), filter == TextureFilter::ripmap) << run.out;
  EXPECT_EQ(contains(run.out, "summed-area table"), filter == TextureFilter::summed_area)
      << run.out;
}

// The core promise: the file the tool writes is what sample() returns, for every filter, on the
// ISA both pick by themselves (active_isa()). The summary names what was built.
TEST(SampleToolRoundTrip, EveryFilterMatchesTheLibraryBitForBit) {
  const TempDirectory dir;
  const RoundTripFiles f = files_in(dir, "texture.png");
  for (TextureFilter filter : kEveryFilter)
    expect_round_trip(f, filter, {}, active_isa());
}

// --isa NAME, or --reference, reaches the sampler: the results are sample()'s on that ISA, and the
// summary names it. What each filter computes on each ISA is sample()'s own test
// (SampleDifferential); the tool's part is to pass the ISA on, shown here with bilinear and EWA.
class SampleToolIsa : public test::IsaTest {};

TEST_P(SampleToolIsa, TheIsaAskedForSamples) {
  const TempDirectory dir;
  const RoundTripFiles f = files_in(dir, "texture.png");
  const std::vector<std::string> isa_args =
      isa() == Isa::reference ? std::vector<std::string>{"--reference"}
                              : std::vector<std::string>{"--isa", std::string(name_of(isa()))};
  for (TextureFilter filter : {TextureFilter::bilinear, TextureFilter::ewa})
    expect_round_trip(f, filter, isa_args, isa());
}

EDGEWISE_INSTANTIATE_PER_ISA(SampleToolIsa, test::every_isa());

// One option on the command line and the SamplerOptions / texture it must produce.
struct OptionCase {
  std::string name;
  TextureFilter filter;
  std::vector<std::string> args;
  std::function<void(SamplerOptions&, TextureBuild&, ColorEncoding&)> apply;
};

// Each option reaches the sampler: the tool's results equal the library's with that option set,
// and differ from the library's without it (so that an ignored option would be caught). No --isa:
// the tool and the library both run active_isa().
TEST(SampleTool, EachOptionReachesTheSampler) {
  const TempDirectory dir;
  const RoundTripFiles f = files_in(dir, "texture.png");
  const std::vector<std::uint8_t> texels = random_rgba8(kWidth, kHeight, 43);
  write_image(f.image, kWidth, kHeight, 4, OIIO::TypeDesc::UINT8, texels.data());
  const std::vector<TextureQuery> queries = mixed_queries(44, kQueryCount, kWidth, kHeight);
  write_queries(f.queries, queries);

  const std::vector<OptionCase> cases = {
      {"wrap",
       TextureFilter::bilinear,
       {"--wrap", "mirror"},
       [](SamplerOptions& o, TextureBuild&, ColorEncoding&) {
         o.wrap_s = o.wrap_t = WrapMode::mirror;
       }},
      {"wrap_s_over_wrap",
       TextureFilter::bilinear,
       {"--wrap-s", "mirror", "--wrap", "clamp"},
       [](SamplerOptions& o, TextureBuild&, ColorEncoding&) {
         o.wrap_s = WrapMode::mirror;
         o.wrap_t = WrapMode::clamp_to_edge;
       }},
      {"wrap_t",
       TextureFilter::bicubic_catmull_rom,
       {"--wrap-t", "clamp"},
       [](SamplerOptions& o, TextureBuild&, ColorEncoding&) {
         o.wrap_t = WrapMode::clamp_to_edge;
       }},
      {"lod",
       TextureFilter::trilinear,
       {"--lod", "max_axis"},
       [](SamplerOptions& o, TextureBuild&, ColorEncoding&) { o.lod = LodFormula::max_axis; }},
      {"lod_bias",
       TextureFilter::mip_nearest,
       {"--lod-bias", "0.75"},
       [](SamplerOptions& o, TextureBuild&, ColorEncoding&) { o.lod_bias = 0.75f; }},
      {"max_aniso",
       TextureFilter::anisotropic,
       {"--max-aniso", "3"},
       [](SamplerOptions& o, TextureBuild&, ColorEncoding&) { o.max_anisotropy = 3; }},
      {"max_aniso_ewa",
       TextureFilter::ewa,
       {"--max-aniso", "2"},
       [](SamplerOptions& o, TextureBuild&, ColorEncoding&) { o.max_anisotropy = 2; }},
      {"taps",
       TextureFilter::supersample,
       {"--taps", "2"},
       [](SamplerOptions& o, TextureBuild&, ColorEncoding&) { o.supersample_taps = 2; }},
      {"pyramid",
       TextureFilter::trilinear,
       {"--pyramid", "lanczos3"},
       [](SamplerOptions&, TextureBuild& b, ColorEncoding&) {
         b.filter = PyramidFilter::lanczos3;
       }},
      {"srgb",
       TextureFilter::trilinear,
       {"--srgb"},
       [](SamplerOptions&, TextureBuild&, ColorEncoding& e) { e = ColorEncoding::srgb; }},
  };
  for (const OptionCase& c : cases) {
    SCOPED_TRACE(c.name);
    const ToolRun run =
        run_sample_tool(tool_args(f.image, c.filter, f.queries, f.out, c.args), f.scratch);
    ASSERT_EQ(run.status, 0) << run.summary();

    SamplerOptions defaults, options;
    defaults.filter = options.filter = c.filter;
    TextureBuild build = build_for(c.filter);
    ColorEncoding encoding = ColorEncoding::linear;
    c.apply(options, build, encoding);
    const Texture plain =
        Texture::from_rgba8(kWidth, kHeight, texels, ColorEncoding::linear, build_for(c.filter));
    const Texture texture = Texture::from_rgba8(kWidth, kHeight, texels, encoding, build);
    const std::vector<Vec4> expected = library_sample(texture, options, queries);
    EXPECT_TRUE(bitwise_equal(read_results(f.out), expected));
    EXPECT_FALSE(bitwise_equal(library_sample(plain, defaults, queries), expected))
        << "the option changes nothing on these queries: the comparison proves nothing";
  }
}

// Float images become rgba32f textures with their values as stored, outside [0, 1] too.
TEST(SampleTool, FloatExrMatchesTheLibrary) {
  const TempDirectory dir;
  const RoundTripFiles f = files_in(dir, "texture.exr");
  constexpr int w = 29, h = 17;
  const std::vector<float> texels =
      random_values<float>(4 * static_cast<std::size_t>(w) * h, 45, -2.0f, 3.0f);
  write_image(f.image, w, h, 4, OIIO::TypeDesc::FLOAT, texels.data());
  const std::vector<TextureQuery> queries = mixed_queries(46, kQueryCount, w, h);
  write_queries(f.queries, queries);
  for (TextureFilter filter : {TextureFilter::bilinear, TextureFilter::trilinear,
                               TextureFilter::summed_area, TextureFilter::ewa}) {
    SCOPED_TRACE(std::string(name_of(filter)));
    const ToolRun run = run_sample_tool(tool_args(f.image, filter, f.queries, f.out), f.scratch);
    ASSERT_EQ(run.status, 0) << run.summary();
    EXPECT_TRUE(contains(run.out, "29x17, 4 channels float -> rgba32f linear")) << run.out;
    const Texture texture = Texture::from_rgba32f(w, h, texels, build_for(filter));
    SamplerOptions options;
    options.filter = filter;
    EXPECT_TRUE(bitwise_equal(read_results(f.out), library_sample(texture, options, queries)));
  }
}

// 1, 2 and 3 channels expand to RGBA: grey -> (g, g, g, 1), grey and alpha -> (g, g, g, a),
// RGB -> (r, g, b, 1).
TEST(SampleTool, ChannelsExpandToRgba) {
  const TempDirectory dir;
  const RoundTripFiles f = files_in(dir, "texture.png");
  constexpr int w = 11, h = 6;
  const std::size_t texels = static_cast<std::size_t>(w) * h;
  const std::vector<TextureQuery> queries = mixed_queries(47, kQueryCount, w, h);
  write_queries(f.queries, queries);
  for (int channels = 1; channels <= 3; ++channels) {
    SCOPED_TRACE(std::to_string(channels) + " channels");
    const std::vector<std::uint8_t> pixels =
        random_values<std::uint8_t>(texels * channels, 48 + channels, 0, 255);
    write_image(f.image, w, h, channels, OIIO::TypeDesc::UINT8, pixels.data());
    std::vector<std::uint8_t> rgba(4 * texels);
    for (std::size_t i = 0; i < texels; ++i) {
      const std::uint8_t* p = &pixels[i * channels];
      const bool grey = channels < 3;
      rgba[4 * i + 0] = p[0];
      rgba[4 * i + 1] = grey ? p[0] : p[1];
      rgba[4 * i + 2] = grey ? p[0] : p[2];
      rgba[4 * i + 3] = channels == 2 ? p[1] : 255;
    }
    const ToolRun run =
        run_sample_tool(tool_args(f.image, TextureFilter::bilinear, f.queries, f.out), f.scratch);
    ASSERT_EQ(run.status, 0) << run.summary();
    const Texture texture = Texture::from_rgba8(w, h, rgba, ColorEncoding::linear);
    SamplerOptions options;
    options.filter = TextureFilter::bilinear;
    EXPECT_TRUE(bitwise_equal(read_results(f.out), library_sample(texture, options, queries)));
  }
}

// A 16-bit image becomes an rgba32f texture of v / 65535. OpenImageIO converts with a float
// multiply by a rounded 1/65535 (or a division): two roundings of 2^-24 relative each, so each
// texel is within 2^-23 |v / 65535| of the exact quotient, and nearest returns a texel as it is.
TEST(SampleTool, SixteenBitImageReadsAsFractionsOf65535) {
  const TempDirectory dir;
  const RoundTripFiles f = files_in(dir, "texture.png");
  constexpr int w = 9, h = 5;
  const std::vector<std::uint16_t> pixels =
      random_values<std::uint16_t>(4 * static_cast<std::size_t>(w) * h, 50, 0, 65535);
  write_image(f.image, w, h, 4, OIIO::TypeDesc::UINT16, pixels.data());
  write_queries(f.queries, texel_centre_queries(w, h));
  const ToolRun run =
      run_sample_tool(tool_args(f.image, TextureFilter::nearest, f.queries, f.out), f.scratch);
  ASSERT_EQ(run.status, 0) << run.summary();
  EXPECT_TRUE(contains(run.out, "4 channels uint16 -> rgba32f")) << run.out;
  const std::vector<Vec4> results = read_results(f.out);
  ASSERT_EQ(results.size(), static_cast<std::size_t>(w) * h);
  for (std::size_t i = 0; i < results.size(); ++i) {
    const float got[4] = {results[i].x, results[i].y, results[i].z, results[i].w};
    for (int c = 0; c < 4; ++c) {
      const double exact = pixels[4 * i + c] / 65535.0;
      EXPECT_NEAR(got[c], exact, 0x1p-23 * exact) << "texel " << i << " channel " << c;
    }
  }
}

// --srgb on an 8-bit image: R, G and B decode through the sRGB curve, which lies below the
// identity strictly inside (0, 1); alpha stays v / 255.
TEST(SampleTool, SrgbDecodesColourButNotAlpha) {
  const TempDirectory dir;
  const RoundTripFiles f = files_in(dir, "texture.png");
  constexpr int w = 16, h = 16;
  // Every code once per channel, alpha included.
  std::vector<std::uint8_t> texels(4 * w * h);
  for (std::size_t i = 0; i < texels.size(); ++i)
    texels[i] = static_cast<std::uint8_t>((i / 4 + 67 * (i % 4)) % 256);
  write_image(f.image, w, h, 4, OIIO::TypeDesc::UINT8, texels.data());
  write_queries(f.queries, texel_centre_queries(w, h));

  const auto run_nearest = [&](std::vector<std::string> extra) {
    const ToolRun run = run_sample_tool(
        tool_args(f.image, TextureFilter::nearest, f.queries, f.out, std::move(extra)), f.scratch);
    EXPECT_EQ(run.status, 0) << run.summary();
    return read_results(f.out);
  };
  const std::vector<Vec4> linear = run_nearest({});
  const std::vector<Vec4> srgb = run_nearest({"--srgb"});
  ASSERT_EQ(linear.size(), texels.size() / 4);
  ASSERT_EQ(srgb.size(), texels.size() / 4);
  for (std::size_t i = 0; i < srgb.size(); ++i) {
    const float l[4] = {linear[i].x, linear[i].y, linear[i].z, linear[i].w};
    const float s[4] = {srgb[i].x, srgb[i].y, srgb[i].z, srgb[i].w};
    for (int c = 0; c < 3; ++c) {
      const int code = texels[4 * i + c];
      if (code == 0 || code == 255) {
        // The curve's fixed points; the linear decode of 255 is 255 times a rounded 1/255,
        // rounded: within two roundings of 2^-24 of 1.
        EXPECT_NEAR(s[c], l[c], 0x1p-23) << "code " << code;
      } else {
        EXPECT_LT(s[c], l[c]) << "code " << code;
      }
    }
    EXPECT_EQ(s[3], l[3]) << "alpha of texel " << i;
  }
}

// --srgb on a float image decodes R, G and B when loading, after clamping to [0, 1].
TEST(SampleTool, SrgbDecodesFloatImagesWhenLoading) {
  const TempDirectory dir;
  const RoundTripFiles f = files_in(dir, "texture.exr");
  constexpr int w = 8, h = 8;
  const std::vector<float> texels =
      random_values<float>(4 * static_cast<std::size_t>(w) * h, 51, -0.25f, 1.25f);
  write_image(f.image, w, h, 4, OIIO::TypeDesc::FLOAT, texels.data());
  const std::vector<TextureQuery> queries = mixed_queries(52, kQueryCount, w, h);
  write_queries(f.queries, queries);
  const ToolRun run = run_sample_tool(
      tool_args(f.image, TextureFilter::trilinear, f.queries, f.out, {"--srgb"}), f.scratch);
  ASSERT_EQ(run.status, 0) << run.summary();
  EXPECT_TRUE(contains(run.out, "-> rgba32f sRGB")) << run.out;

  std::vector<float> decoded = texels;
  for (std::size_t i = 0; i < decoded.size(); ++i) {
    if (i % 4 != 3) decoded[i] = static_cast<float>(srgb_to_linear(decoded[i]));
  }
  SamplerOptions options;
  options.filter = TextureFilter::trilinear;
  EXPECT_TRUE(bitwise_equal(
      read_results(f.out), library_sample(Texture::from_rgba32f(w, h, decoded), options, queries)));
}

// More queries than one chunk (2^20): the chunks join without a gap or an overlap.
TEST(SampleTool, FilesLongerThanOneChunkMatchTheLibrary) {
  const TempDirectory dir;
  const RoundTripFiles f = files_in(dir, "texture.png");
  const std::vector<std::uint8_t> texels = random_rgba8(kWidth, kHeight, 53);
  write_image(f.image, kWidth, kHeight, 4, OIIO::TypeDesc::UINT8, texels.data());
  test::Random random(54);
  std::vector<TextureQuery> queries((std::size_t{1} << 20) + 5);
  for (TextureQuery& q : queries) {
    q = {static_cast<float>(random.uniform(0.0, 1.0)),
         static_cast<float>(random.uniform(0.0, 1.0)),
         0.0f,
         0.0f,
         0.0f,
         0.0f};
  }
  write_queries(f.queries, queries);
  const ToolRun run =
      run_sample_tool(tool_args(f.image, TextureFilter::nearest, f.queries, f.out), f.scratch);
  ASSERT_EQ(run.status, 0) << run.summary();
  EXPECT_TRUE(contains(run.out, "1048581 queries")) << run.out;
  SamplerOptions options;
  options.filter = TextureFilter::nearest;
  const Texture texture = Texture::from_rgba8(kWidth, kHeight, texels, ColorEncoding::linear);
  EXPECT_TRUE(bitwise_equal(read_results(f.out), library_sample(texture, options, queries)));
}

// A stream whose size is not known up front (a pipe) is read to its end.
TEST(SampleTool, ReadsQueriesFromAPipe) {
  const TempDirectory dir;
  const RoundTripFiles f = files_in(dir, "texture.png");
  const std::vector<std::uint8_t> texels = random_rgba8(kWidth, kHeight, 55);
  write_image(f.image, kWidth, kHeight, 4, OIIO::TypeDesc::UINT8, texels.data());
  const std::vector<TextureQuery> queries = mixed_queries(56, kQueryCount, kWidth, kHeight);
  write_queries(f.queries, queries);
  const ToolRun run = run_sample_tool(
      tool_args(f.image, TextureFilter::anisotropic, "/dev/stdin", f.out), f.scratch, f.queries);
  ASSERT_EQ(run.status, 0) << run.summary();
  SamplerOptions options;
  options.filter = TextureFilter::anisotropic;
  const Texture texture = Texture::from_rgba8(kWidth, kHeight, texels, ColorEncoding::linear);
  EXPECT_TRUE(bitwise_equal(read_results(f.out), library_sample(texture, options, queries)));
}

TEST(SampleTool, EmptyQueryFileGivesEmptyResults) {
  const TempDirectory dir;
  const RoundTripFiles f = files_in(dir, "texture.png");
  const std::vector<std::uint8_t> texels = random_rgba8(3, 2, 57);
  write_image(f.image, 3, 2, 4, OIIO::TypeDesc::UINT8, texels.data());
  write_bytes(f.queries, "");
  const ToolRun run =
      run_sample_tool(tool_args(f.image, TextureFilter::ewa, f.queries, f.out), f.scratch);
  ASSERT_EQ(run.status, 0) << run.summary();
  EXPECT_TRUE(contains(run.out, "edgewise-sample: 0 queries")) << run.out;
  ASSERT_TRUE(std::filesystem::exists(f.out));
  EXPECT_EQ(std::filesystem::file_size(f.out), 0u);
}

}  // namespace
}  // namespace edgewise::sample_cli_test
