// The choices draw() makes under DrawOptions::error_budget (draw.hpp), and the bounds behind
// them. One scalar double function per choice, called by every ISA's shading kernel and by the
// scalar reference with the same inputs, so both make the same choices and write the same
// colours where they choose (docs/design/error-budget.md).
//
// The exact colour of a pixel is clamp(shade(p) * texel(p)) per channel, written as
// round(255 v). The choices replace it by one colour C for a whole triangle, or for the pixels a
// textured triangle writes in an 8x8 tile, computed here in double; or, in such a tile, replace
// texel(p) by one value T, the shade staying per pixel. They are taken only where
//   255 (|C - exact value| + the exact path's own float32 rounding) < K,   K = floor(255 budget),
// (for T, 255 max|shade| (|T - exact texel| + rounding) < K), which makes the written codes
// differ by at most K (two numbers less than K apart round to integers at most K apart), that is
// by at most the budget. A tile's choice reads where the sampler's queries lie over the pixels
// written (TileQueries), taken as minima and maxima of the very floats the sampler receives, so
// every path finds the same; a whole triangle's, from bounds on its texture planes over its box.
//
// Why a constant is safe: at a covered pixel centre (inside the triangle) every interpolation
// weight of draw()'s methods, perspective-correct or not, is in [0, 1] and they sum to 1, so a
// colour channel lies between the vertices' least and greatest values, and the interpolated
// normal n is a convex combination of the vertex normals, for which
//   n . l  in [min_i n_i . l, max_i n_i . l],   |n| <= max_i |n_i|,
//   |n| >= n . m / |m| >= min_i n_i . m / |m|   with m = sum_i n_i / |n_i|
// bound the light a + (1 - a) max(0, n . l / |n|). A texture filter that averages texels with
// weights in [0, 1] (nearest, bilinear, mip_nearest and trilinear of a box pyramid, whose every
// level averages level 0) lands within the texels it reads: the ranges of Texture::texel_ranges()
// over the tile's reach bound it. The midpoint of the resulting interval is C, half its width
// the model error.
//
// The exact path's rounding: the float32 plane evaluation of draw()'s plane-equation path
// (shade_planar_rows-inl.hpp), each plane within 7 u M of its exact value (u = 2^-24, M the sum of
// the magnitudes of its terms at the farthest vertex), carried through the perspective division and
// the light as the draw tests' bounds carry them (tests/draw/colour_bounds.cpp), and a filtered
// texel within 16 u of its texels' range. Triangles outside these bounds (slivers whose planes
// lose their digits, w outside the interpolators' range, huge or non-finite values) keep the
// exact method.
#pragma once

#include <cstdint>
#include <optional>

#include "edgewise/draw.hpp"
#include "shade_batch.hpp"
#include "texture_planes.hpp"

namespace edgewise::detail {

// The codes a budget allows, K = floor(255 budget (1 + 2^-20)) clamped to [0, 255]; 0 without a
// budget.
int budget_codes(const std::optional<float>& budget);

// What a triangle's shading needs for the choices: its vertices as the kernels receive them.
struct BudgetTriangle {
  Vec2 position[3];  // snapped screen positions
  double w[3];       // clip-space w
  Vec4 colour[3];
  Vec3 normal[3];  // diffuse only
};

// Each channel's exact shaded value (before any texture) over the triangle's covered pixel
// centres lies in [low, high]; the exact path's float32 value within `rounding` of it.
struct ShadeInterval {
  bool bounded = false;  // false: no bound; the triangle keeps the exact methods
  double low[4]{}, high[4]{};
  double rounding[4]{};
};

// Whether the budget looks at the triangles of `batch` at all: a budget of at least one code
// (which make_shade_batch() gives only to plane-equation shading of one sample per pixel), and
// colour-plane shading (Gouraud, diffuse) or a textured flat one.
bool budget_shades(const ShadeBatch& batch);

// Whether its textured tiles may take one colour: budget_shades(), and a filter that averages the
// texels it reads with weights in [0, 1] (nearest, bilinear, mip_nearest, trilinear).
bool budget_tiles(const ShadeBatch& batch);

// The interval of a triangle of `batch` (budget_shades()), shaded as the batch shades it (flat
// gives the first vertex's colour). An untextured triangle whose clamped interval is not
// narrower than untextured_width_limit() is left unbounded without the cost of the rounding
// bound: it cannot take one colour.
ShadeInterval shade_interval(const BudgetTriangle& triangle, const ShadeBatch& batch);

// The width_limit of shade_interval() for an untextured triangle: wider intervals cannot give
// one colour within K codes.
inline double untextured_width_limit(int codes) {
  return 2.0 * codes / 255.0;
}

// The packed RGBA8 colour that replaces the shading of an untextured triangle within K codes,
// or nothing.
std::optional<std::uint32_t> constant_colour(const ShadeInterval& shade, int codes);

// Pixels x_first..x_last by y_first..y_last, inclusive.
struct PixelBox {
  std::int32_t x_first, x_last, y_first, y_last;
};

// The budget's plan for a textured triangle of `batch`, from its snapped screen positions: one
// colour for all its pixels, else per-tile choices (measured_texture_tile()) when its box spans
// kTilePlanSpan pixels or more on an axis, else the exact methods. A small triangle's own box is
// as tight as its tiles' (each 8x8 whole), and one decision costs what one tile's does.
struct TexturePlan {
  std::optional<std::uint32_t> colour;
  bool tiles = false;
};
constexpr std::int32_t kTilePlanSpan = 16;
TexturePlan texture_plan(const ShadeInterval& shade, const TexturePlanes& planes,
                         const ShadeBatch& batch, const Vec2 (&position)[3]);

// The texture queries of the pixels a tile writes, as the sampler receives them: each field's
// least and greatest value (s, t, ds/dx, dt/dx, ds/dy, dt/dy), and whether all were finite.
struct TileQueries {
  bool finite = true;
  float low[6], high[6];
};

// The choice for a tile: one packed colour for shade times texel, or else (one_texel) one texel
// value for every pixel, with the shade still per pixel; neither when both are empty.
struct TileTexture {
  std::optional<std::uint32_t> colour;
  bool one_texel = false;
  float texel[4]{};
};

// The choice for a tile of a textured triangle of `batch` (texture_plan().tiles) that writes
// pixels whose queries lie within `queries`.
TileTexture measured_texture_tile(const ShadeInterval& shade, const TileQueries& queries,
                                  const ShadeBatch& batch);

}  // namespace edgewise::detail
