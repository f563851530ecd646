// Wavefront OBJ files (and their MTL diffuse colours) as a Mesh, through tinyobjloader.
//
// What the loader makes of a file:
// - Polygons are split into triangles of the same winding (polygon_triangulation.hpp).
// - Each distinct (position, texcoord, normal[, material]) corner becomes one vertex.
// - Normals are normalized (a zero one becomes kFallbackNormal); when some corner has none, smooth
//   normals are computed for the whole mesh (compute_smooth_normals) and a warning says so.
// - Texture coordinates: t = 1 - v, since OBJ puts v = 0 at the image's bottom row and edgewise
//   puts t = 0 at its top row. Corners without one get (0, 0) when others have one.
// - Colours: per-vertex colours (the "v x y z r g b" extension) when every vertex has one,
//   otherwise the MTL diffuse colour Kd with alpha from d; none when the file has neither.
//
// Every failure is a message, never a crash: a file that cannot be read, is empty or too large,
// has a malformed number or index, a NaN or infinite value, an index outside the file's elements,
// a face of fewer than 3 or more than `max_face_vertices` corners, or no face at all.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

#include "scene/mesh.hpp"

namespace edgewise::scene {

struct ObjLoadOptions {
  // Files (OBJ and MTL) larger than this are refused before they are read.
  std::uint64_t max_file_bytes = std::uint64_t{1} << 30;
  // Polygons with more corners are refused: triangulating one costs O(n^3) at worst, and
  // tinyobjloader counts a face's corners in a byte, so larger values act as 255.
  std::size_t max_face_vertices = 255;
  // Read the MTL files named by mtllib (from the OBJ's directory) for diffuse colours.
  bool load_materials = true;
};

// Either a mesh (with the loader's warnings, if any) or the reason there is none.
class MeshResult {
 public:
  static MeshResult success(Mesh mesh, std::string warnings) {
    return MeshResult(std::move(mesh), std::move(warnings));
  }
  static MeshResult failure(std::string error) { return MeshResult(std::move(error), {}); }

  bool ok() const { return std::holds_alternative<Mesh>(value_); }
  explicit operator bool() const { return ok(); }

  // Only when ok(); otherwise these throw std::bad_variant_access.
  const Mesh& mesh() const& { return std::get<Mesh>(value_); }
  Mesh mesh() && { return std::get<Mesh>(std::move(value_)); }

  // Empty when ok().
  std::string_view error() const {
    return ok() ? std::string_view() : std::string_view(std::get<std::string>(value_));
  }
  // Things the file asked for that were ignored or repaired (e.g. a missing MTL file).
  const std::string& warnings() const { return warnings_; }

 private:
  MeshResult(std::variant<Mesh, std::string> value, std::string warnings)
      : value_(std::move(value)), warnings_(std::move(warnings)) {}

  std::variant<Mesh, std::string> value_;
  std::string warnings_;
};

// Loads an OBJ file; messages start with the path.
MeshResult load_obj(const std::string& path, const ObjLoadOptions& options = {});

// Parses OBJ text held in memory; mtllib statements are ignored. Messages start with `name`.
MeshResult parse_obj(std::string_view text, std::string_view name = "<obj text>",
                     const ObjLoadOptions& options = {});

}  // namespace edgewise::scene
