#include "render/render_texture.hpp"

#include <sstream>
#include <vector>

#include "texture_io/texture_loader.hpp"
#include "texture_scene/linear_image.hpp"
#include "texture_scene/procedural_textures.hpp"

namespace edgewise::render_tool {
namespace {

TextureBuild build_for(const TextureSettings& settings) {
  const auto needs = [&](TextureFilter filter) {
    return settings.each_filter || settings.sampler.filter == filter;
  };
  TextureBuild build;
  build.filter = settings.pyramid;
  build.ripmaps = needs(TextureFilter::ripmap);
  build.summed_area_table = needs(TextureFilter::summed_area);
  return build;
}

}  // namespace

RenderTexture load_render_texture(const TextureSettings& settings) {
  const TextureBuild build = build_for(settings);
  const ColorEncoding encoding = settings.srgb ? ColorEncoding::srgb : ColorEncoding::linear;
  if (settings.source == kCheckerTexture) {
    // Its values are 0 and 1, the same in sRGB and linear encodings.
    const std::vector<std::uint8_t> texels =
        texture_scene::to_rgba8(texture_scene::checkerboard(kCheckerSize, kCheckerSquares));
    std::ostringstream origin;
    origin << kCheckerTexture << " (" << kCheckerSquares << "x" << kCheckerSquares << " squares)";
    return {Texture::from_rgba8(kCheckerSize, kCheckerSize, texels, encoding, build), origin.str()};
  }
  texture_io::LoadedTexture loaded =
      texture_io::load_texture(settings.source, settings.srgb, build, settings.limits);
  std::ostringstream origin;
  origin << settings.source << " (" << loaded.file_channels
         << (loaded.file_channels == 1 ? " channel " : " channels ") << loaded.pixel_type << ")";
  return {std::move(loaded.texture), origin.str()};
}

std::string describe_texture(const RenderTexture& texture, const TextureSettings& settings) {
  const Texture& t = texture.texture;
  const SamplerOptions& sampler = settings.sampler;
  std::ostringstream out;
  out << texture.origin << ", " << t.width() << "x" << t.height() << " "
      << (t.format() == TexelFormat::rgba8 ? "rgba8" : "rgba32f")
      << (settings.srgb ? " sRGB" : " linear") << ", " << t.mip_levels().size() << " mip levels ("
      << name_of(settings.pyramid) << ")";
  if (!t.ripmap_levels().empty()) {
    out << ", ripmaps " << t.ripmap_columns() << "x"
        << t.ripmap_levels().size() / static_cast<std::size_t>(t.ripmap_columns());
  }
  if (t.summed_area_table() != nullptr) out << ", summed-area table";
  out << "\n            filter ";
  if (settings.each_filter) {
    out << "each of " << values_of<TextureFilter>().size();
  } else {
    out << name_of(sampler.filter);
  }
  out << ", derivatives " << name_of(settings.derivatives) << ", wrap " << name_of(sampler.wrap_s)
      << ", lod " << name_of(sampler.lod) << ", bias " << sampler.lod_bias << ", max aniso "
      << sampler.max_anisotropy << ", taps " << sampler.supersample_taps;
  return out.str();
}

}  // namespace edgewise::render_tool
