// Small vector types shared by the public API. Plain aggregates of float32, no operators:
// kernels convert them to SIMD lanes, tools and tests to double where they need precision.
#pragma once

namespace edgewise {

struct Vec2 {
  float x, y;
};

struct Vec3 {
  float x, y, z;
};

// A homogeneous position (clip space) or an RGBA colour.
struct Vec4 {
  float x, y, z, w;
};

}  // namespace edgewise
