// The vertex transform of every ISA equals transform() (camera.hpp) bit for bit: clipping,
// snapping and depth then start from the same clip-space numbers on every ISA and in the
// reference, which the bit-exact depth results of draw() rely on.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <vector>

#include "draw/bitwise_same.hpp"
#include "edgewise/camera.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "core/kernel_table.hpp"

namespace edgewise::test {
namespace {

using VertexTransform = IsaTest;

float random_value(Random& random) {
  switch (random.integer(0, 9)) {
    case 0:
      return static_cast<float>(random.uniform(-1e30, 1e30));
    case 1:
      return static_cast<float>(random.uniform(-1e-30, 1e-30));
    case 2:
      return -0.0f;
    case 3:
      return random.chance(0.5) ? std::numeric_limits<float>::infinity()
                                : std::numeric_limits<float>::quiet_NaN();
    default:
      return static_cast<float>(random.uniform(-100.0, 100.0));
  }
}

TEST_P(VertexTransform, EqualsTheScalarTransformBitForBit) {
  Random random(31);
  for (int round = 0; round < 20; ++round) {
    Mat4 m;
    for (auto& row : m.m) {
      for (float& v : row)
        v = round < 10 ? static_cast<float>(random.uniform(-4.0, 4.0)) : random_value(random);
    }
    if (round == 0)
      m = perspective(1.0f, 1.5f, 0.1f, 100.0f) * look_at({1, 2, 3}, {0, 0, 0}, {0, 1, 0});
    const std::size_t count = static_cast<std::size_t>(random.integer(0, 1037));
    std::vector<Vec3> in(count);
    for (Vec3& p : in)
      p = {random_value(random), random_value(random), random_value(random)};
    std::vector<Vec4> out(count);
    detail::kernel_table(isa()).transform_vertices(m, in.data(), count, out.data());
    for (std::size_t i = 0; i < count; ++i) {
      const Vec4 expected = transform(m, in[i]);
      ASSERT_TRUE(same(out[i].x, expected.x) && same(out[i].y, expected.y) &&
                  same(out[i].z, expected.z) && same(out[i].w, expected.w))
          << "round " << round << " vertex " << i << " of " << count;
    }
  }
}

EDGEWISE_INSTANTIATE_PER_ISA(VertexTransform, every_isa());

}  // namespace
}  // namespace edgewise::test
