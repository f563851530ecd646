#include "meshes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace edgewise::test {
namespace {

constexpr int kMaxAttempts = 1000;

std::int64_t cross(FixedPoint o, FixedPoint a, FixedPoint b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

FixedPoint to_lattice(double x, double y) {
  return {static_cast<std::int64_t>(std::llround(x * 256.0)),
          static_cast<std::int64_t>(std::llround(y * 256.0))};
}

// The lattice point as a float input, moved by under half a step so snapping undoes it.
Vec2 to_input(Random& random, FixedPoint p) {
  const auto coordinate = [&random](std::int64_t steps) {
    const double noise = random.chance(0.5) ? random.uniform(-0.45, 0.45) : 0.0;
    return static_cast<float>((static_cast<double>(steps) + noise) / 256.0);
  };
  return {coordinate(p.x), coordinate(p.y)};
}

// Accepts the mesh if every triangle (as built: clockwise on screen) has a non-negative snapped
// area, then hands its triangles out in random windings and rotations.
bool finish(Random& random, std::vector<FixedPoint> points, std::vector<std::uint32_t> triangles,
            std::vector<std::uint32_t> outline, Mesh& mesh) {
  for (std::size_t t = 0; t < triangles.size(); t += 3) {
    if (cross(points[triangles[t]], points[triangles[t + 1]], points[triangles[t + 2]]) < 0) {
      return false;
    }
  }
  mesh.snapped = std::move(points);
  mesh.vertices.clear();
  for (const FixedPoint& p : mesh.snapped)
    mesh.vertices.push_back(to_input(random, p));
  mesh.indices.clear();
  for (std::size_t t = 0; t < triangles.size(); t += 3) {
    std::uint32_t tri[3] = {triangles[t], triangles[t + 1], triangles[t + 2]};
    if (random.chance(0.5)) std::swap(tri[1], tri[2]);
    std::rotate(tri, tri + random.integer(0, 2), tri + 3);
    mesh.indices.insert(mesh.indices.end(), tri, tri + 3);
  }
  mesh.outline = std::move(outline);
  return true;
}

// Random cell sizes along one axis, a quarter of them thin.
std::vector<double> cell_sizes(Random& random) {
  std::vector<double> sizes(static_cast<std::size_t>(random.integer(1, 10)));
  for (double& s : sizes) {
    s = random.chance(0.25) ? random.log_uniform(1.0 / 256.0, 0.5) : random.log_uniform(0.5, 14.0);
  }
  return sizes;
}

// Grid line positions from `start`, each jittered by under a quarter of its neighbouring cells.
double jittered_line(Random& random, const std::vector<double>& sizes, std::size_t line,
                     double position) {
  double room = 1e9;
  if (line > 0) room = std::min(room, sizes[line - 1]);
  if (line < sizes.size()) room = std::min(room, sizes[line]);
  return position + random.uniform(-0.24, 0.24) * room;
}

bool try_grid(Random& random, const PixelRect& area, Mesh& mesh) {
  const std::vector<double> widths = cell_sizes(random), heights = cell_sizes(random);
  const std::size_t nx = widths.size(), ny = heights.size();
  const double x0 = random.uniform(area.x0 - 20.0, area.x1 - 10.0);
  const double y0 = random.uniform(area.y0 - 20.0, area.y1 - 10.0);
  std::vector<double> xs{x0}, ys{y0};
  for (double w : widths)
    xs.push_back(xs.back() + w);
  for (double h : heights)
    ys.push_back(ys.back() + h);
  const bool rotate = random.chance(0.5);
  const double angle = random.uniform(0.0, 2.0 * std::numbers::pi);
  const double cx = 0.5 * (xs.front() + xs.back()), cy = 0.5 * (ys.front() + ys.back());

  const auto vertex = [nx](std::size_t i, std::size_t j) {
    return static_cast<std::uint32_t>(j * (nx + 1) + i);
  };
  std::vector<FixedPoint> points;
  for (std::size_t j = 0; j <= ny; ++j) {
    for (std::size_t i = 0; i <= nx; ++i) {
      double x = jittered_line(random, widths, i, xs[i]);
      double y = jittered_line(random, heights, j, ys[j]);
      if (rotate) {
        const double dx = x - cx, dy = y - cy;
        x = cx + dx * std::cos(angle) - dy * std::sin(angle);
        y = cy + dx * std::sin(angle) + dy * std::cos(angle);
      }
      points.push_back(to_lattice(x, y));
    }
  }
  // Each cell (top-left a, top-right b, bottom-right c, bottom-left d), clockwise on screen.
  std::vector<std::uint32_t> triangles;
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const std::uint32_t a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1),
                          d = vertex(i, j + 1);
      if (random.chance(0.5)) {
        triangles.insert(triangles.end(), {a, b, c, a, c, d});
      } else {
        triangles.insert(triangles.end(), {a, b, d, b, c, d});
      }
    }
  }
  std::vector<std::uint32_t> outline;
  for (std::size_t i = 0; i < nx; ++i)
    outline.push_back(vertex(i, 0));
  for (std::size_t j = 0; j < ny; ++j)
    outline.push_back(vertex(nx, j));
  for (std::size_t i = nx; i > 0; --i)
    outline.push_back(vertex(i, ny));
  for (std::size_t j = ny; j > 0; --j)
    outline.push_back(vertex(0, j));
  return finish(random, std::move(points), std::move(triangles), std::move(outline), mesh);
}

// Which half-plane around the center a direction falls in, for an exact angular sort.
int half(FixedPoint d) {
  return (d.y > 0 || (d.y == 0 && d.x > 0)) ? 0 : 1;
}

bool try_fan(Random& random, const PixelRect& area, Mesh& mesh) {
  double cx = random.uniform(area.x0 - 10.0, area.x1 + 10.0);
  double cy = random.uniform(area.y0 - 10.0, area.y1 + 10.0);
  if (random.chance(0.5)) {
    cx = std::floor(cx) + 0.5;
    cy = std::floor(cy) + 0.5;
  }
  const FixedPoint center = to_lattice(cx, cy);
  const std::size_t spokes = static_cast<std::size_t>(random.integer(3, 40));
  std::vector<double> gaps(spokes);
  double total = 0;
  for (double& g : gaps) {
    g = random.chance(0.2) ? random.log_uniform(1e-5, 1e-2) : random.uniform(0.2, 1.0);
    total += g;
  }
  double angle = random.uniform(0.0, 2.0 * std::numbers::pi);
  std::vector<FixedPoint> rim;
  for (double g : gaps) {
    angle += g * 2.0 * std::numbers::pi / total;
    const double r = random.log_uniform(0.3, 90.0);
    double x = cx + r * std::cos(angle), y = cy + r * std::sin(angle);
    if (random.chance(0.25)) {
      x = std::floor(x) + 0.5;
      y = std::floor(y) + 0.5;
    }
    const FixedPoint p = to_lattice(x, y);
    if (p.x == center.x && p.y == center.y) return false;
    rim.push_back(p);
  }
  // Sort the rim by exact angle around the center (clockwise on screen: y grows downward).
  std::sort(rim.begin(), rim.end(), [center](FixedPoint a, FixedPoint b) {
    const FixedPoint da{a.x - center.x, a.y - center.y}, db{b.x - center.x, b.y - center.y};
    if (half(da) != half(db)) return half(da) < half(db);
    return da.x * db.y - da.y * db.x > 0;
  });
  std::vector<FixedPoint> points{center};
  points.insert(points.end(), rim.begin(), rim.end());
  std::vector<std::uint32_t> triangles, outline;
  for (std::uint32_t i = 1; i <= spokes; ++i) {
    const std::uint32_t next = i == spokes ? 1 : i + 1;
    triangles.insert(triangles.end(), {0, i, next});
    outline.push_back(i);
  }
  // A gap of half a turn or more would fold the fan over itself.
  for (std::size_t t = 0; t < triangles.size(); t += 3) {
    const std::int64_t c =
        cross(points[triangles[t]], points[triangles[t + 1]], points[triangles[t + 2]]);
    if (c == 0 && spokes > 2) {
      const FixedPoint a = points[triangles[t + 1]], b = points[triangles[t + 2]];
      const bool same_direction =
          (a.x - center.x) * (b.x - center.x) + (a.y - center.y) * (b.y - center.y) > 0;
      if (!same_direction) return false;
    }
  }
  return finish(random, std::move(points), std::move(triangles), std::move(outline), mesh);
}

Mesh generate(Random& random, const PixelRect& area,
              bool (*attempt)(Random&, const PixelRect&, Mesh&)) {
  Mesh mesh;
  for (int i = 0; i < kMaxAttempts; ++i) {
    if (attempt(random, area, mesh)) return mesh;
  }
  throw std::logic_error("mesh generator failed to make a valid mesh");
}

}  // namespace

Mesh jittered_grid(Random& random, const PixelRect& area) {
  return generate(random, area, &try_grid);
}

Mesh triangle_fan(Random& random, const PixelRect& area) {
  return generate(random, area, &try_fan);
}

int outline_winding(const Mesh& mesh, FixedPoint p, bool& on_outline) {
  on_outline = false;
  int winding = 0;
  const std::size_t n = mesh.outline.size();
  for (std::size_t i = 0; i < n; ++i) {
    const FixedPoint a = mesh.snapped[mesh.outline[i]];
    const FixedPoint b = mesh.snapped[mesh.outline[(i + 1) % n]];
    const std::int64_t side = cross(a, b, p);
    if (side == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
        std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y)) {
      on_outline = true;
    }
    // Crossings of the horizontal ray from p toward +x, counted with their direction.
    if (a.y <= p.y) {
      if (b.y > p.y && side > 0) ++winding;
    } else if (b.y <= p.y && side < 0) {
      --winding;
    }
  }
  return winding;
}

}  // namespace edgewise::test
