// Random meshes whose triangles share edges, for watertightness: jittered grids and fans.
//
// Vertices are made on the 1/256 px lattice and then moved by less than half a step, so
// snapping restores them exactly; the generator checks, on those snapped positions, that every
// triangle keeps the orientation it was built with (zero area allowed). Then the coverage count
// of any sample off the mesh's outline equals the outline's winding number around it (0 or 1).
// Triangles are handed out in random windings and vertex rotations.
#pragma once

#include <cstdint>
#include <vector>

#include "edgewise/coverage.hpp"
#include "random.hpp"

namespace edgewise::test {

// A snapped position, in 1/256 px.
struct FixedPoint {
  std::int64_t x, y;
};

struct Mesh {
  std::vector<Vec2> vertices;
  std::vector<FixedPoint> snapped;     // what each vertex snaps to
  std::vector<std::uint32_t> indices;  // three per triangle
  std::vector<std::uint32_t> outline;  // the boundary as a closed loop of vertex indices
};

// Columns and rows of random widths (a quarter of them thinner than half a pixel, down to one
// snapping step: slivers), vertices jittered, quads split along random diagonals, sometimes
// rotated; placed over and across the edges of `area`.
Mesh jittered_grid(Random& random, const PixelRect& area);

// Spokes from a center to rim points at random angles, a fifth of the gaps nearly zero
// (slivers); center and rim points often on samples.
Mesh triangle_fan(Random& random, const PixelRect& area);

// Winding number of the outline around the point; `on_outline` tells that the point lies on
// it (where coverage depends on the fill rule, not on the winding).
int outline_winding(const Mesh& mesh, FixedPoint p, bool& on_outline);

}  // namespace edgewise::test
