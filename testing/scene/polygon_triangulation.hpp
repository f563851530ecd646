// Splits an OBJ polygon into triangles.
//
// tinyobjloader 2.0.0rc10 can triangulate too, but its ear test measures a corner's turn against
// the area of the triangle the corner's edge makes with the origin, so a concave polygon may come
// out wrong or vanish depending on where it sits; this one tests ears in the polygon's own plane.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "edgewise/vector.hpp"

namespace edgewise::scene {

// Ear clipping in the plane of the polygon's Newell normal: a simple polygon (convex or not,
// nearly planar) of n >= 3 corners gives n - 2 triangles that cover it exactly and wind the same
// way as its corners. Appends three corner numbers (0 .. n-1) per triangle to `triangles`.
// A polygon with fewer than 3 corners adds nothing. Where no ear can be found (a self-intersecting
// or degenerate polygon, zero area, non-finite corners) the remaining corners are split as a fan,
// so the count is always n - 2. Costs O(n^3) at worst: callers bound n.
void triangulate_polygon(std::span<const Vec3> corners, std::vector<std::uint32_t>& triangles);

}  // namespace edgewise::scene
