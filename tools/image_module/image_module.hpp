// What the tools do through OpenImageIO (encode and read image files, its TextureSystem as a
// peer), in a module of its own that a tool loads the first time it needs it: OpenImageIO and the
// 260 libraries it loads take a tool most of half a second to start, which a run that never
// touches an image file (a usage error, --help, a refused input) need not pay.
//
// The module holds OpenImageIO's code only; the checks, messages and files stay with the tools
// (common/image_file.cpp, texture_io/texture_loader.cpp, texture_quality/oiio_peer.cpp). Every
// function throws std::runtime_error with OpenImageIO's reason, possibly on several lines.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "edgewise/sample.hpp"

namespace edgewise::tools {

// The interface's version: a module built from other sources is refused.
inline constexpr int kImageModuleVersion = 1;

// Interleaved pixels to encode, row-major from the top row (common/image_file.hpp's ImagePixels).
struct EncodeRequest {
  int width = 0, height = 0, channels = 0;
  const void* pixels = nullptr;
  bool is_float = false;                   // float values, else 8-bit ones
  std::vector<std::string> channel_names;  // empty: the format's default
  bool srgb = false;
};

// An image file's header: its first subimage at full resolution.
struct ImageHeader {
  int width = 0, height = 0, depth = 1, channels = 0;
  bool uint8 = false;      // 8-bit unsigned channels
  std::string pixel_type;  // as OpenImageIO names it ("uint8", "half", ...)
  int tile_height = 0;     // 0: the file is in scanlines
};

class ImageReader {
 public:
  virtual ~ImageReader() = default;
  virtual const ImageHeader& header() const = 0;
  // Rows [y0, y1) of channels [0, channels), converted to 8-bit (as_uint8) or float values,
  // into `out` (interleaved). In a tiled file y0 and y1 are on tile rows, or y1 the height.
  virtual void read_rows(int y0, int y1, int channels, bool as_uint8, void* out) = 0;
};

// OpenImageIO's TextureSystem over one texture file, with periodic wrap.
class TextureLookup {
 public:
  virtual ~TextureLookup() = default;
  // out[i] = the lookup of queries[i]: mip 0 none, 1 trilinear, 2 anisotropic; interpolation
  // 0 closest, 1 bilinear, 2 bicubic; `anisotropy` the most samples along the major axis.
  virtual void sample(int mip, int interpolation, int anisotropy,
                      std::span<const TextureQuery> queries, std::span<Vec4> out) = 0;
};

class ImageModule {
 public:
  // The file of `path`'s format (by its extension), encoded in memory.
  virtual std::vector<unsigned char> encode(const std::string& path,
                                            const EncodeRequest& image) const = 0;
  // Opens the file and reads its header; texel values are kept as stored (an unassociated alpha
  // is not premultiplied).
  virtual std::unique_ptr<ImageReader> open(const std::string& path) const = 0;
  // Writes 8-bit RGBA texels as a tiled, mipmapped texture file (box-filtered levels).
  virtual void write_texture_file(const std::string& path, int width, int height,
                                  std::span<const std::uint8_t> rgba) const = 0;
  virtual std::unique_ptr<TextureLookup> open_texture(const std::string& path) const = 0;

 protected:
  ~ImageModule() = default;
};

// The module, loaded on the first call (from the running program's directory, else from where
// the build put it). Throws std::runtime_error when it cannot be loaded.
const ImageModule& image_module();

// The type of the module's one exported function, extern "C" edgewise_image_module: the module,
// or null when `version` is not the kImageModuleVersion it was built with.
using ImageModuleEntry = const ImageModule* (*)(int version);

}  // namespace edgewise::tools
