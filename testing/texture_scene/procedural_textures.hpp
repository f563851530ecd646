// Test textures for scoring the filters: a high-frequency one (a checkerboard, sharp edges that
// alias) and a band-limited one (sums of sinusoids, which a good filter reproduces closely).
//
// Both are square, opaque (alpha 1) and hold 8-bit values exactly (every value is
// unorm8_value(q)), so to_rgba8() gives the bytes of an RGBA8 linear Texture with exactly the
// same values, and the ground truth integrates exactly what the sampler reads.
#pragma once

#include <cstdint>

#include "texture_scene/linear_image.hpp"

namespace edgewise::texture_scene {

// size x size texels of squares x squares alternating black (0) and white (1) squares, square
// (0, 0) white. Texel (a, b) lies in square (floor(a squares / size), floor(b squares / size)),
// so when size is not a multiple of squares the squares differ in width by one texel. Repeating
// is seamless when squares is even. Throws std::invalid_argument unless 1 <= squares <= size
// and size <= 2^15.
LinearImage checkerboard(std::int32_t size, std::int32_t squares);

// size x size texels, each colour channel a fixed sum of three 2D sinusoids about 0.5:
//   value(a, b) = 0.5 + sum_k amplitude_k sin(2 pi (kx_k a + ky_k b) / size + phase_k),
// with integer cycle counts (kx, ky) over the texture, so the texture is periodic and repeat
// wrap is seamless. The components' frequencies, sqrt(kx^2 + ky^2) / size in cycles per texel,
// are fixed fractions (1 down to 1/10) of `highest_frequency` and never exceed it; at most 1/4
// (level 0's Nyquist limit is 1/2), so the texture is smooth on the texel scale. (On a small
// texture a low component may truncate to zero cycles: a constant.) The amplitudes
// sum to 0.45 per channel, keeping values in [0.05, 0.95]. Values are rounded to 8 bits: that
// adds at most 1/510 of broadband noise, part of the texture (the ground truth integrates it
// too). Throws std::invalid_argument unless 1 <= size <= 2^15 and 0 < highest_frequency <= 1/4.
LinearImage sinusoids(std::int32_t size, double highest_frequency = 1.0 / 8.0);

}  // namespace edgewise::texture_scene
