// PNG files encoded by libpng itself, for the 8-bit images the tools write (frames, pictures,
// result images): libpng loads with the tool, where OpenImageIO's module and its 260 libraries
// take most of half a second to load (image_module/image_module.hpp). The file holds what
// OpenImageIO's PNG writer would store: associated (premultiplied) colour is de-associated as
// PNG requires, with OpenImageIO's rounding, so that the two writers' pixels agree bit for bit.
#pragma once

#include <vector>

#include "common/image_file.hpp"

namespace edgewise::tools {

// Whether `path` names a PNG file (its extension, in any case).
bool is_png_path(const std::string& path);

// `image` (8-bit values, 1 to 4 channels: grey, grey and alpha, RGB, RGBA; the alpha channel is
// the last of 2 or 4 and holds associated colour) as a PNG file in memory. An sRGB image says so
// (the sRGB chunk, with gAMA and cHRM for older readers); any other says nothing of its colour
// space, as OpenImageIO's writer does. Throws std::invalid_argument when `image` is not such an
// image, std::runtime_error with libpng's reason when it cannot be encoded.
std::vector<unsigned char> encode_png(const ImagePixels& image);

}  // namespace edgewise::tools
