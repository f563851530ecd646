// The coverage modes of the anti-aliasing accuracy measures (edgewise-aa-accuracy and the
// atlas's anti-aliasing study): the pixel centre, the standard 2, 4, 8 and 16-sample patterns
// (covered samples over samples) and the exact-area fast path, each as an image of covered
// fractions of a 256x256 target, against the exact-area reference; and the scenes they are
// measured on.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "edgewise/edgewise.hpp"

namespace edgewise::tools {

inline constexpr int kAaSize = 256;  // the target, square
inline constexpr int kAaModes = 6;   // centre, 2, 4, 8, 16 samples, exact
inline constexpr int kAaSamples[kAaModes] = {1, 2, 4, 8, 16, 0};  // 0: exact area

std::string aa_mode_name(int mode);

// A coverage image: per pixel, the covered fraction of the pixel.
using CoverageImage = std::vector<double>;

// The coverage image of `triangles` (which must not overlap) in one mode; samples are unioned
// over the triangles, areas added.
CoverageImage coverage_image(std::span<const Vec2> triangles, int mode, Isa isa);
// The exact-area reference's image.
CoverageImage truth_image(std::span<const Vec2> triangles);

struct CoverageErrors {
  double sum = 0.0, worst = 0.0;
  std::uint64_t pixels = 0;
  void add(double error);
  double mean() const { return pixels == 0 ? 0.0 : sum / static_cast<double>(pixels); }
};

// Random triangles from 4 to 64 px across, at every angle, inside the target.
std::vector<Vec2> random_aa_triangles(std::size_t count, std::uint64_t seed);
// A Siemens star: every other of 2 * wedges wedges around the target's centre.
std::vector<Vec2> siemens_star(int wedges);
// A closed mesh: a jittered grid of 28 x 28 cells over [16, 240)^2, each cell cut in two along
// a diagonal; the outline is straight, so every pixel inside it is covered exactly once.
std::vector<Vec2> closed_grid_mesh(std::uint64_t seed);
// Coverage-weighted blending, triangle after triangle ("over"): alpha += area (1 - alpha).
CoverageImage composited_areas(std::span<const Vec2> triangles, Isa isa);
// Mean and largest |image - 1| over the pixels inside the closed mesh's outline.
CoverageErrors interior_errors(const CoverageImage& image);

// Each mode's errors at the pixels an edge crosses, the triangles taken one at a time (pixels
// where the truth or some mode lies strictly between 0 and 1), and over a whole image.
struct ModeErrors {
  CoverageErrors edge[kAaModes];
  double image_rmse[kAaModes], image_worst[kAaModes];
};
// Edge errors over `triangles` (three vertices each), image errors over `scene`.
ModeErrors measure_modes(std::span<const Vec2> triangles, std::span<const Vec2> scene, Isa isa);

}  // namespace edgewise::tools
