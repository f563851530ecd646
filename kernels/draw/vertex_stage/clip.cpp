#include "clip.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "edgewise/coverage.hpp"

// Why kGuardBandMargin = 1/16 px is enough. Let G = kGuardBand - kGuardBandMargin and u = 2^-24.
// Every output vertex satisfies x <= fl(x_max * w) exactly (clip_triangle clamps to the same
// float product its inside test uses), with w >= kMinProjectedW, so that 1/w and x_max * w are
// normal floats. to_screen() then rounds 1/w, x * (1/w), + 1 and * width/2; with the rounding of
// x_max itself and of x_max * w that is six roundings of relative size u (x * (1/w) may fall
// below the normal range only where sx is near width/2, far from the bound), all on
// same-signed quantities, so sx <= G (1 + u)^6 < G + 6.01 u 2^15 = G + 0.0118 px; the same
// holds for -sx, sy and -sy. Snapping to 1/256 px adds at most 2^-9 = 0.002 px. Snapped
// vertices therefore stay within kGuardBand - 0.048 px of the centre on both sides, inside
// [-kGuardBand, kGuardBand). And 1/16 < 0.5: on a kMaxTargetSize target the last pixel center,
// kGuardBand - 0.5, stays inside the band.
static_assert(edgewise::kGuardBandMargin > 0.0118f + 0.002f && edgewise::kGuardBandMargin < 0.5f);

namespace edgewise {
namespace {

enum Plane : int { kNear, kFar, kXMin, kXMax, kYMin, kYMax };

// Outcode bits: the six clipping planes, then the frustum's sides (tested, never clipped).
constexpr unsigned kClipPlaneBits = (1u << kClipPlaneCount) - 1;
constexpr unsigned kLeftBit = 1u << 6, kRightBit = 1u << 7, kBottomBit = 1u << 8, kTopBit = 1u << 9;
constexpr unsigned kFrustumBits =
    (1u << kNear) | (1u << kFar) | kLeftBit | kRightBit | kBottomBit | kTopBit;

// Signed distance to a plane, >= 0 inside. Each guard-band bound is the float product
// fl(bound * w); the final clamp uses the same product, so "inside" means the same thing to the
// classification, the intersections and the clamp. fl(a - b) >= 0 exactly when a >= b.
float distance(const Vec4& p, int plane, const GuardBandPlanes& g) {
  switch (plane) {
    case kNear:
      return p.z;
    case kFar:
      return p.w - p.z;
    case kXMin:
      return p.x - g.x_min * p.w;
    case kXMax:
      return g.x_max * p.w - p.x;
    case kYMin:
      return p.y - g.y_min * p.w;
    default:
      return g.y_max * p.w - p.y;
  }
}

unsigned outcode(const Vec4& p, const GuardBandPlanes& g) {
  unsigned code = 0;
  for (int plane = 0; plane < kClipPlaneCount; ++plane) {
    if (!(distance(p, plane, g) >= 0.0f)) code |= 1u << plane;
  }
  if (p.x < -p.w) code |= kLeftBit;
  if (p.x > p.w) code |= kRightBit;
  if (p.y < -p.w) code |= kBottomBit;
  if (p.y > p.w) code |= kTopBit;
  return code;
}

float lerp(float a, float b, float t) {
  return a + t * (b - a);
}

// The point where the edge from `in` (d_in >= 0) to `out` (d_out < 0) crosses the plane.
// Crack-free: the computation always starts from the inside endpoint, whichever way the polygon
// walks the edge, and reads nothing but the two endpoints. Two triangles sharing the edge hold
// bit-identical endpoints (original vertices, or earlier crossings computed the same way), so they
// get bit-identical crossings. t = d_in / (d_in - d_out) lies in [0, 1], the denominator is > 0,
// and starting from the inside end keeps the error small when `out` is far away.
ClipVertex crossing(const ClipVertex& in, float d_in, const ClipVertex& out, float d_out) {
  const float t = d_in / (d_in - d_out);
  const Vec4& a = in.position;
  const Vec4& b = out.position;
  return {{lerp(a.x, b.x, t), lerp(a.y, b.y, t), lerp(a.z, b.z, t), lerp(a.w, b.w, t)},
          lerp(in.b0, out.b0, t),
          lerp(in.b1, out.b1, t),
          lerp(in.b2, out.b2, t)};
}

float clamp(float v, float lo, float hi) {
  return v < lo ? lo : (v > hi ? hi : v);
}

// The two input checks run one after the other: a NaN or infinity in any vertex is reported as
// such, even when another coordinate is also out of range.
bool any_non_finite(const Vec4* const (&input)[3]) {
  for (const Vec4* p : input) {
    for (float c : {p->x, p->y, p->z, p->w}) {
      if (!std::isfinite(c)) return true;
    }
  }
  return false;
}

bool any_out_of_range(const Vec4* const (&input)[3]) {
  for (const Vec4* p : input) {
    for (float c : {p->x, p->y, p->z, p->w}) {
      if (std::fabs(c) > kMaxClipCoordinate) return true;
    }
  }
  return false;
}

// Each vertex's distance to `plane` into d; whether any vertex is outside it. (d is a reference
// to the array, as in the helpers below, so that the compiler knows its extent and need not
// reload it through a pointer that might alias.)
bool distances_to_plane(const ClipVertex* in, int count, int plane, const GuardBandPlanes& planes,
                        float (&d)[kMaxClipVertices]) {
  bool any_outside = false;
  for (int i = 0; i < count; ++i) {
    d[i] = distance(in[i].position, plane, planes);
    any_outside = any_outside || d[i] < 0.0f;
  }
  return any_outside;
}

// How many edges of the closed polygon have their ends on different sides of the plane.
int sign_changes(const float (&d)[kMaxClipVertices], int count) {
  int changes = 0;
  for (int i = 0; i < count; ++i) {
    const int next = i + 1 == count ? 0 : i + 1;
    changes += (d[i] >= 0.0f) != (d[next] >= 0.0f);
  }
  return changes;
}

// One Sutherland-Hodgman step: the vertices inside the plane and the crossings of the edges
// that cross it, in the polygon's order, into out; returns their count.
int clip_to_plane(const ClipVertex* in, const float (&d)[kMaxClipVertices], int count,
                  ClipVertex* out) {
  int out_count = 0;
  for (int i = 0; i < count; ++i) {
    const int next = i + 1 == count ? 0 : i + 1;
    const bool inside = d[i] >= 0.0f;
    if (inside) out[out_count++] = in[i];
    if (inside != (d[next] >= 0.0f)) {
      out[out_count++] = inside ? crossing(in[i], d[i], in[next], d[next])
                                : crossing(in[next], d[next], in[i], d[i]);
    }
  }
  return out_count;
}

// Clips the polygon buffers[current][0 .. count) against each plane in turn, alternating
// between the two buffers. Returns ClipStatus::clipped with the result in
// buffers[current][0 .. count), or why nothing is left to draw.
ClipStatus clip_polygon(ClipVertex (&buffers)[2][kMaxClipVertices], int& count, int& current,
                        const GuardBandPlanes& planes) {
  for (int plane = 0; plane < kClipPlaneCount; ++plane) {
    const ClipVertex* in = buffers[current];
    float d[kMaxClipVertices];
    // A plane no vertex is outside of leaves the polygon as it is: skipping it changes nothing.
    if (!distances_to_plane(in, count, plane, planes, d)) continue;
    // A convex polygon crosses a plane at most twice; more means its vertices are within
    // rounding of one line, and the output could outgrow the buffers.
    if (sign_changes(d, count) > 2) return ClipStatus::culled_degenerate;
    count = clip_to_plane(in, d, count, buffers[current ^ 1]);
    current ^= 1;
    if (count < 3) return ClipStatus::outside;
  }
  return ClipStatus::clipped;
}

// Copies the polygon into result.vertices, each vertex clamped onto the planes, and returns
// `kept`; at the first vertex that cannot be projected (its w not positive, or positive but below
// kMinProjectedW), why instead, with the vertices before it copied.
ClipStatus store_clamped(const ClipVertex* polygon, int count, const GuardBandPlanes& planes,
                         ClipStatus kept, ClippedPolygon& result) {
  for (int i = 0; i < count; ++i) {
    ClipVertex v = polygon[i];
    Vec4& p = v.position;
    if (!(p.w > 0.0f)) return ClipStatus::culled_degenerate;
    if (p.w < kMinProjectedW) return ClipStatus::error_out_of_range;
    // Crossings may overshoot a plane by a rounding; pull them back onto it so the guard-band
    // bound (see the top of this file) and 0 <= depth <= 1 hold exactly. Inside vertices, and so
    // every vertex of an unclipped triangle, are left bit for bit unchanged.
    p.x = clamp(p.x, planes.x_min * p.w, planes.x_max * p.w);
    p.y = clamp(p.y, planes.y_min * p.w, planes.y_max * p.w);
    p.z = clamp(p.z, 0.0f, p.w);
    result.vertices[i] = v;
  }
  return kept;
}

}  // namespace

GuardBandPlanes guard_band_planes(const Viewport& viewport) {
  if (viewport.width < 1 || viewport.width > kMaxTargetSize || viewport.height < 1 ||
      viewport.height > kMaxTargetSize) {
    throw std::invalid_argument("guard_band_planes: viewport " + std::to_string(viewport.width) +
                                "x" + std::to_string(viewport.height) + " is outside 1.." +
                                std::to_string(kMaxTargetSize) + " pixels per side");
  }
  const double band = kGuardBand - static_cast<double>(kGuardBandMargin);
  const double x_span = 2.0 * band / viewport.width;
  const double y_span = 2.0 * band / viewport.height;
  return {static_cast<float>(-(1.0 + x_span)), static_cast<float>(x_span - 1.0),
          static_cast<float>(1.0 - y_span), static_cast<float>(1.0 + y_span)};
}

ClipClass classify_clip_vertex(const Vec4& p, const GuardBandPlanes& planes) {
  ClipClass result;
  for (float c : {p.x, p.y, p.z, p.w}) {
    if (!std::isfinite(c) || std::fabs(c) > kMaxClipCoordinate) return result;
  }
  const unsigned code = outcode(p, planes);
  result.checked = true;
  result.outside_frustum = static_cast<std::uint16_t>(code & kFrustumBits);
  result.inside = p.w >= kMinProjectedW && code == 0;
  return result;
}

ClippedPolygon clip_triangle(const Vec4& p0, const Vec4& p1, const Vec4& p2,
                             const GuardBandPlanes& planes) {
  ClippedPolygon result;
  const Vec4* input[3] = {&p0, &p1, &p2};

  // Reject bad input before any arithmetic.
  if (any_non_finite(input)) {
    result.status = ClipStatus::error_non_finite;
    return result;
  }
  if (any_out_of_range(input)) {
    result.status = ClipStatus::error_out_of_range;
    return result;
  }

  // Trivial reject and trivial accept from the outcodes.
  const unsigned c0 = outcode(p0, planes), c1 = outcode(p1, planes), c2 = outcode(p2, planes);
  if ((c0 & c1 & c2 & kFrustumBits) != 0) {
    result.status = ClipStatus::outside;
    return result;
  }
  ClipVertex buffers[2][kMaxClipVertices];
  buffers[0][0] = {p0, 1.0f, 0.0f, 0.0f};
  buffers[0][1] = {p1, 0.0f, 1.0f, 0.0f};
  buffers[0][2] = {p2, 0.0f, 0.0f, 1.0f};
  int count = 3;
  int current = 0;
  const bool needs_clipping = ((c0 | c1 | c2) & kClipPlaneBits) != 0;

  if (needs_clipping) {
    const ClipStatus status = clip_polygon(buffers, count, current, planes);
    if (status != ClipStatus::clipped) {
      result.status = status;
      return result;
    }
  }
  const ClipStatus kept = needs_clipping ? ClipStatus::clipped : ClipStatus::inside;
  result.status = store_clamped(buffers[current], count, planes, kept, result);
  if (result.status == kept) result.count = static_cast<std::uint8_t>(count);
  return result;
}

std::string_view name_of(ClipStatus value) {
  switch (value) {
    case ClipStatus::inside:
      return "inside";
    case ClipStatus::clipped:
      return "clipped";
    case ClipStatus::outside:
      return "outside";
    case ClipStatus::culled_degenerate:
      return "culled_degenerate";
    case ClipStatus::error_non_finite:
      return "error_non_finite";
    case ClipStatus::error_out_of_range:
      return "error_out_of_range";
  }
  return "unknown";
}

template <>
std::span<const ClipStatus> values_of<ClipStatus>() {
  static constexpr ClipStatus kValues[] = {
      ClipStatus::inside,           ClipStatus::clipped,
      ClipStatus::outside,          ClipStatus::culled_degenerate,
      ClipStatus::error_non_finite, ClipStatus::error_out_of_range};
  return kValues;
}

}  // namespace edgewise
