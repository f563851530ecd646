// Differential fuzz target for sample(): the input bytes become a small texture (8-bit linear,
// 8-bit sRGB, or float with values outside [0, 1]; 1 to 40 texels a side; box or Lanczos pyramids,
// ripmaps and a summed-area table), the sampler options and a few queries. Every supported ISA and
// the reference sample them in one call. A finding prints the decoded input and every ISA's
// output, then aborts, when:
// - an ISA throws where the reference does not, or the reverse, or either disagrees with the
//   decoder's prediction of std::invalid_argument (sample.hpp's cases), or anything else escapes;
// - the double-precision reference is not finite (the texels are finite), or an ISA's result is
//   not finite where the reference's is;
// - a query with non-finite s or t does not give exactly (0, 0, 0, 0) on some ISA;
// - a result lies further from the reference than tests/texture/sample_bounds.hpp allows for
//   that query (test::distance_to_reference > test::sample_bound).
//
// Input layout (missing bytes read as zero):
//   u8 format                 % 3: rgba8 linear, rgba8 sRGB, rgba32f
//   u8 width, u8 height       1 + v % kMaxTextureSide
//   u8 pyramid                bit 0: lanczos3 (else box)
//   u8 pattern                % 4: random, one constant texel, a checkerboard of two texels,
//                             every channel at an end of its range
//   u32 seed                  of the texel generator (tests/random.hpp)
//   u8 float scale            float texels lie in 2^(v % 21 - 10) [-1, 3]
//   u8 filter                 % 11, in TextureFilter's order
//   u8 wrap                   wrap_s v % 3, wrap_t v / 3 % 3 (WrapMode's order); bit 7 max_axis
//   i8 lod bias               v / 64, in [-2, 2)
//   u8 max anisotropy         1 + v % kMaxAnisotropyLimit
//   u8 supersample taps       1 + v % kMaxSupersampleTaps
//   u8 variant                < 248: as above, ripmaps and a summed-area table built. 248: no
//                             ripmaps; 249: no summed-area table; 250, 251: max_anisotropy 0, 65;
//                             252, 253: supersample_taps 0, 17; 254, 255: lod_bias inf, NaN
//   u8 query count            1 + v % kMaxQueries (full and partial batches of 4 and 8 lanes)
//   per query: 6 numbers      s, t, dsdx, dtdx, dsdy, dtdy
// A number is a u8 tag: < 128 an i16 / 4096 (+-8 in 1/4096 steps: a few periods, footprints
// from 1/4096 to 8); < 192 an i16 times 2^(u8 % 64 - 44) (tiny to far out); < 192 + 48 an entry
// of kSpecialValues (zeros, ones, float's extremes, NaN, infinities); else raw float bits (u32).
//
// Replay: `fuzz_sample <input file>...` runs inputs; a finding prints it and aborts.
// EDGEWISE_FUZZ_PRINT=1 prints every input and its results, and at exit how close the results
// came to their bounds. EDGEWISE_FUZZ_SEEDS=DIR writes seed inputs (seed_inputs below) into DIR.
#include <algorithm>
#include <array>
#include <bit>
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <initializer_list>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "edgewise/edgewise.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "random.hpp"
#include "texture/sample_reference.hpp"
#include "sampler_input.hpp"
#include "seed_files.hpp"
#include "texture/sample_bounds.hpp"

namespace {

using namespace edgewise;

// Small textures keep the reference (and EWA's ellipses) fast; odd and one-texel sides included.
constexpr std::int32_t kMaxTextureSide = 40;
constexpr std::uint32_t kMaxQueries = 12;
using fuzz::kFilterCount;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kFloatMax = std::numeric_limits<float>::max();
constexpr float kFloatMin = std::numeric_limits<float>::min();
constexpr float kDenormMin = std::numeric_limits<float>::denorm_min();
// One line per kind of value.
// clang-format off
constexpr float kSpecialValues[] = {
    0.0f, -0.0f, 1.0f, -1.0f, 0.5f, -0.5f, 0.25f, 2.0f, 1.0f / 3.0f,         // ordinary
    0.99999994f, 1.0000001f, -0.99999994f, -1.0000001f, 1.0f / 40.0f, 0.975f,  // at a period's ends
    1e-3f, 1e-7f, 1e-30f, -1e-30f, kFloatMin, -kFloatMin, kDenormMin, -kDenormMin,  // near zero
    0x1p-24f, 0x1p23f, 8388607.5f, 0x1p24f, -0x1p24f, 1e7f, -1e7f,  // float's integer limits
    1e10f, 1e19f, 1e30f, -1e30f, 0x1p64f, 3e38f, kFloatMax, -kFloatMax,  // huge
    65536.0f, 2147483648.0f, -2147483648.0f, 4294967296.0f,  // int32 limits of a texel index
    kNaN, -kNaN, kInf, -kInf, kNaN, kInf};
// clang-format on
static_assert(std::size(kSpecialValues) == 48);

class FuzzInput {
 public:
  explicit FuzzInput(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  std::uint32_t u8() { return pos_ < bytes_.size() ? bytes_[pos_++] : 0; }
  std::int32_t i8() { return static_cast<std::int8_t>(u8()); }
  std::int32_t i16() { return static_cast<std::int16_t>(u8() | u8() << 8); }
  std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i)
      v |= u8() << (8 * i);
    return v;
  }
  float number() {
    const std::uint32_t tag = u8();
    if (tag < 128) return static_cast<float>(i16()) / 4096.0f;
    if (tag < 192) {
      const float fixed = static_cast<float>(i16());
      return std::ldexp(fixed, static_cast<int>(u8() % 64) - 44);
    }
    if (tag < 192 + std::size(kSpecialValues)) return kSpecialValues[tag - 192];
    return std::bit_cast<float>(u32());
  }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t pos_ = 0;
};

enum class Pattern : std::uint8_t { random, constant, checkerboard, extremes };
constexpr const char* kPatternNames[] = {"random", "constant", "checkerboard", "extremes"};

// Everything one input decodes to, but the texture it describes.
struct Case {
  TexelFormat format = TexelFormat::rgba8;
  ColorEncoding encoding = ColorEncoding::linear;
  std::int32_t width = 1, height = 1;
  TextureBuild build;
  Pattern pattern = Pattern::random;
  std::uint32_t seed = 0;
  int scale_exponent = 0;  // float texels lie in 2^scale_exponent [-1, 3]
  std::uint32_t variant = 0;
  SamplerOptions options;
  std::vector<TextureQuery> queries;
  bool expect_invalid = false;  // sample() documents std::invalid_argument for this input
};

Case decode(std::span<const std::uint8_t> bytes) {
  FuzzInput in(bytes);
  Case c;
  const std::uint32_t format = in.u8() % 3;
  c.format = format == 2 ? TexelFormat::rgba32f : TexelFormat::rgba8;
  c.encoding = format == 1 ? ColorEncoding::srgb : ColorEncoding::linear;
  c.width = 1 + static_cast<std::int32_t>(in.u8() % kMaxTextureSide);
  c.height = 1 + static_cast<std::int32_t>(in.u8() % kMaxTextureSide);
  c.build.filter = (in.u8() & 1) != 0 ? PyramidFilter::lanczos3 : PyramidFilter::box;
  c.pattern = static_cast<Pattern>(in.u8() % 4);
  c.seed = in.u32();
  c.scale_exponent = static_cast<int>(in.u8() % 21) - 10;
  SamplerOptions& o = c.options;
  const fuzz::SamplerInput sampler = fuzz::decode_sampler(in, o, c.build);
  o.lod = (sampler.wrap_byte & 128) != 0 ? LodFormula::max_axis : LodFormula::exact;
  c.variant = sampler.variant;
  const std::uint32_t count = 1 + in.u8() % kMaxQueries;
  for (std::uint32_t i = 0; i < count; ++i) {
    TextureQuery q;
    for (float* v : {&q.s, &q.t, &q.dsdx, &q.dtdx, &q.dsdy, &q.dtdy})
      *v = in.number();
    c.queries.push_back(q);
  }
  // The cases sample.hpp documents as std::invalid_argument.
  c.expect_invalid = c.variant >= 250 || (o.filter == TextureFilter::ripmap && !c.build.ripmaps) ||
                     (o.filter == TextureFilter::summed_area && !c.build.summed_area_table);
  return c;
}

// Level 0: per texel four values in [0, 1] (8-bit: v * 255 rounded; float: 2^scale (4 v - 1)).
Texture make_texture(const Case& c) {
  test::Random random(c.seed);
  const auto unit_texel = [&random, &c] {
    std::array<double, 4> v;
    for (double& k : v)
      k = c.pattern == Pattern::extremes ? (random.chance(0.5) ? 1.0 : 0.0) : random.uniform();
    return v;
  };
  const std::array<double, 4> first = unit_texel(), second = unit_texel();
  const std::size_t count = static_cast<std::size_t>(c.width) * static_cast<std::size_t>(c.height);
  std::vector<double> units;
  units.reserve(4 * count);
  for (std::int32_t y = 0; y < c.height; ++y) {
    for (std::int32_t x = 0; x < c.width; ++x) {
      const std::array<double, 4> texel = c.pattern == Pattern::constant ? first
                                          : c.pattern == Pattern::checkerboard
                                              ? ((x + y) % 2 == 0 ? first : second)
                                              : unit_texel();
      units.insert(units.end(), texel.begin(), texel.end());
    }
  }
  if (c.format == TexelFormat::rgba8) {
    std::vector<std::uint8_t> texels(units.size());
    for (std::size_t i = 0; i < units.size(); ++i)
      texels[i] = static_cast<std::uint8_t>(std::lround(units[i] * 255.0));
    return Texture::from_rgba8(c.width, c.height, texels, c.encoding, c.build);
  }
  std::vector<float> texels(units.size());
  for (std::size_t i = 0; i < units.size(); ++i)
    texels[i] = static_cast<float>(std::ldexp(4.0 * units[i] - 1.0, c.scale_exponent));
  return Texture::from_rgba32f(c.width, c.height, texels, c.build);
}

// Seed inputs: each filter on each kind of texture, with queries from deep magnification to
// strong anisotropy, so that fuzzing starts from every kernel's main path. Written by
// LLVMFuzzerInitialize into the directory EDGEWISE_FUZZ_SEEDS names (tools/check passes its
// corpus).
class InputWriter : public fuzz::SeedWriter<InputWriter> {};

std::vector<std::vector<std::uint8_t>> seed_inputs() {
  struct Shape {
    std::uint32_t format, width, height;
  };
  const Shape shapes[] = {{0, 37, 19}, {1, 33, 33}, {2, 20, 13}, {0, 1, 7}};
  std::vector<std::vector<std::uint8_t>> seeds;
  for (int f = 0; f < kFilterCount; ++f) {
    const Shape& shape = shapes[f % 4];
    InputWriter w;
    // Sizes are decoded as 1 + v % 40.
    w.u8(shape.format).u8(shape.width - 1).u8(shape.height - 1).u8(f % 2).u8(0);
    w.u8(static_cast<std::uint32_t>(f)).u8(17).u8(0).u8(0).u8(10);  // seed, float scale 1
    w.u8(static_cast<std::uint32_t>(f)).u8(static_cast<std::uint32_t>(f) % 9);
    w.u8(0).u8(15).u8(3).u8(0);  // bias 0, max_anisotropy 16, 4 x 4 taps, everything built
    w.u8(9);                     // 10 queries: a full AVX2 batch and a partial one
    w.numbers({0.5f, 0.5f, 0, 0, 0, 0});
    w.numbers({0.3f, 0.7f, 0.001f, 0, 0, 0.001f});
    w.numbers({-1.25f, 2.5f, 0.05f, 0.01f, -0.01f, 0.05f});
    w.numbers({0.75f, 0.125f, 0.25f, 0, 0, 0.25f});
    w.numbers({0.1f, 0.9f, 0.5f, 0.01f, 0, 0.004f});  // anisotropy over 100
    w.numbers({3.5f, -0.25f, 0.02f, 0.2f, -0.2f, 0.02f});
    w.numbers({0.0f, 1.0f, 2.0f, 0.0f, 0.0f, 3.0f});
    w.numbers({0.999f, 0.001f, 0.0625f, 0.0625f, -0.0625f, 0.0625f});
    w.numbers({kNaN, 0.5f, 0.1f, 0, 0, 0.1f});
    w.numbers({0.5f, 0.5f, kInf, 0, 0, 0.1f});
    seeds.push_back(w.bytes);
  }
  return seeds;
}

// One ISA's (or the reference's) results for every query of a case.
struct Output {
  Isa isa;
  bool threw = false;
  std::string error;
  std::vector<Vec4> results;
};

// What one check found for each query, for printing.
struct Verdict {
  reference::Rgba want{};
  double bound = 0;
};

// The largest channel difference (NaN counts as none: finiteness is checked on its own).
double largest_difference(const Vec4& got, const reference::Rgba& want) {
  const float values[4] = {got.x, got.y, got.z, got.w};
  double worst = 0;
  for (int k = 0; k < 4; ++k)
    worst = std::max(worst, std::fabs(double(values[k]) - want[k]));
  return worst;
}

const char* format_name(const Case& c) {
  if (c.format == TexelFormat::rgba32f) return "rgba32f";
  return c.encoding == ColorEncoding::srgb ? "rgba8 sRGB" : "rgba8 linear";
}

void print_float(float v) {
  std::fprintf(stderr, "%.9g (%a)", static_cast<double>(v), static_cast<double>(v));
}

void print_case(const Case& c, const test::TextureExtremes& extremes) {
  const SamplerOptions& o = c.options;
  std::fprintf(stderr,
               "texture %s %dx%d, %s pyramid, %s texels (seed %" PRIu32
               ", float scale 2^%d), ripmaps %s, summed-area table %s; range R %.9g, largest T "
               "%.9g\n",
               format_name(c), c.width, c.height, std::string(name_of(c.build.filter)).c_str(),
               kPatternNames[static_cast<int>(c.pattern)], c.seed, c.scale_exponent,
               c.build.ripmaps ? "yes" : "no", c.build.summed_area_table ? "yes" : "no",
               extremes.range, extremes.largest);
  std::fprintf(stderr,
               "filter %s, wrap %s/%s, lod %s, lod_bias %.9g, max_anisotropy %d, "
               "supersample_taps %d (variant %" PRIu32 ")%s\n",
               std::string(name_of(o.filter)).c_str(), std::string(name_of(o.wrap_s)).c_str(),
               std::string(name_of(o.wrap_t)).c_str(), std::string(name_of(o.lod)).c_str(),
               static_cast<double>(o.lod_bias), o.max_anisotropy, o.supersample_taps, c.variant,
               c.expect_invalid ? "; expected: std::invalid_argument" : "");
}

void print_query(std::size_t i, const TextureQuery& q) {
  std::fprintf(stderr, "query %zu:", i);
  const char* names[6] = {"s", "t", "dsdx", "dtdx", "dsdy", "dtdy"};
  const float values[6] = {q.s, q.t, q.dsdx, q.dtdx, q.dsdy, q.dtdy};
  for (int k = 0; k < 6; ++k) {
    std::fprintf(stderr, " %s ", names[k]);
    print_float(values[k]);
  }
  std::fprintf(stderr, "\n");
}

void print_outputs(const Case& c, std::span<const Output> outputs,
                   std::span<const Verdict> verdicts) {
  for (const Output& o : outputs) {
    if (o.threw) {
      std::fprintf(stderr, "%-10s threw: %s\n", std::string(name_of(o.isa)).c_str(),
                   o.error.c_str());
    }
  }
  for (std::size_t i = 0; i < c.queries.size(); ++i) {
    print_query(i, c.queries[i]);
    if (i < verdicts.size()) {
      const Verdict& v = verdicts[i];
      std::fprintf(stderr, "  %-10s (%.17g, %.17g, %.17g, %.17g), bound %.9g\n", "double",
                   v.want[0], v.want[1], v.want[2], v.want[3], v.bound);
    }
    for (const Output& o : outputs) {
      if (o.threw) continue;
      const Vec4& r = o.results[i];
      std::fprintf(stderr, "  %-10s (%.9g, %.9g, %.9g, %.9g)", std::string(name_of(o.isa)).c_str(),
                   static_cast<double>(r.x), static_cast<double>(r.y), static_cast<double>(r.z),
                   static_cast<double>(r.w));
      if (i < verdicts.size())
        std::fprintf(stderr, ", off by %.3g", largest_difference(r, verdicts[i].want));
      std::fprintf(stderr, "\n");
    }
  }
}

[[noreturn]] void fail(const Case& c, const test::TextureExtremes& extremes, const char* what,
                       std::span<const Output> outputs, std::span<const Verdict> verdicts,
                       const std::string& detail) {
  std::fprintf(stderr, "edgewise fuzz_sample: %s\n", what);
  print_case(c, extremes);
  if (!detail.empty()) std::fprintf(stderr, "%s\n", detail.c_str());
  print_outputs(c, outputs, verdicts);
  std::abort();
}

std::vector<Output> sample_every_isa(const Case& c, const Texture& texture,
                                     const test::TextureExtremes& extremes) {
  std::vector<Output> outputs;
  for (Isa isa : supported_isas()) {  // the reference first
    Output out{isa, false, {}, std::vector<Vec4>(c.queries.size())};
    try {
      sample(texture, {c.options, isa}, c.queries, out.results);
    } catch (const std::invalid_argument& e) {
      out.threw = true;
      out.error = e.what();
    } catch (const std::exception& e) {
      outputs.push_back(std::move(out));
      fail(c, extremes, "sample() threw something other than std::invalid_argument", outputs, {},
           e.what());
    } catch (...) {
      outputs.push_back(std::move(out));
      fail(c, extremes, "sample() threw a non-standard exception", outputs, {}, "");
    }
    outputs.push_back(std::move(out));
  }
  return outputs;
}

bool finite(const Vec4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

// How close the checks came, printed at exit with EDGEWISE_FUZZ_PRINT.
struct Stats {
  std::uint64_t inputs = 0, invalid = 0, results = 0, bad_positions = 0;
  std::uint64_t per_filter[kFilterCount] = {};
  double closest[kFilterCount] = {};  // the largest distance / bound
} stats;

void print_stats() {
  std::fprintf(stderr,
               "fuzz_sample: %" PRIu64 " inputs (%" PRIu64 " invalid), %" PRIu64
               " results compared (%" PRIu64 " at non-finite s or t)\n",
               stats.inputs, stats.invalid, stats.results, stats.bad_positions);
  for (int f = 0; f < kFilterCount; ++f) {
    std::fprintf(stderr, "  %-20s %10" PRIu64 " results, largest distance / bound %.3g\n",
                 std::string(name_of(static_cast<TextureFilter>(f))).c_str(), stats.per_filter[f],
                 stats.closest[f]);
  }
}

bool printing() {
  static const bool print = [] {
    const char* value = std::getenv("EDGEWISE_FUZZ_PRINT");
    const bool on = value != nullptr && value[0] != '\0' && value[0] != '0';
    if (on) std::atexit(print_stats);
    return on;
  }();
  return print;
}

void check_exceptions(const Case& c, const test::TextureExtremes& extremes,
                      std::span<const Output> outputs) {
  for (const Output& o : outputs) {
    if (o.threw != c.expect_invalid) {
      fail(c, extremes,
           o.threw ? "sample() threw for a valid input" : "sample() accepted an invalid input",
           outputs, {}, std::string(name_of(o.isa)));
    }
  }
}

// The double-precision reference and the bound of every query (options valid).
std::vector<Verdict> verdicts_for(const Case& c, const Texture& texture,
                                  const test::TextureExtremes& extremes) {
  std::vector<Verdict> verdicts;
  for (const TextureQuery& q : c.queries) {
    verdicts.push_back({reference::sample(texture, c.options, q),
                        test::sample_bound(texture, extremes, c.options, q)});
  }
  return verdicts;
}

void check_results(const Case& c, const Texture& texture, const test::TextureExtremes& extremes,
                   std::span<const Output> outputs, std::span<const Verdict> verdicts) {
  if (c.expect_invalid) return;  // check_exceptions: every ISA threw
  const int filter = static_cast<int>(c.options.filter);
  for (std::size_t i = 0; i < c.queries.size(); ++i) {
    const TextureQuery& q = c.queries[i];
    const Verdict& v = verdicts[i];
    const std::string where = "query " + std::to_string(i);
    if (!(std::isfinite(v.want[0]) && std::isfinite(v.want[1]) && std::isfinite(v.want[2]) &&
          std::isfinite(v.want[3]))) {
      fail(c, extremes, "the reference is not finite for finite texels", outputs, verdicts, where);
    }
    const bool bad_position = !std::isfinite(q.s) || !std::isfinite(q.t);
    stats.bad_positions += bad_position ? outputs.size() : 0;
    for (const Output& o : outputs) {
      const Vec4& got = o.results[i];
      const std::string detail = std::string(name_of(o.isa)) + ", " + where;
      ++stats.results;
      ++stats.per_filter[filter];
      if (bad_position && !(got.x == 0 && got.y == 0 && got.z == 0 && got.w == 0))
        fail(c, extremes, "non-finite s or t did not give (0, 0, 0, 0)", outputs, verdicts, detail);
      if (!finite(got))
        fail(c, extremes, "a result is not finite; the reference's is", outputs, verdicts, detail);
      // The query's own reference first: the neighbours across the filter's discontinuities
      // (test::accepted_references) cost several more reference evaluations.
      double distance = largest_difference(got, v.want);
      if (distance > v.bound) distance = test::distance_to_reference(texture, c.options, q, got);
      if (v.bound > 0) stats.closest[filter] = std::max(stats.closest[filter], distance / v.bound);
      if (distance > v.bound) {
        char text[160];
        std::snprintf(text, sizeof text, ": %.9g from the closest accepted reference, bound %.9g",
                      distance, v.bound);
        fail(c, extremes, "a result is outside its bound", outputs, verdicts, detail + text);
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  edgewise::fuzz::write_seed_files("fuzz_sample", "sample", seed_inputs());
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Case c = decode({data, size});
  const Texture texture = make_texture(c);
  const test::TextureExtremes extremes = test::texture_extremes(texture);
  ++stats.inputs;
  stats.invalid += c.expect_invalid ? 1 : 0;
  const std::vector<Output> outputs = sample_every_isa(c, texture, extremes);
  check_exceptions(c, extremes, outputs);
  const std::vector<Verdict> verdicts =
      c.expect_invalid ? std::vector<Verdict>() : verdicts_for(c, texture, extremes);
  if (printing()) {
    print_case(c, extremes);
    print_outputs(c, outputs, verdicts);
  }
  check_results(c, texture, extremes, outputs, verdicts);
  return 0;
}
