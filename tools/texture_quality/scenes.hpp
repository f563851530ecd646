// The scenes the filters are scored on: a procedural texture seen through one of the built-in
// views (texture_scene/builtin_views.hpp), with repeat wrap on both axes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "edgewise/texture.hpp"
#include "texture_scene/linear_image.hpp"
#include "texture_scene/texture_view.hpp"

namespace edgewise::texture_quality {

enum class SceneTexture : std::uint8_t {
  checkerboard,  // high frequency: sharp edges that alias
  sinusoids,     // band-limited: a good filter reproduces it closely
};

enum class SceneView : std::uint8_t {
  ground_plane,   // perspective minification, far footprints up to 30:1 anisotropic
  magnification,  // a few texels over the whole screen
};

inline constexpr SceneTexture kSceneTextures[] = {SceneTexture::checkerboard,
                                                  SceneTexture::sinusoids};
inline constexpr SceneView kSceneViews[] = {SceneView::ground_plane, SceneView::magnification};

// The checkerboard's squares are 16 texels wide at every texture size (64 squares across 1024
// texels), so that the texture size changes the footprints' lengths in texels, not the pattern.
inline constexpr std::int32_t kCheckerSquareTexels = 16;

std::string_view scene_texture_name(SceneTexture texture);
std::optional<SceneTexture> parse_scene_texture(std::string_view name);
std::string_view scene_view_name(SceneView view);
std::optional<SceneView> parse_scene_view(std::string_view name);

// size x size texels: checkerboard(size, size / kCheckerSquareTexels) or sinusoids(size).
// Throws std::invalid_argument unless size is a positive multiple of 2 kCheckerSquareTexels
// (an even number of squares, so that repeat wrap is seamless) and at most 2^15.
texture_scene::LinearImage scene_texture_image(SceneTexture texture, std::int32_t size);

// "checkerboard(1024, 64 squares)", "sinusoids(1024)".
std::string scene_texture_description(SceneTexture texture, std::int32_t size);

// The RGBA8 linear Texture of `image` (whose values are all 8-bit, as the procedural textures'
// are), with mipmaps made by `pyramid`, ripmaps and a summed-area table, so every filter runs.
Texture scene_texture(const texture_scene::LinearImage& image, PyramidFilter pyramid);

texture_scene::TextureView scene_view(SceneView view, std::int32_t width, std::int32_t height,
                                      std::int32_t texture_size);

}  // namespace edgewise::texture_quality
