#include "common/image_file.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "common/output_file.hpp"
#include "common/png_encoder.hpp"
#include "image_module/image_module.hpp"

namespace edgewise::tools {
namespace {

std::vector<unsigned char> encode_through_image_module(const std::string& path,
                                                       const ImagePixels& image) {
  const bool is_float = image.bytes.empty();
  EncodeRequest request;
  request.width = image.width;
  request.height = image.height;
  request.channels = image.channels;
  request.is_float = is_float;
  request.pixels = is_float ? static_cast<const void*>(image.floats.data())
                            : static_cast<const void*>(image.bytes.data());
  request.channel_names = image.channel_names;
  request.srgb = image.srgb;
  return image_module().encode(path, request);
}

}  // namespace

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
  // Encoded in memory, then written by OutputFile: some of OpenImageIO's writers (PNG) do not
  // report a failed write to the file, so the file's own writes are ours to check. 8-bit PNG
  // files, the ones the tools write most, are libpng's, without loading OpenImageIO.
  const bool own_png =
      !is_float && image.channels <= 4 && image.channel_names.empty() && is_png_path(path);
  std::vector<unsigned char> encoded;
  try {
    encoded = own_png ? encode_png(image) : encode_through_image_module(path, image);
  } catch (const std::runtime_error& error) {
    // OpenImageIO's messages may span lines; the tools report one.
    std::string line = error.what();
    std::replace(line.begin(), line.end(), '\n', ' ');
    throw std::runtime_error(path + ": cannot write: " + line);
  }
  write_whole_file(path, std::as_bytes(std::span<const unsigned char>(encoded)));
}

}  // namespace edgewise::tools
