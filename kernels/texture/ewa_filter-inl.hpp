// The elliptical weighted average (sample.hpp, ewa; kernels/texture/ewa_reference.cpp):
// the footprint's ellipse per query, its level, and the Gaussian-weighted texels inside it,
// row by row. Magnified lanes take bilinear from TextureFilters.
#pragma once

#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "fast_log2-inl.hpp"
#include "texel_fetch-inl.hpp"
#include "texture_filters-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
class EwaFilter {
 public:
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;

  EwaFilter(const TextureFilters<Arch>& filters, const detail::TextureDescription& texture,
            const SamplerOptions& options)
      : filters_(filters), texture_(texture), options_(options) {}

  Rgba<Arch> filter(const QueryLanes<Arch>& q) const {
    const Floats ux = q.dsdx * Floats(texture_.width), vx = q.dtdx * Floats(texture_.height);
    const Floats uy = q.dsdy * Floats(texture_.width), vy = q.dtdy * Floats(texture_.height);
    const Floats a2 = ux * ux + vx * vx, b2 = uy * uy + vy * vy;
    const auto a_major = a2 >= b2;
    Axes axes{xsimd::select(a_major, ux, uy), xsimd::select(a_major, vx, vy),
              xsimd::select(a_major, uy, ux), xsimd::select(a_major, vy, vx)};
    const Floats major2 = xsimd::max(a2, b2), minor2 = xsimd::min(a2, b2);
    // Eccentricity clamp: a minor axis shorter than major / M becomes major's perpendicular / M.
    const Floats limit(static_cast<float>(options_.max_anisotropy));
    const auto too_thin = minor2 * limit * limit < major2;
    axes.nu = xsimd::select(too_thin, -axes.mv / limit, axes.nu);
    axes.nv = xsimd::select(too_thin, axes.mu / limit, axes.nv);
    const Floats minor_length2 = axes.nu * axes.nu + axes.nv * axes.nv;
    const Floats lambda = Floats(0.5f) * fast_log2<Arch>(minor_length2) + Floats(options_.lod_bias);
    const Floats clamped = filters_.clamp_lambda(lambda);
    Floats level = xsimd::floor(clamped);
    Floats f = clamped - level;
    // Bound the work: a level up, unblended, while the ellipse's box holds over 2 (4 M + 3)^2
    // texels (sample.hpp; the proof that lod_bias >= -1 never gets there is at
    // reference::ewa_box_limit). The limit is an integer below 2^18, exact in float.
    const int m = options_.max_anisotropy;
    const Floats box_limit(static_cast<float>(2 * (4 * m + 3) * (4 * m + 3)));
    const Floats last(static_cast<float>(texture_.mips.count - 1));
    for (std::int32_t k = 0; k < texture_.mips.count; ++k) {
      const LevelLanes<Arch> lanes = level_lanes<Arch>(texture_.mips, xsimd::to_int(level));
      const Floats eu = xsimd::sqrt(scaled_u2(axes, lanes) + Floats(1.0f));
      const Floats ev = xsimd::sqrt(scaled_v2(axes, lanes) + Floats(1.0f));
      const auto up =
          (level < last) &
          ((Floats(2.0f) * eu + Floats(1.0f)) * (Floats(2.0f) * ev + Floats(1.0f)) > box_limit);
      if (!xsimd::any(up)) break;
      level = xsimd::select(up, level + Floats(1.0f), level);
      f = xsimd::select(up, Floats(0.0f), f);
    }
    // Lanes answered otherwise (no footprint, or the last level) take a unit disk in the loops
    // below, so that their sizes (huge or not finite) never set the batch's loop counts.
    // Zero derivatives, not an underflowing squared length: tiny footprints still take the
    // unit disk, as in the reference.
    const Floats zero(0.0f);
    const auto no_footprint = (ux == zero) & (vx == zero) & (uy == zero) & (vy == zero);
    const auto at_last = level >= last;
    const auto elsewhere = no_footprint | at_last;
    for (Floats* axis : {&axes.mu, &axes.mv, &axes.nu, &axes.nv})
      *axis = xsimd::select(elsewhere, Floats(0.0f), *axis);
    const Ints l0 = xsimd::to_int(level);
    Rgba<Arch> result = ewa_level(axes, level_lanes<Arch>(texture_.mips, l0), q.s, q.t);
    if (xsimd::any(f > Floats(0.0f))) {
      const Ints l1 = xsimd::min(l0 + Ints(1), Ints(texture_.mips.count - 1));
      result =
          weighted_sum<Arch>(result, Floats(1.0f) - f,
                             ewa_level(axes, level_lanes<Arch>(texture_.mips, l1), q.s, q.t), f);
    }
    // No footprint magnifies; the last level is its single texel.
    const Rgba<Arch> magnified = filters_.bilinear0(q.s, q.t);
    const Rgba<Arch> coarsest =
        fetch_texels<Arch>(texture_, Ints(texture_.mips.start[texture_.mips.count - 1]));
    for (int k = 0; k < 4; ++k) {
      result.c[k] = xsimd::select(at_last, coarsest.c[k], result.c[k]);
      result.c[k] = xsimd::select(no_footprint, magnified.c[k], result.c[k]);
    }
    return result;
  }

 private:
  // The EWA footprint's axes in level-0 texels: major (mu, mv) and minor (nu, nv).
  struct Axes {
    Floats mu, mv, nu, nv;
  };
  // Squared half extents of the ellipse's box in a level, less the reconstruction disk's 1.
  Floats scaled_u2(const Axes& a, const LevelLanes<Arch>& lanes) const {
    const Floats scale = lanes.widthf / Floats(texture_.width);
    const Floats mu = a.mu * scale, nu = a.nu * scale;
    return mu * mu + nu * nu;
  }
  Floats scaled_v2(const Axes& a, const LevelLanes<Arch>& lanes) const {
    const Floats scale = lanes.heightf / Floats(texture_.height);
    const Floats mv = a.mv * scale, nv = a.nv * scale;
    return mv * mv + nv * nv;
  }

  // The Gaussian-weighted average over the ellipse in one level (per-lane level), row by row:
  // each row visits only the texels between the ellipse's two crossings of it (widened by one
  // texel, the Q < 1 test decides), lanes running to the widest row of the batch.
  Rgba<Arch> ewa_level(const Axes& axes, const LevelLanes<Arch>& level, Floats s, Floats t) const {
    const Floats su = level.widthf / Floats(texture_.width);
    const Floats sv = level.heightf / Floats(texture_.height);
    const Floats au = axes.mu * su, av = axes.mv * sv, bu = axes.nu * su, bv = axes.nv * sv;
    // Heckbert's conic with the unit disk added; F by Lagrange's identity (no cancellation).
    const Floats cross = au * bv - av * bu;
    const Floats A0 = av * av + bv * bv + Floats(1.0f);
    const Floats C0 = au * au + bu * bu + Floats(1.0f);
    const Floats F = cross * cross + A0 + C0 - Floats(1.0f);
    const Floats A = A0 / F, B = Floats(-2.0f) * (au * av + bu * bv) / F, C = C0 / F;
    const Floats eu = xsimd::sqrt(C0), ev = xsimd::sqrt(A0);  // the box's half extents
    const Floats cu = centre(s, level.widthf, eu, options_.wrap_s);
    const Floats cv = centre(t, level.heightf, ev, options_.wrap_t);
    const Floats row_first = xsimd::ceil(cv - ev);
    const Floats rows = xsimd::floor(cv + ev) - row_first + Floats(1.0f);
    const auto most_rows = static_cast<std::int32_t>(largest_lane(rows));
    Rgba<Arch> sum = zero_rgba<Arch>();
    Floats weight_sum(0.0f);
    const Floats table_last(static_cast<float>(detail::kEwaWeights - 2));
    for (std::int32_t r = 0; r < most_rows; ++r) {
      const Floats row(static_cast<float>(r));
      const Floats y = row_first + row;
      const Floats dv = y - cv;
      // A du^2 + (B dv) du + (C dv^2 - 1) < 0 between the roots.
      const Floats half_b = Floats(0.5f) * B * dv;
      const Floats disc = half_b * half_b - A * (C * dv * dv - Floats(1.0f));
      const Floats root = xsimd::sqrt(xsimd::max(disc, Floats(0.0f)));
      const Floats x_first = xsimd::floor(cu + (-half_b - root) / A);
      const Floats x_end = xsimd::ceil(cu + (-half_b + root) / A) + Floats(1.0f);
      const auto row_used = (row < rows) & (disc >= Floats(0.0f));
      const Floats columns = xsimd::select(row_used, x_end - x_first, Floats(0.0f));
      const auto most_columns = static_cast<std::int32_t>(largest_lane(columns));
      const Ints texel_y = wrap_any_index<Arch>(xsimd::to_int(y), level.height, options_.wrap_t);
      for (std::int32_t c = 0; c < most_columns; ++c) {
        const Floats column(static_cast<float>(c));
        const Floats x = x_first + column;
        const Floats du = x - cu;
        const Floats Q = (A * du + B * dv) * du + C * dv * dv;
        const auto inside = (column < columns) & (Q < Floats(1.0f));
        const Floats position = xsimd::min(xsimd::max(Q, Floats(0.0f)), Floats(1.0f)) * table_last;
        const Floats bin = xsimd::floor(position);
        const Ints index = xsimd::to_int(bin);
        const Floats w0 = gather_float<Arch>(texture_.ewa_weights, index);
        const Floats w1 = gather_float<Arch>(texture_.ewa_weights, index + Ints(1));
        const Floats weight =
            xsimd::select(inside, w0 + (w1 - w0) * (position - bin), Floats(0.0f));
        const Ints texel_x = wrap_any_index<Arch>(xsimd::to_int(x), level.width, options_.wrap_s);
        accumulate<Arch>(sum, fetch<Arch>(texture_, level, texel_x, texel_y), weight);
        weight_sum = weight_sum + weight;
      }
    }
    const Floats inverse = Floats(1.0f) / weight_sum;
    for (int k = 0; k < 4; ++k)
      sum.c[k] = sum.c[k] * inverse;
    return sum;
  }

  // The ellipse's centre in the level's texels: s w - 1/2, with s moved by whole periods
  // (repeat, mirror) or, for clamp, by whole texels to at most ceil(half extent + 1) texels
  // beyond the border: every texel the ellipse reaches there is the border one, as before, and
  // the texel grid keeps its place under the ellipse.
  Floats centre(Floats s, Floats size, Floats half_extent, WrapMode mode) const {
    if (mode == WrapMode::clamp_to_edge) {
      const Floats x = s * size;  // +-inf for a huge s: moved to the bound below
      const Floats bound = size + xsimd::ceil(half_extent + Floats(1.0f));
      // frac(s w) = frac((s - floor(s)) w), w being whole: s w itself may have lost its fraction.
      const Floats within = (s - xsimd::floor(s)) * size;
      const Floats fraction = within - xsimd::floor(within);
      Floats moved = xsimd::select(x > bound, bound + fraction, x);
      moved = xsimd::select(x < -bound, -bound - Floats(1.0f) + fraction, moved);
      return moved - Floats(0.5f);
    }
    return reduce_coordinate<Arch>(s, mode) * size - Floats(0.5f);
  }

  static float largest_lane(Floats v) {
    alignas(64) float lanes[Floats::size];
    v.store_aligned(lanes);
    float most = 0.0f;
    for (float lane : lanes)
      most = lane > most ? lane : most;
    return most;
  }

  const TextureFilters<Arch>& filters_;
  const detail::TextureDescription& texture_;
  const SamplerOptions& options_;
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
