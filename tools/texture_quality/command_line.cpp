#include "texture_quality/command_line.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>
#include <system_error>

#include "option_values.hpp"
#include "texture_quality/usage_error.hpp"

namespace edgewise::texture_quality {

const std::string_view kUsage =
    "usage: edgewise-texture-quality [options]\n"
    "\n"
    "Scores every texture filter against ground truth: for each texture and view, each filter's\n"
    "result over the whole screen is compared with the texture integrated over every pixel's\n"
    "true footprint (testing/texture_scene/ground_truth.hpp). Prints RMSE, PSNR and the worst "
    "error\n"
    "(linear units, R, G, B) with the time per sample, and marks the Pareto front: the methods\n"
    "no other method beats on both RMSE and time.\n"
    "\n"
    "Scenes (repeat wrap):\n"
    "  --texture NAME         checkerboard (16-texel squares), sinusoids or all (default all)\n"
    "  --view NAME            ground_plane, magnification or all (default all)\n"
    "  --size WxH             the screen (default 480x270; at most 4096x4096 pixels in all)\n"
    "  --texture-size N       the textures' N x N texels, a multiple of 32 (default 1024)\n"
    "  --pyramid box|lanczos3 how the mipmaps and ripmaps are made (default box)\n"
    "\n"
    "Methods: every edgewise filter, supersample at 4x4 and 8x8 taps, and OpenImageIO's\n"
    "TextureSystem on the same queries (closest, bilinear, bicubic, trilinear, anisotropic16).\n"
    "  --filter NAME          score this filter (repeatable; default every filter)\n"
    "  --max-aniso N          anisotropic probes, EWA eccentricity: 1..64 (default 16)\n"
    "  --lod exact|max_axis   level-of-detail formula (default exact)\n"
    "  --lod-bias F           added to the level of detail (default 0); the methods\n"
    "                         that read a formula or bias other than the default name it:\n"
    "                         trilinear_max_axis_bias-0.5\n"
    "  --isa NAME             the kernel (repeatable; default: the best ISA of this CPU, or\n"
    "                         EDGEWISE_ISA)\n"
    "  --reference            the scalar double-precision reference (with or without --isa)\n"
    "  --no-peer              leave OpenImageIO's TextureSystem out\n"
    "  --draw                 also draw each view with draw() (its mesh textured with each\n"
    "                         method, white flat shading) with derivatives from 2x2 quads and\n"
    "                         from the planes: methods draw_quad_<name>, draw_analytic_<name>;\n"
    "                         8-bit framebuffer, so errors include its rounding (59 dB alone)\n"
    "  --repeat N             timed runs per method, the median kept: 1..1000 (default 5)\n"
    "\n"
    "Times are this tool's: sample() over the whole screen in one call, one thread. The\n"
    "benchmark suite (edgewise-bench, Sample/...) gives the official throughput figures.\n"
    "\n"
    "Files:\n"
    "  --cache DIR            where ground truths are kept, one file per texture, view and size\n"
    "                         (default $XDG_CACHE_HOME/edgewise or ~/.cache/edgewise). Computing\n"
    "                         one is slow: about 80 s of CPU for the checkerboard ground plane at\n"
    "                         480x270, 4.5 min at 1920x1080.\n"
    "  --csv FILE             the scores, one row per texture, view, method and ISA:\n"
    "                         "
    "texture,view,size,method,isa,rmse,psnr_db,worst,ns_per_sample,pareto\n"
    "  --images DIR           PNGs of the ground truth, of each method's result and of its\n"
    "                         absolute error times 8: linear values clamped to [0, 1] and written\n"
    "                         sRGB-encoded (8-bit) for viewing\n"
    "\n"
    "Exit status: 0 done; 1 a file or directory cannot be written; 2 a mistake on the command\n"
    "line. Errors are one line on standard error.\n";

namespace {

using tools::quoted;
using Values = tools::OptionValues<UsageError>;

void parse_size(std::string_view text, std::int32_t& width, std::int32_t& height) {
  const std::size_t x = text.find('x');
  const std::optional<std::int64_t> parsed_w =
      x == std::string_view::npos ? std::nullopt : tools::parse_integer(text.substr(0, x));
  const std::optional<std::int64_t> parsed_h =
      x == std::string_view::npos ? std::nullopt : tools::parse_integer(text.substr(x + 1));
  const std::int64_t w = parsed_w.value_or(0), h = parsed_h.value_or(0);
  if (!parsed_w || !parsed_h || w < 1 || h < 1 || w > kMaxScreenSide || h > kMaxScreenSide ||
      w * h > kMaxPixels) {
    throw UsageError("--size " + quoted(text) + " is not WxH with W, H in 1.." +
                     std::to_string(kMaxScreenSide) + " and W H <= " + std::to_string(kMaxPixels));
  }
  width = static_cast<std::int32_t>(w);
  height = static_cast<std::int32_t>(h);
}

// One of `all` or "all" (the whole list).
template <class T, class Parse>
std::vector<T> parse_choice(std::string_view option, std::string_view text, Parse parse,
                            std::span<const T> all, std::string_view names) {
  if (text == "all") return {all.begin(), all.end()};
  if (const std::optional<T> value = parse(text)) return {*value};
  throw UsageError("unknown " + std::string(option) + " value " + quoted(text) + "; expected " +
                   std::string(names));
}

}  // namespace

QualitySettings parse_command_line(std::span<char* const> args) {
  QualitySettings settings;
  const auto add_isa = [&settings](Isa isa) {
    if (std::find(settings.isas.begin(), settings.isas.end(), isa) != settings.isas.end()) {
      throw UsageError("ISA " + quoted(name_of(isa)) + " given twice");
    }
    settings.isas.push_back(isa);
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string_view arg = args[i];
    const auto value = [&]() -> std::string_view {
      if (i + 1 == args.size()) throw UsageError(std::string(arg) + " needs a value");
      return args[++i];
    };
    const auto path_value = [&]() {
      const std::string_view path = value();
      if (path.empty()) throw UsageError(std::string(arg) + " needs a non-empty path");
      return std::string(path);
    };
    if (arg == "-h" || arg == "--help") {
      settings.help = true;
    } else if (arg == "--texture") {
      settings.textures = parse_choice<SceneTexture>(
          arg, value(), parse_scene_texture, kSceneTextures, "checkerboard, sinusoids or all");
    } else if (arg == "--view") {
      settings.views = parse_choice<SceneView>(arg, value(), parse_scene_view, kSceneViews,
                                               "ground_plane, magnification or all");
    } else if (arg == "--size") {
      parse_size(value(), settings.width, settings.height);
    } else if (arg == "--texture-size") {
      const std::string_view text = value();
      settings.texture_size = Values::integer_in(arg, text, 2 * kCheckerSquareTexels, 1 << 15);
      if (settings.texture_size % (2 * kCheckerSquareTexels) != 0) {
        throw UsageError("--texture-size " + quoted(text) + " is not a multiple of " +
                         std::to_string(2 * kCheckerSquareTexels));
      }
    } else if (arg == "--pyramid") {
      const std::string_view text = value();
      const std::optional<PyramidFilter> pyramid = parse_name<PyramidFilter>(text);
      if (!pyramid) {
        throw UsageError("unknown --pyramid value " + quoted(text) + "; expected box or lanczos3");
      }
      settings.pyramid = *pyramid;
    } else if (arg == "--filter") {
      const TextureFilter filter = Values::named(arg, value(), parse_name<TextureFilter>,
                                                 "a filter name (edgewise-sample --help)");
      std::vector<TextureFilter>& filters = settings.methods.filters;
      if (std::find(filters.begin(), filters.end(), filter) != filters.end()) {
        throw UsageError("filter " + quoted(name_of(filter)) + " given twice");
      }
      filters.push_back(filter);
    } else if (arg == "--max-aniso") {
      settings.methods.max_anisotropy = Values::integer_in(arg, value(), 1, kMaxAnisotropyLimit);
    } else if (arg == "--lod") {
      settings.methods.lod =
          Values::named(arg, value(), parse_name<LodFormula>, "exact or max_axis");
    } else if (arg == "--lod-bias") {
      settings.methods.lod_bias = Values::number(arg, value());
    } else if (arg == "--isa") {
      try {
        add_isa(parse_supported_isa(value()));
      } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
      }
    } else if (arg == "--reference") {
      add_isa(Isa::reference);
    } else if (arg == "--no-peer") {
      settings.peer = false;
    } else if (arg == "--draw") {
      settings.draw = true;
    } else if (arg == "--repeat") {
      settings.repetitions = Values::integer_in(arg, value(), 1, kMaxRepetitions);
    } else if (arg == "--cache") {
      settings.cache_directory = path_value();
    } else if (arg == "--csv") {
      settings.csv_path = path_value();
    } else if (arg == "--images") {
      settings.images_directory = path_value();
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option " + quoted(arg));
    } else {
      throw UsageError("unexpected argument " + quoted(arg));
    }
  }
  return settings;
}

std::vector<Isa> resolve_isas(const QualitySettings& settings) {
  if (!settings.isas.empty()) return settings.isas;
  try {
    return {active_isa()};
  } catch (const std::invalid_argument& error) {
    throw UsageError(std::string("EDGEWISE_ISA: ") + error.what());
  }
}

}  // namespace edgewise::texture_quality
