// The float32 clipper against the double-precision reference on random triangles seen by random
// cameras: inside the frustum, crossing the near or far plane, the guard band, several planes at
// once, behind the camera, across w = 0, huge and tiny. Outcomes and vertex counts must agree
// except at ties (a decision within float rounding of a plane); vertices must agree within the
// bound derived below.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "edgewise/camera.hpp"
#include "float_roundoff.hpp"
#include "draw/vertex_stage/clip.hpp"
#include "random.hpp"
#include "draw/vertex_stage/clip_reference.hpp"

namespace edgewise::test {
namespace {

constexpr int kTriangles = 40000;
constexpr std::uint64_t kDifferentialSeed = 0xc11b'0dd5'2024ull;

// Error analysis of the float32 clipper (clip.cpp), per clipping plane p with the plane scale
// S_p = max over the three input vertices of the summed |coefficient * coordinate| (the size of
// the terms float32 rounds when it evaluates the plane's distance d_p):
// - d_p is computed with an error of at most 3u S_p (the float bound coefficient, its product
//   with w, the subtraction).
// - A crossing P = I + t (O - I), t = d_I / (d_I - d_O), lies off the plane by at most
//   3u S_p (d_I's error) + 2 * 3u S_p (t's use of both errors, t <= 1) + 4u S_p (t's two
//   roundings times |d_I - d_O| <= 2 S_p) + 3u S_p (rounding of the lerp) = 16u S_p.
// - Barycentrics are lerped with the same t but rounded separately (3u each), so seen through
//   the barycentrics, sum b_i d_p(P_i), a vertex drifts by up to 3 * 3u S_p more per stage; its
//   distance to every earlier line it lies on grows by at most that drift plus 3u S_p per stage.
// Over at most six stages, every constraint a vertex was built on holds, in barycentrics, within
// 6 * (16 + 9 + 3) u S_p = 168 u S_p (lines b_i = 0 of the triangle's edges: 168 u).
constexpr double kResidualGrowth = 168.0;

// A line in the triangle's barycentric plane: sum b_i g_i = 0 (the three g_i of an edge b_k = 0
// are e_k; those of a plane are d_p at the input vertices), and the residual float32 may leave.
struct Line {
  std::array<double, 3> g;
  double tolerance;
  double value(const std::array<double, 3>& b) const {
    return b[0] * g[0] + b[1] * g[1] + b[2] * g[2];
  }
};

// A vertex lies on two lines (a triangle edge or a plane each). If float32 leaves residuals r1,
// r2 on them, its barycentrics move by A^-1 r, A the lines' gradients in (b1, b2) (b0 = 1 - b1 -
// b2): the bound is |A^-1| times the tolerances, for each of b0, b1, b2. Nearly parallel lines
// (an edge almost in a plane) make it large: that vertex is ill-conditioned, not wrong.
double barycentric_bound(const Line& l1, const Line& l2) {
  const double a11 = l1.g[1] - l1.g[0], a12 = l1.g[2] - l1.g[0];
  const double a21 = l2.g[1] - l2.g[0], a22 = l2.g[2] - l2.g[0];
  const double det = a11 * a22 - a12 * a21;
  if (det == 0.0) return INFINITY;
  const double d1 = l1.tolerance, d2 = l2.tolerance;
  const double e1 = (std::fabs(a22) * d1 + std::fabs(a12) * d2) / std::fabs(det);
  const double e2 = (std::fabs(a21) * d1 + std::fabs(a11) * d2) / std::fabs(det);
  const double e0 = (std::fabs(a22 - a21) * d1 + std::fabs(a11 - a12) * d2) / std::fabs(det);
  return std::max({e0, e1, e2});
}

struct Case {
  Vec4 p[3];
  Viewport viewport;
  int kind;
};

const char* const kKindNames[] = {"inside", "near",  "far",  "guard band", "several",
                                  "behind", "w = 0", "huge", "tiny",       "orthographic"};
constexpr int kKinds = 10;

// A view-space point at `distance` in front of the camera (negative: behind), `spread` times the
// distance off axis.
Vec3 view_point(Random& random, double distance, double spread) {
  const double lateral = std::fabs(distance) * spread;
  return {static_cast<float>(random.uniform(-lateral, lateral)),
          static_cast<float>(random.uniform(-lateral, lateral)), static_cast<float>(-distance)};
}

Case random_case(Random& random, int kind) {
  static const Viewport kViewports[] = {{1, 1}, {64, 48}, {1920, 1080}, {7, 3000}, {32768, 32768}};
  Case c{};
  c.kind = kind;
  c.viewport = kViewports[random.integer(0, 4)];
  const double aspect = static_cast<double>(c.viewport.width) / c.viewport.height;
  const double near = random.log_uniform(0.01, 1.0), far = near * random.log_uniform(10, 1e4);
  Mat4 projection =
      perspective(static_cast<float>(random.uniform(0.3, 2.5)), static_cast<float>(aspect),
                  static_cast<float>(near), static_cast<float>(far));
  if (kind == 9) {
    const double half = random.log_uniform(0.1, 100);
    projection = orthographic(static_cast<float>(-half * aspect), static_cast<float>(half * aspect),
                              static_cast<float>(-half), static_cast<float>(half),
                              static_cast<float>(near), static_cast<float>(far));
  }
  const auto visible_depth = [&] { return random.log_uniform(near, far); };
  Vec3 v[3];
  for (int i = 0; i < 3; ++i) {
    switch (kind) {
      case 0:
        v[i] = view_point(random, visible_depth(), 0.5);
        break;
      case 1:  // near: some vertices between the eye and the near plane
        v[i] = view_point(random, i == 0 ? random.uniform(0, near) : visible_depth(), 0.5);
        break;
      case 2:
        v[i] = view_point(random, i == 0 ? far * random.uniform(1, 3) : visible_depth(), 0.5);
        break;
      case 3:
        v[i] = view_point(random, visible_depth(), random.log_uniform(1, 1e5));
        break;
      case 4:  // several: near, far and the guard band together
        v[i] = view_point(random, random.uniform(-far, 2 * far), random.log_uniform(0.1, 1e4));
        break;
      case 5:
        v[i] = view_point(random, -random.log_uniform(near, far), 1.0);
        break;
      case 6:  // across w = 0: one vertex behind the eye, the others in front
        v[i] = view_point(random, i == 0 ? -random.log_uniform(0.01, far) : visible_depth(),
                          random.log_uniform(0.1, 10));
        break;
      case 7:  // huge: far apart around the view, one of them behind the camera
        v[i] = view_point(random, (i == 2 ? -1 : 1) * random.log_uniform(1e3, 1e12),
                          random.log_uniform(0.1, 10));
        if (i == 1) v[i].x = -v[i].x;
        break;
      case 8: {  // tiny: a triangle of size 1e-6 .. 1e-3 of its distance, anywhere near the view
        const Vec3 center = view_point(random, random.uniform(-near, far), 2.0);
        const double size = std::fabs(center.z) * random.log_uniform(1e-6, 1e-3) + 1e-6;
        v[i] = {center.x + static_cast<float>(random.uniform(-size, size)),
                center.y + static_cast<float>(random.uniform(-size, size)),
                center.z + static_cast<float>(random.uniform(-size, size))};
        break;
      }
      default:
        v[i] =
            view_point(random, random.uniform(-0.5 * far, 2 * far), random.log_uniform(0.1, 1e5));
        break;
    }
  }
  for (int i = 0; i < 3; ++i)
    c.p[i] = transform(projection, v[i]);
  return c;
}

std::string describe(const Case& c) {
  std::ostringstream out;
  out << kKindNames[c.kind] << " case, viewport " << c.viewport.width << "x" << c.viewport.height;
  char text[160];
  for (const Vec4& p : c.p) {
    std::snprintf(text, sizeof text, "\n  (%a, %a, %a, %a)", p.x, p.y, p.z, p.w);
    out << text;
  }
  return out.str();
}

struct Tally {
  std::uint64_t compared_vertices = 0, ties = 0, ill_conditioned = 0, clipped = 0;
  double worst_ratio = 0.0;  // largest error / bound seen
};

// Compares one case; false (with a failure recorded) on a disagreement that is not a tie.
bool compare(const Case& c, Tally& tally) {
  const ClippedPolygon fast = clip_triangle(c.p[0], c.p[1], c.p[2], guard_band_planes(c.viewport));
  const reference::ClippedPolygon exact =
      reference::clip_triangle(c.p[0], c.p[1], c.p[2], c.viewport);
  // The fast clipper's decisions err by at most the residual tolerance relative to the plane's
  // scale; nearer than that, either side is right.
  // At a tie the two may build different, equally right polygons: a disagreement is excused
  // (and counted) when a decision came within the residual tolerance of a plane.
  const bool tie = exact.closest_decision <= kResidualGrowth * kFloatUnitRoundoff;
  const auto excused = [&] {
    if (tie) ++tally.ties;
    return tie;
  };
  if (fast.status != exact.status || fast.count != exact.vertices.size()) {
    if (excused()) return true;
    ADD_FAILURE() << "status " << static_cast<int>(fast.status) << " vs reference "
                  << static_cast<int>(exact.status) << ", " << int{fast.count} << " vs "
                  << exact.vertices.size() << " vertices, closest decision "
                  << exact.closest_decision << "\n"
                  << describe(c);
    return false;
  }
  if (fast.status == ClipStatus::clipped) ++tally.clipped;

  std::array<Line, 3 + kClipPlaneCount> lines;
  for (int k = 0; k < 3; ++k) {
    lines[k] = {{0, 0, 0}, kResidualGrowth * kFloatUnitRoundoff};
    lines[k].g[k] = 1;
  }
  double largest_scale = 0;
  for (int p = 0; p < kClipPlaneCount; ++p) {
    const double scale = reference::plane_scale(p, c.p[0], c.p[1], c.p[2], c.viewport);
    largest_scale = std::max(largest_scale, scale);
    Line& line = lines[3 + p];
    line.tolerance = kResidualGrowth * kFloatUnitRoundoff * scale;
    for (int i = 0; i < 3; ++i)
      line.g[i] = reference::plane_distance(p, c.p[i].x, c.p[i].y, c.p[i].z, c.p[i].w, c.viewport);
  }

  for (int v = 0; v < fast.count; ++v) {
    const ClipVertex& f = fast.vertices[v];
    const reference::ClipVertex& r = exact.vertices[static_cast<std::size_t>(v)];
    const std::array<double, 3> b{r.b0, r.b1, r.b2};
    // The lines the reference vertex lies on (to double rounding).
    int on[3 + kClipPlaneCount];
    int on_count = 0;
    for (std::size_t l = 0; l < lines.size(); ++l) {
      const double size = l < 3 ? 1.0 : lines[l].tolerance / (kResidualGrowth * kFloatUnitRoundoff);
      if (std::fabs(lines[l].value(b)) <= 1e-12 * size) on[on_count++] = static_cast<int>(l);
    }
    if (on_count < 2) {
      if (excused()) return true;
      ADD_FAILURE() << "reference vertex " << v << " lies on " << on_count << " lines\n"
                    << describe(c);
      return false;
    }
    // Input vertices pass through untouched.
    const int zeros = (r.b0 == 0) + (r.b1 == 0) + (r.b2 == 0);
    if (zeros == 2) {
      const Vec4& input = c.p[r.b0 == 1 ? 0 : (r.b1 == 1 ? 1 : 2)];
      if (f.position.x != input.x || f.position.y != input.y || f.position.z != input.z ||
          f.position.w != input.w || f.b0 != static_cast<float>(r.b0) ||
          f.b1 != static_cast<float>(r.b1) || f.b2 != static_cast<float>(r.b2)) {
        if (excused()) return true;
        ADD_FAILURE() << "input vertex " << v << " changed\n" << describe(c);
        return false;
      }
      continue;
    }
    // The fast vertex was built on two of those lines; which two is not known, so take the
    // largest bound of any pair.
    double bound = 0.0;
    for (int i = 0; i < on_count; ++i)
      for (int j = i + 1; j < on_count; ++j)
        bound = std::max(bound, barycentric_bound(lines[on[i]], lines[on[j]]));
    if (!(bound < 1.0)) {
      ++tally.ill_conditioned;  // no useful bound: the vertex is ill-conditioned
      continue;
    }
    const double error_b =
        std::max({std::fabs(f.b0 - r.b0), std::fabs(f.b1 - r.b1), std::fabs(f.b2 - r.b2)});
    // Positions: the barycentric error moves the point by sum |e_i| |p_i|; the position's own
    // drift from its barycentrics adds 12u of the largest input coordinate per stage (72u over
    // six); the final clamp onto a plane moves a coordinate by at most its residual,
    // 168u S_p.
    const double fp[4] = {f.position.x, f.position.y, f.position.z, f.position.w};
    const double rp[4] = {r.x, r.y, r.z, r.w};
    double error_p_ratio = 0.0;
    for (int axis = 0; axis < 4; ++axis) {
      double coordinate_bound = 0.0, largest = 0.0;
      for (const Vec4& p : c.p) {
        const double value = std::fabs((&p.x)[axis]);
        coordinate_bound += bound * value;
        largest = std::max(largest, value);
      }
      coordinate_bound += 72 * kFloatUnitRoundoff * largest +
                          (axis < 3 ? kResidualGrowth * kFloatUnitRoundoff * largest_scale : 0);
      error_p_ratio = std::max(error_p_ratio, std::fabs(fp[axis] - rp[axis]) / coordinate_bound);
    }
    const double ratio = std::max(error_b / bound, error_p_ratio);
    if (ratio > 1.0) {
      if (excused()) return true;
      ADD_FAILURE() << "vertex " << v << ": barycentric error " << error_b << " (bound " << bound
                    << "), position error / bound " << error_p_ratio << "\n"
                    << describe(c);
      return false;
    }
    tally.worst_ratio = std::max(tally.worst_ratio, ratio);
    ++tally.compared_vertices;
  }
  return true;
}

TEST(ClipDifferential, MatchesTheDoubleReference) {
  Random random(kDifferentialSeed);
  Tally tally;
  std::uint64_t per_kind_clipped[kKinds] = {}, per_kind_ties[kKinds] = {};
  for (int n = 0; n < kTriangles; ++n) {
    const Case c = random_case(random, n % kKinds);
    const std::uint64_t clipped_before = tally.clipped, ties_before = tally.ties;
    if (!compare(c, tally)) {
      ADD_FAILURE() << "triangle " << n << " of seed " << kDifferentialSeed;
      return;
    }
    per_kind_clipped[c.kind] += tally.clipped - clipped_before;
    per_kind_ties[c.kind] += tally.ties - ties_before;
  }
  for (int kind = 0; kind < kKinds; ++kind) {
    std::printf("[ clipping ] %-12s %6" PRIu64 " clipped, %5" PRIu64 " ties\n", kKindNames[kind],
                per_kind_clipped[kind], per_kind_ties[kind]);
  }
  std::printf("[ clipping ] %d triangles, %" PRIu64 " clipped, %" PRIu64
              " vertices compared, worst error/bound %.3g, %" PRIu64 " ties, %" PRIu64
              " ill-conditioned vertices\n",
              kTriangles, tally.clipped, tally.compared_vertices, tally.worst_ratio, tally.ties,
              tally.ill_conditioned);
  // Every kind of case must really exercise the clipper (inside and behind excepted), and ties
  // and unbounded vertices must stay rare for the comparison to mean something.
  for (int kind = 1; kind < kKinds; ++kind) {
    if (kind == 5) continue;
    EXPECT_GT(per_kind_clipped[kind], kTriangles / kKinds / 20u) << kKindNames[kind];
  }
  // Huge triangles are the exception: their crossings near the eye carry float32's rounding of
  // coordinates up to 1e12, so most decisions about them are ties.
  for (int kind = 0; kind < kKinds; ++kind) {
    if (kind != 7) {
      EXPECT_LE(per_kind_ties[kind], kTriangles / kKinds / 1000u) << kKindNames[kind];
    }
  }
  EXPECT_LT(tally.ill_conditioned, tally.compared_vertices / 20u);
}

}  // namespace
}  // namespace edgewise::test
