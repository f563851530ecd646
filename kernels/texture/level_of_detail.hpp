// The level of detail of the isotropic mip filters (mip_nearest, trilinear): which level of the
// box pyramid, read bilinearly, blurs like the pixel's footprint.
//
// Level k of the box pyramid averages 2^k x 2^k texels of level 0 (a box of width B = 2^k, in
// level-0 texels), and the bilinear read of it adds a tent of half-width B. Per axis their
// variances add: B^2 / 12 + B^2 / 6 = B^2 / 4. The ground truth averages the texture over the
// footprint, a box whose longer side rho (sample.hpp) has the variance rho^2 / 12. The level of
// equal variance has B^2 / 4 = rho^2 / 12, B = rho / sqrt(3):
//   lambda = log2(rho) - log2(3) / 2 + lod_bias.
// The plain lambda = log2(rho) (B = rho) blurs three times the footprint's variance. Queries with
// rho <= sqrt(3) read level 0 alone, as magnification (docs/texture-filtering.md has the figures).
#pragma once

namespace edgewise {

// log2(3) / 2, subtracted from log2(rho).
inline constexpr double kBoxPyramidLodOffset = 0.792481250360578;

}  // namespace edgewise
