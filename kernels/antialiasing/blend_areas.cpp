// blend_triangle_areas(): coverage-weighted blending by exact area (path.hpp).
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

#include "edgewise/path.hpp"

namespace edgewise {
namespace {

class BlendSink final : public AreaSink {
 public:
  BlendSink(Framebuffer& target, const Vec4& color) : target_(target) {
    const float c[4] = {color.x, color.y, color.z, color.w};
    for (int k = 0; k < 4; ++k)
      color_[k] = c[k] > 0.0f ? (c[k] < 1.0f ? c[k] : 1.0f) : 0.0f;  // NaN: 0
  }
  void consume(std::span<const AreaTile> tiles) override {
    std::uint32_t* storage = target_.color_tiles();
    for (const AreaTile& tile : tiles) {
      std::uint32_t* pixels =
          storage + (static_cast<std::size_t>(tile.tile_y) * target_.tiles_x() + tile.tile_x) * 64;
      for (std::uint64_t m = tile.mask; m != 0; m &= m - 1) {
        const int bit = std::countr_zero(m);
        const float a = tile.area[bit] < 1.0f ? tile.area[bit] : 1.0f;
        std::uint32_t blended = 0;
        for (int k = 0; k < 4; ++k) {
          const float old = static_cast<float>((pixels[bit] >> (8 * k)) & 0xFF) / 255.0f;
          const float value = old + a * (color_[k] - old);
          blended |= static_cast<std::uint32_t>(std::lrint(value * 255.0f)) << (8 * k);
        }
        pixels[bit] = blended;
      }
    }
  }

 private:
  Framebuffer& target_;
  float color_[4];
};

}  // namespace

RasterReport blend_triangle_areas(Framebuffer& target, std::span<const Vec2> triangles,
                                  const Vec4& color, std::optional<Isa> isa) {
  if (target.samples() != 1) {
    throw std::invalid_argument("blend_triangle_areas: the target has " +
                                std::to_string(target.samples()) +
                                " samples per pixel; exact-area blending paints one");
  }
  if (triangles.size() % 3 != 0) {
    throw std::invalid_argument("blend_triangle_areas: " + std::to_string(triangles.size()) +
                                " points is not a multiple of 3");
  }
  RasterOptions options;
  options.isa = isa;
  BlendSink sink(target, color);
  return rasterize_areas(triangles, {}, RasterTarget{target.width(), target.height(), {}}, options,
                         sink);
}

}  // namespace edgewise
