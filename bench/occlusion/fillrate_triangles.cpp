#include "fillrate_triangles.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <utility>

#include "../benchmarks.hpp"

namespace edgewise::bench {
namespace {

FillrateTriangles make(int size, std::size_t count) {
  FillrateTriangles out;
  out.size = size;
  BenchRandom random{0x5eed0000ull + static_cast<std::uint64_t>(size)};
  const double legs[3][2] = {{0.0, 0.0}, {2.0 * size / kWidth, 0.0}, {0.0, 2.0 * size / kHeight}};
  for (std::size_t t = 0; t < count; ++t) {
    // Nearest last: depth and w fall with the index.
    const double order = static_cast<double>(count - t);
    for (;;) {
      const double ox = random.uniform() * 2.0 - 1.0, oy = random.uniform() * 2.0 - 1.0;
      const double angle = random.uniform() * 6.283185307179586;
      const double c = std::cos(angle), s = std::sin(angle);
      Vec3 v[3];
      bool on_screen = true;
      for (int i = 0; i < 3; ++i) {
        const double x = c * legs[i][0] - s * legs[i][1] + ox;
        const double y = s * legs[i][0] + c * legs[i][1] + oy;
        on_screen = on_screen && x >= -1.0 && x <= 1.0 && y >= -1.0 && y <= 1.0;
        v[i] = {static_cast<float>(x), static_cast<float>(y),
                static_cast<float>(order / static_cast<double>(count))};
      }
      if (!on_screen) continue;
      for (const Vec3& p : v) {
        out.ndc.push_back(p);
        out.clip_w.push_back(static_cast<float>(order));
      }
      break;
    }
  }
  return out;
}

}  // namespace

std::size_t fillrate_count(int size) {
  const double area = 0.5 * size * size;
  return static_cast<std::size_t>(std::clamp(std::exp2(25.0) / area, 4096.0, std::exp2(20.0)));
}

const FillrateTriangles& fillrate_triangles(int size, std::size_t count) {
  static std::mutex mutex;
  static std::map<std::pair<int, std::size_t>, FillrateTriangles> made;
  const std::lock_guard lock(mutex);
  auto [it, inserted] = made.try_emplace({size, count});
  if (inserted) it->second = make(size, count);
  return it->second;
}

}  // namespace edgewise::bench
