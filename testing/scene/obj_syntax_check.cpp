#include "scene/obj_syntax_check.hpp"

#include <cctype>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <system_error>

namespace edgewise::scene {
namespace {

// tinyobjloader's field separators (its IS_SPACE).
bool is_field_space(char c) {
  return c == ' ' || c == '\t';
}

// Splits a line into fields the way tinyobjloader skips between them.
class Fields {
 public:
  explicit Fields(std::string_view line) : rest_(line) {}

  // The next field, or an empty view at the end of the line.
  std::string_view next() {
    std::size_t start = 0;
    while (start < rest_.size() && is_field_space(rest_[start]))
      ++start;
    std::size_t end = start;
    while (end < rest_.size() && !is_field_space(rest_[end]))
      ++end;
    const std::string_view field = rest_.substr(start, end - start);
    rest_.remove_prefix(end);
    return field;
  }

 private:
  std::string_view rest_;
};

// A field as it appears in a message: quoted, cut short, control bytes shown as '?'.
std::string quoted(std::string_view field) {
  constexpr std::size_t kShown = 24;
  std::string text = "'";
  for (std::size_t i = 0; i < field.size() && i < kShown; ++i) {
    const auto c = static_cast<unsigned char>(field[i]);
    text += std::isprint(c) ? static_cast<char>(c) : '?';
  }
  if (field.size() > kShown) text += "...";
  return text + "'";
}

// Accepts what tinyobjloader's number parser reads to the same value: one optional sign, then
// what std::from_chars reads in full. The value must be finite once rounded to float32.
std::optional<std::string> check_number(std::string_view field) {
  std::string_view digits = field;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  if (!digits.empty() && digits.front() == '+') return quoted(field) + " is not a number";
  double value = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error == std::errc::result_out_of_range) return quoted(field) + " is out of range";
  if (error != std::errc() || end != digits.data() + digits.size() || digits.empty()) {
    return quoted(field) + " is not a number";
  }
  if (!std::isfinite(value)) return quoted(field) + " is not a finite number";
  if (std::fabs(value) > FLT_MAX) return quoted(field) + " is out of float32 range";
  return std::nullopt;
}

// Checks a v, vn or vt line's fields (after the keyword): `min` to `max` numbers, and never
// `forbidden` of them (a vertex with 5 numbers is neither x y z w nor x y z r g b).
std::optional<std::string> check_numbers(Fields fields, std::size_t min, std::size_t max,
                                         std::size_t forbidden, const char* what) {
  std::size_t count = 0;
  for (std::string_view field = fields.next(); !field.empty(); field = fields.next()) {
    if (field.front() == '#') break;  // a trailing comment (tinyobjloader ignores it here)
    if (auto problem = check_number(field)) return std::string(what) + ": " + *problem;
    ++count;
  }
  if (count < min || count > max || count == forbidden) {
    return std::string(what) + ": " + std::to_string(count) + " numbers";
  }
  return std::nullopt;
}

// The elements of one kind (positions, texcoords or normals) that faces may name.
struct IndexedKind {
  const char* name;
  std::size_t defined = 0;
  // The largest positive index seen and its line: faces may name elements defined further down,
  // so positive indices are checked against the final count at the end.
  std::int64_t largest_forward = 0;
  std::size_t largest_forward_line = 0;
};

// One index of a corner: a non-zero integer, counting from 1, or backwards from the last element
// defined above this line when negative (tinyobjloader's rule).
std::optional<std::string> check_index(std::string_view field, IndexedKind& kind,
                                       std::size_t line_number) {
  std::string_view digits = field;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  int index = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
  if (error == std::errc::result_out_of_range) {
    return std::string(kind.name) + " index " + quoted(field) + " is out of range";
  }
  if (error != std::errc() || end != digits.data() + digits.size() || digits.empty()) {
    return quoted(field) + " is not an index";
  }
  if (index == 0) return std::string(kind.name) + " index 0 (indices count from 1)";
  if (index < 0 && static_cast<std::size_t>(-static_cast<std::int64_t>(index)) > kind.defined) {
    return std::string(kind.name) + " index " + std::to_string(index) + " reaches before the " +
           "first " + kind.name + " (" + std::to_string(kind.defined) + " defined above)";
  }
  if (index > kind.largest_forward) {
    kind.largest_forward = index;
    kind.largest_forward_line = line_number;
  }
  return std::nullopt;
}

struct Kinds {
  IndexedKind position{"position"};
  IndexedKind texcoord{"texcoord"};
  IndexedKind normal{"normal"};
};

// One corner of a face: v, v/t, v//n or v/t/n.
std::optional<std::string> check_corner(std::string_view corner, Kinds& kinds,
                                        std::size_t line_number) {
  const std::size_t first_slash = corner.find('/');
  const std::string_view v = corner.substr(0, first_slash);
  if (auto problem = check_index(v, kinds.position, line_number)) return problem;
  if (first_slash == std::string_view::npos) return std::nullopt;

  const std::string_view after = corner.substr(first_slash + 1);
  const std::size_t second_slash = after.find('/');
  const std::string_view t = after.substr(0, second_slash);
  const std::string_view n =
      second_slash == std::string_view::npos ? std::string_view() : after.substr(second_slash + 1);
  const bool has_n = second_slash != std::string_view::npos;
  if ((t.empty() && !has_n) || (has_n && n.empty()) || n.find('/') != std::string_view::npos) {
    return "corner " + quoted(corner) + " is not v, v/t, v//n or v/t/n";
  }
  if (!t.empty()) {
    if (auto problem = check_index(t, kinds.texcoord, line_number)) return problem;
  }
  if (has_n) return check_index(n, kinds.normal, line_number);
  return std::nullopt;
}

std::optional<std::string> check_face(Fields fields, Kinds& kinds, std::size_t line_number,
                                      std::size_t max_face_vertices) {
  std::size_t corners = 0;
  for (std::string_view corner = fields.next(); !corner.empty(); corner = fields.next()) {
    if (++corners > max_face_vertices) {
      return "face with more than " + std::to_string(max_face_vertices) + " corners";
    }
    if (auto problem = check_corner(corner, kinds, line_number)) return "face: " + *problem;
  }
  if (corners < 3) return "face with " + std::to_string(corners) + " corners";
  return std::nullopt;
}

std::string at_line(std::size_t line_number, const std::string& problem) {
  return "line " + std::to_string(line_number) + ": " + problem;
}

// A face named a positive index past the last element of its kind in the whole file.
std::optional<std::string> check_forward(const IndexedKind& kind) {
  if (kind.largest_forward <= 0 || static_cast<std::size_t>(kind.largest_forward) <= kind.defined) {
    return std::nullopt;
  }
  return at_line(kind.largest_forward_line,
                 std::string(kind.name) + " index " + std::to_string(kind.largest_forward) +
                     " is out of range (the file defines " + std::to_string(kind.defined) + ")");
}

}  // namespace

ObjSyntaxCheck check_obj_syntax(std::string_view text, std::size_t max_face_vertices) {
  ObjSyntaxCheck result;
  Kinds kinds;
  std::size_t line_number = 0;
  while (!text.empty()) {
    // Lines end at "\n", "\r" or "\r\n", as tinyobjloader's safeGetline splits them.
    const std::size_t end = text.find_first_of("\r\n");
    std::string_view line = text.substr(0, end);
    if (end == std::string_view::npos) {
      text = {};
    } else {
      const bool crlf = text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n';
      text.remove_prefix(end + (crlf ? 2 : 1));
    }
    ++line_number;
    // tinyobjloader reads a line as a C string: it ends at the first NUL byte.
    line = line.substr(0, line.find('\0'));
    while (!line.empty() && is_field_space(line.front()))
      line.remove_prefix(1);

    const auto keyword = [&](std::string_view name) {
      return line.size() > name.size() && line.starts_with(name) &&
             is_field_space(line[name.size()]);
    };
    std::optional<std::string> problem;
    if (keyword("v")) {
      problem = check_numbers(Fields(line.substr(1)), 3, 6, 5, "vertex");
      ++kinds.position.defined;
    } else if (keyword("vt")) {
      problem = check_numbers(Fields(line.substr(2)), 1, 3, 0, "texcoord");
      ++kinds.texcoord.defined;
    } else if (keyword("vn")) {
      problem = check_numbers(Fields(line.substr(2)), 3, 3, 0, "normal");
      ++kinds.normal.defined;
    } else if (keyword("f")) {
      problem = check_face(Fields(line.substr(1)), kinds, line_number, max_face_vertices);
      ++result.summary.faces;
    }
    if (problem) {
      result.problem = at_line(line_number, *problem);
      return result;
    }
  }
  result.summary.positions = kinds.position.defined;
  result.summary.texcoords = kinds.texcoord.defined;
  result.summary.normals = kinds.normal.defined;
  for (const IndexedKind* kind : {&kinds.position, &kinds.texcoord, &kinds.normal}) {
    if (auto problem = check_forward(*kind)) {
      result.problem = std::move(problem);
      break;
    }
  }
  return result;
}

}  // namespace edgewise::scene
