// How far a textured draw()'s pixel may be from the scalar reference's: the sampler's bound
// (tests/texture/sample_bounds.hpp) carried through the product with the shaded colour, whose
// own bound is tests/draw/colour_bounds.hpp's. Shared by the textured draw() tests and the
// draw() fuzz target.
//
// Both sides sample the texture at the same queries (kernels/draw/shading/texture_planes.hpp is one
// float32 formula), so a check recomputes each pixel's query with that formula. With C the shaded
// colour channel before the texture and T the filtered texel channel (both unclamped), a fast
// channel is F = clamp(round(fl(255 C_f T_f))) (the product rounded once in float, clamped to
// 0 .. 255 after it), the reference's R = clamp(round(255 C_r T_r)) in double. Then:
// - texel: for one of the texels T the sampler's bound accepts at the query (several across a
//   filter's discontinuities: accepted_references()), |T_f - T| <= b (sample_bound());
// - colour: |C_f - C_r| <= e (colour_error() or plane_colour_error(), linear);
// - C_r itself is known from the untextured reference render of the same triangle,
//   R0 = clamp(round(255 C_r)): 255 C_r lies within R0 -+ 1/2, unbounded on the clamped side where
//   R0 is 0 or 255. It also lies in shaded_range() (below), which bounds that side too.
// So with C_r in [c_lo, c_hi], 255 C_f T_f lies in the interval product
//   P = 255 [c_lo - e, c_hi + e] x [T - b, T + b],
// its float rounding moves it by at most 2^-24 |P| (the interval's own double arithmetic by far
// less: 2^-23 |P| covers both), and clamping and rounding are monotone and move a value by at most
// 1/2, so F is accepted when, for some accepted T and on every channel,
//   clamp(min P - 2^-23 |min P|) - 1/2 <= F <= clamp(max P + 2^-23 |max P|) + 1/2.
// The reference's own code satisfies this (C_r and T_r are in the intervals), so a check also
// holds the reference to it. Where the colour bound is unbounded, nothing is checked.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "edgewise/draw.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "draw/colour_bounds.hpp"
#include "texture/sample_bounds.hpp"

namespace edgewise::test {

// Where the reference's shaded channel C_r of a covered pixel lies, from the vertex colours
// alone: every interpolation method's reference weights at a point of the triangle are convex
// (nonnegative, summing to 1: kernels/interpolation/interpolation_reference.hpp, and one-hot for
// flat shading and nearest vertex), so C_r lies in the hull of the three vertex values; diffuse
// shading multiplies red, green and blue by a light between the ambient term and 1 (up to the float
// rounding of the unit light direction). Widened by 2^-40 of the larger end for the double
// roundings of the weights and products (a few units of 2^-53 each).
struct ShadedRange {
  double lo[4], hi[4];
};
ShadedRange shaded_range(const VertexAttributes& triangle, Shading shading, float ambient);

// The codes one channel of a fast pixel may take for one accepted texel: [lo[k], hi[k]].
struct CodeRanges {
  double lo[4], hi[4];
};

// The header's check for one texture and sampler.
class TexturedPixelCheck {
 public:
  TexturedPixelCheck(const Texture& texture, const SamplerOptions& sampler);

  // One range per accepted texel at `query`, for a pixel whose untextured reference code is
  // `untextured` (RGBA) and whose shaded colour lies in `shaded` within `colour_error`.
  std::vector<CodeRanges> allowed(const TextureQuery& query, const std::uint8_t untextured[4],
                                  const ShadedRange& shaded, double colour_error) const;

  // The largest excess of `fast` (RGBA) over its allowed codes on any channel, for the best of
  // the ranges (<= 0 passes).
  static double excess(std::span<const CodeRanges> allowed, const std::uint8_t fast[4]);

  const TextureExtremes& extremes() const { return extremes_; }
  double texel_bound(const TextureQuery& query) const;

 private:
  const Texture& texture_;
  SamplerOptions sampler_;
  TextureExtremes extremes_;
};

}  // namespace edgewise::test
