#include "common/image_file.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "common/output_file.hpp"
#include "image_module/image_module.hpp"

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
  const auto fail = [&path](const std::string& reason) {
    // OpenImageIO's messages may span lines; the tools report one.
    std::string line = reason;
    std::replace(line.begin(), line.end(), '\n', ' ');
    throw std::runtime_error(path + ": cannot write: " + line);
  };
  EncodeRequest request;
  request.width = image.width;
  request.height = image.height;
  request.channels = image.channels;
  request.is_float = is_float;
  request.pixels = is_float ? static_cast<const void*>(image.floats.data())
                            : static_cast<const void*>(image.bytes.data());
  request.channel_names = image.channel_names;
  request.srgb = image.srgb;
  // Encoded in memory, then written by OutputFile: some of OpenImageIO's writers (PNG) do not
  // report a failed write to the file, so the file's own writes are ours to check.
  std::vector<unsigned char> encoded;
  try {
    encoded = image_module().encode(path, request);
  } catch (const std::runtime_error& error) {
    fail(error.what());
  }
  write_whole_file(path, std::as_bytes(std::span<const unsigned char>(encoded)));
}

}  // namespace edgewise::tools
