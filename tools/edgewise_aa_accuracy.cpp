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
#include <fstream>
#include <iomanip>
#include <iostream>
#include <numbers>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "common/isa_options.hpp"
#include "common/median.hpp"
#include "common/run_tool.hpp"
#include "common/usage_error.hpp"
#include "common/value_options.hpp"
#include "edgewise/edgewise.hpp"

namespace {

using namespace edgewise;

constexpr const char* kDescription =
    "Measures every coverage mode against the exact area of each pixel inside each triangle\n"
    "(the exact-area reference): the pixel centre, 2, 4, 8 and 16 samples (covered samples over\n"
    "samples) and the exact-area fast path. Random triangles give the mean and largest error at\n"
    "the pixels their edges cross; a Siemens star of 64 wedges gives the image's RMSE and\n"
    "largest error. Each mode's time per triangle is the median of 5 runs over the random set.";

constexpr int kSize = 256;  // the target, square
constexpr int kModes = 6;   // centre, 2, 4, 8, 16 samples, exact
constexpr int kSamples[kModes] = {1, 2, 4, 8, 16, 0};

std::string mode_name(int mode) {
  if (kSamples[mode] == 0) return "exact area";
  if (kSamples[mode] == 1) return "centre (1 sample)";
  return std::to_string(kSamples[mode]) + " samples";
}

// A coverage image: per pixel, the covered fraction of the pixel.
using Image = std::vector<double>;

class MaskSink final : public CoverageSink {
 public:
  explicit MaskSink(std::vector<std::uint32_t>& samples) : samples_(samples) {}
  void consume(std::span<const TileCoverage> tiles) override {
    for (const TileCoverage& tile : tiles) {
      for (std::uint64_t mask = tile.mask; mask != 0; mask &= mask - 1) {
        const int bit = std::countr_zero(mask);
        const int x = tile.tile_x * 8 + bit % 8, y = tile.tile_y * 8 + bit / 8;
        samples_[static_cast<std::size_t>(y) * kSize + x] |= 1u << tile.sample;
      }
    }
  }

 private:
  std::vector<std::uint32_t>& samples_;
};

class AreaImageSink final : public AreaSink {
 public:
  explicit AreaImageSink(Image& image) : image_(image) {}
  void consume(std::span<const AreaTile> tiles) override {
    for (const AreaTile& tile : tiles) {
      for (int bit = 0; bit < 64; ++bit) {
        const int x = tile.tile_x * 8 + bit % 8, y = tile.tile_y * 8 + bit / 8;
        image_[static_cast<std::size_t>(y) * kSize + x] += tile.area[bit];
      }
    }
  }

 private:
  Image& image_;
};

const RasterTarget kTarget{kSize, kSize, std::nullopt};

// The coverage image of `triangles` (which must not overlap) in one mode; samples are unioned
// over the triangles, areas added.
Image coverage_image(std::span<const Vec2> triangles, int mode, Isa isa) {
  RasterOptions options;
  options.isa = isa;
  Image image(static_cast<std::size_t>(kSize) * kSize, 0.0);
  if (kSamples[mode] == 0) {
    AreaImageSink sink(image);
    rasterize_areas(triangles, {}, kTarget, options, sink);
    return image;
  }
  options.samples = kSamples[mode];
  std::vector<std::uint32_t> samples(image.size(), 0);
  MaskSink sink(samples);
  rasterize(triangles, {}, kTarget, options, sink);
  for (std::size_t i = 0; i < image.size(); ++i)
    image[i] = static_cast<double>(std::popcount(samples[i])) / kSamples[mode];
  return image;
}

Image truth_image(std::span<const Vec2> triangles) {
  Image image(static_cast<std::size_t>(kSize) * kSize, 0.0);
  RasterOptions options;
  options.isa = Isa::reference;
  AreaImageSink sink(image);
  rasterize_areas(triangles, {}, kTarget, options, sink);
  return image;
}

struct Errors {
  double sum = 0.0, worst = 0.0;
  std::uint64_t pixels = 0;
  void add(double error) {
    sum += error;
    worst = std::max(worst, error);
    ++pixels;
  }
  double mean() const { return pixels == 0 ? 0.0 : sum / static_cast<double>(pixels); }
};

// Random triangles from 4 to 64 px across, at every angle, inside the target.
std::vector<Vec2> random_triangles(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec2> vertices;
  while (vertices.size() < 3 * count) {
    const double size = 4.0 * std::pow(16.0, unit(rng));
    const double cx = size + unit(rng) * (kSize - 2 * size);
    const double cy = size + unit(rng) * (kSize - 2 * size);
    for (int i = 0; i < 3; ++i) {
      const double angle = 2.0 * std::numbers::pi * unit(rng);
      const double radius = size * (0.3 + 0.7 * unit(rng));
      vertices.push_back({static_cast<float>(cx + radius * std::cos(angle)),
                          static_cast<float>(cy + radius * std::sin(angle))});
    }
  }
  return vertices;
}

// A Siemens star: every other of 2 * wedges wedges around the target's centre.
std::vector<Vec2> siemens_star(int wedges) {
  std::vector<Vec2> vertices;
  const double centre = kSize / 2.0, radius = kSize / 2.0 - 4.0;
  for (int w = 0; w < wedges; ++w) {
    const double a0 = std::numbers::pi * (2 * w) / wedges;
    const double a1 = std::numbers::pi * (2 * w + 1) / wedges;
    vertices.push_back({static_cast<float>(centre), static_cast<float>(centre)});
    vertices.push_back({static_cast<float>(centre + radius * std::cos(a0)),
                        static_cast<float>(centre + radius * std::sin(a0))});
    vertices.push_back({static_cast<float>(centre + radius * std::cos(a1)),
                        static_cast<float>(centre + radius * std::sin(a1))});
  }
  return vertices;
}

// A closed mesh: a jittered grid of 28 x 28 cells over [16, 240)^2, each cell cut in two along
// a diagonal; the outline is straight, so every pixel inside it is covered exactly once.
std::vector<Vec2> jittered_grid(std::uint64_t seed) {
  constexpr int kCells = 28;
  constexpr double kFirst = 16.0, kCell = 8.0;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-2.5, 2.5);
  Vec2 corner[kCells + 1][kCells + 1];
  for (int j = 0; j <= kCells; ++j) {
    for (int i = 0; i <= kCells; ++i) {
      const bool border_x = i == 0 || i == kCells, border_y = j == 0 || j == kCells;
      corner[j][i] = {static_cast<float>(kFirst + kCell * i + (border_x ? 0.0 : jitter(rng))),
                      static_cast<float>(kFirst + kCell * j + (border_y ? 0.0 : jitter(rng)))};
    }
  }
  std::vector<Vec2> vertices;
  for (int j = 0; j < kCells; ++j) {
    for (int i = 0; i < kCells; ++i) {
      const Vec2 a = corner[j][i], b = corner[j][i + 1], c = corner[j + 1][i + 1],
                 d = corner[j + 1][i];
      vertices.insert(vertices.end(), {a, b, c, a, c, d});
    }
  }
  return vertices;
}

// Coverage-weighted blending, triangle after triangle ("over"): alpha += area (1 - alpha).
Image composited_areas(std::span<const Vec2> triangles, Isa isa) {
  Image alpha(static_cast<std::size_t>(kSize) * kSize, 0.0);
  for (std::size_t t = 0; 3 * t < triangles.size(); ++t) {
    const Image area = coverage_image(triangles.subspan(3 * t, 3), kModes - 1, isa);
    for (std::size_t i = 0; i < alpha.size(); ++i)
      alpha[i] += area[i] * (1.0 - alpha[i]);
  }
  return alpha;
}

// Mean and largest |image - 1| over the pixels inside the mesh's outline.
Errors interior_errors(const Image& image) {
  Errors errors;
  for (int y = 16; y < 240; ++y) {
    for (int x = 16; x < 240; ++x)
      errors.add(std::abs(1.0 - image[static_cast<std::size_t>(y) * kSize + x]));
  }
  return errors;
}

struct Arguments {
  std::size_t triangles = 2000;
  std::uint64_t seed = 1;
  std::optional<Isa> isa;
  std::optional<std::string> csv;
};

int run(const Arguments& arguments) {
  const Isa isa = tools::tool_isa(arguments.isa);
  const std::vector<Vec2> triangles = random_triangles(arguments.triangles, arguments.seed);
  // Random triangles: each on its own, at every pixel where the truth is strictly between 0 and
  // 1 (an edge crosses it) or where some mode says so.
  Errors edge[kModes];
  for (std::size_t t = 0; t < arguments.triangles; ++t) {
    const std::span<const Vec2> one(triangles.data() + 3 * t, 3);
    const Image truth = truth_image(one);
    Image modes[kModes];
    for (int m = 0; m < kModes; ++m)
      modes[m] = coverage_image(one, m, isa);
    for (std::size_t i = 0; i < truth.size(); ++i) {
      bool edge_pixel = truth[i] > 0.0 && truth[i] < 1.0;
      for (int m = 0; m < kModes && !edge_pixel; ++m)
        edge_pixel = modes[m][i] > 0.0 && modes[m][i] < 1.0;
      if (!edge_pixel) continue;
      for (int m = 0; m < kModes; ++m)
        edge[m].add(std::abs(modes[m][i] - truth[i]));
    }
  }
  // The star: the whole image.
  const std::vector<Vec2> star = siemens_star(64);
  const Image star_truth = truth_image(star);
  double star_rmse[kModes], star_worst[kModes];
  for (int m = 0; m < kModes; ++m) {
    const Image image = coverage_image(star, m, isa);
    double squares = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < image.size(); ++i) {
      const double error = std::abs(image[i] - star_truth[i]);
      squares += error * error;
      worst = std::max(worst, error);
    }
    star_rmse[m] = std::sqrt(squares / static_cast<double>(image.size()));
    star_worst[m] = worst;
  }
  // The closed mesh: samples are unioned, areas added or composited.
  const std::vector<Vec2> mesh = jittered_grid(arguments.seed);
  Errors mesh_errors[kModes];
  for (int m = 0; m < kModes; ++m)
    mesh_errors[m] = interior_errors(coverage_image(mesh, m, isa));
  const Errors conflation = interior_errors(composited_areas(mesh, isa));
  // Cost: the random set in one call per mode, median of 5.
  double nanoseconds[kModes];
  for (int m = 0; m < kModes; ++m) {
    std::vector<double> runs;
    for (int r = 0; r < 5; ++r) {
      const auto start = std::chrono::steady_clock::now();
      const Image image = coverage_image(triangles, m, isa);
      const auto stop = std::chrono::steady_clock::now();
      runs.push_back(std::chrono::duration<double, std::nano>(stop - start).count() /
                     static_cast<double>(arguments.triangles));
    }
    nanoseconds[m] = tools::median(runs);
  }

  std::cout << "edgewise-aa-accuracy: " << arguments.triangles << " random triangles (4 to 64 px"
            << " across, seed " << arguments.seed << ") and a 64-wedge Siemens star in " << kSize
            << "x" << kSize << ", " << name_of(isa) << "\n"
            << "errors are |coverage - exact area| per pixel, in pixels; edge pixels are those "
               "an edge crosses\n\n"
            << std::left << std::setw(20) << "mode" << std::right << std::setw(14) << "edge mean"
            << std::setw(12) << "edge worst" << std::setw(12) << "star RMSE" << std::setw(12)
            << "star worst" << std::setw(16) << "ns / triangle\n";
  for (int m = 0; m < kModes; ++m) {
    std::cout << std::left << std::setw(20) << mode_name(m) << std::right << std::setprecision(4)
              << std::setw(14) << edge[m].mean() << std::setw(12) << edge[m].worst << std::setw(12)
              << star_rmse[m] << std::setw(12) << star_worst[m] << std::setw(15)
              << std::setprecision(5) << nanoseconds[m] << "\n";
  }
  std::cout << "(" << edge[0].pixels << " edge pixels; the time includes building the image)\n\n"
            << "closed mesh (" << mesh.size() / 3 << " triangles of a jittered grid), |1 - "
            << "coverage| over the " << mesh_errors[0].pixels << " pixels inside it:\n";
  for (int m = 0; m < kModes; ++m) {
    std::cout << std::left << std::setw(37)
              << (kSamples[m] == 0 ? "exact area, added" : mode_name(m) + ", unioned") << std::right
              << std::setprecision(4) << "mean " << std::setw(11) << mesh_errors[m].mean()
              << "  worst " << mesh_errors[m].worst << "\n";
  }
  std::cout << std::left << std::setw(37) << "exact area, composited (conflation)" << std::right
            << "mean " << std::setw(11) << conflation.mean() << "  worst " << conflation.worst
            << "\n";
  if (arguments.csv) {
    std::ofstream csv(*arguments.csv);
    if (!csv) throw tools::UsageError(*arguments.csv + ": cannot create");
    csv << "mode,samples,edge_mean_error,edge_worst_error,star_rmse,star_worst_error,"
           "ns_per_triangle,isa\n";
    for (int m = 0; m < kModes; ++m) {
      csv << mode_name(m) << ',' << kSamples[m] << ',' << std::setprecision(9) << edge[m].mean()
          << ',' << edge[m].worst << ',' << star_rmse[m] << ',' << star_worst[m] << ','
          << nanoseconds[m] << ',' << name_of(isa) << '\n';
    }
    if (!csv) throw tools::UsageError(*arguments.csv + ": write error");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Arguments arguments;
  return tools::run_tool(
      argc, argv, "edgewise-aa-accuracy", {"[--triangles N] [--seed S] [--isa NAME] [--csv FILE]"},
      [&arguments](CLI::App& app) {
        app.description(kDescription);
        app.add_option("--triangles", arguments.triangles, "random triangles (default 2000)")
            ->check(CLI::Range(std::size_t{1}, std::size_t{1000000}))
            ->type_name("N");
        app.add_option("--seed", arguments.seed, "the random triangles' seed (default 1)")
            ->type_name("S");
        tools::add_isa_options(app, arguments.isa,
                               "the ISA of the fast paths (default: the best of this CPU)",
                               "measure the reference's paths");
        app.add_option("--csv", arguments.csv, "also write the table to FILE")->type_name("FILE");
        return [&arguments] { return run(arguments); };
      });
}
