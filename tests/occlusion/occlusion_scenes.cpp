#include "occlusion/occlusion_scenes.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace edgewise::test {

OccluderSoup random_occluders(Random& random, int triangles) {
  OccluderSoup soup;
  // A tilted backdrop over the whole view, so that rectangles behind it are occluded.
  const double back = random.uniform(0.3, 0.9), slope_x = random.uniform(-0.05, 0.05),
               slope_y = random.uniform(-0.05, 0.05);
  const auto backdrop = [&](double x, double y) {
    return Vec3{static_cast<float>(x), static_cast<float>(y),
                static_cast<float>(back + slope_x * x + slope_y * y)};
  };
  for (const auto& [x, y] :
       {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
    soup.positions.push_back(backdrop(x, y));
  }
  for (int t = 0; t < triangles; ++t) {
    const double size = random.log_uniform(0.01, 1.0);
    const double cx = random.uniform(-1.1, 1.1), cy = random.uniform(-1.1, 1.1);
    const double depth = random.uniform(0.0, 1.0), tilt = random.uniform(-0.2, 0.2);
    for (int i = 0; i < 3; ++i) {
      const double x = cx + size * random.uniform(-1.0, 1.0);
      const double y = cy + size * random.uniform(-1.0, 1.0);
      const double z = std::fmin(std::fmax(depth + tilt * random.uniform(-1.0, 1.0), 0.0), 1.0);
      soup.positions.push_back(
          {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)});
    }
  }
  return soup;
}

std::vector<OcclusionRect> random_rects(Random& random, int count, std::int32_t width,
                                        std::int32_t height) {
  std::vector<OcclusionRect> rects;
  const double inf = std::numeric_limits<double>::infinity();
  for (int i = 0; i < count; ++i) {
    const double w = random.log_uniform(0.05, 1.5 * width);
    const double h = random.log_uniform(0.05, 1.5 * height);
    const double x = random.uniform(-0.3 * width, 1.1 * width);
    const double y = random.uniform(-0.3 * height, 1.1 * height);
    OcclusionRect r;
    // Whole or half pixels now and then: centres on the rectangle's edges.
    const bool on_grid = random.chance(0.2);
    const auto grid = [&](double v) { return on_grid ? std::round(v * 2.0) / 2.0 : v; };
    r.x0 = static_cast<float>(grid(x));
    r.y0 = static_cast<float>(grid(y));
    r.x1 = static_cast<float>(grid(x + w));
    r.y1 = static_cast<float>(grid(y + h));
    if (r.x1 < r.x0) r.x1 = r.x0;
    if (r.y1 < r.y0) r.y1 = r.y0;
    if (random.chance(0.01)) r.x0 = static_cast<float>(-inf);
    if (random.chance(0.01)) r.y1 = static_cast<float>(inf);
    r.depth = static_cast<float>(random.uniform(-0.1, 1.1));
    rects.push_back(r);
  }
  return rects;
}

Mat4 random_camera(Random& random, float aspect) {
  const double angle = random.uniform(0.0, 6.283185307179586);
  const double height = random.uniform(-2.0, 4.0);
  const double distance = random.log_uniform(3.0, 30.0);
  const Vec3 eye{static_cast<float>(distance * std::cos(angle)), static_cast<float>(height),
                 static_cast<float>(distance * std::sin(angle))};
  const Vec3 target{static_cast<float>(random.uniform(-1.0, 1.0)), 0.0f,
                    static_cast<float>(random.uniform(-1.0, 1.0))};
  const Mat4 view = look_at(eye, target, {0.0f, 1.0f, 0.0f});
  if (random.chance(0.25)) {
    const float half = static_cast<float>(random.uniform(2.0, 8.0));
    return orthographic(-half * aspect, half * aspect, -half, half, 0.5f,
                        static_cast<float>(2.0 * distance + 10.0)) *
           view;
  }
  const float fovy = static_cast<float>(random.uniform(0.4, 1.6));
  return perspective(fovy, aspect, static_cast<float>(random.log_uniform(0.05, 2.0)),
                     static_cast<float>(2.0 * distance + 10.0)) *
         view;
}

std::vector<OcclusionBox> random_boxes(Random& random, int count) {
  std::vector<OcclusionBox> boxes;
  for (int i = 0; i < count; ++i) {
    OcclusionBox box;
    float* low = &box.min.x;
    float* high = &box.max.x;
    for (int k = 0; k < 3; ++k) {
      const double centre = random.uniform(-6.0, 6.0);
      const double half = random.log_uniform(0.01, 3.0);
      low[k] = static_cast<float>(centre - half);
      high[k] = static_cast<float>(centre + half);
    }
    boxes.push_back(box);
  }
  return boxes;
}

}  // namespace edgewise::test
