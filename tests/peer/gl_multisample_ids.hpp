// Triangles drawn by the current GL context into a multisampled RGBA8 texture, each in a flat
// colour of its own, depth test and blending off, in submission order, so that each sample ends
// holding the colour of the last triangle that covers it; then every sample read back.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "edgewise/vector.hpp"

namespace edgewise::test {

class GlMultisampleIds {
 public:
  // A width x height target of `samples` samples per pixel; null, with `why_not`, when the
  // context cannot make one of exactly that many samples. Needs a current GL 3.3 context.
  static std::unique_ptr<GlMultisampleIds> create(std::int32_t width, std::int32_t height,
                                                  int samples, std::string& why_not);
  ~GlMultisampleIds();
  GlMultisampleIds(const GlMultisampleIds&) = delete;
  GlMultisampleIds& operator=(const GlMultisampleIds&) = delete;

  // Where GL puts each sample in its pixel (glGetMultisamplefv(GL_SAMPLE_POSITION)): in window
  // coordinates, from the pixel's corner at the smaller x and y, in [0, 1).
  const std::vector<Vec2>& sample_positions() const { return positions_; }

  // Clears every sample to 0, draws triangle t with corners clip_xy[3t .. 3t + 2] (z = 0,
  // w = 1; the viewport is the whole target) in the packed RGBA8 colour colors[t]
  // (R | G << 8 | B << 16 | A << 24), and returns every sample's packed colour: sample k of the
  // pixel at window (x, y) is element (k * height + y) * width + x. Empty, with `why_not`, on a
  // GL error.
  std::vector<std::uint32_t> draw(std::span<const Vec2> clip_xy,
                                  std::span<const std::uint32_t> colors, std::string& why_not);

 private:
  GlMultisampleIds() = default;

  std::int32_t width_ = 0, height_ = 0;
  int samples_ = 0;
  std::vector<Vec2> positions_;
  // The multisampled target, and the single-sample one that holds its samples side by side.
  unsigned multisampled_ = 0, multisampled_framebuffer_ = 0;
  unsigned planes_ = 0, planes_framebuffer_ = 0;
  unsigned draw_program_ = 0, read_program_ = 0;
  unsigned vertex_array_ = 0, buffers_[2] = {};
};

}  // namespace edgewise::test
