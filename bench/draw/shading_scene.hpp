// The shading workload's scene, shared by Shading/ (draw_bench.cpp) and its GL peer
// (draw_peer_bench.cpp): random triangles of one exact screen area (exact_area_triangles.hpp, a
// fixed seed), each vertex at a random distance in front of the camera with a random opaque
// colour, through an orthographic camera (x, y in pixels, y down) or a perspective one that
// unprojects the same pixels.
#pragma once

#include <cstddef>
#include <vector>

#include "edgewise/edgewise.hpp"

namespace edgewise::bench {

struct ShadingCase {
  int area;               // px^2 per triangle
  std::size_t triangles;  // per draw() call
};
inline constexpr ShadingCase kShadingCases[] = {
    {8, 200'000}, {64, 100'000}, {1000, 20'000}, {200'000, 200}};

enum class Camera { orthographic, perspective };

struct ShadingScene {
  std::vector<Vec3> positions;  // three per triangle, view space
  std::vector<Vec4> colors;
};

// Built once per camera and area, then cached; the whole set (c.triangles triangles).
const ShadingScene& shading_scene(Camera camera, const ShadingCase& c);

// View space to clip space for `camera`.
Mat4 camera_transform(Camera camera);

// The workload's draw() settings: `camera`'s transform, depth test less with writes, Gouraud,
// one thread.
DrawOptions shading_options(Isa isa, Camera camera);

// Clear colour with alpha 0: every written pixel has alpha 255 (vertex alphas are 1), so the
// pixels written can be counted after drawing.
inline constexpr Vec4 kShadingClearColor{0.1f, 0.2f, 0.3f, 0.0f};
inline constexpr float kShadingClearDepth = 1.0f;

}  // namespace edgewise::bench
