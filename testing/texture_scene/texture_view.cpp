#include "texture_scene/texture_view.hpp"

#include <cmath>
#include <stdexcept>

#include "texture_scene/linear_image.hpp"

namespace edgewise::texture_scene {
namespace {

constexpr std::int32_t kMaxScreenSize = 1 << 15;

double dot(const std::array<double, 3>& row, double x, double y) {
  return row[0] * x + row[1] * y + row[2];
}

bool finite_row(const std::array<double, 3>& row) {
  return std::isfinite(row[0]) && std::isfinite(row[1]) && std::isfinite(row[2]);
}

}  // namespace

TextureView::TextureView(std::int32_t width, std::int32_t height, const ProjectiveMap& map)
    : width_(width), height_(height), map_(map) {
  if (width < 1 || height < 1 || width > kMaxScreenSize || height > kMaxScreenSize)
    throw std::invalid_argument("TextureView: screen size outside [1, 32768]");
  if (!finite_row(map.s_row) || !finite_row(map.t_row) || !finite_row(map.w_row))
    throw std::invalid_argument("TextureView: non-finite mapping coefficient");
  for (double x : {0.0, double(width)}) {
    for (double y : {0.0, double(height)}) {
      if (!(dot(map.w_row, x, y) > 0.0))
        throw std::invalid_argument("TextureView: the plane is not in front everywhere on screen");
    }
  }
}

TexturePoint TextureView::point(double x, double y) const {
  const double w = dot(map_.w_row, x, y);
  return {dot(map_.s_row, x, y) / w, dot(map_.t_row, x, y) / w};
}

ScreenJacobian TextureView::jacobian(double x, double y) const {
  const double w = dot(map_.w_row, x, y);
  const double s_numerator = dot(map_.s_row, x, y);
  const double t_numerator = dot(map_.t_row, x, y);
  const double w2 = w * w;
  return {(map_.s_row[0] * w - s_numerator * map_.w_row[0]) / w2,
          (map_.t_row[0] * w - t_numerator * map_.w_row[0]) / w2,
          (map_.s_row[1] * w - s_numerator * map_.w_row[1]) / w2,
          (map_.t_row[1] * w - t_numerator * map_.w_row[1]) / w2};
}

TextureQuery TextureView::query(std::int32_t i, std::int32_t j) const {
  check_region({i, j, 1, 1});
  const double x = i + 0.5, y = j + 0.5;
  const TexturePoint p = point(x, y);
  const ScreenJacobian d = jacobian(x, y);
  return {round_to_float(p.s),    round_to_float(p.t),    round_to_float(d.dsdx),
          round_to_float(d.dtdx), round_to_float(d.dsdy), round_to_float(d.dtdy)};
}

void TextureView::check_region(const ScreenRegion& region) const {
  if (region.width < 1 || region.height < 1 || region.x0 < 0 || region.y0 < 0 ||
      region.x0 > width_ - region.width || region.y0 > height_ - region.height)
    throw std::invalid_argument("TextureView: region empty or outside the screen");
}

std::vector<TextureQuery> TextureView::queries(const ScreenRegion& region) const {
  check_region(region);
  std::vector<TextureQuery> result;
  result.reserve(static_cast<std::size_t>(region.width) * static_cast<std::size_t>(region.height));
  for (std::int32_t j = region.y0; j < region.y0 + region.height; ++j) {
    for (std::int32_t i = region.x0; i < region.x0 + region.width; ++i)
      result.push_back(query(i, j));
  }
  return result;
}

}  // namespace edgewise::texture_scene
