// PNG files written by write_image_file() through libpng: OpenImageIO reads back exactly the
// values its own PNG writer stores for the same pixels, with the colour space said the same way.

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "common/image_file.hpp"
#include "common/png_encoder.hpp"
#include "random.hpp"
#include "scene/temp_directory.hpp"

namespace edgewise::tools {
namespace {

using scene::test::TempDirectory;

struct StoredImage {
  int width = 0, height = 0, channels = 0;
  std::string colour_space;
  std::vector<std::uint8_t> values;
};

// The values as stored in the file: an unassociated alpha is not premultiplied on reading.
StoredImage read_stored(const std::string& path) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &config);
  if (!in) {
    ADD_FAILURE() << path << ": " << OIIO::geterror();
    return {};
  }
  const OIIO::ImageSpec& spec = in->spec();
  StoredImage image{
      spec.width, spec.height, spec.nchannels, spec.get_string_attribute("oiio:ColorSpace"), {}};
  image.values.resize(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, image.values.data()))
      << in->geterror();
  return image;
}

// The chunks of a PNG file that say what its colour space is, in the file's order.
std::string colour_chunks(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string chunks;
  for (std::size_t at = 8; at + 8 <= bytes.size();) {
    const auto byte = [&](std::size_t i) {
      return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + i]));
    };
    const std::uint32_t length = byte(0) << 24 | byte(1) << 16 | byte(2) << 8 | byte(3);
    const std::string type = bytes.substr(at + 4, 4);
    if (type == "gAMA" || type == "sRGB" || type == "cHRM" || type == "iCCP") chunks += type + " ";
    at += 12 + static_cast<std::size_t>(length);
  }
  return chunks;
}

// What OpenImageIO's PNG writer stores for `pixels`.
void write_through_openimageio(const std::string& path, int width, int height, int channels,
                               const std::vector<std::uint8_t>& pixels, bool srgb) {
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT8);
  if (srgb) spec.attribute("oiio:ColorSpace", "sRGB");
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out != nullptr) << OIIO::geterror();
  ASSERT_TRUE(out->open(path, spec)) << out->geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data())) << out->geterror();
  ASSERT_TRUE(out->close()) << out->geterror();
}

void write_ours(const std::string& path, int width, int height, int channels,
                const std::vector<std::uint8_t>& pixels, bool srgb) {
  ImagePixels image;
  image.width = width;
  image.height = height;
  image.channels = channels;
  image.bytes = pixels;
  image.srgb = srgb;
  write_image_file(path, image);
}

void expect_same_as_openimageio(const TempDirectory& dir, int width, int height, int channels,
                                const std::vector<std::uint8_t>& pixels, bool srgb) {
  const std::string ours = (dir.path() / "ours.png").string();
  const std::string theirs = (dir.path() / "theirs.png").string();
  write_ours(ours, width, height, channels, pixels, srgb);
  write_through_openimageio(theirs, width, height, channels, pixels, srgb);
  const StoredImage a = read_stored(ours), b = read_stored(theirs);
  EXPECT_EQ(a.width, width);
  EXPECT_EQ(a.height, height);
  EXPECT_EQ(a.channels, channels);
  EXPECT_EQ(a.values, b.values) << channels << " channels, srgb " << srgb;
  EXPECT_EQ(a.colour_space, b.colour_space);
  EXPECT_EQ(colour_chunks(ours), colour_chunks(theirs));
  EXPECT_EQ(colour_chunks(ours), srgb ? "gAMA sRGB cHRM " : "");
}

// Every colour under every alpha: the de-association's rounding is OpenImageIO's, and a pixel of
// alpha 0 keeps its colour.
TEST(PngEncoder, EveryColourUnderEveryAlphaStoresWhatOpenImageIoStores) {
  const TempDirectory dir;
  std::vector<std::uint8_t> pixels(256 * 256 * 4);
  for (int alpha = 0; alpha < 256; ++alpha) {
    for (int colour = 0; colour < 256; ++colour) {
      std::uint8_t* p = &pixels[static_cast<std::size_t>(alpha * 256 + colour) * 4];
      p[0] = static_cast<std::uint8_t>(colour);
      p[1] = static_cast<std::uint8_t>(255 - colour);
      p[2] = static_cast<std::uint8_t>(colour * 7);
      p[3] = static_cast<std::uint8_t>(alpha);
    }
  }
  for (const bool srgb : {false, true})
    expect_same_as_openimageio(dir, 256, 256, 4, pixels, srgb);
}

// Grey and RGB images, odd sizes: the rows and the colour type.
TEST(PngEncoder, GreyAndRgbImagesOfAnySizeStoreTheirValues) {
  const TempDirectory dir;
  test::Random random(29);
  for (const int channels : {1, 3}) {
    for (const auto& [width, height] : {std::pair{1, 1}, std::pair{3, 5}, std::pair{97, 31}}) {
      std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * height * channels);
      for (std::uint8_t& value : pixels)
        value = static_cast<std::uint8_t>(random.next() >> 56);
      expect_same_as_openimageio(dir, width, height, channels, pixels, false);
      EXPECT_EQ(read_stored((dir.path() / "ours.png").string()).values, pixels);
    }
  }
}

// Grey and alpha: PNG stores it unassociated too, the same rule as RGBA's.
TEST(PngEncoder, GreyAndAlphaIsDeassociated) {
  const TempDirectory dir;
  const std::vector<std::uint8_t> pixels = {100, 200, 100, 0, 255, 255, 50, 25, 200, 100};
  const std::string path = (dir.path() / "ga.png").string();
  write_ours(path, 5, 1, 2, pixels, false);
  const std::vector<std::uint8_t> stored = {127, 200, 100, 0, 255, 255, 255, 25, 255, 100};
  EXPECT_EQ(read_stored(path).values, stored);
}

TEST(PngEncoder, ExtensionDecidesInAnyCase) {
  EXPECT_TRUE(is_png_path("frame.png"));
  EXPECT_TRUE(is_png_path("dir/FRAME.PNG"));
  EXPECT_TRUE(is_png_path("a.b.Png"));
  EXPECT_FALSE(is_png_path("frame.exr"));
  EXPECT_FALSE(is_png_path("frame.png.exr"));
  EXPECT_FALSE(is_png_path("png"));
  EXPECT_FALSE(is_png_path("dir.png/frame"));
  EXPECT_FALSE(is_png_path("frame.pngx"));
}

TEST(PngEncoder, RefusesWhatPngCannotHold) {
  const std::vector<std::uint8_t> five(5 * 4, 0);
  ImagePixels image;
  image.width = 2;
  image.height = 2;
  image.channels = 5;
  image.bytes = five;
  EXPECT_THROW(encode_png(image), std::invalid_argument);
  image.channels = 4;
  image.bytes = std::span<const std::uint8_t>(five).first(15);
  EXPECT_THROW(encode_png(image), std::invalid_argument);
}

}  // namespace
}  // namespace edgewise::tools
