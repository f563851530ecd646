// How far a fast filter's result may lie from the double-precision reference, per query: the
// bound the differential tests and the sampling fuzz target assert.
//
// The bound (texture_filters-inl.hpp states the fast path's error sources):
// - position: a texel position is off by at most kPositionError w texels of a w-wide level, plus,
//   for the taps of supersample and anisotropic, three float roundings of the tap position
//   (2^-24 each, relative to M = |s| + |dsdx| + |dsdy|). A filter's value moves by at most its
//   weights' Lipschitz constant times the texel range R per texel of position: 1 for linear
//   weights; for the cubics, half the largest sum of |w_i'(f)| times the other axis's largest
//   sum of |w_i| (Catmull-Rom: 3.78 / 2 and 1.25; B-spline: 2.34 / 2 and 1).
// - level of detail: lambda is off by at most 2^-19 (|lambda| + 1) (fast_log2-inl.hpp's 2^-20
//   plus the roundings of the squared lengths and the bias; mip_nearest and trilinear fold
//   lod_bias - log2(3) / 2 into one float, whose rounding, 2^-24 |lod_bias - 0.79| < 2^-17 for
//   |lod_bias| < 64, is within the slack of fast_log2's 2^-20, a bound on a truncation below
//   1e-9 plus a few ulps); where lambda is not clamped on both
//   sides |lambda| < 64, so 2^-13 bounds it. A blend between levels moves by at most that times R
//   (twice for the ripmap's two axes).
// - rounding: weights, products and sums in float add at most (64 + taps^2 + probes) 2^-24 times
//   the largest texel magnitude T: 64 covers a bicubic's 16 products and its weights' own
//   roundings, taps^2 and probes the terms of the supersample and anisotropic means.
// - fixed point (FilterPrecision::fixed16): every tap weight off by at most 2^-15, T each.
// Discontinuities are accepted on either side: nearest's texel choice (positions moved by the
// position error), mip_nearest's level choice (lambda moved by its error) and the anisotropic
// probe count (the minor axis scaled by 1 +- 2^-18).
#pragma once

#include <vector>

#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "texture/sample_reference.hpp"

namespace edgewise::test {

// R and T of the bound: over every level (mipmaps and ripmaps) of the texture.
struct TextureExtremes {
  double range = 0;    // R: largest minus smallest linear channel value
  double largest = 0;  // T: largest |linear channel value|
};
TextureExtremes texture_extremes(const Texture& texture);

// The largest difference allowed, on any channel, between a fast result and one of
// accepted_references() (finite texels assumed).
double sample_bound(const Texture& texture, const TextureExtremes& extremes,
                    const SamplerOptions& options, const TextureQuery& query);

// The reference at the query and, across the filter's discontinuities, at its neighbours within
// the fast path's input error.
std::vector<reference::Rgba> accepted_references(const Texture& texture,
                                                 const SamplerOptions& options,
                                                 const TextureQuery& query);

// The smallest, over accepted_references(), of the largest channel difference to `got`.
double distance_to_reference(const Texture& texture, const SamplerOptions& options,
                             const TextureQuery& query, const Vec4& got);

}  // namespace edgewise::test
