#include "texture_io/load_options.hpp"

#include <string>

#include "common/sampler_options.hpp"
#include "common/value_options.hpp"

namespace edgewise::texture_io {

void add_texture_load_options(tools::CommandLine& line, PyramidFilter& pyramid, bool& srgb,
                              LoadLimits& limits) {
  tools::add_pyramid_option(line, pyramid, "how coarser levels are made (default box)");
  line.add_flag("--srgb", srgb,
                "R, G, B are sRGB-encoded: 8-bit texels are decoded by the sampler,\n"
                "others when loaded (clamped to [0, 1] first); alpha is linear");
  tools::add_mebibytes_option(line, "--max-texture-mb", limits.max_texture_bytes,
                              "refuse an image file whose texels would take more than MB MiB\n"
                              "as a texture (read from its header, before any pixel; default " +
                                  std::to_string(kDefaultMaxTextureBytes >> 20) + ")");
}

}  // namespace edgewise::texture_io
