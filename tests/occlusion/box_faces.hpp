// The twelve triangles of a box's faces, as draw() takes them: each face a quad of corners in
// order around it, cut along one diagonal. A box query's oracle draws them.
#pragma once

#include <vector>

#include "edgewise/occlusion.hpp"

namespace edgewise::test {

inline std::vector<Vec3> box_faces(const OcclusionBox& box) {
  Vec3 c[8];
  for (int k = 0; k < 8; ++k) {
    c[k] = {(k & 1) ? box.max.x : box.min.x, (k & 2) ? box.max.y : box.min.y,
            (k & 4) ? box.max.z : box.min.z};
  }
  static constexpr int kQuads[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  std::vector<Vec3> out;
  for (const auto& q : kQuads) {
    for (const int k : {q[0], q[1], q[2], q[0], q[2], q[3]})
      out.push_back(c[k]);
  }
  return out;
}

}  // namespace edgewise::test
