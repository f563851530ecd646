#include "texture_quality/oiio_peer.hpp"

#include <unistd.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/texture.h>

#include <cstdint>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace edgewise::texture_quality {
namespace {

struct PeerMode {
  OIIO::TextureOpt::MipMode mip;
  OIIO::TextureOpt::InterpMode interpolation;
  int anisotropy;
};

// In kPeerModeNames' order, as bench/sample_bench.cpp sets them.
constexpr PeerMode kPeerModes[] = {
    {OIIO::TextureOpt::MipModeNoMIP, OIIO::TextureOpt::InterpClosest, 1},
    {OIIO::TextureOpt::MipModeNoMIP, OIIO::TextureOpt::InterpBilinear, 1},
    {OIIO::TextureOpt::MipModeNoMIP, OIIO::TextureOpt::InterpBicubic, 1},
    {OIIO::TextureOpt::MipModeTrilinear, OIIO::TextureOpt::InterpBilinear, 1},
    {OIIO::TextureOpt::MipModeAniso, OIIO::TextureOpt::InterpBilinear, 16},
};
static_assert(std::size(kPeerModes) == std::size(kPeerModeNames));

void write_texture_file(const texture_scene::LinearImage& image,
                        const std::filesystem::path& path) {
  const std::vector<std::uint8_t> texels = texture_scene::to_rgba8(image);
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
  // ImageBuf only reads the wrapped memory here.
  OIIO::ImageBuf buffer(spec, const_cast<std::uint8_t*>(texels.data()));
  OIIO::ImageSpec config;
  config.attribute("maketx:filtername", "box");
  if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, buffer, path.string(),
                                        config)) {
    throw std::runtime_error(path.string() +
                             ": OpenImageIO cannot write the texture: " + OIIO::geterror());
  }
}

}  // namespace

struct OiioPeer::System {
  OIIO::TextureSystem* system = nullptr;
  OIIO::TextureSystem::Perthread* thread = nullptr;
  OIIO::TextureSystem::TextureHandle* handle = nullptr;
};

OiioPeer::OiioPeer(const texture_scene::LinearImage& image, std::string_view label)
    : file_(std::filesystem::temp_directory_path() /
            ("edgewise-texture-quality-" + std::to_string(::getpid()) + "-" + std::string(label) +
             ".tx")),
      system_(std::make_unique<System>()) {
  write_texture_file(image, file_);
  // The process-wide system: destroying a private one trips AddressSanitizer on a sized delete
  // inside OpenImageIO 2.4 (new-delete-type-mismatch); the shared one is only released by it.
  system_->system = OIIO::TextureSystem::create(/*shared=*/true);
  system_->thread = system_->system->get_perthread_info();
  system_->handle = system_->system->get_texture_handle(OIIO::ustring(file_.string()));
}

OiioPeer::~OiioPeer() {
  if (system_->system != nullptr) OIIO::TextureSystem::destroy(system_->system);
  std::error_code ignored;
  std::filesystem::remove(file_, ignored);
}

void OiioPeer::sample(std::size_t mode, std::span<const TextureQuery> queries,
                      std::span<Vec4> out) {
  if (mode >= std::size(kPeerModes) || queries.size() != out.size()) {
    throw std::invalid_argument("OiioPeer::sample: mode out of range or spans' sizes differ");
  }
  OIIO::TextureOpt options;
  options.swrap = options.twrap = OIIO::TextureOpt::WrapPeriodic;
  options.mipmode = kPeerModes[mode].mip;
  options.interpmode = kPeerModes[mode].interpolation;
  options.anisotropic = kPeerModes[mode].anisotropy;
  bool ok = true;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const TextureQuery& q = queries[i];
    float rgba[4];
    ok &= system_->system->texture(system_->handle, system_->thread, options, q.s, q.t, q.dsdx,
                                   q.dtdx, q.dsdy, q.dtdy, 4, rgba);
    out[i] = Vec4{rgba[0], rgba[1], rgba[2], rgba[3]};
  }
  if (!ok) {
    throw std::runtime_error(file_.string() +
                             ": OpenImageIO lookup failed: " + system_->system->geterror());
  }
}

}  // namespace edgewise::texture_quality
