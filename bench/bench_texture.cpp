#include "bench_texture.hpp"

#include <vector>

#include "texture_scene/procedural_textures.hpp"

namespace edgewise::bench {

const texture_scene::LinearImage& checkerboard() {
  static const texture_scene::LinearImage image =
      texture_scene::checkerboard(kTextureSize, kSquares);
  return image;
}

const Texture& checkerboard_texture() {
  static const Texture texture = [] {
    const std::vector<std::uint8_t> texels = texture_scene::to_rgba8(checkerboard());
    return Texture::from_rgba8(kTextureSize, kTextureSize, texels, ColorEncoding::linear,
                               TextureBuild{PyramidFilter::box, true, true});
  }();
  return texture;
}

}  // namespace edgewise::bench
