#include "draw/draw_scenes.hpp"

#include <cmath>

#include "edgewise/camera.hpp"

namespace edgewise::test {

namespace {

Vec3 unit(double x, double y, double z) {
  const double n = std::sqrt(x * x + y * y + z * z);
  return {static_cast<float>(x / n), static_cast<float>(y / n), static_cast<float>(z / n)};
}

// A point in view space inside the frustum: NDC (x, y) and a distance in front of the camera.
Vec3 frustum_point(double ndc_x, double ndc_y, double distance, double aspect) {
  const double half = std::tan(kFov / 2.0);
  return {static_cast<float>(ndc_x * distance * half * aspect),
          static_cast<float>(ndc_y * distance * half), static_cast<float>(-distance)};
}

}  // namespace

Scene random_scene(Random& random, int triangles, double aspect, double min_size, double max_size) {
  Scene scene;
  for (int t = 0; t < triangles; ++t) {
    const double size = random.log_uniform(min_size, max_size);
    const double cx = random.uniform(-0.6, 0.6), cy = random.uniform(-0.6, 0.6);
    const double base = random.log_uniform(kNear * 2.0, kFar * 0.5);
    const Vec3 axis = unit(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(0.5, 1));
    for (int i = 0; i < 3; ++i) {
      const double distance = base * random.uniform(0.6, 1.6);
      scene.positions.push_back(frustum_point(cx + random.uniform(-size, size),
                                              cy + random.uniform(-size, size), distance, aspect));
      scene.colors.push_back({static_cast<float>(random.uniform()),
                              static_cast<float>(random.uniform()),
                              static_cast<float>(random.uniform()), 1.0f});
      const double spread = 0.5;  // tan of about 27 degrees per component
      scene.normals.push_back(unit(axis.x + random.uniform(-spread, spread),
                                   axis.y + random.uniform(-spread, spread),
                                   axis.z + random.uniform(-spread, spread)));
    }
  }
  return scene;
}

DrawMesh mesh_of(const Scene& scene) {
  return {scene.positions, scene.colors, scene.normals, {}, scene.uvs};
}

Rendered render(Isa isa, const Scene& scene, DrawOptions options, std::int32_t width,
                std::int32_t height, int samples) {
  Framebuffer target(width, height, samples);
  target.clear({0.1f, 0.2f, 0.3f, 1.0f}, 1.0f);
  options.isa = isa;
  Rendered out;
  out.report = draw(target, mesh_of(scene), options);
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  out.rgba.resize(pixels * 4 * static_cast<std::size_t>(samples));
  out.depth.resize(pixels * static_cast<std::size_t>(samples));
  for (int k = 0; k < samples; ++k) {
    const std::size_t at = pixels * static_cast<std::size_t>(k);
    target.read_rgba8(std::span<std::uint8_t>(out.rgba).subspan(4 * at, 4 * pixels), k);
    target.read_depth(std::span<float>(out.depth).subspan(at, pixels), k);
  }
  return out;
}

DrawOptions perspective_options(std::int32_t width, std::int32_t height) {
  DrawOptions options;
  options.transform = perspective(kFov, static_cast<float>(width) / height, kNear, kFar);
  return options;
}

ScreenTriangle screen_triangle(const Scene& scene, std::size_t t, const DrawOptions& options,
                               const Viewport& viewport) {
  ScreenTriangle s;
  for (int i = 0; i < 3; ++i) {
    const Vec4 clip = transform(options.transform, scene.positions[3 * t + i]);
    const ScreenVertex v = to_screen(clip, viewport);
    s.x[i] = std::nearbyint(static_cast<double>(v.x) * 256.0) / 256.0;
    s.y[i] = std::nearbyint(static_cast<double>(v.y) * 256.0) / 256.0;
    s.w[i] = clip.w;
  }
  return s;
}

VertexAttributes attributes_of(const Scene& scene, std::size_t t) {
  VertexAttributes a;
  for (int i = 0; i < 3; ++i) {
    a.colors[i] = scene.colors[3 * t + i];
    a.normals[i] = scene.normals[3 * t + i];
  }
  return a;
}

void add_uvs(Random& random, Scene& scene, double min_span, double max_span) {
  scene.uvs.clear();
  for (std::size_t t = 0; t < scene.positions.size() / 3; ++t) {
    const double span = random.log_uniform(min_span, max_span);
    const double s = random.uniform(-2.0, 3.0), u = random.uniform(-2.0, 3.0);
    for (int i = 0; i < 3; ++i) {
      scene.uvs.push_back({static_cast<float>(s + random.uniform(-span, span)),
                           static_cast<float>(u + random.uniform(-span, span))});
    }
  }
}

Scene triangle_of(const Scene& scene, std::size_t t) {
  Scene one;
  one.positions.assign(scene.positions.begin() + 3 * t, scene.positions.begin() + 3 * t + 3);
  one.colors.assign(scene.colors.begin() + 3 * t, scene.colors.begin() + 3 * t + 3);
  one.normals.assign(scene.normals.begin() + 3 * t, scene.normals.begin() + 3 * t + 3);
  if (!scene.uvs.empty()) one.uvs.assign(scene.uvs.begin() + 3 * t, scene.uvs.begin() + 3 * t + 3);
  return one;
}

}  // namespace edgewise::test
