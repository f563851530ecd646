#include "triangle_sources.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>

namespace edgewise::test {
namespace {

constexpr double kBandLow = -32768.0;
constexpr double kBandHigh = 32767.99609375;  // the last position inside the band

struct Point {
  double x, y;
};

Vec2 to_vec(Point p) {
  return {static_cast<float>(p.x), static_cast<float>(p.y)};
}

double clamp_to_band(double v) {
  return std::clamp(v, kBandLow, kBandHigh);
}

Point in_rect(Random& random, const PixelRect& r, double margin) {
  return {random.uniform(r.x0 - margin, r.x1 + margin),
          random.uniform(r.y0 - margin, r.y1 + margin)};
}

Point unit_direction(Random& random) {
  const double angle = random.uniform(0.0, 2.0 * std::numbers::pi);
  return {std::cos(angle), std::sin(angle)};
}

// Vertices anywhere over the target and a third of its size beyond each side.
void make_uniform(Random& random, const PixelRect& aim, Vec2 (&tri)[3]) {
  const double margin = 0.3 * std::max(aim.x1 - aim.x0, aim.y1 - aim.y0);
  for (Vec2& v : tri)
    v = to_vec(in_rect(random, aim, margin));
}

// Sub-pixel to a few pixels across, anywhere on the largest target (and just off its sides).
void make_tiny(Random& random, const PixelRect& aim, Vec2 (&tri)[3]) {
  const Point center = in_rect(random, aim, 8.0);
  const double scale = random.log_uniform(1.0 / 256.0, 6.0);
  for (Vec2& v : tri) {
    v = to_vec(
        {center.x + random.uniform(-scale, scale), center.y + random.uniform(-scale, scale)});
  }
}

// How far from p one can go along d and stay in the guard band.
double reach_in_band(Point p, Point d) {
  double reach = 1e9;
  if (d.x > 0) reach = std::min(reach, (kBandHigh - p.x) / d.x);
  if (d.x < 0) reach = std::min(reach, (kBandLow - p.x) / d.x);
  if (d.y > 0) reach = std::min(reach, (kBandHigh - p.y) / d.y);
  if (d.y < 0) reach = std::min(reach, (kBandLow - p.y) / d.y);
  return reach;
}

Point along(Point p, Point d, double t) {
  return {clamp_to_band(p.x + t * d.x), clamp_to_band(p.y + t * d.y)};
}

// From tens of pixels to the whole guard band, with an edge through the (small) clip window so
// that partial tiles see edge functions of every magnitude, narrow and wide walks alike.
void make_huge(Random& random, const PixelRect& aim, Vec2 (&tri)[3]) {
  if (random.chance(0.2)) {  // anywhere in the band: mostly full or empty windows
    for (Vec2& v : tri)
      v = to_vec({random.uniform(kBandLow, kBandHigh), random.uniform(kBandLow, kBandHigh)});
    return;
  }
  const Point p = in_rect(random, aim, 2.0);
  const Point d = unit_direction(random);
  const Point back{-d.x, -d.y};
  const double forward_reach = reach_in_band(p, d), back_reach = reach_in_band(p, back);
  tri[0] = to_vec(along(p, d, random.log_uniform(8.0, std::max(16.0, forward_reach))));
  tri[1] = to_vec(along(p, back, random.log_uniform(8.0, std::max(16.0, back_reach))));
  const Point e = unit_direction(random);
  tri[2] = to_vec(along(p, e, random.log_uniform(8.0, std::max(16.0, reach_in_band(p, e)))));
}

// Long and thin: the third vertex within a few pixels (or a fraction of a snapping step) of the
// line through the other two.
void make_sliver(Random& random, const PixelRect& aim, Vec2 (&tri)[3]) {
  const Point a = in_rect(random, aim, 20.0);
  const Point d = unit_direction(random);
  const double length = random.log_uniform(0.5, 120.0);
  const double t = random.uniform(-0.2, 1.2);
  const double width = random.sign() * random.log_uniform(1.0 / 1024.0, 2.0);
  tri[0] = to_vec(a);
  tri[1] = to_vec({a.x + length * d.x, a.y + length * d.y});
  tri[2] = to_vec({a.x + t * length * d.x - width * d.y, a.y + t * length * d.y + width * d.x});
}

// Edges a few snapping steps (or less) off horizontal or vertical, often through samples.
void make_near_axis(Random& random, const PixelRect& aim, Vec2 (&tri)[3]) {
  Point a = in_rect(random, aim, 10.0);
  if (random.chance(0.5)) a = {std::floor(a.x) + 0.5, std::floor(a.y) + 0.5};
  const auto skew = [&random]() {
    return random.chance(0.5) ? static_cast<double>(random.integer(-3, 3)) / 256.0
                              : random.sign() * random.log_uniform(1.0 / 4096.0, 0.05);
  };
  const double along1 = random.sign() * random.log_uniform(1.0, 100.0);
  const double along2 = random.sign() * random.log_uniform(0.25, 100.0);
  const bool horizontal = random.chance(0.5);
  // b: along the main axis from a; c: along the other axis (a near-right triangle) or anywhere.
  Point b{a.x + along1, a.y + skew()}, c{a.x + skew(), a.y + along2};
  if (!horizontal) {
    b = {a.x + skew(), a.y + along1};
    c = {a.x + along2, a.y + skew()};
  }
  if (random.chance(0.3)) c = {a.x + random.uniform(-50, 50), a.y + random.uniform(-50, 50)};
  tri[0] = to_vec(a);
  tri[1] = to_vec(b);
  tri[2] = to_vec(c);
}

// Vertices on pixel centers, pixel corners, and odd multiples of 1/512 px (exact snapping ties).
void make_ties(Random& random, const PixelRect& aim, Vec2 (&tri)[3]) {
  const Point base = in_rect(random, aim, 4.0);
  const double size = random.log_uniform(0.5, 24.0);
  for (Vec2& v : tri) {
    float c[2];
    for (int axis = 0; axis < 2; ++axis) {
      const double raw = (axis == 0 ? base.x : base.y) + random.uniform(-size, size);
      const double kind = random.uniform();
      if (kind < 0.4) {
        c[axis] = static_cast<float>(std::floor(raw) + 0.5);  // a sample
      } else if (kind < 0.55) {
        c[axis] = static_cast<float>(std::floor(raw));  // a pixel corner
      } else {
        c[axis] = static_cast<float>(std::floor(raw * 512.0) / 512.0);  // a step or a tie
      }
    }
    v = {c[0], c[1]};
  }
}

// Coordinates at and around the guard band's ends (in and out, exact ties included), random
// bit patterns (denormals, huge values, NaN, infinities), and points in the clip window.
float guard_band_coordinate(Random& random, std::int32_t lo, std::int32_t hi) {
  static constexpr float kSpecial[] = {-32768.0f,
                                       32767.99609375f,
                                       -32767.998046875f,
                                       32767.998046875f,
                                       32768.0f,
                                       -32768.00390625f,
                                       -32767.99609375f,
                                       32767.5f,
                                       -32767.5f,
                                       0.0f,
                                       0.5f,
                                       -0.001953125f,
                                       65536.0f,
                                       -1e20f};
  const double kind = random.uniform();
  if (kind < 0.35) {
    return kSpecial[random.integer(0, std::size(kSpecial) - 1)];
  }
  if (kind < 0.7) {
    const double inset = random.log_uniform(1.0 / 512.0, 64.0);
    return static_cast<float>(random.chance(0.5) ? kBandLow + inset - 0.01 : 32768.0 - inset);
  }
  if (kind < 0.95) return static_cast<float>(random.uniform(lo - 4.0, hi + 4.0));
  if (kind < 0.96) {
    return random.chance(0.5) ? std::numeric_limits<float>::quiet_NaN()
                              : random.sign() * std::numeric_limits<float>::infinity();
  }
  return std::bit_cast<float>(static_cast<std::uint32_t>(random.next()));
}

void make_guard_band(Random& random, const PixelRect& aim, Vec2 (&tri)[3]) {
  for (Vec2& v : tri) {
    v.x = guard_band_coordinate(random, aim.x0, aim.x1);
    v.y = guard_band_coordinate(random, aim.y0, aim.y1);
  }
}

const TriangleSource kSources[] = {
    {"uniform", {160, 144, std::nullopt}, 0.08, 0, &make_uniform},
    {"tiny", {kMaxTargetSize, kMaxTargetSize, std::nullopt}, 0.30, 0, &make_tiny},
    {"huge", {kMaxTargetSize, kMaxTargetSize, std::nullopt}, 0.10, 64, &make_huge},
    {"slivers", {160, 150, std::nullopt}, 0.14, 0, &make_sliver},
    {"near_axis", {128, 128, std::nullopt}, 0.12, 0, &make_near_axis},
    {"ties", {64, 64, std::nullopt}, 0.16, 0, &make_ties},
    {"guard_band", {kMaxTargetSize, kMaxTargetSize, std::nullopt}, 0.10, 64, &make_guard_band},
};

}  // namespace

std::span<const TriangleSource> triangle_sources() {
  return kSources;
}

}  // namespace edgewise::test
