// A strict pass over the lines of an OBJ file that tinyobjloader reads too leniently.
//
// tinyobjloader 2.0.0rc10 (Debian 12) reads a number it cannot parse ("abc", "nan") as 0, wraps an
// index past INT_MAX into a different valid index, keeps out-of-range indices with only a warning,
// and silently drops faces of fewer than three corners. This pass looks at the lines tinyobjloader
// turns into geometry (v, vn, vt, f) with the same line splitting and keyword rules, and reports
// the first such problem with its line number, so that the loader can refuse the file instead of
// drawing something the file did not say. It builds nothing: tinyobjloader still does the parsing.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace edgewise::scene {

struct ObjSyntaxSummary {
  std::size_t positions = 0;
  std::size_t texcoords = 0;
  std::size_t normals = 0;
  std::size_t faces = 0;
};

struct ObjSyntaxCheck {
  ObjSyntaxSummary summary;
  // "line N: ..." for the first problem found; empty when the file passed.
  std::optional<std::string> problem;
};

// Checks that every v, vn and vt line holds only finite float32 numbers (v: 3, 4 or 6 of them,
// vn: 3, vt: 1 to 3), and that every f line has 3 to `max_face_vertices` corners of the forms
// v, v/t, v//n or v/t/n, each a non-zero integer naming an existing element (negative = relative
// to the elements defined above the line). Lines, points and other statements are left to
// tinyobjloader.
ObjSyntaxCheck check_obj_syntax(std::string_view text, std::size_t max_face_vertices);

}  // namespace edgewise::scene
