#include "aa_accuracy/coverage_modes.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>

namespace edgewise::tools {
namespace {

class MaskSink final : public CoverageSink {
 public:
  explicit MaskSink(std::vector<std::uint32_t>& samples) : samples_(samples) {}
  void consume(std::span<const TileCoverage> tiles) override {
    for (const TileCoverage& tile : tiles) {
      for (std::uint64_t mask = tile.mask; mask != 0; mask &= mask - 1) {
        const int bit = std::countr_zero(mask);
        const int x = tile.tile_x * 8 + bit % 8, y = tile.tile_y * 8 + bit / 8;
        samples_[static_cast<std::size_t>(y) * kAaSize + x] |= 1u << tile.sample;
      }
    }
  }

 private:
  std::vector<std::uint32_t>& samples_;
};

// Each pixel's area into the image through `combine(value, area)`: added, or composited.
template <class Combine>
class AreaImageSink final : public AreaSink {
 public:
  AreaImageSink(CoverageImage& image, Combine combine) : image_(image), combine_(combine) {}
  void consume(std::span<const AreaTile> tiles) override {
    for (const AreaTile& tile : tiles) {
      for (int bit = 0; bit < 64; ++bit) {
        const int x = tile.tile_x * 8 + bit % 8, y = tile.tile_y * 8 + bit / 8;
        combine_(image_[static_cast<std::size_t>(y) * kAaSize + x], tile.area[bit]);
      }
    }
  }

 private:
  CoverageImage& image_;
  Combine combine_;
};

void add_area(double& value, double area) {
  value += area;
}

// Coverage-weighted blending of one triangle's area over the image ("over").
void composite_area(double& alpha, double area) {
  alpha += area * (1.0 - alpha);
}

const RasterTarget kTarget{kAaSize, kAaSize, std::nullopt};

}  // namespace

std::string aa_mode_name(int mode) {
  if (kAaSamples[mode] == 0) return "exact area";
  if (kAaSamples[mode] == 1) return "centre (1 sample)";
  return std::to_string(kAaSamples[mode]) + " samples";
}

// The coverage image of `triangles` (which must not overlap) in one mode; samples are unioned
// over the triangles, areas added.
CoverageImage coverage_image(std::span<const Vec2> triangles, int mode, Isa isa) {
  RasterOptions options;
  options.isa = isa;
  CoverageImage image(static_cast<std::size_t>(kAaSize) * kAaSize, 0.0);
  if (kAaSamples[mode] == 0) {
    AreaImageSink sink(image, add_area);
    rasterize_areas(triangles, {}, kTarget, options, sink);
    return image;
  }
  options.samples = kAaSamples[mode];
  std::vector<std::uint32_t> samples(image.size(), 0);
  MaskSink sink(samples);
  rasterize(triangles, {}, kTarget, options, sink);
  for (std::size_t i = 0; i < image.size(); ++i)
    image[i] = static_cast<double>(std::popcount(samples[i])) / kAaSamples[mode];
  return image;
}

CoverageImage truth_image(std::span<const Vec2> triangles) {
  CoverageImage image(static_cast<std::size_t>(kAaSize) * kAaSize, 0.0);
  RasterOptions options;
  options.isa = Isa::reference;
  AreaImageSink sink(image, add_area);
  rasterize_areas(triangles, {}, kTarget, options, sink);
  return image;
}

void CoverageErrors::add(double error) {
  sum += error;
  worst = std::max(worst, error);
  ++pixels;
}

// Random triangles from 4 to 64 px across, at every angle, inside the target.
std::vector<Vec2> random_aa_triangles(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec2> vertices;
  while (vertices.size() < 3 * count) {
    const double size = 4.0 * std::pow(16.0, unit(rng));
    const double cx = size + unit(rng) * (kAaSize - 2 * size);
    const double cy = size + unit(rng) * (kAaSize - 2 * size);
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
  const double centre = kAaSize / 2.0, radius = kAaSize / 2.0 - 4.0;
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
std::vector<Vec2> closed_grid_mesh(std::uint64_t seed) {
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

// Coverage-weighted blending, triangle after triangle ("over"): alpha += area (1 - alpha). Each
// triangle is rasterized on its own, so that each pixel's area is one triangle's.
CoverageImage composited_areas(std::span<const Vec2> triangles, Isa isa) {
  CoverageImage alpha(static_cast<std::size_t>(kAaSize) * kAaSize, 0.0);
  RasterOptions options;
  options.isa = isa;
  AreaImageSink sink(alpha, composite_area);
  for (std::size_t t = 0; 3 * t < triangles.size(); ++t)
    rasterize_areas(triangles.subspan(3 * t, 3), {}, kTarget, options, sink);
  return alpha;
}

// Mean and largest |image - 1| over the pixels inside the mesh's outline.
CoverageErrors interior_errors(const CoverageImage& image) {
  CoverageErrors errors;
  for (int y = 16; y < 240; ++y) {
    for (int x = 16; x < 240; ++x)
      errors.add(std::abs(1.0 - image[static_cast<std::size_t>(y) * kAaSize + x]));
  }
  return errors;
}

ModeErrors measure_modes(std::span<const Vec2> triangles, std::span<const Vec2> scene, Isa isa) {
  ModeErrors errors;
  // Random triangles: each on its own, at every pixel where the truth is strictly between 0 and
  // 1 (an edge crosses it) or where some mode says so.
  for (std::size_t t = 0; t < triangles.size() / 3; ++t) {
    const std::span<const Vec2> one(triangles.data() + 3 * t, 3);
    const CoverageImage truth = truth_image(one);
    CoverageImage modes[kAaModes];
    for (int m = 0; m < kAaModes; ++m)
      modes[m] = coverage_image(one, m, isa);
    for (std::size_t i = 0; i < truth.size(); ++i) {
      bool edge_pixel = truth[i] > 0.0 && truth[i] < 1.0;
      for (int m = 0; m < kAaModes && !edge_pixel; ++m)
        edge_pixel = modes[m][i] > 0.0 && modes[m][i] < 1.0;
      if (!edge_pixel) continue;
      for (int m = 0; m < kAaModes; ++m)
        errors.edge[m].add(std::abs(modes[m][i] - truth[i]));
    }
  }
  // The scene: the whole image.
  const CoverageImage scene_truth = truth_image(scene);
  for (int m = 0; m < kAaModes; ++m) {
    const CoverageImage image = coverage_image(scene, m, isa);
    double squares = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < image.size(); ++i) {
      const double error = std::abs(image[i] - scene_truth[i]);
      squares += error * error;
      worst = std::max(worst, error);
    }
    errors.image_rmse[m] = std::sqrt(squares / static_cast<double>(image.size()));
    errors.image_worst[m] = worst;
  }
  return errors;
}

}  // namespace edgewise::tools
