#include "texture_quality/scenes.hpp"

#include <stdexcept>
#include <vector>

#include "texture_scene/builtin_views.hpp"
#include "texture_scene/procedural_textures.hpp"

namespace edgewise::texture_quality {

std::string_view scene_texture_name(SceneTexture texture) {
  return texture == SceneTexture::checkerboard ? "checkerboard" : "sinusoids";
}

std::optional<SceneTexture> parse_scene_texture(std::string_view name) {
  for (SceneTexture texture : kSceneTextures) {
    if (name == scene_texture_name(texture)) return texture;
  }
  return std::nullopt;
}

std::string_view scene_view_name(SceneView view) {
  return view == SceneView::ground_plane ? "ground_plane" : "magnification";
}

std::optional<SceneView> parse_scene_view(std::string_view name) {
  for (SceneView view : kSceneViews) {
    if (name == scene_view_name(view)) return view;
  }
  return std::nullopt;
}

texture_scene::LinearImage scene_texture_image(SceneTexture texture, std::int32_t size) {
  if (size < 1 || size > (1 << 15) || size % (2 * kCheckerSquareTexels) != 0) {
    throw std::invalid_argument("scene_texture_image: size " + std::to_string(size) +
                                " is not a multiple of " +
                                std::to_string(2 * kCheckerSquareTexels) + " in 1..32768");
  }
  return texture == SceneTexture::checkerboard
             ? texture_scene::checkerboard(size, size / kCheckerSquareTexels)
             : texture_scene::sinusoids(size);
}

std::string scene_texture_description(SceneTexture texture, std::int32_t size) {
  const std::string n = std::to_string(size);
  return texture == SceneTexture::checkerboard
             ? "checkerboard(" + n + ", " + std::to_string(size / kCheckerSquareTexels) +
                   " squares)"
             : "sinusoids(" + n + ")";
}

Texture scene_texture(const texture_scene::LinearImage& image, PyramidFilter pyramid) {
  const std::vector<std::uint8_t> texels = texture_scene::to_rgba8(image);
  return Texture::from_rgba8(image.width, image.height, texels, ColorEncoding::linear,
                             TextureBuild{pyramid, /*ripmaps=*/true, /*summed_area_table=*/true});
}

texture_scene::TextureView scene_view(SceneView view, std::int32_t width, std::int32_t height,
                                      std::int32_t texture_size) {
  return view == SceneView::ground_plane
             ? texture_scene::ground_plane_view(width, height)
             : texture_scene::magnification_view(width, height, texture_size, texture_size);
}

}  // namespace edgewise::texture_quality
