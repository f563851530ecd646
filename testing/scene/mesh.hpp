// An indexed triangle mesh as the tools hand it to the renderer, and the checks and repairs every
// mesh source (OBJ files, procedural shapes) shares.
//
// Conventions:
// - World space is right-handed with y up. A triangle's front face is counter-clockwise seen from
//   the side its normal points to, so cross(p1 - p0, p2 - p0) points out of a closed surface.
// - Texture coordinates follow docs/design/textures.md: s to the right, t down (row 0 of the
//   image at t = 0).
//   They may leave [0, 1) where a texture is meant to repeat.
// - Colours are linear RGBA in [0, 1].
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "edgewise/vector.hpp"

namespace edgewise::scene {

// One index triple per triangle. Every attribute array is either empty (the mesh lacks it) or
// as long as `positions`.
struct Mesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
  std::vector<Vec2> uvs;
  std::vector<Vec4> colors;
  std::vector<std::uint32_t> indices;
};

inline std::size_t triangle_count(const Mesh& mesh) {
  return mesh.indices.size() / 3;
}

struct Box3 {
  Vec3 min;
  Vec3 max;
};

// The smallest box holding every finite position; positions with a NaN or infinite coordinate
// are skipped. Empty when no position is finite.
std::optional<Box3> bounding_box(const Mesh& mesh);

// The first problem found, in words, or nothing when the mesh is usable: attribute arrays of the
// wrong length, an index count that is not a multiple of 3, an index past the last vertex, more
// vertices than a 32-bit index can name, or a NaN or infinite value in any attribute.
std::optional<std::string> validate(const Mesh& mesh);

// Replaces `normals` with smooth per-vertex normals: the sum of the unit normals of the triangles
// around each vertex, each weighted by its angle at the vertex (so how a polygon was cut into
// triangles does not matter), normalized. Vertices at bit-identical positions share one normal,
// so a texture seam (a vertex split for its uvs) does not show as a crease. Triangles with an
// out-of-range index, a non-finite corner or zero area add nothing; a vertex without any other
// triangle (or whose sum cancels) gets kFallbackNormal.
void compute_smooth_normals(Mesh& mesh);
inline constexpr Vec3 kFallbackNormal{0.0f, 0.0f, 1.0f};

// Appends `part` to `mesh`, offsetting its indices. An attribute that only one side has is given
// to the other: smooth normals computed over that side, uv (0, 0), colour opaque white.
void append(Mesh& mesh, const Mesh& part);

}  // namespace edgewise::scene
