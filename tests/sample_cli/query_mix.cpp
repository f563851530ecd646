#include "query_mix.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "random.hpp"

namespace edgewise::sample_cli_test {

std::vector<TextureQuery> mixed_queries(std::uint64_t seed, std::size_t count, int width,
                                        int height) {
  test::Random random(seed);
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const double texel = 1.0 / std::max(width, height);
  std::vector<TextureQuery> queries(count);
  for (std::size_t i = 0; i < count; ++i) {
    TextureQuery& q = queries[i];
    q.s = static_cast<float>(random.uniform(-1.5, 2.5));
    q.t = static_cast<float>(random.uniform(-1.5, 2.5));
    // A footprint: two axes of random lengths (1/64 to 64 texels) and directions; every tenth
    // query has one axis 50 times shorter (anisotropy beyond any probe limit).
    const double angle = random.uniform(0.0, 2.0 * std::numbers::pi);
    const double major = random.log_uniform(texel / 64.0, texel * 64.0);
    const double minor = i % 10 == 0 ? major / 50.0 : random.log_uniform(texel / 64.0, major);
    q.dsdx = static_cast<float>(major * std::cos(angle));
    q.dtdx = static_cast<float>(major * std::sin(angle));
    q.dsdy = static_cast<float>(-minor * std::sin(angle));
    q.dtdy = static_cast<float>(minor * std::cos(angle));
    switch (i % 16) {
      case 1:  // magnification
        q.dsdx = q.dtdx = q.dsdy = q.dtdy = 0.0f;
        break;
      case 3:  // huge footprint: the coarsest level
        q.dsdx = 1e30f;
        break;
      case 5:
        q.dtdy = inf;
        break;
      case 7:
        q.dsdy = nan;
        break;
      case 9:  // far outside [0, 1)
        q.s += 1000.0f;
        q.t -= 4096.0f;
        break;
      case 11:
        q.s = nan;
        break;
      case 13:
        q.t = -inf;
        break;
      default:
        break;
    }
  }
  return queries;
}

std::vector<TextureQuery> texel_centre_queries(int width, int height) {
  std::vector<TextureQuery> queries;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      queries.push_back({static_cast<float>((x + 0.5) / width),
                         static_cast<float>((y + 0.5) / height), 0.0f, 0.0f, 0.0f, 0.0f});
    }
  }
  return queries;
}

}  // namespace edgewise::sample_cli_test
