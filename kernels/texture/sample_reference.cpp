// The scalar reference sampler (sample_reference.hpp): each filter literally, in double precision.
#include "sample_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "../core/reference_kernels.hpp"
#include "level_of_detail.hpp"
#include "sample_reference_terms.hpp"
#include "texture_description.hpp"

namespace edgewise::reference {

using namespace sample_terms;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// How far from floor(x) the fixed-size filters reach (bicubic: -1 .. +2).
constexpr double kFixedFilterReach = 2.0;

// The summed_area filter's cap on each half extent, in level-0 texels.
constexpr double kMaxBoxHalfExtent = 1048576.0;  // 2^20

bool all_finite(const TextureQuery& q) {
  return std::isfinite(q.dsdx) && std::isfinite(q.dtdx) && std::isfinite(q.dsdy) &&
         std::isfinite(q.dtdy);
}

// floor(x) of a reduced coordinate, as an index.
std::int64_t floor_index(double x) {
  return static_cast<std::int64_t>(std::floor(x));
}

// The coordinates a fixed-size filter works with in `level`: x = s w - 0.5, y = t h - 0.5 for
// bilinear and bicubic (texel centres at integers), or s w, t h for nearest.
struct LevelPoint {
  double x, y;
};

LevelPoint level_point(const TextureLevel& level, WrapMode wrap_s, WrapMode wrap_t, double s,
                       double t, double centre_offset) {
  return {reduce_texel_coordinate(s * level.width, level.width, wrap_s, kFixedFilterReach) -
              centre_offset,
          reduce_texel_coordinate(t * level.height, level.height, wrap_t, kFixedFilterReach) -
              centre_offset};
}

const TextureLevel& ripmap_level(const Texture& texture, int column, int row) {
  return texture.ripmap_levels()[static_cast<std::size_t>(row) *
                                     static_cast<std::size_t>(texture.ripmap_columns()) +
                                 static_cast<std::size_t>(column)];
}

int ripmap_rows(const Texture& texture) {
  return static_cast<int>(texture.ripmap_levels().size()) / texture.ripmap_columns();
}

// lambda clamped to [0, top], NaN taken as +inf (the coarsest level).
double clamp_lambda(double lambda, double top) {
  if (std::isnan(lambda)) return top;
  return std::clamp(lambda, 0.0, top);
}

// --- Summed-area table helpers ---

// S_ext on one axis as a combination of the table's entries: S_ext = sum of weight * S(index).
struct PrefixTerm {
  std::int64_t index;
  double weight;
};

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  std::int64_t q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return q;
}

// S_ext at the integer X of an axis of n texels, times `weight`.
void append_lattice_terms(std::int64_t X, std::int64_t n, WrapMode mode, double weight,
                          std::vector<PrefixTerm>& out) {
  switch (mode) {
    case WrapMode::repeat: {
      // S_ext(X + k n) = S_ext(X) + k S(n).
      const std::int64_t k = floor_div(X, n);
      out.push_back({n, weight * static_cast<double>(k)});
      out.push_back({X - k * n, weight});
      return;
    }
    case WrapMode::clamp_to_edge:
      if (X < 0) {
        // Column 0 continues to the left: S_ext(X) = X (S(1) - S(0)), and S(0) = 0.
        out.push_back({1, weight * static_cast<double>(X)});
        out.push_back({0, -weight * static_cast<double>(X)});
      } else if (X > n) {
        // Column n - 1 continues to the right.
        const double beyond = static_cast<double>(X - n);
        out.push_back({n, weight * (1.0 + beyond)});
        out.push_back({n - 1, -weight * beyond});
      } else {
        out.push_back({X, weight});
      }
      return;
    case WrapMode::mirror: {
      // Period 2n holding the texture then its mirror image, whose integral from n to r is
      // S(n) - S(2n - r).
      const std::int64_t k = floor_div(X, 2 * n);
      const std::int64_t r = X - k * 2 * n;
      out.push_back({n, weight * 2.0 * static_cast<double>(k)});
      if (r <= n) {
        out.push_back({r, weight});
      } else {
        out.push_back({n, 2.0 * weight});
        out.push_back({2 * n - r, -weight});
      }
      return;
    }
  }
}

// S_ext at a real x: linear between the lattice values (the function is constant per cell).
void append_prefix_terms(double x, std::int64_t n, WrapMode mode, double weight,
                         std::vector<PrefixTerm>& out) {
  const double X = std::floor(x);
  const double f = x - X;
  const auto lattice = static_cast<std::int64_t>(X);
  append_lattice_terms(lattice, n, mode, weight * (1.0 - f), out);
  append_lattice_terms(lattice + 1, n, mode, weight * f, out);
}

// The sum over both axes' terms: S_ext is separable in the wrap extension, so a 2D value is the
// product combination of the 1D ones.
Rgba combine_terms(const SummedAreaTable& table, const std::vector<PrefixTerm>& xs,
                   const std::vector<PrefixTerm>& ys) {
  const auto stride = static_cast<std::size_t>(table.width) + 1;
  Rgba sum{};
  for (const PrefixTerm& y : ys) {
    for (const PrefixTerm& x : xs) {
      const std::size_t entry =
          4 * (static_cast<std::size_t>(y.index) * stride + static_cast<std::size_t>(x.index));
      for (int c = 0; c < 4; ++c)
        sum[c] += x.weight * y.weight * table.sums[entry + c];
    }
  }
  return scaled(sum, table.scale);
}

void require_ripmaps(const Texture& texture) {
  if (texture.ripmap_levels().empty()) {
    throw std::invalid_argument(
        "reference::sample: the ripmap filter needs a texture built with ripmaps");
  }
}

const SummedAreaTable& require_summed_area_table(const Texture& texture) {
  const SummedAreaTable* table = texture.summed_area_table();
  if (table == nullptr) {
    throw std::invalid_argument(
        "reference::sample: the summed_area filter needs a texture built with a summed-area table");
  }
  return *table;
}

}  // namespace

// --- Texel addressing ---

std::int64_t wrap_index(std::int64_t i, std::int64_t n, WrapMode mode) {
  switch (mode) {
    case WrapMode::repeat:
      return ((i % n) + n) % n;
    case WrapMode::clamp_to_edge:
      return std::clamp<std::int64_t>(i, 0, n - 1);
    case WrapMode::mirror: {
      const std::int64_t m = ((i % (2 * n)) + 2 * n) % (2 * n);
      return m < n ? m : 2 * n - 1 - m;
    }
  }
  return 0;
}

Rgba texel(const Texture& texture, const TextureLevel& level, WrapMode wrap_s, WrapMode wrap_t,
           std::int64_t x, std::int64_t y) {
  const std::int64_t a = wrap_index(x, level.width, wrap_s);
  const std::int64_t b = wrap_index(y, level.height, wrap_t);
  const auto first = 4 * static_cast<std::size_t>(b * level.width + a);
  const std::byte* data = texture.texels(level);
  Rgba out{};
  if (texture.format() == TexelFormat::rgba32f) {
    float values[4];
    std::memcpy(values, data + first * sizeof(float), sizeof(values));
    for (int c = 0; c < 4; ++c)
      out[c] = values[c];
    return out;
  }
  for (int c = 0; c < 4; ++c) {
    const double encoded = static_cast<double>(std::to_integer<int>(data[first + c])) / 255.0;
    const bool decode = texture.encoding() == ColorEncoding::srgb && c < 3;
    out[c] = decode ? srgb_to_linear(encoded) : encoded;
  }
  return out;
}

Rgba coarsest_texel(const Texture& texture) {
  return texel(texture, texture.mip_levels().back(), WrapMode::clamp_to_edge,
               WrapMode::clamp_to_edge, 0, 0);
}

// --- Filters within one level ---

Rgba nearest(const Texture& texture, const TextureLevel& level, WrapMode wrap_s, WrapMode wrap_t,
             double s, double t) {
  const LevelPoint p = level_point(level, wrap_s, wrap_t, s, t, 0.0);
  return texel(texture, level, wrap_s, wrap_t, floor_index(p.x), floor_index(p.y));
}

Rgba bilinear(const Texture& texture, const TextureLevel& level, WrapMode wrap_s, WrapMode wrap_t,
              double s, double t) {
  const LevelPoint p = level_point(level, wrap_s, wrap_t, s, t, 0.5);
  const std::int64_t i0 = floor_index(p.x), j0 = floor_index(p.y);
  const double fu = p.x - static_cast<double>(i0), fv = p.y - static_cast<double>(j0);
  Rgba out{};
  add_scaled(out, texel(texture, level, wrap_s, wrap_t, i0, j0), (1 - fu) * (1 - fv));
  add_scaled(out, texel(texture, level, wrap_s, wrap_t, i0 + 1, j0), fu * (1 - fv));
  add_scaled(out, texel(texture, level, wrap_s, wrap_t, i0, j0 + 1), (1 - fu) * fv);
  add_scaled(out, texel(texture, level, wrap_s, wrap_t, i0 + 1, j0 + 1), fu * fv);
  return out;
}

std::array<double, 4> cubic_weights(CubicKernel kernel, double f) {
  const double f2 = f * f, f3 = f2 * f;
  if (kernel == CubicKernel::catmull_rom) {
    return {(-f3 + 2 * f2 - f) / 2, (3 * f3 - 5 * f2 + 2) / 2, (-3 * f3 + 4 * f2 + f) / 2,
            (f3 - f2) / 2};
  }
  const double g = 1 - f;
  return {g * g * g / 6, (3 * f3 - 6 * f2 + 4) / 6, (-3 * f3 + 3 * f2 + 3 * f + 1) / 6, f3 / 6};
}

Rgba bicubic(const Texture& texture, const TextureLevel& level, WrapMode wrap_s, WrapMode wrap_t,
             double s, double t, CubicKernel kernel) {
  const LevelPoint p = level_point(level, wrap_s, wrap_t, s, t, 0.5);
  const std::int64_t i1 = floor_index(p.x), j1 = floor_index(p.y);
  const std::array<double, 4> wx = cubic_weights(kernel, p.x - static_cast<double>(i1));
  const std::array<double, 4> wy = cubic_weights(kernel, p.y - static_cast<double>(j1));
  Rgba out{};
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      add_scaled(out, texel(texture, level, wrap_s, wrap_t, i1 - 1 + i, j1 - 1 + j),
                 wx[static_cast<std::size_t>(i)] * wy[static_cast<std::size_t>(j)]);
    }
  }
  return out;
}

// --- Level of detail and the mip filters ---

double level_of_detail(const Texture& texture, const SamplerOptions& options,
                       const TextureQuery& query) {
  if (!all_finite(query)) return kInfinity;
  const TexelDerivatives d = texel_derivatives(texture, query);
  const double rho =
      options.lod == LodFormula::exact
          ? std::max(std::hypot(d.ux, d.vx), std::hypot(d.uy, d.vy))
          : std::max({std::abs(d.ux), std::abs(d.vx), std::abs(d.uy), std::abs(d.vy)});
  const double lambda = std::log2(rho) - kBoxPyramidLodOffset + double{options.lod_bias};
  return std::isnan(lambda) ? kInfinity : lambda;
}

double clamp_level_of_detail(const Texture& texture, double lambda) {
  return clamp_lambda(lambda, static_cast<double>(texture.mip_levels().size() - 1));
}

int mip_nearest_level(const Texture& texture, double lambda) {
  const double lambda_c = clamp_level_of_detail(texture, lambda);
  return lambda_c <= 0.5 ? 0 : static_cast<int>(std::ceil(lambda_c - 0.5));
}

Rgba mip_nearest(const Texture& texture, WrapMode wrap_s, WrapMode wrap_t, double s, double t,
                 double lambda) {
  const auto level = static_cast<std::size_t>(mip_nearest_level(texture, lambda));
  return bilinear(texture, texture.mip_levels()[level], wrap_s, wrap_t, s, t);
}

Rgba trilinear(const Texture& texture, WrapMode wrap_s, WrapMode wrap_t, double s, double t,
               double lambda) {
  const std::span<const TextureLevel> levels = texture.mip_levels();
  const double lambda_c = clamp_level_of_detail(texture, lambda);
  const auto l0 = static_cast<std::size_t>(std::floor(lambda_c));
  const Rgba fine = bilinear(texture, levels[l0], wrap_s, wrap_t, s, t);
  if (l0 + 1 == levels.size()) return fine;
  const double f = lambda_c - static_cast<double>(l0);
  Rgba out = scaled(fine, 1 - f);
  add_scaled(out, bilinear(texture, levels[l0 + 1], wrap_s, wrap_t, s, t), f);
  return out;
}

// --- Summed-area table ---

Rgba extended_prefix_sum(const SummedAreaTable& table, WrapMode wrap_s, WrapMode wrap_t, double x,
                         double y) {
  std::vector<PrefixTerm> xs, ys;
  append_prefix_terms(x, table.width, wrap_s, 1.0, xs);
  append_prefix_terms(y, table.height, wrap_t, 1.0, ys);
  return combine_terms(table, xs, ys);
}

Rgba box_integral(const SummedAreaTable& table, WrapMode wrap_s, WrapMode wrap_t, double x0,
                  double y0, double x1, double y1) {
  // S(x1, y1) - S(x0, y1) - S(x1, y0) + S(x0, y0), gathered per axis first: (S(x1) - S(x0)) on
  // each axis, then the product combination.
  std::vector<PrefixTerm> xs, ys;
  append_prefix_terms(x1, table.width, wrap_s, 1.0, xs);
  append_prefix_terms(x0, table.width, wrap_s, -1.0, xs);
  append_prefix_terms(y1, table.height, wrap_t, 1.0, ys);
  append_prefix_terms(y0, table.height, wrap_t, -1.0, ys);
  return combine_terms(table, xs, ys);
}

// --- Footprint filters ---

Rgba supersample(const Texture& texture, const SamplerOptions& options, const TextureQuery& query) {
  const int n = options.supersample_taps;
  const TextureLevel& level0 = texture.mip_levels().front();
  Rgba sum{};
  for (int j = 0; j < n; ++j) {
    const double b = (j + 0.5) / n - 0.5;
    for (int i = 0; i < n; ++i) {
      const double a = (i + 0.5) / n - 0.5;
      const double s = double{query.s} + a * double{query.dsdx} + b * double{query.dsdy};
      const double t = double{query.t} + a * double{query.dtdx} + b * double{query.dtdy};
      add_scaled(sum, bilinear(texture, level0, options.wrap_s, options.wrap_t, s, t), 1.0);
    }
  }
  return scaled(sum, 1.0 / (static_cast<double>(n) * n));
}

Rgba ripmap(const Texture& texture, const SamplerOptions& options, const TextureQuery& query) {
  require_ripmaps(texture);
  const TexelDerivatives d = texel_derivatives(texture, query);
  const int columns = texture.ripmap_columns(), rows = ripmap_rows(texture);
  // Per axis: the level from the bounding box's extent, its fraction, and the next level.
  const double lambda_s = clamp_lambda(
      std::log2(std::max(std::abs(d.ux), std::abs(d.uy))) + double{options.lod_bias}, columns - 1);
  const double lambda_t = clamp_lambda(
      std::log2(std::max(std::abs(d.vx), std::abs(d.vy))) + double{options.lod_bias}, rows - 1);
  const int i0 = static_cast<int>(std::floor(lambda_s)),
            j0 = static_cast<int>(std::floor(lambda_t));
  const double fs = lambda_s - i0, ft = lambda_t - j0;
  const int i1 = std::min(i0 + 1, columns - 1), j1 = std::min(j0 + 1, rows - 1);
  const double s = query.s, t = query.t;
  const WrapMode ws = options.wrap_s, wt = options.wrap_t;
  Rgba out{};
  add_scaled(out, bilinear(texture, ripmap_level(texture, i0, j0), ws, wt, s, t),
             (1 - fs) * (1 - ft));
  add_scaled(out, bilinear(texture, ripmap_level(texture, i1, j0), ws, wt, s, t), fs * (1 - ft));
  add_scaled(out, bilinear(texture, ripmap_level(texture, i0, j1), ws, wt, s, t), (1 - fs) * ft);
  add_scaled(out, bilinear(texture, ripmap_level(texture, i1, j1), ws, wt, s, t), fs * ft);
  return out;
}

Rgba summed_area(const Texture& texture, const SamplerOptions& options, const TextureQuery& query) {
  const SummedAreaTable& table = require_summed_area_table(texture);
  const TexelDerivatives d = texel_derivatives(texture, query);
  const double hu =
      std::min(std::max(0.5, (std::abs(d.ux) + std::abs(d.uy)) / 2), kMaxBoxHalfExtent);
  const double hv =
      std::min(std::max(0.5, (std::abs(d.vx) + std::abs(d.vy)) / 2), kMaxBoxHalfExtent);
  // The box moved by whole periods (or kept beyond the border) covers the same values.
  const double cu =
      reduce_texel_coordinate(double{query.s} * table.width, table.width, options.wrap_s, hu + 1);
  const double cv =
      reduce_texel_coordinate(double{query.t} * table.height, table.height, options.wrap_t, hv + 1);
  const Rgba integral =
      box_integral(table, options.wrap_s, options.wrap_t, cu - hu, cv - hv, cu + hu, cv + hv);
  return scaled(integral, 1.0 / (4 * hu * hv));
}

AnisotropicFootprint anisotropic_footprint(const Texture& texture, const SamplerOptions& options,
                                           const TextureQuery& query) {
  const TexelDerivatives d = texel_derivatives(texture, query);
  const bool exact = options.lod == LodFormula::exact;
  const double px = exact ? std::hypot(d.ux, d.vx) : std::max(std::abs(d.ux), std::abs(d.vx));
  const double py = exact ? std::hypot(d.uy, d.vy) : std::max(std::abs(d.uy), std::abs(d.vy));
  const double p_max = std::max(px, py), p_min = std::min(px, py);
  AnisotropicFootprint footprint;
  // Pmin = 0 (an infinite ratio) takes max_anisotropy probes.
  const double max_probes = options.max_anisotropy;
  const double probes = p_max == 0   ? 1.0
                        : p_min == 0 ? max_probes
                                     : std::min(std::ceil(p_max / p_min), max_probes);
  footprint.probes = static_cast<int>(probes);
  footprint.lambda = std::log2(p_max / footprint.probes) + double{options.lod_bias};
  footprint.major_s = px >= py ? query.dsdx : query.dsdy;
  footprint.major_t = px >= py ? query.dtdx : query.dtdy;
  return footprint;
}

Rgba anisotropic(const Texture& texture, const SamplerOptions& options, const TextureQuery& query) {
  const AnisotropicFootprint footprint = anisotropic_footprint(texture, options, query);
  const int n = footprint.probes;
  Rgba sum{};
  for (int k = 0; k < n; ++k) {
    const double a = (k + 0.5) / n - 0.5;
    const double s = double{query.s} + a * footprint.major_s;
    const double t = double{query.t} + a * footprint.major_t;
    add_scaled(sum, trilinear(texture, options.wrap_s, options.wrap_t, s, t, footprint.lambda),
               1.0);
  }
  return scaled(sum, 1.0 / n);
}

// --- The entry point ---

Rgba sample(const Texture& texture, const SamplerOptions& options, const TextureQuery& query) {
  // The pyramids a filter needs are checked before any query is looked at.
  if (options.filter == TextureFilter::ripmap) require_ripmaps(texture);
  if (options.filter == TextureFilter::summed_area) require_summed_area_table(texture);

  const double s = query.s, t = query.t;
  if (!std::isfinite(s) || !std::isfinite(t)) return {0, 0, 0, 0};
  const TextureLevel& level0 = texture.mip_levels().front();
  const WrapMode ws = options.wrap_s, wt = options.wrap_t;
  switch (options.filter) {
    case TextureFilter::nearest:
      return nearest(texture, level0, ws, wt, s, t);
    case TextureFilter::bilinear:
      return bilinear(texture, level0, ws, wt, s, t);
    case TextureFilter::bicubic_catmull_rom:
      return bicubic(texture, level0, ws, wt, s, t, CubicKernel::catmull_rom);
    case TextureFilter::bicubic_bspline:
      return bicubic(texture, level0, ws, wt, s, t, CubicKernel::bspline);
    default:
      break;
  }

  // Every filter below reads the derivatives.
  if (!all_finite(query)) return coarsest_texel(texture);
  switch (options.filter) {
    case TextureFilter::mip_nearest:
      return mip_nearest(texture, ws, wt, s, t, level_of_detail(texture, options, query));
    case TextureFilter::trilinear:
      return trilinear(texture, ws, wt, s, t, level_of_detail(texture, options, query));
    case TextureFilter::supersample:
      return supersample(texture, options, query);
    case TextureFilter::ripmap:
      return ripmap(texture, options, query);
    case TextureFilter::summed_area:
      return summed_area(texture, options, query);
    case TextureFilter::anisotropic:
      return anisotropic(texture, options, query);
    case TextureFilter::ewa:
      return ewa(texture, options, query);
    default:
      break;
  }
  throw std::invalid_argument("reference::sample: unknown filter");
}

// The reference's sampling kernels (kernel_table.hpp): each query by sample() above, rounded to
// float on the way out.

namespace {

Vec4 to_float(const reference::Rgba& rgba) {
  return {static_cast<float>(rgba[0]), static_cast<float>(rgba[1]), static_cast<float>(rgba[2]),
          static_cast<float>(rgba[3])};
}

}  // namespace

void sample(const detail::TextureDescription& texture, const SamplerOptions& options,
            const TextureQuery* queries, std::size_t count, Vec4* out) {
  for (std::size_t i = 0; i < count; ++i)
    out[i] = to_float(reference::sample(*texture.texture, options, queries[i]));
}

void sample_fields(const detail::TextureDescription& texture, const SamplerOptions& options,
                   const detail::QueryFields& queries, std::size_t count,
                   const detail::ResultChannels& out) {
  for (std::size_t i = 0; i < count; ++i) {
    const TextureQuery query{queries.s[i],    queries.t[i],    queries.dsdx[i],
                             queries.dtdx[i], queries.dsdy[i], queries.dtdy[i]};
    const Vec4 rgba = to_float(reference::sample(*texture.texture, options, query));
    out.c[0][i] = rgba.x;
    out.c[1][i] = rgba.y;
    out.c[2][i] = rgba.z;
    out.c[3][i] = rgba.w;
  }
}

}  // namespace edgewise::reference
