// The error budget's choices for textured tiles (shading_budget.hpp states them): where a tile's
// texture coordinates may lie, the texels its filter may read, and the tile's colour from them.
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "budget_intervals.hpp"
#include "../../texture/level_of_detail.hpp"
#include "shading_budget.hpp"

namespace edgewise::detail {

using namespace budget;
namespace {

// A closed range of texel indices on one axis.
struct IndexRange {
  std::int64_t first, last;
};

// Indices on one axis of texels [first, last] of a level `size` texels long, wrapped as the
// sampler wraps them: at most two ranges.
int wrapped_ranges(std::int64_t first, std::int64_t last, std::int32_t size, WrapMode wrap,
                   IndexRange out[2]) {
  if (last - first + 1 >= size) {
    out[0] = {0, size - 1};
    return 1;
  }
  if (wrap == WrapMode::repeat) {
    const std::int64_t a = ((first % size) + size) % size;
    const std::int64_t b = a + (last - first);
    if (b < size) {
      out[0] = {a, b};
      return 1;
    }
    out[0] = {a, size - 1};
    out[1] = {0, b - size};
    return 2;
  }
  if (wrap == WrapMode::clamp_to_edge) {
    out[0] = {std::clamp<std::int64_t>(first, 0, size - 1),
              std::clamp<std::int64_t>(last, 0, size - 1)};
    return 1;
  }
  out[0] = first >= 0 && last < size ? IndexRange{first, last} : IndexRange{0, size - 1};
  return 1;
}

// The texel ranges' union over a box of a level: over its blocks when it spans at most 2 x 2 of
// them, else over the coarse cells that hold it. False past 3 x 3 coarse cells, or once a
// channel's range is wider than its `widest` (a tile that cannot take one colour: the caller
// gives up early, which both the kernels and the reference do alike).
bool add_box(const TexelRanges& ranges, const IndexRange& x, const IndexRange& y, double low[4],
             double high[4], const double widest[4]) {
  std::int64_t x0 = x.first / TexelRanges::kBlock, x1 = x.last / TexelRanges::kBlock;
  std::int64_t y0 = y.first / TexelRanges::kBlock, y1 = y.last / TexelRanges::kBlock;
  const float* lows = ranges.low.data();
  const float* highs = ranges.high.data();
  std::int64_t columns = ranges.columns;
  if (x1 - x0 > 1 || y1 - y0 > 1) {
    x0 /= TexelRanges::kCoarse;
    x1 /= TexelRanges::kCoarse;
    y0 /= TexelRanges::kCoarse;
    y1 /= TexelRanges::kCoarse;
    if (x1 - x0 > 2 || y1 - y0 > 2) return false;
    lows = ranges.coarse_low.data();
    highs = ranges.coarse_high.data();
    columns = ranges.coarse_columns;
  }
  for (std::int64_t by = y0; by <= y1; ++by) {
    for (std::int64_t bx = x0; bx <= x1; ++bx) {
      const std::size_t at = 4 * static_cast<std::size_t>(by * columns + bx);
      for (int k = 0; k < 4; ++k) {
        low[k] = std::min(low[k], static_cast<double>(lows[at + k]));
        high[k] = std::max(high[k], static_cast<double>(highs[at + k]));
      }
    }
    for (int k = 0; k < 4; ++k) {
      if (high[k] - low[k] > widest[k]) return false;
    }
  }
  return true;
}

// The exact value of a float plane at (dx, dy), in double (within 2^-52 of it relatively).
double plane_at(const AttributePlane& plane, double dx, double dy) {
  return static_cast<double>(plane.at_vertex) + static_cast<double>(plane.dy) * dy +
         static_cast<double>(plane.dx) * dx;
}

double plane_size(const AttributePlane& plane, double reach_x, double reach_y) {
  return std::abs(static_cast<double>(plane.at_vertex)) +
         std::abs(static_cast<double>(plane.dy)) * reach_y +
         std::abs(static_cast<double>(plane.dx)) * reach_x;
}

// Where the sampler's coordinates may lie over the tile's pixels, and how large its derivatives
// may be, from the float planes every path evaluates (texture_planes.hpp).
struct TileCoordinates {
  double s_low, s_high, t_low, t_high;
  double ds[2], dt[2];  // bounds on |ds/dx|, |ds/dy| and |dt/dx|, |dt/dy|
  double rho_low;       // a lower bound on the sampler's rho, in texels of level 0
};

// A lower bound on |ds/dx| (f the plane of s/w, along x; or of t/w, or along y) over the tile,
// from the planes' values at its corners: ds/dx = N / q^2 with N = (dx slope of s/w) q - (s/w)
// (dx slope of q) a plane, so where N keeps its sign over the tile |ds/dx| >= min |N| / max q^2,
// both at corners; the quad's mean of it, less the two values' errors (`extra`).
double least_derivative(const TexturePlanes& planes, const AttributePlane& f,
                        const double (&corner_q)[4], const double* values, double q_high,
                        bool along_x, double extra) {
  const double f_slope = along_x ? f.dx : f.dy;
  const double q_slope = planes.divides ? (along_x ? planes.q.dx : planes.q.dy) : 0.0;
  double low = kInfinity, high = -kInfinity;
  for (int c = 0; c < 4; ++c) {
    // N at the corner, give or take its double evaluation (the planes' values within 2^-50
    // of their terms, the products and the difference a few roundings more).
    const double a = f_slope * corner_q[c], b = values[c] * q_slope;
    const double error = 0x1p-46 * (std::abs(a) + std::abs(b));
    low = std::min(low, a - b - error);
    high = std::max(high, a - b + error);
  }
  return std::max(0.0, least_magnitude(low, high) / (q_high * q_high) * (1.0 - 0x1p-40) - extra);
}

bool tile_coordinates(const TexturePlanes& planes, TextureDerivatives derivatives,
                      const PixelBox& box, double width, double height, TileCoordinates& out) {
  // The box's outermost pixel centres, relative to the planes' origin (exact in double).
  const double xs[2] = {box.x_first + 0.5 - planes.x0, box.x_last + 0.5 - planes.x0};
  const double ys[2] = {box.y_first + 0.5 - planes.y0, box.y_last + 0.5 - planes.y0};
  const double reach_x = std::max(std::abs(xs[0]), std::abs(xs[1]));
  const double reach_y = std::max(std::abs(ys[0]), std::abs(ys[1]));
  out.s_low = out.t_low = kInfinity;
  out.s_high = out.t_high = -kInfinity;
  double q_low = kInfinity;
  // The planes' values at the corners (q, s/w, t/w).
  double corner_q[4], corner_s[4], corner_t[4];
  int corner = 0;
  for (double dx : xs) {
    for (double dy : ys) {
      // A projective map over a rectangle where q > 0 throughout (q is a plane, so positive at
      // the corners is enough) is monotonic along every line: its extremes are at the corners.
      const double q = planes.divides ? plane_at(planes.q, dx, dy) : 1.0;
      q_low = std::min(q_low, q);
      corner_q[corner] = q;
      corner_s[corner] = plane_at(planes.s, dx, dy);
      corner_t[corner] = plane_at(planes.t, dx, dy);
      const double s = corner_s[corner] / q, t = corner_t[corner] / q;
      ++corner;
      out.s_low = std::min(out.s_low, s);
      out.s_high = std::max(out.s_high, s);
      out.t_low = std::min(out.t_low, t);
      out.t_high = std::max(out.t_high, t);
    }
  }
  // The float evaluation: each plane within 5 u of its terms' magnitude (four roundings and the
  // double evaluation above), 1 / q and the product one rounding each.
  const double s_size = plane_size(planes.s, reach_x, reach_y);
  const double t_size = plane_size(planes.t, reach_x, reach_y);
  double s_error = 5.0 * kUnit * s_size, t_error = 5.0 * kUnit * t_size;
  double s_abs = s_size, t_abs = t_size;
  if (planes.divides) {
    const double q_error = 5.0 * kUnit * plane_size(planes.q, reach_x, reach_y);
    if (!(q_low > 2.0 * q_error)) return false;
    s_abs = s_size / q_low;
    t_abs = t_size / q_low;
    s_error = (s_error + s_abs * q_error) / (q_low - q_error) + 3.0 * kUnit * 2.0 * s_abs;
    t_error = (t_error + t_abs * q_error) / (q_low - q_error) + 3.0 * kUnit * 2.0 * t_abs;
  }
  out.s_low -= s_error;
  out.s_high += s_error;
  out.t_low -= t_error;
  out.t_high += t_error;
  // The derivatives of the projective map anywhere in the tile: ds/dx = (dx slope of s/w -
  // s dx slope of q) / q, and likewise; a quad's difference of two computed values one pixel
  // apart is the mean of ds/dx between them, off by both values' errors.
  const double slack = 1.0 + 16.0 * kUnit;
  const double q_x = planes.divides ? std::abs(static_cast<double>(planes.q.dx)) : 0.0;
  const double q_y = planes.divides ? std::abs(static_cast<double>(planes.q.dy)) : 0.0;
  const double inverse = planes.divides ? 1.0 / q_low : 1.0;
  const bool quad = derivatives == TextureDerivatives::quad;
  const double s_extra = quad ? 2.0 * s_error : 0.0, t_extra = quad ? 2.0 * t_error : 0.0;
  out.ds[0] =
      (std::abs(static_cast<double>(planes.s.dx)) + s_abs * q_x) * inverse * slack + s_extra;
  out.ds[1] =
      (std::abs(static_cast<double>(planes.s.dy)) + s_abs * q_y) * inverse * slack + s_extra;
  out.dt[0] =
      (std::abs(static_cast<double>(planes.t.dx)) + t_abs * q_x) * inverse * slack + t_extra;
  out.dt[1] =
      (std::abs(static_cast<double>(planes.t.dy)) + t_abs * q_y) * inverse * slack + t_extra;
  // Every rho is at least the largest of the four least derivatives.
  const double q_high = std::max({corner_q[0], corner_q[1], corner_q[2], corner_q[3]});
  const auto least = [&](const AttributePlane& f, const double* values, bool along_x,
                         double extra) {
    return least_derivative(planes, f, corner_q, values, q_high, along_x, extra);
  };
  out.rho_low = std::max({least(planes.s, corner_s, true, s_extra) * width,
                          least(planes.t, corner_t, true, t_extra) * height,
                          least(planes.s, corner_s, false, s_extra) * width,
                          least(planes.t, corner_t, false, t_extra) * height});
  return std::isfinite(out.s_low) && std::isfinite(out.s_high) && std::isfinite(out.t_low) &&
         std::isfinite(out.t_high) && std::isfinite(out.ds[0] + out.ds[1] + out.dt[0] + out.dt[1]);
}

// The least and greatest texel over every texel the filter may read in the tile, per channel.
bool tile_texel_range(const TileCoordinates& c, const Texture& texture,
                      const SamplerOptions& sampler, const double widest[4], double low[4],
                      double high[4]) {
  const std::span<const TextureLevel> levels = texture.mip_levels();
  const double width = texture.width(), height = texture.height();
  int first_level = 0, last_level = 0;
  if (sampler.filter == TextureFilter::mip_nearest || sampler.filter == TextureFilter::trilinear) {
    // rho <= the longer of the derivative vectors in texels (the max_axis rho is below it); the
    // sampler's float log2 and rounding are within 1/64 of a level.
    const double x =
        std::sqrt(c.ds[0] * width * c.ds[0] * width + c.dt[0] * height * c.dt[0] * height);
    const double y =
        std::sqrt(c.ds[1] * width * c.ds[1] * width + c.dt[1] * height * c.dt[1] * height);
    const double rho_high = std::max(x, y) * (1.0 + 0x1p-20);
    const double shift = sampler.lod_bias - kBoxPyramidLodOffset;
    const double lambda_high = std::log2(rho_high) + shift + 1.0 / 64.0;  // -inf for 0
    const double lambda_low = std::log2(c.rho_low) + shift - 1.0 / 64.0;
    const double last = static_cast<double>(levels.size() - 1);
    // trilinear reads floor(lambda) and the next level; mip_nearest the level nearest lambda.
    const bool trilinear = sampler.filter == TextureFilter::trilinear;
    const double top = trilinear ? std::floor(lambda_high) + 1.0 : std::floor(lambda_high + 0.5);
    const double bottom = trilinear ? std::floor(lambda_low) : std::floor(lambda_low - 0.5);
    last_level = static_cast<int>(std::clamp(top, 0.0, last));
    first_level = static_cast<int>(std::clamp(bottom, 0.0, static_cast<double>(last_level)));
  }
  constexpr double kLargest = 0x1p30;  // texel indices beyond this: no bound
  if (!(std::abs(c.s_low) * width < kLargest && std::abs(c.s_high) * width < kLargest &&
        std::abs(c.t_low) * height < kLargest && std::abs(c.t_high) * height < kLargest))
    return false;
  for (int k = 0; k < 4; ++k) {
    low[k] = kInfinity;
    high[k] = -kInfinity;
  }
  // Coarsest first: its box is the smallest, and an edge there rejects the tile soonest.
  for (int level = last_level; level >= first_level; --level) {
    const TextureLevel& l = levels[static_cast<std::size_t>(level)];
    // The texels read around s: floor(s W) for nearest, floor(s W - 1/2) and the next for the
    // bilinear reads.
    const double offset = sampler.filter == TextureFilter::nearest ? 0.0 : 0.5;
    const std::int64_t extra = sampler.filter == TextureFilter::nearest ? 0 : 1;
    const auto first = [&](double v, std::int32_t n) {
      return static_cast<std::int64_t>(std::floor(v * n - offset));
    };
    // One texel more on each side: a fast filter's position is off by up to 2^-21 w texels
    // (texture_filters-inl.hpp, kPositionError), below one texel.
    IndexRange xs[2], ys[2];
    const int nx = wrapped_ranges(first(c.s_low, l.width) - 1, first(c.s_high, l.width) + extra + 1,
                                  l.width, sampler.wrap_s, xs);
    const int ny =
        wrapped_ranges(first(c.t_low, l.height) - 1, first(c.t_high, l.height) + extra + 1,
                       l.height, sampler.wrap_t, ys);
    const TexelRanges& ranges = texture.texel_ranges()[static_cast<std::size_t>(level)];
    for (int i = 0; i < nx; ++i) {
      for (int j = 0; j < ny; ++j) {
        if (!add_box(ranges, xs[i], ys[j], low, high, widest)) return false;
      }
    }
  }
  for (int k = 0; k < 4; ++k) {
    if (!std::isfinite(low[k]) || !std::isfinite(high[k])) return false;
  }
  return true;
}

}  // namespace

namespace {

// The tile's choice from where its queries lie (`coordinates`): one colour for shade times texel,
// else one texel value for every pixel (the shade still per pixel), else nothing.
TileTexture texture_choice(const ShadeInterval& shade, const TileCoordinates& coordinates,
                           const ShadeBatch& batch) {
  const int codes = batch.budget_codes;
  if (!shade.bounded || codes <= 0) return {};
  // A texel range wider than 2 K / 255 over the least shade magnitude makes the product wider
  // than one colour allows (where the shade keeps its sign; clamping could only narrow it), and
  // one texel value allows less (the largest magnitude): giving up there is always allowed.
  double widest[4];
  for (int k = 0; k < 4; ++k) {
    const double least = least_magnitude(shade.low[k], shade.high[k]);
    widest[k] = least > 0.0 ? 2.0 * codes / 255.0 / least : kInfinity;
  }
  double texel_low[4], texel_high[4];
  if (!tile_texel_range(coordinates, *batch.texture, batch.sampler, widest, texel_low, texel_high))
    return {};
  TileTexture choice;
  std::uint32_t packed = 0;
  bool one_colour = true, one_texel = true;
  for (int k = 0; k < 4; ++k) {
    // The exact path: its shaded value within `rounding` of the interval, its filtered texel
    // within 16 u of the texels' range, the product one rounding more.
    const double texel_abs = std::max(std::abs(texel_low[k]), std::abs(texel_high[k]));
    const double shade_abs =
        std::max(std::abs(shade.low[k]), std::abs(shade.high[k])) + shade.rounding[k];
    double low, high;
    multiply(shade.low[k], shade.high[k], texel_low[k], texel_high[k], low, high);
    low = clamp01(low);
    high = clamp01(high);
    const double rounding = shade.rounding[k] * texel_abs * (1.0 + 16.0 * kUnit) +
                            shade_abs * 16.0 * kUnit * texel_abs +
                            4.0 * kUnit * shade_abs * texel_abs;
    one_colour = one_colour && 255.0 * ((high - low) / 2.0 + rounding) < codes;
    packed |= to_byte((low + high) / 2.0) << (8 * k);
    // One texel value T for every pixel: the midpoint of the range, rounded to float. The exact
    // texel is within half the range and 16 u of it, T within u more; times the pixel's float
    // shade (at most shade_abs), each product rounded once and clamped (which only narrows).
    const double middle = (texel_low[k] + texel_high[k]) / 2.0;
    choice.texel[k] = static_cast<float>(middle);
    const double texel_error = (texel_high[k] - texel_low[k]) / 2.0 + 17.0 * kUnit * texel_abs;
    one_texel = one_texel && 255.0 * (shade_abs * texel_error +
                                      2.0 * kUnit * shade_abs * (texel_abs + texel_error)) <
                                 codes;
  }
  if (one_colour) {
    choice.colour = packed;
  } else if (!one_texel) {
    return {};
  }
  choice.one_texel = one_texel;
  return choice;
}

}  // namespace

TileTexture measured_texture_tile(const ShadeInterval& shade, const TileQueries& queries,
                                  const ShadeBatch& batch) {
  if (!queries.finite || !budget_tiles(batch)) return {};
  const double width = batch.texture->width(), height = batch.texture->height();
  // The sampler filters at exactly these queries: the coordinates need no widening beyond
  // tile_texel_range()'s own (the fast filters' index arithmetic, one texel), the derivatives
  // none beyond its lambda margin (the float rho and log2).
  TileCoordinates c;
  c.s_low = queries.low[0];
  c.s_high = queries.high[0];
  c.t_low = queries.low[1];
  c.t_high = queries.high[1];
  double magnitude[4];
  for (int f = 0; f < 4; ++f) {
    magnitude[f] = std::max(std::abs(static_cast<double>(queries.low[2 + f])),
                            std::abs(static_cast<double>(queries.high[2 + f])));
  }
  c.ds[0] = magnitude[0];  // ds/dx
  c.dt[0] = magnitude[1];  // dt/dx
  c.ds[1] = magnitude[2];  // ds/dy
  c.dt[1] = magnitude[3];  // dt/dy
  // Every rho (exact or max_axis) is at least each derivative's magnitude in texels.
  c.rho_low = 0.0;
  for (int f = 0; f < 4; ++f) {
    const double scale = f % 2 == 0 ? width : height;
    c.rho_low =
        std::max(c.rho_low, least_magnitude(queries.low[2 + f], queries.high[2 + f]) * scale);
  }
  return texture_choice(shade, c, batch);
}

TexturePlan texture_plan(const ShadeInterval& shade, const TexturePlanes& planes,
                         const ShadeBatch& batch, const Vec2 (&position)[3]) {
  TexturePlan plan;
  if (!budget_tiles(batch) || !shade.bounded) return plan;
  double x_low = kInfinity, x_high = -kInfinity, y_low = kInfinity, y_high = -kInfinity;
  for (const Vec2& p : position) {
    x_low = std::min(x_low, static_cast<double>(p.x));
    x_high = std::max(x_high, static_cast<double>(p.x));
    y_low = std::min(y_low, static_cast<double>(p.y));
    y_high = std::max(y_high, static_cast<double>(p.y));
  }
  // Pixel centres px + 1/2 in [x_low, x_high] have px in [ceil(x_low - 1/2), floor(x_high - 1/2)];
  // the box holds those and may hold a few more.
  constexpr double kLargest = 0x1p24;
  if (!(std::abs(x_low) < kLargest && std::abs(x_high) < kLargest && std::abs(y_low) < kLargest &&
        std::abs(y_high) < kLargest))
    return plan;
  const PixelBox box{static_cast<std::int32_t>(std::floor(x_low - 0.5)),
                     static_cast<std::int32_t>(std::ceil(x_high - 0.5)),
                     static_cast<std::int32_t>(std::floor(y_low - 0.5)),
                     static_cast<std::int32_t>(std::ceil(y_high - 0.5))};
  TileCoordinates coordinates;
  const Texture& texture = *batch.texture;
  if (tile_coordinates(planes, batch.derivatives, box, texture.width(), texture.height(),
                       coordinates)) {
    plan.colour = texture_choice(shade, coordinates, batch).colour;
  }
  plan.tiles = !plan.colour && (box.x_last - box.x_first >= kTilePlanSpan ||
                                box.y_last - box.y_first >= kTilePlanSpan);
  return plan;
}

}  // namespace edgewise::detail
