// Ground truth for texture filtering: the average of level 0 over each pixel's true footprint,
// the pixel square carried into texture space by the view's exact projective mapping.
//
// The reference signal is level 0 reconstructed bilinearly (bilinear_reconstruction.hpp), the
// texture as a continuous function, because:
//  - it is the function the filters themselves reconstruct (bilinear filtering samples exactly
//    it, and every mip and anisotropic filter uses it at its finest level), so in the
//    magnification view, with footprints far below a texel, a good filter scores nearly
//    perfectly;
//  - it interpolates the texels and stays within their range (no ringing, unlike Catmull-Rom
//    or a sinc), so it adds no detail the texture does not have;
//  - it is continuous, so the box average converges quickly under stratified sampling (error
//    about n^-2 once the grid resolves the texels; a piecewise-constant texture would converge
//    only as n^-1 at every texel edge).
// The summed-area filter integrates the piecewise-constant texture instead; that difference (up
// to half a texel of blur) is part of its measured error, small for footprints of many texels.
//
// The integral: an n x n grid over the pixel square, the centres of its cells (i + (a + 0.5)/n,
// j + (b + 0.5)/n) mapped exactly, the bilinear values averaged. n starts at initial_grid and
// doubles until the estimate changes by less than `tolerance` in every channel (RGBA) from the
// previous one; the finer estimate is the result. If the error falls as n^-2, the result is
// within about a third of its last change of the true average. A pixel reaching max_grid stops
// there and is counted in the report (with its last change), never silently.
// Non-finite texels give non-finite averages (compare_images() counts them as infinite errors);
// their change reads as 0, so such a pixel stops at the first doubling.
//
// Cost: the grid needed grows with the footprint's extent in texels (the samples must resolve
// the texel edges along the footprint's long axis) and with the texture edges inside it (a pixel
// inside one checkerboard square stops at n = 8), so the far rows of a ground plane cost nearly
// everything. Measured (x86-64 AMD EPYC VM at 2.6 GHz, Release, about 26 ns per sample per
// core; 2 cores shared with other jobs), ground_plane_view() with its defaults, repeat wrap:
//   checkerboard(1024, 64), 1920 x 1080: 1.0e10 samples, 270 s of CPU (255 s wall), largest
//     grid 512, none capped; the top 108 rows (10%) take 76% of the samples, the bottom half 3%;
//   the same at 480 x 270: 3.0e9 samples, 82 s of CPU (55 s wall), largest grid 1024;
//   sinusoids(1024), 480 x 270: 9.4e8 samples, 25 s of CPU;
//   checkerboard(1024, 1024) (1-texel squares), 480 x 270: 5.5e9 samples, 145 s of CPU,
//     108 pixels needing the default cap's 2048 (and converging there).
// Cache full-screen results (ground_truth_cache.hpp); tests use small regions.
#pragma once

#include <cstdint>
#include <vector>

#include "edgewise/sample.hpp"
#include "texture_scene/bilinear_reconstruction.hpp"
#include "texture_scene/linear_image.hpp"
#include "texture_scene/texture_view.hpp"

namespace edgewise::texture_scene {

struct GroundTruthOptions {
  double tolerance = 1e-4;        // largest change of any channel when n doubles
  std::int32_t initial_grid = 4;  // n of the first estimate
  std::int32_t max_grid = 2048;   // the cap on n (a power-of-two multiple of initial_grid)
  int threads = 0;                // worker threads over rows; 0: hardware_concurrency()
};

struct GroundTruthReport {
  std::int64_t pixels = 0;
  std::int64_t capped_pixels = 0;       // pixels that reached max_grid unconverged
  double worst_capped_change = 0.0;     // the largest last change among them (0 if none)
  double worst_converged_change = 0.0;  // the largest last change among the others (< tolerance)
  std::int32_t largest_grid = 0;        // the largest final n
  std::int64_t samples = 0;             // texture evaluations, every estimate counted
  double seconds = 0.0;                 // wall-clock time of the evaluation
};

struct GroundTruth {
  ScreenRegion region;
  LinearImage image;               // region.width x region.height, linear RGBA
  std::vector<std::int32_t> grid;  // each pixel's final n, row-major like `image`
  GroundTruthReport report;
};

// The ground truth of `region` of `view` over `texture` (its wrap modes apply per axis, as the
// sampler's). Throws std::invalid_argument for a region outside the view's screen, a texture
// with no texels, or options out of range (tolerance not positive, initial_grid < 1, max_grid
// not initial_grid times a power of two or above 65536).
GroundTruth ground_truth(const LinearImage& texture, WrapMode wrap_s, WrapMode wrap_t,
                         const TextureView& view, const ScreenRegion& region,
                         const GroundTruthOptions& options = {});

// One estimate: the mean over the n x n grid of cell centres of pixel (i, j). Throws
// std::invalid_argument for a pixel outside the view's screen or n outside [1, 65536].
void pixel_average(const BilinearReconstruction& texture, const TextureView& view, std::int32_t i,
                   std::int32_t j, std::int32_t n, double out[4]);

}  // namespace edgewise::texture_scene
