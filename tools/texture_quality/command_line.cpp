#include "texture_quality/command_line.hpp"

#include <algorithm>

#include "common/choice_options.hpp"
#include "common/isa_options.hpp"
#include "common/option_values.hpp"
#include "common/sampler_options.hpp"
#include "common/usage_error.hpp"
#include "common/value_options.hpp"

namespace edgewise::texture_quality {
namespace {

using tools::UsageError;

constexpr const char* kScenesGroup = "Scenes (repeat wrap)";
constexpr const char* kMethodsGroup =
    "Methods (every edgewise filter, supersample at 4x4 and 8x8 taps, OpenImageIO's peer)";
constexpr const char* kFilesGroup = "Files";

constexpr const char* kDescription =
    "Scores every texture filter against ground truth: for each texture and view, each filter's\n"
    "result over the whole screen is compared with the texture integrated over every pixel's\n"
    "true footprint (testing/texture_scene/ground_truth.hpp). Prints RMSE, PSNR and the worst\n"
    "error (linear units, R, G, B) with the time per sample, and marks the Pareto front: the\n"
    "methods no other method beats on both RMSE and time. While a ground truth is computed, a\n"
    "terminal shows its progress on standard error.";

constexpr const char* kFooter =
    "OpenImageIO's TextureSystem samples the same queries (closest, bilinear, bicubic,\n"
    "trilinear, anisotropic16).\n"
    "Times are this tool's: sample() over the whole screen in one call, one thread. The\n"
    "benchmark suite (edgewise-bench, Sample/...) gives the official throughput figures.\n"
    "\n"
    "Exit status: 0 done; 1 a file or directory cannot be written; 2 a mistake on the command\n"
    "line. Errors are one line on standard error.";

void parse_size(std::string_view text, std::int32_t& width, std::int32_t& height) {
  const std::size_t x = text.find('x');
  const std::optional<std::int64_t> parsed_w =
      x == std::string_view::npos ? std::nullopt : tools::parse_integer(text.substr(0, x));
  const std::optional<std::int64_t> parsed_h =
      x == std::string_view::npos ? std::nullopt : tools::parse_integer(text.substr(x + 1));
  const std::int64_t w = parsed_w.value_or(0), h = parsed_h.value_or(0);
  if (!parsed_w || !parsed_h || w < 1 || h < 1 || w > kMaxScreenSide || h > kMaxScreenSide ||
      w * h > kMaxPixels) {
    throw UsageError("--size " + tools::quoted(text) + " is not WxH with W, H in 1.." +
                     std::to_string(kMaxScreenSide) + " and W H <= " + std::to_string(kMaxPixels));
  }
  width = static_cast<std::int32_t>(w);
  height = static_cast<std::int32_t>(h);
}

// One of `all` by the name `name_of_value` gives it, or "all" (the whole list), into `chosen`.
template <class T, std::size_t N, class NameOf>
tools::Option add_scene_option(tools::CommandLine& command_line, const std::string& name,
                               std::vector<T>& chosen, const T (&all)[N], NameOf name_of_value,
                               const std::string& description) {
  std::vector<std::string> names;
  for (const T& value : all)
    names.emplace_back(name_of_value(value));
  names.emplace_back("all");
  return tools::add_choice_option(
      command_line, name, std::move(names),
      [&chosen, &all](std::size_t i) {
        chosen = i < N ? std::vector<T>{all[i]} : std::vector<T>(std::begin(all), std::end(all));
      },
      description);
}

void add_scene_options(tools::CommandLine& command_line, QualitySettings& settings) {
  add_scene_option(command_line, "--texture", settings.textures, kSceneTextures, scene_texture_name,
                   "checkerboard (16-texel squares), sinusoids or all (default all)")
      .group(kScenesGroup);
  add_scene_option(command_line, "--view", settings.views, kSceneViews, scene_view_name,
                   "(default all)")
      .group(kScenesGroup);
  command_line
      .add_value(
          "--size",
          [&settings](const std::string& text) {
            parse_size(text, settings.width, settings.height);
          },
          "the screen (default 480x270; at most 4096x4096 pixels in all)")
      .type_name("WxH")
      .group(kScenesGroup);
  constexpr int kMultiple = 2 * kCheckerSquareTexels;
  tools::add_parsed_option(
      command_line, "--texture-size", settings.texture_size,
      [](const std::string& text) {
        const auto size = static_cast<std::int32_t>(
            tools::integer_in("--texture-size", text, kMultiple, 1 << 15));
        if (size % kMultiple != 0) {
          throw UsageError("--texture-size " + tools::quoted(text) + " is not a multiple of " +
                           std::to_string(kMultiple));
        }
        return size;
      },
      "the textures' N x N texels, a multiple of " + std::to_string(kMultiple) + " (default 1024)")
      .type_name("N")
      .group(kScenesGroup);
  tools::add_pyramid_option(command_line, settings.pyramid,
                            "how the mipmaps and ripmaps are made (default box)")
      .group(kScenesGroup);
}

void add_method_options(tools::CommandLine& command_line, QualitySettings& settings) {
  MethodSettings& methods = settings.methods;
  std::vector<std::string> filter_names;
  for (TextureFilter filter : values_of<TextureFilter>())
    filter_names.emplace_back(name_of(filter));
  command_line
      .add_values(
          "--filter",
          [&filters = methods.filters](const std::vector<std::string>& names) {
            for (const std::string& name : names) {
              const TextureFilter filter = *parse_name<TextureFilter>(name);
              if (std::find(filters.begin(), filters.end(), filter) != filters.end()) {
                throw UsageError("filter " + tools::quoted(name) + " given twice");
              }
              filters.push_back(filter);
            }
          },
          "score this filter (repeatable; default every filter)")
      .type_name("NAME")
      .one_of(filter_names)
      .group(kMethodsGroup);
  command_line
      .add_values(
          "--precision",
          [&methods](const std::vector<std::string>& names) {
            for (const std::string& name : names) {
              const FilterPrecision precision = *parse_name<FilterPrecision>(name);
              if (std::find(methods.precisions.begin(), methods.precisions.end(), precision) !=
                  methods.precisions.end()) {
                throw UsageError("precision " + tools::quoted(name) + " given twice");
              }
              methods.precisions.push_back(precision);
            }
          },
          "score the filters made of bilinear taps in this precision (repeatable;\n"
          "default float32 and fixed16; fixed16 ends the name: trilinear_fixed16)")
      .type_name("NAME")
      .one_of({"float32", "fixed16"})
      .group(kMethodsGroup);
  tools::add_max_aniso_option(command_line, methods.max_anisotropy).group(kMethodsGroup);
  tools::add_lod_option(command_line, methods.lod).group(kMethodsGroup);
  tools::add_lod_bias_option(command_line, methods.lod_bias,
                             "added to the level of detail (default 0); the methods\n"
                             "that read a formula or bias other than the default name it:\n"
                             "trilinear_max_axis_bias-0.5")
      .group(kMethodsGroup);
  tools::add_isa_list_options(command_line, settings.isas,
                              "the kernel (repeatable; default: the best ISA of this CPU, or\n"
                              "EDGEWISE_ISA)",
                              "the scalar double-precision reference (with or without --isa)");
  command_line.option("--isa").group(kMethodsGroup);
  command_line.option("--reference").group(kMethodsGroup);
  command_line
      .add_flag(
          "--no-peer", [&settings] { settings.peer = false; },
          "leave OpenImageIO's TextureSystem out")
      .group(kMethodsGroup);
  command_line
      .add_flag("--draw", settings.draw,
                "also draw each view with draw() (its mesh textured with each\n"
                "method, white flat shading) with derivatives from 2x2 quads and\n"
                "from the planes: methods draw_quad_<name>, draw_analytic_<name>;\n"
                "8-bit framebuffer, so errors include its rounding (59 dB alone)")
      .group(kMethodsGroup);
  tools::add_integer_option(command_line, "--repeat", settings.repetitions, 1, kMaxRepetitions,
                            "timed runs per method, the median kept: 1.." +
                                std::to_string(kMaxRepetitions) + " (default 5)")
      .group(kMethodsGroup);
}

void add_file_options(tools::CommandLine& command_line, QualitySettings& settings) {
  tools::add_path_option(command_line, "--cache", settings.cache_directory,
                         "where ground truths are kept, one file per texture, view and size\n"
                         "(default $XDG_CACHE_HOME/edgewise or ~/.cache/edgewise). Computing\n"
                         "one is slow: about 80 s of CPU for the checkerboard ground plane at\n"
                         "480x270, 4.5 min at 1920x1080.")
      .type_name("DIR")
      .group(kFilesGroup);
  tools::add_path_option(command_line, "--csv", settings.csv_path,
                         "the scores, one row per texture, view, method and ISA:\n"
                         "texture,view,size,method,isa,rmse,psnr_db,worst,ns_per_sample,pareto")
      .type_name("FILE")
      .group(kFilesGroup);
  tools::add_path_option(command_line, "--images", settings.images_directory,
                         "PNGs of the ground truth, of each method's result and of its\n"
                         "absolute error times 8: linear values clamped to [0, 1] and written\n"
                         "sRGB-encoded (8-bit) for viewing")
      .type_name("DIR")
      .group(kFilesGroup);
}

}  // namespace

std::vector<std::string> usage_lines() {
  return {"[options]"};
}

void add_options(tools::CommandLine& command_line, QualitySettings& settings) {
  command_line.description(kDescription);
  command_line.footer(kFooter);
  add_scene_options(command_line, settings);
  add_method_options(command_line, settings);
  add_file_options(command_line, settings);
}

std::vector<Isa> resolve_isas(const QualitySettings& settings) {
  if (!settings.isas.empty()) return settings.isas;
  return {tools::tool_isa(std::nullopt)};
}

}  // namespace edgewise::texture_quality
