// No crack along a clip edge. A large triangle, split into a grid of small ones sharing edges,
// crosses the near plane (and, in a second scene, the guard band); its pieces are clipped one by
// one, mapped to the screen and rasterized on every ISA. Then:
// - where a shared edge crosses a plane, both triangles computed bit-identical points;
// - every pixel whose center lies inside the visible region (the large triangle clipped by the
//   double reference, projected) is covered exactly once, every pixel outside it never, and those
//   within the error margin of its outline at most once.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "clipped_mesh.hpp"
#include "coverage_result.hpp"
#include "float_roundoff.hpp"
#include "isa_params.hpp"
#include "draw/vertex_stage/clip_reference.hpp"

namespace edgewise::test {
namespace {

struct Scene {
  const char* name;
  Vec3 corners[3];  // view space, before the tilt
  int grid;         // subdivisions per side
  Viewport viewport;
};

// A floor just below the eye, reaching behind the camera; tilted so the near-plane edge is not
// axis-aligned on screen. The guard-band scene's floor starts just beyond the near plane, coarse
// and so wide that its triangles reach from the screen to tens of thousands of pixels beside it.
const Scene kScenes[] = {
    {"near plane", {{-1.2f, -0.25f, 1}, {1.2f, -0.25f, 1}, {0, -0.25f, -20}}, 48, {96, 80}},
    {"guard band", {{-3000, -0.25f, -0.6f}, {3000, -0.25f, -0.6f}, {2, -0.25f, -60}}, 6, {96, 80}},
};
constexpr float kNear = 0.5f, kFar = 100.0f;

struct Built {
  std::vector<Vec4> clip;  // grid vertices in clip space
  std::vector<std::uint32_t> indices;
  Vec4 corners[3];  // the large triangle in clip space (grid vertices too)
  double largest_coordinate = 0;
};

Built build(const Scene& scene) {
  const Mat4 camera = perspective(1.3f,
                                  static_cast<float>(scene.viewport.width) /
                                      static_cast<float>(scene.viewport.height),
                                  kNear, kFar) *
                      rotate({0, 0, 1}, 0.3f) * rotate({1, 0, 0}, 0.05f);
  Built out;
  std::map<std::pair<int, int>, std::uint32_t> index;
  const Vec3* c = scene.corners;
  const int n = scene.grid;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      const double s = static_cast<double>(i) / n, t = static_cast<double>(j) / n;
      const auto at = [&](float Vec3::*axis) {
        return static_cast<float>(c[0].*axis + s * (c[1].*axis - c[0].*axis) +
                                  t * (c[2].*axis - c[0].*axis));
      };
      index[{i, j}] = static_cast<std::uint32_t>(out.clip.size());
      const Vec4 p = transform(camera, Vec3{at(&Vec3::x), at(&Vec3::y), at(&Vec3::z)});
      out.clip.push_back(p);
      for (float v : {p.x, p.y, p.z, p.w})
        out.largest_coordinate = std::max(out.largest_coordinate, std::fabs(double{v}));
    }
  }
  out.corners[0] = out.clip[index[{0, 0}]];
  out.corners[1] = out.clip[index[{n, 0}]];
  out.corners[2] = out.clip[index[{0, n}]];
  for (int i = 0; i < n; ++i) {
    for (int j = 0; i + j < n; ++j) {
      out.indices.insert(out.indices.end(), {index[{i, j}], index[{i + 1, j}], index[{i, j + 1}]});
      if (i + j + 1 < n) {
        out.indices.insert(out.indices.end(),
                           {index[{i + 1, j}], index[{i + 1, j + 1}], index[{i, j + 1}]});
      }
    }
  }
  return out;
}

using Bits = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>;
Bits bits(const Vec4& p) {
  return {std::bit_cast<std::uint32_t>(p.x), std::bit_cast<std::uint32_t>(p.y),
          std::bit_cast<std::uint32_t>(p.z), std::bit_cast<std::uint32_t>(p.w)};
}

// Points each triangle placed on each of its edges (one barycentric exactly 0, the others not:
// crossings keep an exact 0 for the vertex opposite the edge they lie on).
void check_shared_crossings(const Built& built, const ClippedMesh& mesh, std::uint64_t& crossings) {
  // Edge (sorted global indices) -> the crossings each triangle put on it.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::set<Bits>>> edges;
  for (std::size_t t = 0; t < mesh.polygons.size(); ++t) {
    const ClippedPolygon& polygon = mesh.polygons[t];
    if (polygon.status != ClipStatus::clipped && polygon.status != ClipStatus::inside) continue;
    const std::uint32_t* corner = &built.indices[3 * t];
    std::set<Bits> on_edge[3];  // edge k is opposite corner k
    for (int v = 0; v < polygon.count; ++v) {
      const ClipVertex& x = polygon.vertices[v];
      const float b[3] = {x.b0, x.b1, x.b2};
      for (int k = 0; k < 3; ++k) {
        if (b[k] == 0.0f && b[(k + 1) % 3] != 0.0f && b[(k + 2) % 3] != 0.0f)
          on_edge[k].insert(bits(x.position));
      }
    }
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = corner[(k + 1) % 3], b = corner[(k + 2) % 3];
      edges[{std::min(a, b), std::max(a, b)}].push_back(on_edge[k]);
      crossings += on_edge[k].size();
    }
  }
  for (const auto& [edge, sides] : edges) {
    if (sides.size() == 2) {
      EXPECT_EQ(sides[0], sides[1]) << "triangles sharing edge " << edge.first << "-" << edge.second
                                    << " cross planes at different points";
    }
  }
}

// The visible region on screen: the large triangle clipped in double, projected in double.
std::vector<std::pair<double, double>> visible_region(const Built& built, const Viewport& vp) {
  const reference::ClippedPolygon exact =
      reference::clip_triangle(built.corners[0], built.corners[1], built.corners[2], vp);
  std::vector<std::pair<double, double>> outline;
  for (const reference::ClipVertex& v : exact.vertices)
    outline.push_back({(v.x / v.w + 1) / 2 * vp.width, (1 - v.y / v.w) / 2 * vp.height});
  return outline;
}

// Signed distance, positive inside, from a point to a convex polygon's nearest edge line.
double inside_distance(const std::vector<std::pair<double, double>>& outline, double x, double y) {
  double area2 = 0;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const auto& [ax, ay] = outline[i];
    const auto& [bx, by] = outline[(i + 1) % outline.size()];
    area2 += ax * by - bx * ay;
  }
  double nearest = INFINITY;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const auto& [ax, ay] = outline[i];
    const auto& [bx, by] = outline[(i + 1) % outline.size()];
    const double length = std::hypot(bx - ax, by - ay);
    if (length == 0) continue;
    const double cross = (bx - ax) * (y - ay) - (by - ay) * (x - ax);
    nearest = std::min(nearest, (area2 > 0 ? cross : -cross) / length);
  }
  return nearest;
}

using ClipWatertight = IsaTest;

TEST_P(ClipWatertight, GridAcrossClipPlanes) {
  for (const Scene& scene : kScenes) {
    SCOPED_TRACE(scene.name);
    const Built built = build(scene);
    const Viewport& vp = scene.viewport;
    const ClippedMesh mesh = clip_mesh(built.clip, built.indices, vp);

    std::uint64_t crossings = 0;
    check_shared_crossings(built, mesh, crossings);
    EXPECT_GE(crossings, static_cast<std::uint64_t>(scene.grid / 2));  // the mesh really was cut

    const RasterCall call{mesh.positions, {}, RasterTarget{vp.width, vp.height, {}}};
    const RasterRun run = run_checked(isa(), call);
    std::vector<int> counts(static_cast<std::size_t>(vp.width) * vp.height, 0);
    for (const Pixel& p : covered_pixels(run))
      ++counts[static_cast<std::size_t>(p.y * vp.width + p.x)];

    // Error margin of the outline on screen: snapping moves a vertex by up to 2^-9 px per axis;
    // float32 carries each clip coordinate with an error of at most 32u of the scene's largest
    // coordinate M (grid vertex rounding u, the transform 7u, one plane crossing 16u, the lerp
    // of the near edge's neighbours: rounded up), which the divide by w >= near turns into
    // 2 * 32u M / near in NDC (x and w both err), and the viewport into pixels.
    const double margin = 0x1p-8 + std::max(vp.width, vp.height) / 2.0 * 2 * 32 *
                                       kFloatUnitRoundoff * built.largest_coordinate / kNear;
    const auto outline = visible_region(built, vp);
    std::uint64_t inside = 0, boundary = 0;
    for (int y = 0; y < vp.height; ++y) {
      for (int x = 0; x < vp.width; ++x) {
        const int count = counts[static_cast<std::size_t>(y * vp.width + x)];
        const double d = inside_distance(outline, x + 0.5, y + 0.5);
        const int expected_low = d > margin ? 1 : 0, expected_high = d < -margin ? 0 : 1;
        inside += d > margin;
        boundary += std::fabs(d) <= margin;
        ASSERT_TRUE(count >= expected_low && count <= expected_high)
            << "pixel (" << x << ", " << y << ") covered " << count << " times, " << d
            << " px inside the visible region (margin " << margin << ")";
      }
    }
    // The near-plane edge must cross the viewport for the test to mean anything.
    EXPECT_GT(inside, static_cast<std::uint64_t>(vp.width * vp.height / 5));
    EXPECT_LT(inside, static_cast<std::uint64_t>(vp.width * vp.height));
    std::printf("[ %-8s ] %s: %zu triangles -> %zu, %" PRIu64 " crossings, %" PRIu64
                " pixels inside, %" PRIu64 " within the %.3g px margin\n",
                std::string(name_of(isa())).c_str(), scene.name, built.indices.size() / 3,
                mesh.source.size(), crossings, inside, boundary, margin);
  }
}

EDGEWISE_INSTANTIATE_PER_ISA(ClipWatertight, every_isa());

}  // namespace
}  // namespace edgewise::test
