// Texture sampling: every filter from magnification to EWA, from texture coordinates and their
// screen derivatives, 8 queries per step on AVX2 (4 on SSE and NEON).
//
// Footprint and level of detail. With W x H the size of level 0, the derivatives in texels are
//   ux = dsdx W, vx = dtdx H, uy = dsdy W, vy = dtdy H,
// and the level of detail of mip_nearest and trilinear is lambda = log2(rho) - log2(3) / 2 +
// lod_bias, with
//   LodFormula::exact:    rho = max(sqrt(ux^2 + vx^2), sqrt(uy^2 + vy^2))
//   LodFormula::max_axis: rho = max(|ux|, |vx|, |uy|, |vy|)   (cheaper; up to sqrt(2) lower)
// The level 2^lambda texels wide, read bilinearly, blurs as much as a box of width rho (equal
// variances, docs/design/textures.md). lambda <= 0 (rho <= sqrt(3) texels) magnifies
// (level 0); mip filters clamp lambda to [0, levels - 1].
//
// The filters (all results linear RGBA, 8-bit textures decoded first):
//   nearest                the texel containing (s, t) in level 0
//   bilinear               the 2x2 texels around (s, t) in level 0, weighted by distance
//   bicubic_catmull_rom    4x4 texels of level 0, Catmull-Rom weights (interpolating)
//   bicubic_bspline        4x4 texels of level 0, cubic B-spline weights (smoothing, not
//                          interpolating)
//   mip_nearest            bilinear in the level nearest lambda (round half down)
//   trilinear              bilinear in levels floor(lambda) and floor(lambda) + 1, blended by the
//                          fraction
//   supersample            N x N bilinear taps of level 0 at the centres of an N x N grid over the
//                          footprint parallelogram (s, t) + a (dsdx, dtdx) + b (dsdy, dtdy),
//                          a, b in [-1/2, 1/2]
//   ripmap                 the rip levels chosen per axis from the footprint's bounding box
//                          (extents max(|ux|, |uy|) and max(|vx|, |vy|)), bilinear in each, blended
//                          between neighbouring levels on both axes
//   summed_area            the exact average of the nearest-neighbour texture over the footprint's
//                          axis-aligned bounding box (at least one texel on each axis)
//   anisotropic            GPU-style: N = min(ceil(Pmax / Pmin), max_anisotropy) trilinear probes
//                          spread evenly along the major axis (P = the two axis lengths), lambda
//                          = log2(Pmax / N) + lod_bias: no variance offset, the probes' spacing
//                          sets their level
//   ewa                    elliptical weighted average (Heckbert): texels inside the footprint
//                          ellipse (widened by the unit reconstruction disk) weighted by a
//                          Gaussian table (128 entries generated at start-up, interpolated);
//                          level from the minor axis after clamping the eccentricity to
//                          max_anisotropy, blended between two levels; while the ellipse's
//                          bounding box in the finer level holds over 2 (4 M + 3)^2 texels
//                          (M = max_anisotropy: 98 to 134,162) a coarser level is used alone,
//                          which bounds a query's work to a few times what lod_bias 0 needs
//                          (at most (sqrt(8 M^2 + 12) + 1)^2 texels). With lod_bias >= -1 it
//                          never applies in a level that halves both sides (every level but the
//                          last of a square texture; docs/design/proofs.md indexes the
//                          proof); a level stuck at 1 texel on its shorter side holds more of
//                          the footprint and may reach it sooner
//
// Wrap modes apply per axis to every texel fetched. Results for bad input are defined: a query
// with non-finite s or t gives (0, 0, 0, 0); derivatives that are zero magnify; huge ones select
// the coarsest level; a non-finite derivative makes every filter that reads derivatives return
// the coarsest level's single texel (the texture's average). Float textures holding NaN or
// infinite texels give NaN or infinite results wherever a filter reads them (even at weight 0).
//
// Thread safety: sample() only reads the texture and the queries and writes `out`: any number of
// calls may share a texture at once.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "edgewise/isa.hpp"
#include "edgewise/texture.hpp"
#include "edgewise/vector.hpp"
#include "edgewise/names.hpp"

namespace edgewise {

enum class TextureFilter : std::uint8_t {
  nearest,
  bilinear,
  bicubic_catmull_rom,
  bicubic_bspline,
  mip_nearest,
  trilinear,
  supersample,
  ripmap,
  summed_area,
  anisotropic,
  ewa,
};

enum class WrapMode : std::uint8_t {
  repeat,         // the texture tiles the plane
  clamp_to_edge,  // coordinates outside [0, 1) take the border texel
  mirror,         // every other copy is mirrored (period 2)
};

enum class LodFormula : std::uint8_t { exact, max_axis };

// The arithmetic of the bilinear taps on linear 8-bit textures (the taps of bilinear,
// mip_nearest, trilinear, supersample, ripmap and anisotropic):
//   float32  texels decoded to float, weights and sums in float (a few ulps from exact)
//   fixed16  texels widened to 16-bit integers, each weight rounded to a multiple of 2^-15 and
//            the products summed exactly in 32-bit integers, as GPUs filter: a result is off by
//            at most 2^-15 times the texels' largest value per weight (8 for trilinear, 8 per
//            anisotropic probe before the probes' mean), about 1/128 of an 8-bit step
//   automatic  the precision measured best for the filter (default_precision())
// sRGB and float textures, and the other filters, are filtered in float32 whatever is asked;
// Isa::reference computes the exact result whatever the precision.
enum class FilterPrecision : std::uint8_t { automatic, float32, fixed16 };

// The ranges of SamplerOptions' integer options.
inline constexpr int kMaxAnisotropyLimit = 64;
inline constexpr int kMaxSupersampleTaps = 16;

struct SamplerOptions {
  TextureFilter filter = TextureFilter::trilinear;
  WrapMode wrap_s = WrapMode::repeat;
  WrapMode wrap_t = WrapMode::repeat;
  LodFormula lod = LodFormula::exact;
  float lod_bias = 0.0f;
  int max_anisotropy = 16;   // anisotropic probes, EWA eccentricity; 1 .. kMaxAnisotropyLimit
  int supersample_taps = 4;  // N of the N x N grid; 1 .. kMaxSupersampleTaps
  FilterPrecision precision = FilterPrecision::automatic;
};

// Whether `filter` is made of bilinear taps, those FilterPrecision applies to.
bool reads_bilinear_taps(TextureFilter filter);

// The precision `automatic` stands for with `filter`: fixed16 where, on every view of the texture
// study (docs/texture-filtering.md, "Fixed-point taps"), its error against ground truth stays
// within 0.05 dB of float32's, float32 elsewhere.
FilterPrecision default_precision(TextureFilter filter);

// The precision sample() and draw() use for `options` on `texture`: float32 wherever fixed16
// does not apply (above), else the one asked for, `automatic` resolved by default_precision().
FilterPrecision effective_precision(const Texture& texture, const SamplerOptions& options);

// One query: the position and its screen derivatives, in texture coordinates (per pixel).
// The same six floats, in this order, as a record of edgewise-sample's query files.
struct TextureQuery {
  float s, t, dsdx, dtdx, dsdy, dtdy;
};

// What sample() is asked for: the filter, and the ISA that runs it, as RasterOptions and
// DrawOptions choose theirs. A SamplerOptions converts to it with the default ISA.
struct SampleOptions {
  SamplerOptions sampler;
  std::optional<Isa> isa;  // default: active_isa(); Isa::reference runs the scalar
                           // double-precision reference

  SampleOptions() = default;
  SampleOptions(const SamplerOptions& sampler_options, std::optional<Isa> chosen = std::nullopt)
      : sampler(sampler_options), isa(chosen) {}
};

// out[i] = the filtered linear RGBA at queries[i]. Throws std::invalid_argument when the spans'
// sizes differ, an option is out of range, the ISA is not supported (isa.hpp), or the filter
// needs ripmaps or a summed-area table the texture was built without.
void sample(const Texture& texture, const SampleOptions& options,
            std::span<const TextureQuery> queries, std::span<Vec4> out);

// Names of the values (names.hpp).
std::string_view name_of(TextureFilter value);
template <>
std::span<const TextureFilter> values_of<TextureFilter>();
std::string_view name_of(WrapMode value);
template <>
std::span<const WrapMode> values_of<WrapMode>();
std::string_view name_of(LodFormula value);
template <>
std::span<const LodFormula> values_of<LodFormula>();
std::string_view name_of(FilterPrecision value);
template <>
std::span<const FilterPrecision> values_of<FilterPrecision>();

}  // namespace edgewise
