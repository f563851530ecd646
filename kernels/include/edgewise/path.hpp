// 2D paths and their strokes (docs/design/anti-aliasing.md): polylines and quadratic Bezier
// curves in pixel coordinates (x right, y down, the screen's frame of coverage.hpp), flattened to
// a stated tolerance, stroked to triangles with caps and joins, and painted into a Framebuffer
// through draw(): anti-aliased by the target's samples (multisampling) and resolve().
//
// Flattening. A quadratic B(t) = (1 - t)^2 P0 + 2 t (1 - t) P1 + t^2 P2 is split into n equal
// steps of t. On a step of length h the exact chord misses the curve by |d| h^2 s (1 - s) at the
// step's fraction s, at most |d| h^2 / 4 (at its middle), d = P0 - 2 P1 + P2. The polyline's
// points are not exact: each interior one is B(t) computed in double and rounded to float, which
// moves it by at most r = 1.5 2^-24 m + 2^-149, m the largest |coordinate| of P0, P1 and P2
// (path_rounding()); P0 and P2 are kept exactly. Between two points the polyline strays from the
// exact chord by a blend of their two offsets, at most r, so
//     n = ceil(sqrt(|d| / (4 (tolerance - r)))), at least 1,
// keeps every point of the polyline within |d| h^2 / 4 + r <= tolerance of the curve at the same
// t, and no fewer equal steps keep the chords within tolerance - r (quad_segments(), tested
// against the curve). A tolerance below least_path_tolerance(m) = 2 r is refused: float points of
// that magnitude cannot keep it with half of it left for the chords. That half bounds n too:
// |d| <= 4 sqrt(2) m and m / tolerance <= 2^24 / 3 give n <= 3978 (kMaxQuadSegments).
//
// Stroking. Each segment becomes a rectangle of the stroke's width (two triangles); joins fill
// the outer side of each turn (miter: up to miter_limit times the half width from the vertex,
// else a bevel; round: an arc; bevel: a triangle); open subpaths end in caps (butt: none; square:
// half a width beyond the end; round: a half disk). Arcs are polygons inscribed in their circle,
// with as many sides as keep them within `tolerance` of it once their corners are rounded to
// float: the sides' sagitta is kept within tolerance - r, r = path_rounding(m) for the arc's
// coordinates, m = max(|cx|, |cy|) + the half width; a tolerance below 2 r is refused. The
// triangles overlap at joins and share edges along each segment: paint them opaque (painting
// overwrites, so overlaps cost nothing), with multisampling for anti-aliasing; blending each
// triangle by its exact area would double-count the overlaps and leak at the shared edges
// (conflation).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "edgewise/draw.hpp"
#include "edgewise/framebuffer.hpp"
#include "edgewise/names.hpp"
#include "edgewise/pixel_area.hpp"
#include "edgewise/vector.hpp"

namespace edgewise {

// A flattening tolerance that suits anti-aliased output: an eighth of a pixel.
inline constexpr float kDefaultPathTolerance = 0.125f;

class Path {
 public:
  // Starts a new subpath at p.
  void move_to(Vec2 p);
  // A straight segment from the current point. Without one (a new path, or after close()), a
  // subpath starts first at the last subpath's start, or at (0, 0).
  void line_to(Vec2 p);
  // A quadratic Bezier curve from the current point, through the pull of `control`, to `end`.
  void quad_to(Vec2 control, Vec2 end);
  // Closes the current subpath with a segment back to its start (joined there, no caps).
  void close();

  bool empty() const { return commands_.empty(); }

  enum class Verb : std::uint8_t { move, line, quad, close };
  struct Command {
    Verb verb;
    Vec2 points[2];  // move, line: points[0]; quad: control, end
  };
  std::span<const Command> commands() const { return commands_; }

 private:
  std::vector<Command> commands_;
  bool open_ = false;       // a subpath has begun
  Vec2 start_{0.0f, 0.0f};  // the last subpath's start
};

// The flattened subpaths: points in order, consecutive duplicates removed.
struct Polyline {
  std::vector<Vec2> points;
  bool closed = false;
};

// The most that rounding a point computed in double to float moves it, for a point whose exact
// coordinates are at most `magnitude` in absolute value: 1.5 2^-24 magnitude + 2^-149 px. Half an
// ulp per coordinate is at most 2^-24 magnitude (2^-150 among subnormals), the double arithmetic
// before it adds below 2^-48 magnitude, and sqrt(2) (2^-24 + 2^-47) < 1.5 2^-24 over the two
// coordinates; the 6% to spare also covers the few ulps of the segment and side counts' own
// double arithmetic.
double path_rounding(double magnitude);

// The least tolerance flatten() and stroke() accept for coordinates up to `magnitude`:
// 2 path_rounding(magnitude), about 1.8e-7 px per px of magnitude (0.0059 px at 32768 px, 1/8 px
// at 700,000 px).
double least_path_tolerance(double magnitude);

// The most segments quad_segments() returns for any tolerance it accepts.
inline constexpr std::size_t kMaxQuadSegments = 3978;

// The segment count of a quadratic for `tolerance` (the formula at the top); 1 for a straight
// or degenerate curve, at most kMaxQuadSegments. Throws std::invalid_argument for a tolerance
// that is not finite or is below least_path_tolerance() of the control points' largest
// |coordinate| (in particular one that is not positive).
std::size_t quad_segments(Vec2 p0, Vec2 p1, Vec2 p2, float tolerance);

// The path's subpaths as polylines within `tolerance` of it. Throws std::invalid_argument for a
// tolerance that is not positive and finite, one that a curve's coordinates cannot keep (as
// quad_segments()), or a non-finite point.
std::vector<Polyline> flatten(const Path& path, float tolerance = kDefaultPathTolerance);

enum class LineCap : std::uint8_t { butt, round, square };
enum class LineJoin : std::uint8_t { miter, round, bevel };

struct StrokeStyle {
  float width = 1.0f;  // in pixels, > 0
  LineCap cap = LineCap::butt;
  LineJoin join = LineJoin::miter;
  // A miter longer than this many half widths from its vertex becomes a bevel (SVG's rule).
  float miter_limit = 4.0f;
};

// The stroke's triangles, three points each, in pixel coordinates. Zero-length segments are
// skipped; a subpath of one point gets the dot of its cap (round: a disk, square: a square,
// butt: nothing). Throws std::invalid_argument for a width or miter limit that is not positive
// and finite (miter_limit at least 1), a tolerance that an arc's coordinates cannot keep (the
// stroking rule at the top), and what flatten() throws.
std::vector<Vec2> stroke(const Path& path, const StrokeStyle& style,
                         float tolerance = kDefaultPathTolerance);

// Paints triangles given in pixel coordinates (three points each) in one opaque colour into
// every sample they cover: draw() with the depth test off and flat shading, positions mapped to
// clip space (exact when the target's sides are powers of two, else within float rounding).
// Throws std::invalid_argument when the point count is not a multiple of 3.
DrawReport paint_triangles(Framebuffer& target, std::span<const Vec2> triangles, const Vec4& color,
                           std::optional<Isa> isa = std::nullopt);

// Paints triangles given in pixel coordinates by their exact coverage (pixel_area.hpp): each
// pixel a triangle touches moves towards `color` by the area a of its square inside the
// triangle, c + a (color - c) per channel in linear light, rounded to 8 bits, triangles in
// order. Exact for a shape drawn as one triangle, or as triangles that share no pixel; wrong
// where triangles overlap (blended twice) or meet inside a pixel (each blends its part alone, so
// the background shows through the seam: conflation). Strokes do both. Throws
// std::invalid_argument for a multisampled target (use paint_triangles()) or a point count that
// is not a multiple of 3.
RasterReport blend_triangle_areas(Framebuffer& target, std::span<const Vec2> triangles,
                                  const Vec4& color, std::optional<Isa> isa = std::nullopt);

std::string_view name_of(LineCap value);
template <>
std::span<const LineCap> values_of<LineCap>();
std::string_view name_of(LineJoin value);
template <>
std::span<const LineJoin> values_of<LineJoin>();

}  // namespace edgewise
