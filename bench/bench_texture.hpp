// The texture the sampling and textured-drawing benchmarks share: a 1024 x 1024 RGBA8
// checkerboard of 64 x 64 squares, linear, with box mipmaps, ripmaps and a summed-area table
// (so that every filter runs on it).
#pragma once

#include <cstdint>

#include "edgewise/texture.hpp"
#include "texture_scene/linear_image.hpp"

namespace edgewise::bench {

inline constexpr std::int32_t kTextureSize = 1024;
inline constexpr std::int32_t kSquares = 64;

const texture_scene::LinearImage& checkerboard();
const Texture& checkerboard_texture();

}  // namespace edgewise::bench
