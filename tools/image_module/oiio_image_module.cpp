// The image module (image_module.hpp): OpenImageIO's side of the tools' image files and of its
// TextureSystem peer. Built as a shared module that links OpenImageIO; nothing of edgewise's
// library is in it.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "image_module/image_module.hpp"

namespace edgewise::tools {
namespace {

class OiioReader final : public ImageReader {
 public:
  explicit OiioReader(std::unique_ptr<OIIO::ImageInput> in) : in_(std::move(in)) {
    const OIIO::ImageSpec& spec = in_->spec();
    header_.width = spec.width;
    header_.height = spec.height;
    header_.depth = spec.depth;
    header_.channels = spec.nchannels;
    header_.uint8 = spec.format == OIIO::TypeDesc::UINT8;
    header_.pixel_type = spec.format.c_str();
    header_.tile_height = spec.tile_width > 0 ? spec.tile_height : 0;
  }

  const ImageHeader& header() const override { return header_; }

  void read_rows(int y0, int y1, int channels, bool as_uint8, void* out) override {
    const OIIO::ImageSpec& spec = in_->spec();
    const OIIO::TypeDesc type = as_uint8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
    const bool read =
        spec.tile_width > 0
            ? in_->read_tiles(0, 0, spec.x, spec.x + spec.width, spec.y + y0, spec.y + y1, spec.z,
                              spec.z + 1, 0, channels, type, out)
            : in_->read_scanlines(0, 0, spec.y + y0, spec.y + y1, spec.z, 0, channels, type, out);
    if (!read) throw std::runtime_error("cannot read image: " + in_->geterror());
  }

 private:
  std::unique_ptr<OIIO::ImageInput> in_;
  ImageHeader header_;
};

class OiioTextureLookup final : public TextureLookup {
 public:
  explicit OiioTextureLookup(const std::string& path) : path_(path) {
    // The process-wide system: destroying a private one trips AddressSanitizer on a sized delete
    // inside OpenImageIO 2.4 (new-delete-type-mismatch); the shared one is only released by it.
    system_ = OIIO::TextureSystem::create(/*shared=*/true);
    thread_ = system_->get_perthread_info();
    handle_ = system_->get_texture_handle(OIIO::ustring(path));
  }
  ~OiioTextureLookup() override { OIIO::TextureSystem::destroy(system_); }
  OiioTextureLookup(const OiioTextureLookup&) = delete;
  OiioTextureLookup& operator=(const OiioTextureLookup&) = delete;

  void sample(int mip, int interpolation, int anisotropy, std::span<const TextureQuery> queries,
              std::span<Vec4> out) override {
    constexpr OIIO::TextureOpt::MipMode kMips[] = {OIIO::TextureOpt::MipModeNoMIP,
                                                   OIIO::TextureOpt::MipModeTrilinear,
                                                   OIIO::TextureOpt::MipModeAniso};
    constexpr OIIO::TextureOpt::InterpMode kInterpolations[] = {OIIO::TextureOpt::InterpClosest,
                                                                OIIO::TextureOpt::InterpBilinear,
                                                                OIIO::TextureOpt::InterpBicubic};
    if (mip < 0 || mip > 2 || interpolation < 0 || interpolation > 2 ||
        queries.size() != out.size()) {
      throw std::invalid_argument(
          "TextureLookup::sample: mode out of range or spans' sizes differ");
    }
    OIIO::TextureOpt options;
    options.swrap = options.twrap = OIIO::TextureOpt::WrapPeriodic;
    options.mipmode = kMips[mip];
    options.interpmode = kInterpolations[interpolation];
    options.anisotropic = anisotropy;
    bool ok = true;
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const TextureQuery& q = queries[i];
      float rgba[4];
      ok &= system_->texture(handle_, thread_, options, q.s, q.t, q.dsdx, q.dtdx, q.dsdy, q.dtdy, 4,
                             rgba);
      out[i] = Vec4{rgba[0], rgba[1], rgba[2], rgba[3]};
    }
    if (!ok)
      throw std::runtime_error(path_ + ": OpenImageIO lookup failed: " + system_->geterror());
  }

 private:
  std::string path_;
  OIIO::TextureSystem* system_ = nullptr;
  OIIO::TextureSystem::Perthread* thread_ = nullptr;
  OIIO::TextureSystem::TextureHandle* handle_ = nullptr;
};

class OiioImageModule final : public ImageModule {
 public:
  std::vector<unsigned char> encode(const std::string& path,
                                    const EncodeRequest& image) const override {
    const OIIO::TypeDesc type = image.is_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
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

    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) throw std::runtime_error(OIIO::geterror());
    if (!out->supports("ioproxy") || !out->set_ioproxy(&memory)) {
      throw std::runtime_error(std::string("OpenImageIO's ") + out->format_name() +
                               " writer cannot encode in memory");
    }
    if (!out->open(path, spec)) throw std::runtime_error(out->geterror());
    if (!out->write_image(type, image.pixels)) throw std::runtime_error(out->geterror());
    if (!out->close()) throw std::runtime_error(out->geterror());
    return encoded;
  }

  std::unique_ptr<ImageReader> open(const std::string& path) const override {
    // Keep texels as stored: OpenImageIO would otherwise premultiply an unassociated alpha.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &config);
    if (!in) throw std::runtime_error("cannot read image: " + OIIO::geterror());
    return std::make_unique<OiioReader>(std::move(in));
  }

  void write_texture_file(const std::string& path, int width, int height,
                          std::span<const std::uint8_t> rgba) const override {
    OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
    // ImageBuf only reads the wrapped memory here.
    OIIO::ImageBuf buffer(spec, const_cast<std::uint8_t*>(rgba.data()));
    OIIO::ImageSpec config;
    config.attribute("maketx:filtername", "box");
    if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, buffer, path,
                                          config)) {
      throw std::runtime_error(path +
                               ": OpenImageIO cannot write the texture: " + OIIO::geterror());
    }
  }

  std::unique_ptr<TextureLookup> open_texture(const std::string& path) const override {
    return std::make_unique<OiioTextureLookup>(path);
  }
};

}  // namespace
}  // namespace edgewise::tools

// Null when the tools were built from another version of image_module.hpp.
extern "C" [[gnu::visibility("default")]] const edgewise::tools::ImageModule* edgewise_image_module(
    int version) {
  static const edgewise::tools::OiioImageModule module;
  return version == edgewise::tools::kImageModuleVersion ? &module : nullptr;
}
