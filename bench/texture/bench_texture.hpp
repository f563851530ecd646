// The texture the sampling and textured-drawing benchmarks share: a 1024 x 1024 RGBA8
// checkerboard of 64 x 64 squares, linear, with box mipmaps, ripmaps and a summed-area table
// (so that every filter runs on it); and the ground-plane view drawn as geometry.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include <benchmark/benchmark.h>

#include "edgewise/draw.hpp"
#include "edgewise/texture.hpp"
#include "edgewise/vector.hpp"
#include "texture_scene/linear_image.hpp"
#include "texture_scene/texture_view.hpp"
#include "texture_scene/view_mesh.hpp"

namespace edgewise::bench {

inline constexpr std::int32_t kTextureSize = 1024;
inline constexpr std::int32_t kSquares = 64;

const texture_scene::LinearImage& checkerboard();
const Texture& checkerboard_texture();

// texture_scene's ground-plane view at kWidth x kHeight, and the two triangles that draw it
// (texture_scene::view_mesh()), built once.
const texture_scene::TextureView& ground_plane();
const texture_scene::ViewMesh& ground_plane_mesh();
// How TexturedDraw/ draws that mesh: the checkerboard through `filter` and `derivatives`, white
// flat shading, depth test less with writes, into a target cleared to kGroundPlaneClearColor
// and depth 1.
DrawOptions ground_plane_options(Isa isa, TextureFilter filter, TextureDerivatives derivatives);
inline constexpr Vec4 kGroundPlaneClearColor{0.0f, 0.0f, 0.0f, 0.0f};

// For a filter made of bilinear taps, the precision its default does not use on the
// checkerboard (float32 or fixed16), which the benchmarks run beside the default.
inline FilterPrecision other_precision(TextureFilter filter) {
  return default_precision(filter) == FilterPrecision::fixed16 ? FilterPrecision::float32
                                                               : FilterPrecision::fixed16;
}
inline constexpr float kGroundPlaneClearDepth = 1.0f;

// Error beside speed: when edgewise-texture-quality has stored the ground truth of the
// checkerboard seen through `view` (named `view_name`, its file in the default cache directory;
// computing it takes minutes, too long for a benchmark run), sets the counter "rmse" (linear
// R, G, B, as that tool scores) of `colours`, one per pixel of the view, and "psnr_db".
// Otherwise sets neither.
void report_error(benchmark::State& state, const std::string& view_name,
                  const texture_scene::TextureView& view, std::span<const Vec4> colours);

}  // namespace edgewise::bench
