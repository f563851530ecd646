// The scalar reference sampler: every filter of sample.hpp in double precision, in plain loops,
// taken literally from its definition. It is the oracle the fast kernels are tested against, so
// it is written to be read, not to be fast; it shares no code with them.
//
// The query's float inputs are promoted to double and every step after that is double. The
// building blocks are public because the fast kernels' tests derive their bounds from them.
//
// Conventions, stated once:
// - "Texel space" of a w x h level: x = s w, y = t h; texel (a, b) fills [a, a + 1) x [b, b + 1)
//   and is centred at (a + 0.5, b + 0.5). Level-0 texels measure footprints: ux = dsdx W,
//   vx = dtdx H, uy = dsdy W, vy = dtdy H.
// - Results are linear RGBA: 8-bit texels are decoded first (v / 255, or srgb_to_linear for R, G
//   and B of an sRGB texture), float texels are used as they are.
// - Far-out coordinates are exact: a coordinate is first moved by a whole number of periods (or,
//   for clamp_to_edge, to just beyond the border), which changes no texel fetched and no weight,
//   so huge s or t cost no precision (a literal s w - 0.5 in double rounds once |s w| >= 2^52)
//   and every index fits in 64 bits.
//
// Bad input (sample()): non-finite s or t gives (0, 0, 0, 0) for every filter; a non-finite
// derivative makes every filter that reads derivatives return coarsest_texel(); zero derivatives
// magnify; huge ones reach the coarsest level. Every result is finite for finite texels.
//
// Preconditions, not checked (sampler.cpp validates them for the public entry point): options
// in range (max_anisotropy 1 .. 64, supersample_taps 1 .. 16, lod_bias finite), levels that
// belong to `texture`. The ripmap and summed_area filters throw std::invalid_argument when the
// texture was built without ripmaps or a summed-area table.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"

namespace edgewise::reference {

using Rgba = std::array<double, 4>;

// The filtered linear RGBA at one query, for options.filter.
Rgba sample(const Texture& texture, const SamplerOptions& options, const TextureQuery& query);

// --- Texel addressing -------------------------------------------------------------------------

// The texel index in [0, n) that integer index i reads on an axis of n texels (1 <= n <= 2^31):
// repeat ((i mod n) + n) mod n; clamp_to_edge clamp(i, 0, n - 1); mirror m = ((i mod 2n) + 2n)
// mod 2n, then m < n ? m : 2n - 1 - m.
std::int64_t wrap_index(std::int64_t i, std::int64_t n, WrapMode mode);

// Texel (x, y) of `level`, wrapped on each axis, as linear RGBA.
Rgba texel(const Texture& texture, const TextureLevel& level, WrapMode wrap_s, WrapMode wrap_t,
           std::int64_t x, std::int64_t y);

// The single texel of the last (1 x 1) mip level: the texture's average.
Rgba coarsest_texel(const Texture& texture);

// --- Filters within one level, at finite (s, t) ------------------------------------------------

// The texel (floor(s w), floor(t h)).
Rgba nearest(const Texture& texture, const TextureLevel& level, WrapMode wrap_s, WrapMode wrap_t,
             double s, double t);

// The 2x2 texels around (s w - 0.5, t h - 0.5), weighted by the fractions.
Rgba bilinear(const Texture& texture, const TextureLevel& level, WrapMode wrap_s, WrapMode wrap_t,
              double s, double t);

enum class CubicKernel { catmull_rom, bspline };

// The weights of texels i1 - 1 .. i1 + 2 at fraction f in [0, 1) (Catmull-Rom with a = -1/2,
// or the uniform cubic B-spline). Both sum to 1; only Catmull-Rom has negative lobes.
std::array<double, 4> cubic_weights(CubicKernel kernel, double f);

// The 4x4 texels around (s w - 0.5, t h - 0.5), separable cubic weights; not clamped.
Rgba bicubic(const Texture& texture, const TextureLevel& level, WrapMode wrap_s, WrapMode wrap_t,
             double s, double t, CubicKernel kernel);

// --- Level of detail and the mip filters -------------------------------------------------------

// lambda = log2(rho) - log2(3) / 2 + lod_bias before clamping (rho by options.lod; the offset
// from kernels/texture/level_of_detail.hpp): -inf for zero derivatives,
// +inf for a non-finite derivative or a NaN lambda.
double level_of_detail(const Texture& texture, const SamplerOptions& options,
                       const TextureQuery& query);

// lambda clamped to [0, L - 1] (L mip levels); NaN counts as +inf.
double clamp_level_of_detail(const Texture& texture, double lambda);

// The mip level mip_nearest reads at lambda: round half down of the clamped lambda.
int mip_nearest_level(const Texture& texture, double lambda);

// Bilinear in mip_nearest_level(lambda).
Rgba mip_nearest(const Texture& texture, WrapMode wrap_s, WrapMode wrap_t, double s, double t,
                 double lambda);

// Bilinear in floor(lambda_c) and the next level, blended by the fraction (only the last level
// once lambda reaches it).
Rgba trilinear(const Texture& texture, WrapMode wrap_s, WrapMode wrap_t, double s, double t,
               double lambda);

// --- Summed-area table ------------------------------------------------------------------------

// S_ext(x, y): the integral of the wrap-extended level-0 texture over [0, x] x [0, y] (signed:
// negative x counts [x, 0] negatively), x, y in level-0 texel units, linear units, from the
// table's entries: exact lattice values by the wrap mode, bilinear within each cell.
Rgba extended_prefix_sum(const SummedAreaTable& table, WrapMode wrap_s, WrapMode wrap_t, double x,
                         double y);

// The integral over the box [x0, x1] x [y0, y1] (level-0 texel units), by inclusion-exclusion
// of S_ext at its corners.
Rgba box_integral(const SummedAreaTable& table, WrapMode wrap_s, WrapMode wrap_t, double x0,
                  double y0, double x1, double y1);

// --- Footprint filters (finite query; sample() handles the rest) ------------------------------

// The mean of N x N bilinear taps of level 0 over the footprint parallelogram.
Rgba supersample(const Texture& texture, const SamplerOptions& options, const TextureQuery& query);

// The rip levels chosen per axis from the footprint's bounding box, bilinear in each, blended.
Rgba ripmap(const Texture& texture, const SamplerOptions& options, const TextureQuery& query);

// The average of level 0 over the footprint's bounding box (half extents at least 1/2 texel,
// at most 2^20), from the summed-area table.
Rgba summed_area(const Texture& texture, const SamplerOptions& options, const TextureQuery& query);

// The anisotropic filter's probes: N trilinear probes along the major axis.
struct AnisotropicFootprint {
  int probes = 1;      // N = Pmax = 0 ? 1 : min(ceil(Pmax / Pmin), max_anisotropy)
  double lambda = 0;   // log2(Pmax / N) + lod_bias, before clamping
  double major_s = 0;  // the major axis, (dsdx, dtdx) or (dsdy, dtdy), texture units
  double major_t = 0;
};
AnisotropicFootprint anisotropic_footprint(const Texture& texture, const SamplerOptions& options,
                                           const TextureQuery& query);
Rgba anisotropic(const Texture& texture, const SamplerOptions& options, const TextureQuery& query);

// The EWA ellipse's axes in level-0 texels after the eccentricity clamp, and its level.
struct EwaFootprint {
  double major_u = 0, major_v = 0;
  double minor_u = 0, minor_v = 0;  // replaced by major's perpendicular / M when too short
  double lambda = 0;                // log2(|minor|) + lod_bias, before clamping
};
EwaFootprint ewa_footprint(const Texture& texture, const SamplerOptions& options,
                           const TextureQuery& query);

// The most texels the ellipse's bounding box may hold in the level EWA reads, for max_anisotropy
// M: 2 (4 M + 3)^2, from 98 (M = 1) to 134,162 (M = 64). It bounds a query's work to a small
// multiple of what lod_bias 0 needs, and with lod_bias >= -1 it is never reached in a level l no
// wider than W / 2^l and no taller than H / 2^l (every level of a W x H texture down to where its
// shorter side reaches 1 texel: every level but the last of a square one). Proof: lambda = log2
// |b| + lod_bias puts the clamped minor axis b below 2^(1 - lod_bias) <= 4 texels of level
// l0 = floor(lambda) (l0 = 0 only shrinks it), and the clamp keeps the major axis a within M |b|,
// below 4 M. The box's half extents satisfy eu^2 + ev^2 = |a|^2 + |b|^2 + 2 < 16 (M^2 + 1) + 2,
// and (2 eu + 1)(2 ev + 1) <= (sqrt(2 (eu^2 + ev^2)) + 1)^2 < (sqrt(32 M^2 + 36) + 1)^2, which
// is below 2 (4 M + 3)^2 for every M >= 0.7 (with 1.7% to spare at M = 64). At lod_bias 0 the
// same steps give (sqrt(8 M^2 + 12) + 1)^2, about a quarter of the limit.
double ewa_box_limit(int max_anisotropy);

// The texels of the ellipse's bounding box in `level`, (2 eu + 1) (2 ev + 1) with the half
// extents eu = sqrt(au^2 + bu^2 + 1) and ev = sqrt(av^2 + bv^2 + 1) (a, b the footprint's axes in
// the level's texels); +inf or NaN for a footprint too large for doubles.
double ewa_box_texels(const Texture& texture, const TextureLevel& level,
                      const EwaFootprint& footprint);

// The levels EWA reads: `level` and, with weight `blend`, the next one. From l0 = floor(lambda_c)
// and blend = lambda_c - l0 (lambda_c = lambda clamped to [0, L - 1]), l0 moves one level
// coarser, and the blend is dropped (0), while the box in l0 holds more than
// ewa_box_limit(max_anisotropy) texels and l0 is not the last level. level = L - 1: the
// coarsest texel alone.
struct EwaLevels {
  std::size_t level = 0;
  double blend = 0;
};
EwaLevels ewa_levels(const Texture& texture, const SamplerOptions& options,
                     const EwaFootprint& footprint);

// The Gaussian-weighted average over the ellipse (with the unit reconstruction disk added) in
// one level, centred at (s w - 0.5, t h - 0.5). The weights never all vanish: the ellipse
// contains a unit disk, which holds a texel centre at Q <= 1/2. Throws std::invalid_argument
// when the ellipse's bounding box in this level holds more than
// ewa_box_limit(kMaxAnisotropyLimit) texels, more than ewa() ever reads in one level.
Rgba ewa_level(const Texture& texture, const TextureLevel& level, WrapMode wrap_s, WrapMode wrap_t,
               double s, double t, const EwaFootprint& footprint);

// EWA as sample.hpp defines it, in the levels of ewa_levels(): without a footprint it magnifies
// (bilinear in level 0).
Rgba ewa(const Texture& texture, const SamplerOptions& options, const TextureQuery& query);

// The 128 Gaussian weights: entry i = exp(-2 i / 127) - exp(-2), the weight at Q = i / 127, from
// 1 - exp(-2) down to 0; generated on first use. A texel at Q weighs the table interpolated
// linearly at 127 Q.
inline constexpr int kEwaWeightCount = 128;
std::span<const double> ewa_weight_table();

}  // namespace edgewise::reference
