// OpenImageIO's TextureSystem as a peer, on the same queries and the same texels: the texture is
// written as a tiled, mipmapped file (box-filtered mipmaps, as edgewise's default pyramid) and
// looked up one query at a time with periodic wrap, in the modes the benchmark suite measures
// (bench/texture/sample_bench.cpp).
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "edgewise/sample.hpp"
#include "edgewise/vector.hpp"
#include "texture_scene/linear_image.hpp"

namespace edgewise::texture_quality {

// closest, bilinear and bicubic read level 0 only; trilinear and anisotropic16 use the mipmaps.
inline constexpr std::string_view kPeerModeNames[] = {"closest", "bilinear", "bicubic", "trilinear",
                                                      "anisotropic16"};

class OiioPeer {
 public:
  // Writes `image` (whose values are all 8-bit, as the procedural textures' are) to a temporary
  // .tx file named after `label`, which the destructor removes. Throws std::runtime_error when
  // OpenImageIO cannot write it.
  OiioPeer(const texture_scene::LinearImage& image, std::string_view label);
  ~OiioPeer();
  OiioPeer(const OiioPeer&) = delete;
  OiioPeer& operator=(const OiioPeer&) = delete;

  // out[i] = the lookup of queries[i] in the mode kPeerModeNames[mode] (linear RGBA). Throws
  // std::invalid_argument for a mode out of range or spans of different sizes, and
  // std::runtime_error when a lookup fails.
  void sample(std::size_t mode, std::span<const TextureQuery> queries, std::span<Vec4> out);

 private:
  struct System;
  std::filesystem::path file_;
  std::unique_ptr<System> system_;
};

}  // namespace edgewise::texture_quality
