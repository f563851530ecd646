// edgewise-atlas-study: one study of the method atlas (tools/edgewise-atlas): measures each
// method of a family for its error against ground truth and its time (Google Benchmark,
// medians), and writes <out>/<study>.csv and <out>/<study>.json for tools/atlas/plot_atlas.py.
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

#include <benchmark/benchmark.h>

#include "atlas/aa_study.hpp"
#include "atlas/coverage_study.hpp"
#include "atlas/cpu_name.hpp"
#include "atlas/depth_study.hpp"
#include "atlas/interpolation_study.hpp"
#if EDGEWISE_ATLAS_TEXTURE
#include "atlas/texture_study.hpp"
#include "texture_quality/ground_truth_store.hpp"
#include "texture_quality/writable_directory.hpp"
#endif
#include "common/run_tool.hpp"
#include "common/usage_error.hpp"
#include "common/value_options.hpp"

namespace {

using namespace edgewise;

constexpr const char* kDescription =
    "Runs one study of the method atlas and writes its numbers (STUDY.csv: chart, series, x, y)\n"
    "and its charts' descriptions (STUDY.json) into the output folder. Studies:\n"
    "  coverage  the exact fixed-point rasterizer against float64 and float32 edge functions:\n"
    "            pixels decided differently and watertightness failures against coordinate\n"
    "            magnitude, sliver aspect ratio and triangle size; time per triangle.\n"
    "  interpolation  every interpolation method of draw() against the exact perspective-correct\n"
    "            value: error and time per fragment on every ISA, affine weights by depth range,\n"
    "            each method on slivers.\n"
    "  depth     the smallest separation of two surfaces that z/w, reversed z/w and a linear\n"
    "            depth resolve, by distance and far/near ratio; why interpolate z, in images.\n"
    "  texture   every filter and OpenImageIO's TextureSystem against ground truth on the\n"
    "            checkerboard ground plane (error against time), each filter by anisotropy,\n"
    "            float32 summed-area sums by texture size (needs OpenImageIO).\n"
    "  aa        each coverage mode (pixel centre, 2 to 16 samples, exact area) against the\n"
    "            exact area: error at edge pixels and on a Siemens star, time per triangle.\n"
    "Times are Google Benchmark medians of --repetitions runs.";

}  // namespace

int main(int argc, char** argv) {
  // Google Benchmark reads its own flags; the atlas passes none.
  int benchmark_argc = 1;
  benchmark::Initialize(&benchmark_argc, argv);
  std::string study, out_dir = "atlas", cache;
  bool quick = false;
  int repetitions = 5;
  return tools::run_tool(
      argc, argv, "edgewise-atlas-study",
      {"STUDY [-o DIR] [--quick] [--repetitions N] [--cache DIR]"},
      [&](tools::CommandLine& command_line) -> tools::ToolWork {
        command_line.description(kDescription);
        tools::add_text_option(command_line, "study", study,
                               "the study: coverage, interpolation, depth, texture or aa")
            .required();
        tools::add_text_option(command_line, "-o,--out", out_dir,
                               "output folder (made if missing; default atlas)");
        command_line.add_flag("--quick", quick, "a short run with few cases, for testing the tool");
        tools::add_text_option(command_line, "--cache", cache,
                               "where ground truths are kept (default: edgewise-texture-quality's, "
                               "$XDG_CACHE_HOME/edgewise or ~/.cache/edgewise)");
        tools::add_integer_option(command_line, "--repetitions", repetitions, 2, 100,
                                  "timed repetitions per method, 2..100 (default 5)");
        return [&]() {
          atlas::TimerSettings timer;
          timer.repetitions = repetitions;
          if (quick) timer.min_seconds = 0.01;
          const std::string cpu = atlas::cpu_name();
          atlas::StudySettings settings{quick, timer, {}};
          std::optional<atlas::StudyOutput> result;
          if (study == "coverage") {
            result = atlas::coverage_study(settings, cpu);
          } else if (study == "interpolation") {
            result = atlas::interpolation_study(settings, cpu);
          } else if (study == "texture") {
#if EDGEWISE_ATLAS_TEXTURE
            settings.cache = cache.empty() ? texture_quality::default_cache_directory()
                                           : std::filesystem::path(cache);
            texture_quality::prepare_writable_directory(settings.cache);
            result = atlas::texture_study(settings, cpu);
#else
            throw std::runtime_error("the texture study needs OpenImageIO, not found at build");
#endif
          } else if (study == "aa") {
            result = atlas::aa_study(settings, cpu);
          } else if (study == "depth") {
            std::filesystem::create_directories(out_dir);
            result = atlas::depth_study(settings, cpu, out_dir);
          } else {
            throw tools::UsageError("unknown study '" + study + "'");
          }
          std::filesystem::create_directories(out_dir);
          const atlas::StudyOutput& output = *result;
          output.write(out_dir);
          std::cout << "wrote " << (std::filesystem::path(out_dir) / (study + ".csv")).string()
                    << " and " << study << ".json\n";
          return 0;
        };
      });
}
