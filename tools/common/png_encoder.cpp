#include "common/png_encoder.hpp"

#include <png.h>

#include <algorithm>
#include <csetjmp>
#include <cstdint>
#include <new>
#include <stdexcept>
#include <string>

#include "common/file_extension.hpp"

namespace edgewise::tools {
namespace {

constexpr int kColourTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                PNG_COLOR_TYPE_RGB_ALPHA};

// PNG stores colour unassociated from alpha: colour * 255 / alpha, truncated and clamped, as
// OpenImageIO's PNG writer computes it; a pixel of alpha 0 keeps its colour.
std::vector<std::uint8_t> deassociated(std::span<const std::uint8_t> values, int channels) {
  std::vector<std::uint8_t> out(values.begin(), values.end());
  for (std::size_t pixel = 0; pixel < out.size(); pixel += static_cast<std::size_t>(channels)) {
    const unsigned alpha = out[pixel + channels - 1];
    if (alpha == 0) continue;
    for (int c = 0; c < channels - 1; ++c)
      out[pixel + c] = static_cast<std::uint8_t>(std::min(255u, out[pixel + c] * 255u / alpha));
  }
  return out;
}

// What libpng's callbacks report to: the encoded bytes and the first error's reason.
struct Encoding {
  std::vector<unsigned char> bytes;
  std::string error;
};

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* encoding = static_cast<Encoding*>(png_get_io_ptr(png));
  bool out_of_memory = false;
  try {
    encoding->bytes.insert(encoding->bytes.end(), data, data + length);
  } catch (const std::bad_alloc&) {
    out_of_memory = true;
  }
  // png_error leaves by longjmp, which must not cross the catch block.
  if (out_of_memory) png_error(png, "out of memory");
}

void flush_nothing(png_structp) {}

void record_error(png_structp png, png_const_charp message) {
  auto* encoding = static_cast<Encoding*>(png_get_error_ptr(png));
  if (encoding->error.empty()) encoding->error = message;
  png_longjmp(png, 1);
}

void ignore_warning(png_structp, png_const_charp) {}

// The libpng calls, which report an error by longjmp back here: nothing in this function has a
// destructor that the jump would skip.
bool write_png(png_structp png, png_infop info, const ImagePixels& image, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png)) != 0) return false;
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, kColourTypes[image.channels - 1],
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (image.srgb) png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_set_rows(png, info, rows);
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  return true;
}

}  // namespace

bool is_png_path(const std::string& path) {
  return lower_case_extension(path) == ".png";
}

std::vector<unsigned char> encode_png(const ImagePixels& image) {
  const std::size_t row_values =
      static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.channels);
  if (image.width < 1 || image.height < 1 || image.channels < 1 || image.channels > 4 ||
      image.bytes.size() != row_values * static_cast<std::size_t>(image.height)) {
    throw std::invalid_argument("encode_png: not an 8-bit image of 1 to 4 channels");
  }
  const bool has_alpha = image.channels == 2 || image.channels == 4;
  std::vector<std::uint8_t> stored;
  if (has_alpha) stored = deassociated(image.bytes, image.channels);
  const std::uint8_t* values = has_alpha ? stored.data() : image.bytes.data();
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
  for (std::size_t y = 0; y < rows.size(); ++y)
    rows[y] = const_cast<png_bytep>(values + y * row_values);  // libpng only reads them

  Encoding encoding;
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &encoding, record_error, ignore_warning);
  png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    throw std::runtime_error("libpng cannot start (out of memory)");
  }
  png_set_write_fn(png, &encoding, append_bytes, flush_nothing);
  const bool written = write_png(png, info, image, rows.data());
  png_destroy_write_struct(&png, &info);
  if (!written) throw std::runtime_error(encoding.error);
  return std::move(encoding.bytes);
}

}  // namespace edgewise::tools
