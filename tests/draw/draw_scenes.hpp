// Random perspective scenes for the draw() tests, rendering them into plain arrays, and the
// screen-space view of a triangle as the shading kernels receive it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "interpolation/screen_triangle.hpp"
#include "edgewise/draw.hpp"
#include "random.hpp"
#include "draw/colour_bounds.hpp"

namespace edgewise::test {

inline constexpr float kFov = 1.0f, kNear = 0.5f, kFar = 40.0f;

struct Scene {
  std::vector<Vec3> positions;
  std::vector<Vec4> colors;
  std::vector<Vec3> normals;
  std::vector<Vec2> uvs;  // empty unless add_uvs()
};

// Random triangles well inside the frustum (none needs clipping), of mixed sizes and depths,
// with random colours and normals within 60 degrees of a common direction (so the interpolated
// normal never comes near zero length: |n| >= cos 60 = 1/2). Sizes are log-uniform in
// [min_size, max_size], in units of the view's height.
Scene random_scene(Random& random, int triangles, double aspect, double min_size = 0.02,
                   double max_size = 0.6);

// Texture coordinates for every vertex: each triangle spans between `min_span` and `max_span`
// texture periods around a random point of [-2, 3]^2 (so every wrap mode sees coordinates
// outside [0, 1)).
void add_uvs(Random& random, Scene& scene, double min_span, double max_span);

// Triangle t alone.
Scene triangle_of(const Scene& scene, std::size_t t);

DrawMesh mesh_of(const Scene& scene);

struct Rendered {
  DrawReport report;
  std::vector<std::uint8_t> rgba;
  std::vector<float> depth;
};

// Cleared to colour (0.1, 0.2, 0.3, 1) and depth 1, then drawn with `options` on `isa` into a
// target with `samples` per pixel; rgba and depth hold every sample's image, sample 0's first.
Rendered render(Isa isa, const Scene& scene, DrawOptions options, std::int32_t width,
                std::int32_t height, int samples = 1);

DrawOptions perspective_options(std::int32_t width, std::int32_t height);

// The screen triangle draw() rasterizes for an unclipped triangle: viewport mapping, then the
// 1/256 px snap.
ScreenTriangle screen_triangle(const Scene& scene, std::size_t t, const DrawOptions& options,
                               const Viewport& viewport);

VertexAttributes attributes_of(const Scene& scene, std::size_t t);

}  // namespace edgewise::test
