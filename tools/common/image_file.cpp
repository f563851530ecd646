#include "common/image_file.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <vector>

#include "common/output_file.hpp"

namespace edgewise::tools {

void write_image_file(const std::string& path, const ImagePixels& image) {
  const bool is_float = image.bytes.empty();
  const std::size_t values = static_cast<std::size_t>(image.width) *
                             static_cast<std::size_t>(image.height) *
                             static_cast<std::size_t>(image.channels);
  if (image.width < 1 || image.height < 1 || image.channels < 1 ||
      (is_float ? image.floats.size() : image.bytes.size()) != values ||
      (!image.channel_names.empty() &&
       image.channel_names.size() != static_cast<std::size_t>(image.channels))) {
    throw std::invalid_argument("write_image_file: empty or inconsistent image");
  }
  const OIIO::TypeDesc type = is_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  OIIO::ImageSpec spec(image.width, image.height, image.channels, type);
  if (!image.channel_names.empty()) {
    spec.channelnames = image.channel_names;
    const auto index_of = [&image](const char* name) {
      const auto found = std::find(image.channel_names.begin(), image.channel_names.end(), name);
      return found == image.channel_names.end()
                 ? -1
                 : static_cast<int>(found - image.channel_names.begin());
    };
    spec.alpha_channel = index_of("A");
    spec.z_channel = index_of("Z");
  }
  if (image.srgb) spec.attribute("oiio:ColorSpace", "sRGB");

  const auto fail = [&path](const std::string& reason) {
    // OpenImageIO's messages may span lines; the tools report one.
    std::string line = reason;
    std::replace(line.begin(), line.end(), '\n', ' ');
    throw std::runtime_error(path + ": cannot write: " + line);
  };
  const void* pixels = is_float ? static_cast<const void*>(image.floats.data())
                                : static_cast<const void*>(image.bytes.data());
  // Encoded in memory, then written by OutputFile: some of OpenImageIO's writers (PNG) do not
  // report a failed write to the file, so the file's own writes are ours to check.
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput memory(encoded);
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
  if (!out) fail(OIIO::geterror());
  if (!out->supports("ioproxy") || !out->set_ioproxy(&memory)) {
    fail(std::string("OpenImageIO's ") + out->format_name() + " writer cannot encode in memory");
  }
  if (!out->open(path, spec)) fail(out->geterror());
  if (!out->write_image(type, pixels)) fail(out->geterror());
  if (!out->close()) fail(out->geterror());
  write_whole_file(path, std::as_bytes(std::span<const unsigned char>(encoded)));
}

}  // namespace edgewise::tools
