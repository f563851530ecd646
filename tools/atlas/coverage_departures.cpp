#include "atlas/coverage_departures.hpp"

#include <algorithm>
#include <bit>
#include <iterator>
#include <span>
#include <stdexcept>

namespace edgewise::atlas {
namespace {

// Per triangle, the pixels (y * window width + x, from the window's corner) it covers, sorted.
using TrianglePixels = std::vector<std::vector<std::uint32_t>>;

std::size_t triangle_count(const std::vector<Vec2>& vertices) {
  return vertices.size() / 3;
}

// The library's coverage (the best ISA), clipped to the window by a scissor: the exact answer.
class PixelListSink final : public CoverageSink {
 public:
  PixelListSink(TrianglePixels& pixels, const PixelRect& window)
      : pixels_(pixels), window_(window) {}
  void consume(std::span<const TileCoverage> tiles) override {
    const auto width = static_cast<std::uint32_t>(window_.x1 - window_.x0);
    for (const TileCoverage& tile : tiles) {
      for (std::uint64_t mask = tile.mask; mask != 0; mask &= mask - 1) {
        const int bit = std::countr_zero(mask);
        const auto x = static_cast<std::uint32_t>(tile.tile_x * 8 + bit % 8 - window_.x0);
        const auto y = static_cast<std::uint32_t>(tile.tile_y * 8 + bit / 8 - window_.y0);
        pixels_[tile.triangle].push_back(y * width + x);
      }
    }
  }

 private:
  TrianglePixels& pixels_;
  PixelRect window_;
};

TrianglePixels exact_pixels(const std::vector<Vec2>& vertices, const PixelRect& window) {
  TrianglePixels pixels(triangle_count(vertices));
  PixelListSink sink(pixels, window);
  const RasterTarget target{window.x1, window.y1, window};
  rasterize(vertices, {}, target, RasterOptions{}, sink);
  for (auto& list : pixels)
    std::sort(list.begin(), list.end());
  return pixels;
}

TrianglePixels method_pixels(EdgeArithmetic arithmetic, const std::vector<Vec2>& vertices,
                             const PixelRect& window) {
  TrianglePixels pixels(triangle_count(vertices));
  const auto width = static_cast<std::uint32_t>(window.x1 - window.x0);
  for (std::size_t t = 0; t < pixels.size(); ++t) {
    const Vec2 triangle[3] = {vertices[3 * t], vertices[3 * t + 1], vertices[3 * t + 2]};
    cover_triangle(arithmetic, triangle, window, [&](std::int32_t x, std::int32_t y) {
      pixels[t].push_back(static_cast<std::uint32_t>(y - window.y0) * width +
                          static_cast<std::uint32_t>(x - window.x0));
    });
  }
  return pixels;
}

Departure compare(const TrianglePixels& exact, const TrianglePixels& method,
                  std::size_t window_pixels) {
  Departure d;
  std::vector<std::uint16_t> exact_count(window_pixels), method_count(window_pixels);
  std::vector<std::uint32_t> difference;
  for (std::size_t t = 0; t < exact.size(); ++t) {
    d.covered += exact[t].size();
    difference.clear();
    std::set_symmetric_difference(exact[t].begin(), exact[t].end(), method[t].begin(),
                                  method[t].end(), std::back_inserter(difference));
    d.differing += difference.size();
    for (std::uint32_t p : exact[t])
      ++exact_count[p];
    for (std::uint32_t p : method[t])
      ++method_count[p];
  }
  for (std::size_t p = 0; p < window_pixels; ++p) {
    d.holes += exact_count[p] > 0 && method_count[p] == 0;
    d.doubles += method_count[p] > 1 && method_count[p] > exact_count[p];
  }
  return d;
}

}  // namespace

Departures measure_departures(const std::vector<Vec2>& vertices, const PixelRect& window) {
  const TrianglePixels exact = exact_pixels(vertices, window);
  const auto window_pixels = static_cast<std::size_t>(window.x1 - window.x0) *
                             static_cast<std::size_t>(window.y1 - window.y0);
  if (compare(exact, method_pixels(EdgeArithmetic::fixed_point, vertices, window), window_pixels)
          .differing != 0) {
    throw std::logic_error("the study's fixed-point loop departs from the library's coverage");
  }
  Departures d;
  for (int i = 0; i < 2; ++i)
    d.method[i] = compare(exact, method_pixels(kInexact[i], vertices, window), window_pixels);
  return d;
}

}  // namespace edgewise::atlas
