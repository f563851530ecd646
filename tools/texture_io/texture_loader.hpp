// Reading an image file into an edgewise::Texture through OpenImageIO (edgewise-sample and
// edgewise-render load their textures alike).
//
// 8-bit images become RGBA8 textures (sRGB-encoded when asked, linear otherwise); every other
// pixel type is read as float (OpenImageIO maps 16-bit v to v / 65535) into an RGBA float
// texture, sRGB-decoded at load when asked. Channels expand to RGBA: grey -> (g, g, g, 1), grey
// and alpha -> (g, g, g, a), RGB -> (r, g, b, 1); beyond four, the first four are R, G, B, A.
// Texel values are taken as stored: an unassociated alpha (PNG) is not premultiplied.
//
// An image's size is read from its header and checked before any pixel is read or allocated:
// a file of a few bytes may claim 32768 x 32768 texels, and a compressed one may inflate a
// thousandfold. The limit is on level 0 as the Texture keeps it (4 bytes a texel for 8-bit
// files, 16 for the rest); loading takes at most about three times that in all (the decoder's
// buffer, level 0, and the Texture with its pyramid and ranges), read in bands of rows so that
// no second copy of the whole image is made.
#pragma once

#include <cstdint>
#include <string>

#include "edgewise/texture.hpp"

namespace edgewise::texture_io {

// The default limit on level 0's memory: 128 MiB, e.g. 8192 x 4096 8-bit texels or 4096 x 2048
// float ones. Tools raise it with --max-texture-mb.
inline constexpr std::uint64_t kDefaultMaxTextureBytes = std::uint64_t{128} << 20;

struct LoadLimits {
  std::uint64_t max_texture_bytes = kDefaultMaxTextureBytes;
};

struct LoadedTexture {
  Texture texture;
  int file_channels = 0;   // before expansion to RGBA
  std::string pixel_type;  // as OpenImageIO names it ("uint8", "half", ...)
};

// Throws std::runtime_error("PATH: reason") when the file is not a readable regular file
// (common/input_file.hpp), cannot be read as an image, is not 2D, is larger than a Texture may
// be, or needs more than limits.max_texture_bytes.
LoadedTexture load_texture(const std::string& path, bool srgb, const TextureBuild& build,
                           const LoadLimits& limits = {});

}  // namespace edgewise::texture_io
