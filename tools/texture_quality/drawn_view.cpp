#include "texture_quality/drawn_view.hpp"

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace edgewise::texture_quality {

DrawnView::DrawnView(const texture_scene::TextureView& view)
    : mesh_(texture_scene::view_mesh(view)), target_(view.width(), view.height()) {}

void DrawnView::draw(const Texture& texture, const SamplerOptions& sampler,
                     TextureDerivatives derivatives, Isa isa) {
  target_.clear({0.0f, 0.0f, 0.0f, 0.0f}, 1.0f);
  DrawOptions options;
  options.transform = mesh_.transform;
  options.shading = Shading::flat;
  options.isa = isa;
  options.texture = DrawTexture{&texture, sampler, derivatives};
  const DrawReport report = edgewise::draw(target_, mesh_.mesh(), options);
  const std::uint64_t pixels =
      static_cast<std::uint64_t>(target_.width()) * static_cast<std::uint64_t>(target_.height());
  if (report.fragments_passed != pixels) {
    throw std::logic_error("the view's mesh did not cover every pixel exactly once");
  }
}

void DrawnView::read(std::span<Vec4> colours) const {
  std::vector<std::uint8_t> rgba(colours.size() * 4);
  target_.read_rgba8(rgba);
  for (std::size_t i = 0; i < colours.size(); ++i) {
    const std::uint8_t* p = &rgba[4 * i];
    colours[i] = {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f, p[3] / 255.0f};
  }
}

}  // namespace edgewise::texture_quality
