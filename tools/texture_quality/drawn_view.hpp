// A scored view drawn by draw() instead of sampled by sample(): the view's mesh
// (texture_scene/view_mesh.hpp) textured with a filter, its derivatives from 2x2 quads or from
// the planes, read back as linear colours. The framebuffer holds 8 bits per channel: its
// rounding alone gives an RMSE of 1 / (255 sqrt 12) ~ 0.0011 (59 dB) on a smooth image.
#pragma once

#include <span>

#include "edgewise/isa.hpp"
#include "edgewise/draw.hpp"
#include "edgewise/texture.hpp"
#include "texture_scene/texture_view.hpp"
#include "texture_scene/view_mesh.hpp"

namespace edgewise::texture_quality {

class DrawnView {
 public:
  explicit DrawnView(const texture_scene::TextureView& view);

  // Clears the framebuffer and draws the view (white flat shading, so the colour is the filtered
  // texel); `colours` (one per pixel, row-major) receives the result.
  void draw(const Texture& texture, const SamplerOptions& sampler, TextureDerivatives derivatives,
            Isa isa);
  void read(std::span<Vec4> colours) const;

 private:
  texture_scene::ViewMesh mesh_;
  Framebuffer target_;
};

}  // namespace edgewise::texture_quality
