// The reference clipper: clip.hpp's clipping, in double precision, written to be read.
//
// Same planes, same order, same outcomes (ClipStatus) as edgewise::clip_triangle, with the guard
// band derived afresh in double from the viewport. It shares no code with the fast clipper.
// Where a vertex lies within float rounding of a plane the two may decide differently;
// closest_decision says how near the closest decision came, so a comparison can tell such ties.
#pragma once

#include <vector>

#include "clip.hpp"

namespace edgewise::reference {

struct ClipVertex {
  double x, y, z, w;
  double b0, b1, b2;  // weights of the original vertices 0, 1, 2
};

struct ClippedPolygon {
  ClipStatus status = ClipStatus::outside;
  std::vector<ClipVertex> vertices;  // empty, or a convex polygon of 3 or more vertices
  // The smallest |distance to plane| / plane_scale over the inside/outside decisions that
  // float32 takes with rounding: input vertices against the guard-band planes (near, far and
  // the sides compare input floats exactly), intersections against every later plane.
  double closest_decision = 1.0;
};

// The plane's scale for a triangle: the largest sum of |coefficient * coordinate| over its three
// vertices, i.e. the size of the terms that float32 rounds when it evaluates the distance.
// `plane` numbers the clipping planes 0 .. 5 in order (near, far, x_min, x_max, y_min, y_max).
double plane_scale(int plane, const Vec4& p0, const Vec4& p1, const Vec4& p2,
                   const Viewport& viewport);
// Signed distance of (x, y, z, w) to clipping plane `plane`, >= 0 inside.
double plane_distance(int plane, double x, double y, double z, double w, const Viewport& viewport);

ClippedPolygon clip_triangle(const Vec4& p0, const Vec4& p1, const Vec4& p2,
                             const Viewport& viewport);

}  // namespace edgewise::reference
