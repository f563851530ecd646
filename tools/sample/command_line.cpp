#include "sample/command_line.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>
#include <system_error>

#include "option_values.hpp"
#include "sample/usage_error.hpp"

namespace edgewise::sample_tool {

const std::string_view kUsage =
    "usage: edgewise-sample --texture IMG --filter NAME --queries Q --out R [options]\n"
    "\n"
    "Samples the texture IMG with edgewise::sample() at every query of Q and writes the filtered\n"
    "colours to R; prints the texture, the sampler and the sampling speed.\n"
    "\n"
    "Files:\n"
    "  IMG  any image OpenImageIO reads (its first subimage, full resolution, at most 32768\n"
    "       texels a side). 8-bit images become an RGBA8 texture, others (16-bit, half, float)\n"
    "       an RGBA float texture (16-bit v reads as v / 65535). Values are used as stored: alpha\n"
    "       is not premultiplied. Channels: 1 = grey (R = G = B, A = 1), 2 = grey and alpha,\n"
    "       3 = RGB (A = 1), 4 or more = the first four as RGBA.\n"
    "  Q    queries: records of six little-endian float32 (s, t, dsdx, dtdx, dsdy, dtdy), 24\n"
    "       bytes each, without header (edgewise::TextureQuery). Read 1M queries at a time;\n"
    "       a pipe works too (--queries /dev/stdin).\n"
    "  R    results: four little-endian float32 per query (linear R, G, B, A), in query order.\n"
    "       A run that fails removes it (not a device such as /dev/stdout).\n"
    "\n"
    "Sampler:\n"
    "  --filter NAME          nearest, bilinear, bicubic_catmull_rom, bicubic_bspline,\n"
    "                         mip_nearest, trilinear, supersample, ripmap, summed_area,\n"
    "                         anisotropic, ewa (ripmaps and the summed-area table are built only\n"
    "                         for their filter)\n"
    "  --wrap W               repeat (default), clamp or mirror, on both axes\n"
    "  --wrap-s W, --wrap-t W one axis (s across, t down), over --wrap\n"
    "  --lod exact|max_axis   level-of-detail formula (default exact)\n"
    "  --lod-bias F           added to log2 of the footprint (default 0)\n"
    "  --max-aniso N          anisotropic probes, EWA eccentricity: 1..64 (default 16)\n"
    "  --taps N               supersample: N x N taps, 1..16 (default 4)\n"
    "  --pyramid box|lanczos3 how coarser levels are made (default box)\n"
    "  --srgb                 R, G, B are sRGB-encoded: 8-bit texels are decoded by the sampler,\n"
    "                         others when loaded (clamped to [0, 1] first); alpha is linear\n"
    "  --isa NAME | --reference   the kernel (default: the best ISA of this CPU, or\n"
    "                         EDGEWISE_ISA); --reference runs the scalar double-precision one\n"
    "\n"
    "Exit status: 0 done; 1 a file cannot be read or written, or its contents are invalid\n"
    "(an image OpenImageIO cannot read, a query file that is not whole records); 2 a mistake on\n"
    "the command line. Errors are one line on standard error.\n";

namespace {

using tools::quoted;
using Values = tools::OptionValues<UsageError>;

constexpr std::string_view kFilterNames =
    "nearest, bilinear, bicubic_catmull_rom, bicubic_bspline, mip_nearest, trilinear, "
    "supersample, ripmap, summed_area, anisotropic or ewa";
constexpr std::string_view kWrapNames = "repeat, clamp or mirror";

Isa parse_isa_option(std::string_view name) {
  try {
    return parse_supported_isa(name);
  } catch (const std::invalid_argument& error) {
    throw UsageError(error.what());
  }
}

}  // namespace

SampleSettings parse_command_line(std::span<char* const> args) {
  SampleSettings settings;
  bool filter_given = false;
  std::optional<WrapMode> wrap, wrap_s, wrap_t;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string_view arg = args[i];
    const auto value = [&]() -> std::string_view {
      if (i + 1 == args.size()) throw UsageError(std::string(arg) + " needs a value");
      return args[++i];
    };
    const auto set_isa = [&](Isa isa) {
      if (settings.isa) throw UsageError("give at most one of --isa and --reference");
      settings.isa = isa;
    };
    SamplerOptions& sampler = settings.sampler;
    if (arg == "-h" || arg == "--help") {
      settings.help = true;
    } else if (arg == "--texture") {
      settings.texture_path = std::string(value());
    } else if (arg == "--queries") {
      settings.queries_path = std::string(value());
    } else if (arg == "--out") {
      settings.output_path = std::string(value());
    } else if (arg == "--filter") {
      sampler.filter = Values::named(arg, value(), parse_name<TextureFilter>, kFilterNames);
      filter_given = true;
    } else if (arg == "--wrap") {
      wrap = Values::named(arg, value(), parse_name<WrapMode>, kWrapNames);
    } else if (arg == "--wrap-s") {
      wrap_s = Values::named(arg, value(), parse_name<WrapMode>, kWrapNames);
    } else if (arg == "--wrap-t") {
      wrap_t = Values::named(arg, value(), parse_name<WrapMode>, kWrapNames);
    } else if (arg == "--lod") {
      sampler.lod = Values::named(arg, value(), parse_name<LodFormula>, "exact or max_axis");
    } else if (arg == "--lod-bias") {
      sampler.lod_bias = Values::number(arg, value());
    } else if (arg == "--max-aniso") {
      sampler.max_anisotropy = Values::integer_in(arg, value(), 1, edgewise::kMaxAnisotropyLimit);
    } else if (arg == "--taps") {
      sampler.supersample_taps = Values::integer_in(arg, value(), 1, edgewise::kMaxSupersampleTaps);
    } else if (arg == "--pyramid") {
      settings.pyramid = Values::named(arg, value(), parse_name<PyramidFilter>, "box or lanczos3");
    } else if (arg == "--srgb") {
      settings.srgb = true;
    } else if (arg == "--isa") {
      set_isa(parse_isa_option(value()));
    } else if (arg == "--reference") {
      set_isa(Isa::reference);
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option " + quoted(arg));
    } else {
      throw UsageError("unexpected argument " + quoted(arg));
    }
  }
  if (settings.help) return settings;
  // --wrap-s and --wrap-t win over --wrap wherever they stand on the line.
  settings.sampler.wrap_s = wrap_s.value_or(wrap.value_or(WrapMode::repeat));
  settings.sampler.wrap_t = wrap_t.value_or(wrap.value_or(WrapMode::repeat));
  const auto require = [](bool given, std::string_view option) {
    if (!given) throw UsageError(std::string(option) + " is required");
  };
  require(!settings.texture_path.empty(), "--texture IMG");
  require(filter_given, "--filter NAME");
  require(!settings.queries_path.empty(), "--queries Q");
  require(!settings.output_path.empty(), "--out R");
  return settings;
}

Isa resolve_isa(const SampleSettings& settings) {
  if (settings.isa) return *settings.isa;
  try {
    return active_isa();
  } catch (const std::invalid_argument& error) {
    throw UsageError(std::string("EDGEWISE_ISA: ") + error.what());
  }
}

}  // namespace edgewise::sample_tool
