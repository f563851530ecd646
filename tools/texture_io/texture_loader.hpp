// Reading an image file into an edgewise::Texture through OpenImageIO (edgewise-sample and
// edgewise-render load their textures alike).
//
// 8-bit images become RGBA8 textures (sRGB-encoded when asked, linear otherwise); every other
// pixel type is read as float (OpenImageIO maps 16-bit v to v / 65535) into an RGBA float
// texture, sRGB-decoded at load when asked. Channels expand to RGBA: grey -> (g, g, g, 1), grey
// and alpha -> (g, g, g, a), RGB -> (r, g, b, 1); beyond four, the first four are R, G, B, A.
// Texel values are taken as stored: an unassociated alpha (PNG) is not premultiplied.
#pragma once

#include <string>

#include "edgewise/texture.hpp"

namespace edgewise::texture_io {

struct LoadedTexture {
  Texture texture;
  int file_channels = 0;   // before expansion to RGBA
  std::string pixel_type;  // as OpenImageIO names it ("uint8", "half", ...)
};

// Throws std::runtime_error("PATH: reason") when the file cannot be read as an image, is not 2D,
// or is larger than a Texture may be.
LoadedTexture load_texture(const std::string& path, bool srgb, const TextureBuild& build);

}  // namespace edgewise::texture_io
