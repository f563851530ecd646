#include "texture_quality/oiio_peer.hpp"

#include <unistd.h>

#include <cstdint>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "image_module/image_module.hpp"

namespace edgewise::texture_quality {
namespace {

// In kPeerModeNames' order, as bench/texture/sample_bench.cpp sets them: TextureLookup::sample's
// mip mode, interpolation and anisotropy.
struct PeerMode {
  int mip;
  int interpolation;
  int anisotropy;
};
constexpr PeerMode kPeerModes[] = {{0, 0, 1}, {0, 1, 1}, {0, 2, 1}, {1, 1, 1}, {2, 1, 16}};
static_assert(std::size(kPeerModes) == std::size(kPeerModeNames));

}  // namespace

struct OiioPeer::System {
  std::unique_ptr<tools::TextureLookup> lookup;
};

OiioPeer::OiioPeer(const texture_scene::LinearImage& image, std::string_view label)
    : file_(std::filesystem::temp_directory_path() /
            ("edgewise-texture-quality-" + std::to_string(::getpid()) + "-" + std::string(label) +
             ".tx")),
      system_(std::make_unique<System>()) {
  const std::vector<std::uint8_t> texels = texture_scene::to_rgba8(image);
  const tools::ImageModule& module = tools::image_module();
  module.write_texture_file(file_.string(), image.width, image.height, texels);
  system_->lookup = module.open_texture(file_.string());
}

OiioPeer::~OiioPeer() {
  system_->lookup.reset();
  std::error_code ignored;
  std::filesystem::remove(file_, ignored);
}

void OiioPeer::sample(std::size_t mode, std::span<const TextureQuery> queries,
                      std::span<Vec4> out) {
  if (mode >= std::size(kPeerModes) || queries.size() != out.size()) {
    throw std::invalid_argument("OiioPeer::sample: mode out of range or spans' sizes differ");
  }
  const PeerMode& m = kPeerModes[mode];
  system_->lookup->sample(m.mip, m.interpolation, m.anisotropy, queries, out);
}

}  // namespace edgewise::texture_quality
