#include "bench_texture.hpp"

#include <map>
#include <optional>
#include <stdexcept>
#include <vector>

#include "../benchmarks.hpp"
#include "texture_scene/builtin_views.hpp"
#include "texture_scene/ground_truth_cache.hpp"
#include "texture_scene/image_metrics.hpp"
#include "texture_scene/procedural_textures.hpp"

namespace edgewise::bench {

const texture_scene::LinearImage& checkerboard() {
  static const texture_scene::LinearImage image =
      texture_scene::checkerboard(kTextureSize, kSquares);
  return image;
}

const Texture& checkerboard_texture() {
  static const Texture texture = [] {
    const std::vector<std::uint8_t> texels = texture_scene::to_rgba8(checkerboard());
    return Texture::from_rgba8(kTextureSize, kTextureSize, texels, ColorEncoding::linear,
                               TextureBuild{PyramidFilter::box, true, true});
  }();
  return texture;
}

const texture_scene::TextureView& ground_plane() {
  static const texture_scene::TextureView view = texture_scene::ground_plane_view(kWidth, kHeight);
  return view;
}

const texture_scene::ViewMesh& ground_plane_mesh() {
  static const texture_scene::ViewMesh mesh = texture_scene::view_mesh(ground_plane());
  return mesh;
}

DrawOptions ground_plane_options(Isa isa, TextureFilter filter, TextureDerivatives derivatives) {
  DrawOptions options;
  options.transform = ground_plane_mesh().transform;
  options.shading = Shading::flat;
  options.isa = isa;
  options.threads = 1;  // one core, as the results compare
  options.texture = DrawTexture{&checkerboard_texture(), {}, derivatives};
  options.texture->sampler.filter = filter;
  return options;
}

namespace {

std::optional<texture_scene::LinearImage> stored_ground_truth(
    const std::string& view_name, const texture_scene::TextureView& view) {
  const std::uint64_t fingerprint = texture_scene::ground_truth_fingerprint(
      checkerboard(), WrapMode::repeat, WrapMode::repeat, view, view.screen(), {});
  const std::string name = "checkerboard" + std::to_string(kTextureSize) + "_" + view_name + "_" +
                           std::to_string(view.width()) + "x" + std::to_string(view.height());
  try {
    const std::filesystem::path file = texture_scene::ground_truth_file(
        texture_scene::default_cache_directory(), name, fingerprint);
    std::optional<texture_scene::GroundTruth> truth =
        texture_scene::read_ground_truth(file, fingerprint);
    if (truth) return std::move(truth->image);
  } catch (const std::runtime_error&) {  // no cache directory
  }
  return std::nullopt;
}

}  // namespace

void report_error(benchmark::State& state, const std::string& view_name,
                  const texture_scene::TextureView& view, std::span<const Vec4> colours) {
  static std::map<std::string, std::optional<texture_scene::LinearImage>> truths;
  auto it = truths.find(view_name);
  if (it == truths.end())
    it = truths.emplace(view_name, stored_ground_truth(view_name, view)).first;
  if (!it->second) return;
  const texture_scene::ImageError error = texture_scene::compare_images(
      texture_scene::image_from_samples(view.width(), view.height(), colours), *it->second);
  state.counters["rmse"] = error.rmse;
  state.counters["psnr_db"] = error.psnr;
}

}  // namespace edgewise::bench
