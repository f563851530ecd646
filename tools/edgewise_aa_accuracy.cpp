// edgewise-aa-accuracy: how far each coverage mode is from the exact area, and what it costs.
// Modes: the pixel centre (one sample), the standard 2, 4, 8 and 16-sample patterns (covered
// samples / samples), and the exact-area fast path. Ground truth: the exact-area reference.
// Two studies: random triangles at every angle and position (the error at each pixel an edge
// crosses), and a Siemens star of thin wedges (the error of the whole image).
#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "aa_accuracy/coverage_modes.hpp"
#include "common/isa_options.hpp"
#include "common/median.hpp"
#include "common/option_values.hpp"
#include "common/output_file.hpp"
#include "common/run_tool.hpp"
#include "common/usage_error.hpp"
#include "common/value_options.hpp"
#include "edgewise/edgewise.hpp"

namespace {

using namespace edgewise;
using namespace edgewise::tools;

constexpr const char* kDescription =
    "Measures every coverage mode against the exact area of each pixel inside each triangle\n"
    "(the exact-area reference): the pixel centre, 2, 4, 8 and 16 samples (covered samples over\n"
    "samples) and the exact-area fast path. Random triangles give the mean and largest error at\n"
    "the pixels their edges cross; a Siemens star of 64 wedges gives the image's RMSE and\n"
    "largest error. Each mode's time per triangle is the median of 5 runs over the random set.";

struct Arguments {
  std::size_t triangles = 2000;
  std::uint64_t seed = 1;
  std::optional<Isa> isa;
  std::optional<std::string> csv;
};

int run(const Arguments& arguments) {
  const Isa isa = tools::tool_isa(arguments.isa);
  const std::vector<Vec2> triangles = random_aa_triangles(arguments.triangles, arguments.seed);
  // Random triangles one at a time at their edge pixels, and the star's whole image.
  const std::vector<Vec2> star = siemens_star(64);
  const ModeErrors errors = measure_modes(triangles, star, isa);
  const CoverageErrors* edge = errors.edge;
  const double* star_rmse = errors.image_rmse;
  const double* star_worst = errors.image_worst;
  // The closed mesh: samples are unioned, areas added or composited.
  const std::vector<Vec2> mesh = closed_grid_mesh(arguments.seed);
  CoverageErrors mesh_errors[kAaModes];
  for (int m = 0; m < kAaModes; ++m)
    mesh_errors[m] = interior_errors(coverage_image(mesh, m, isa));
  const CoverageErrors conflation = interior_errors(composited_areas(mesh, isa));
  // Cost: the random set in one call per mode, median of 5.
  double nanoseconds[kAaModes];
  for (int m = 0; m < kAaModes; ++m) {
    std::vector<double> runs;
    for (int r = 0; r < 5; ++r) {
      const auto start = std::chrono::steady_clock::now();
      const CoverageImage image = coverage_image(triangles, m, isa);
      const auto stop = std::chrono::steady_clock::now();
      runs.push_back(std::chrono::duration<double, std::nano>(stop - start).count() /
                     static_cast<double>(arguments.triangles));
    }
    nanoseconds[m] = tools::median(runs);
  }

  std::cout << "edgewise-aa-accuracy: " << arguments.triangles << " random triangles (4 to 64 px"
            << " across, seed " << arguments.seed << ") and a 64-wedge Siemens star in " << kAaSize
            << "x" << kAaSize << ", " << name_of(isa) << "\n"
            << "errors are |coverage - exact area| per pixel, in pixels; edge pixels are those "
               "an edge crosses\n\n"
            << std::left << std::setw(20) << "mode" << std::right << std::setw(14) << "edge mean"
            << std::setw(12) << "edge worst" << std::setw(12) << "star RMSE" << std::setw(12)
            << "star worst" << std::setw(16) << "ns / triangle\n";
  for (int m = 0; m < kAaModes; ++m) {
    std::cout << std::left << std::setw(20) << aa_mode_name(m) << std::right << std::setprecision(4)
              << std::setw(14) << edge[m].mean() << std::setw(12) << edge[m].worst << std::setw(12)
              << star_rmse[m] << std::setw(12) << star_worst[m] << std::setw(15)
              << std::setprecision(5) << nanoseconds[m] << "\n";
  }
  std::cout << "(" << edge[0].pixels << " edge pixels; the time includes building the image)\n\n"
            << "closed mesh (" << mesh.size() / 3 << " triangles of a jittered grid), |1 - "
            << "coverage| over the " << mesh_errors[0].pixels << " pixels inside it:\n";
  for (int m = 0; m < kAaModes; ++m) {
    std::cout << std::left << std::setw(37)
              << (kAaSamples[m] == 0 ? "exact area, added" : aa_mode_name(m) + ", unioned")
              << std::right << std::setprecision(4) << "mean " << std::setw(11)
              << mesh_errors[m].mean() << "  worst " << mesh_errors[m].worst << "\n";
  }
  std::cout << std::left << std::setw(37) << "exact area, composited (conflation)" << std::right
            << "mean " << std::setw(11) << conflation.mean() << "  worst " << conflation.worst
            << "\n";
  if (arguments.csv) {
    tools::OutputStream csv(*arguments.csv);
    csv << "mode,samples,edge_mean_error,edge_worst_error,star_rmse,star_worst_error,"
           "ns_per_triangle,isa\n";
    for (int m = 0; m < kAaModes; ++m) {
      csv << aa_mode_name(m) << ',' << kAaSamples[m] << ',' << std::setprecision(9)
          << edge[m].mean() << ',' << edge[m].worst << ',' << star_rmse[m] << ',' << star_worst[m]
          << ',' << nanoseconds[m] << ',' << name_of(isa) << '\n';
    }
    csv.finish();
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Arguments arguments;
  return tools::run_tool(
      argc, argv, "edgewise-aa-accuracy", {"[--triangles N] [--seed S] [--isa NAME] [--csv FILE]"},
      [&arguments](tools::CommandLine& command_line) {
        command_line.description(kDescription);
        tools::add_parsed_option(
            command_line, "--triangles", arguments.triangles,
            [](const std::string& text) {
              return static_cast<std::size_t>(tools::unsigned_in("--triangles", text, 1, 1000000));
            },
            "random triangles, 1..1000000 (default 2000)")
            .type_name("N");
        tools::add_parsed_option(
            command_line, "--seed", arguments.seed,
            [](const std::string& text) {
              return tools::unsigned_in("--seed", text, 0,
                                        std::numeric_limits<std::uint64_t>::max());
            },
            "the random triangles' seed (default 1)")
            .type_name("S");
        tools::add_isa_options(command_line, arguments.isa,
                               "the ISA of the fast paths (default: the best of this CPU)",
                               "measure the reference's paths");
        tools::add_text_option(command_line, "--csv", arguments.csv, "also write the table to FILE")
            .type_name("FILE");
        return [&arguments] { return run(arguments); };
      });
}
