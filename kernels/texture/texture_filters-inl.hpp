// The texture filters over a batch of queries, as defined in sample.hpp: the level-0 filters
// (nearest, bilinear, bicubic), the level of detail, and the filters built from bilinear taps
// (mip_nearest, trilinear, supersample, ripmap, anisotropic). EWA has a file of its own
// (ewa_filter-inl.hpp).
//
// Accuracy against the double-precision reference (kernels/texture/sample_reference.*), used by
// the tests' bounds: a texel position u = s' w - 1/2 is off by at most kPositionError w texels
// (the reduction s' = s - floor(s) rounds by at most 2^-24, then s' w and the subtraction round
// by at most 2^-24 |u| <= 2^-23 w each: 5 * 2^-24 w < 2^-21 w); weights and sums
// add a few float ulps of the largest texel magnitude; the level of detail is off by at most
// kLog2RelativeError (|lambda| + 1).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include <xsimd/xsimd.hpp>

#include "level_of_detail.hpp"
#include "fast_log2-inl.hpp"
#include "../simd/simd_ops-inl.hpp"
#include "float_taps-inl.hpp"
#include "texel_fetch-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

inline constexpr double kPositionError = 0x1p-21;

template <class Arch>
struct QueryLanes {
  xsimd::batch<float, Arch> s, t, dsdx, dtdx, dsdy, dtdy;
};

template <class Arch>
EDGEWISE_INLINE Rgba<Arch> zero_rgba() {
  const xsimd::batch<float, Arch> zero(0.0f);
  return {{zero, zero, zero, zero}};
}

template <class Arch>
EDGEWISE_INLINE Rgba<Arch> weighted_sum(const Rgba<Arch>& a, xsimd::batch<float, Arch> wa,
                                        const Rgba<Arch>& b, xsimd::batch<float, Arch> wb) {
  Rgba<Arch> out;
  for (int k = 0; k < 4; ++k)
    out.c[k] = a.c[k] * wa + b.c[k] * wb;
  return out;
}

template <class Arch>
EDGEWISE_INLINE void accumulate(Rgba<Arch>& sum, const Rgba<Arch>& value,
                                xsimd::batch<float, Arch> weight) {
  for (int k = 0; k < 4; ++k)
    sum.c[k] = fused_multiply_add<Arch>(value.c[k], weight, sum.c[k]);
}

// Sums: how the bilinear taps of 8-bit textures are weighted and summed, FloatTapSums or
// FixedTapSums (fixed_taps-inl.hpp; linear 8-bit textures only).
template <class Arch, class Sums = FloatTapSums<Arch>>
class TextureFilters {
 public:
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;

  TextureFilters(const detail::TextureDescription& texture, const SamplerOptions& options)
      : texture_(texture),
        options_(options),
        level0_(level_lanes<Arch>(texture.mips, 0)),
        lod_offset_(static_cast<float>(double{options.lod_bias} - kBoxPyramidLodOffset)) {}

  [[gnu::always_inline]] Rgba<Arch> nearest(Floats s, Floats t) const {
    const Floats u = reduce_coordinate<Arch>(s, options_.wrap_s) * level0_.widthf;
    const Floats v = reduce_coordinate<Arch>(t, options_.wrap_t) * level0_.heightf;
    const Ints x =
        wrap_index<Arch, 1>(xsimd::to_int(xsimd::floor(u)), level0_.width, options_.wrap_s);
    const Ints y =
        wrap_index<Arch, 1>(xsimd::to_int(xsimd::floor(v)), level0_.height, options_.wrap_t);
    return fetch<Arch>(texture_, level0_, x, y);
  }

  [[gnu::always_inline]] Rgba<Arch> bilinear(const LevelLanes<Arch>& level, Floats s,
                                             Floats t) const {
    const Floats sr = reduce_coordinate<Arch>(s, options_.wrap_s);
    const Floats tr = reduce_coordinate<Arch>(t, options_.wrap_t);
    if (texture_.format == TexelFormat::rgba8) {
      Sums sums(texture_);
      add_bilinear(sums, level, sr, tr, Floats(1.0f));
      return sums.total();
    }
    const Floats u = sr * level.widthf - Floats(0.5f);
    const Floats v = tr * level.heightf - Floats(0.5f);
    const Floats u0 = xsimd::floor(u), v0 = xsimd::floor(v);
    const Floats fu = u - u0, fv = v - v0;
    const Ints x0 = xsimd::to_int(u0), y0 = xsimd::to_int(v0);
    const Ints xs[2] = {wrap_index<Arch, 1>(x0, level.width, options_.wrap_s),
                        wrap_index<Arch, 1>(x0 + Ints(1), level.width, options_.wrap_s)};
    const Ints ys[2] = {wrap_index<Arch, 1>(y0, level.height, options_.wrap_t),
                        wrap_index<Arch, 1>(y0 + Ints(1), level.height, options_.wrap_t)};
    const Rgba<Arch> top =
        weighted_sum<Arch>(fetch<Arch>(texture_, level, xs[0], ys[0]), Floats(1.0f) - fu,
                           fetch<Arch>(texture_, level, xs[1], ys[0]), fu);
    const Rgba<Arch> bottom =
        weighted_sum<Arch>(fetch<Arch>(texture_, level, xs[0], ys[1]), Floats(1.0f) - fu,
                           fetch<Arch>(texture_, level, xs[1], ys[1]), fu);
    return weighted_sum<Arch>(top, Floats(1.0f) - fv, bottom, fv);
  }

  [[gnu::always_inline]] Rgba<Arch> bilinear0(Floats s, Floats t) const {
    return bilinear(level0_, s, t);
  }

  // Catmull-Rom or cubic B-spline over 4x4 texels of level 0.
  Rgba<Arch> bicubic(Floats s, Floats t, bool catmull_rom) const {
    const Floats u = reduce_coordinate<Arch>(s, options_.wrap_s) * level0_.widthf - Floats(0.5f);
    const Floats v = reduce_coordinate<Arch>(t, options_.wrap_t) * level0_.heightf - Floats(0.5f);
    const Floats u1 = xsimd::floor(u), v1 = xsimd::floor(v);
    Floats wx[4], wy[4];
    cubic_weights(u - u1, catmull_rom, wx);
    cubic_weights(v - v1, catmull_rom, wy);
    const Ints x1 = xsimd::to_int(u1), y1 = xsimd::to_int(v1);
    Ints xs[4];
    for (int i = 0; i < 4; ++i)
      xs[i] = wrap_index<Arch>(x1 + Ints(i - 1), level0_.width, options_.wrap_s);
    Rgba<Arch> sum = zero_rgba<Arch>();
    for (int j = 0; j < 4; ++j) {
      const Ints y = wrap_index<Arch>(y1 + Ints(j - 1), level0_.height, options_.wrap_t);
      Rgba<Arch> row = zero_rgba<Arch>();
      for (int i = 0; i < 4; ++i)
        accumulate<Arch>(row, fetch<Arch>(texture_, level0_, xs[i], y), wx[i]);
      accumulate<Arch>(sum, row, wy[j]);
    }
    return sum;
  }

  // lambda = log2(rho) - log2(3) / 2 + bias (level_of_detail.hpp); +inf where a derivative is
  // not finite.
  [[gnu::always_inline]] Floats level_of_detail(const QueryLanes<Arch>& q) const {
    const Floats ux = q.dsdx * Floats(texture_.width), vx = q.dtdx * Floats(texture_.height);
    const Floats uy = q.dsdy * Floats(texture_.width), vy = q.dtdy * Floats(texture_.height);
    Floats lambda;
    if (options_.lod == LodFormula::exact) {
      // log2 of the squared length, halved: no square root.
      const Floats rho2 = xsimd::max(ux * ux + vx * vx, uy * uy + vy * vy);
      lambda = Floats(0.5f) * fast_log2<Arch>(rho2);
    } else {
      const Floats rho = xsimd::max(xsimd::max(xsimd::abs(ux), xsimd::abs(vx)),
                                    xsimd::max(xsimd::abs(uy), xsimd::abs(vy)));
      lambda = fast_log2<Arch>(rho);
    }
    return lambda + Floats(lod_offset_);
  }

  // lambda clamped to [0, levels - 1]; NaN is not expected (level_of_detail() gives +inf).
  [[gnu::always_inline]] Floats clamp_lambda(Floats lambda) const {
    return xsimd::min(xsimd::max(lambda, Floats(0.0f)),
                      Floats(static_cast<float>(texture_.mips.count - 1)));
  }

  [[gnu::always_inline]] Rgba<Arch> mip_nearest(Floats s, Floats t, Floats lambda) const {
    const Floats level = xsimd::ceil(clamp_lambda(lambda) - Floats(0.5f));
    return bilinear(
        level_lanes<Arch>(texture_.mips, xsimd::to_int(xsimd::max(level, Floats(0.0f)))), s, t);
  }

  [[gnu::always_inline]] Rgba<Arch> trilinear(Floats s, Floats t, Floats lambda) const {
    const LevelPair levels = level_pair(lambda);
    if (texture_.format == TexelFormat::rgba8) {
      Sums sums(texture_);
      add_trilinear(sums, levels, reduce_coordinate<Arch>(s, options_.wrap_s),
                    reduce_coordinate<Arch>(t, options_.wrap_t), Floats(1.0f));
      return sums.total();
    }
    const Rgba<Arch> fine = bilinear(levels.fine, s, t);
    if (!levels.blends) return fine;
    return weighted_sum<Arch>(fine, Floats(1.0f) - levels.f, bilinear(levels.coarse, s, t),
                              levels.f);
  }

  Rgba<Arch> supersample(const QueryLanes<Arch>& q) const {
    const int n = options_.supersample_taps;
    Rgba<Arch> sum = zero_rgba<Arch>();
    const Floats weight(1.0f / static_cast<float>(n * n));
    for (int j = 0; j < n; ++j) {
      const Floats b((static_cast<float>(j) + 0.5f) / static_cast<float>(n) - 0.5f);
      for (int i = 0; i < n; ++i) {
        const Floats a((static_cast<float>(i) + 0.5f) / static_cast<float>(n) - 0.5f);
        const Floats s = q.s + a * q.dsdx + b * q.dsdy;
        const Floats t = q.t + a * q.dtdx + b * q.dtdy;
        accumulate<Arch>(sum, bilinear0(s, t), weight);
      }
    }
    return sum;
  }

  Rgba<Arch> anisotropic(const QueryLanes<Arch>& q) const {
    const Floats ux = q.dsdx * Floats(texture_.width), vx = q.dtdx * Floats(texture_.height);
    const Floats uy = q.dsdy * Floats(texture_.width), vy = q.dtdy * Floats(texture_.height);
    Floats px, py;
    if (options_.lod == LodFormula::exact) {
      px = xsimd::sqrt(ux * ux + vx * vx);
      py = xsimd::sqrt(uy * uy + vy * vy);
    } else {
      px = xsimd::max(xsimd::abs(ux), xsimd::abs(vx));
      py = xsimd::max(xsimd::abs(uy), xsimd::abs(vy));
    }
    const Floats longest = xsimd::max(px, py), shortest = xsimd::min(px, py);
    const Floats limit(static_cast<float>(options_.max_anisotropy));
    // ceil(Pmax / Pmin) clamped to the limit; Pmin = 0 gives the limit, Pmax = 0 one probe.
    Floats probes =
        xsimd::select(shortest * limit > longest, xsimd::ceil(longest / shortest), limit);
    probes = xsimd::select(longest > Floats(0.0f), probes, Floats(1.0f));
    const Floats lambda = fast_log2<Arch>(longest / probes) + Floats(options_.lod_bias);
    const auto x_major = px >= py;
    const Floats ds = xsimd::select(x_major, q.dsdx, q.dsdy);
    const Floats dt = xsimd::select(x_major, q.dtdx, q.dtdy);
    // Lanes run the largest probe count of the batch; probes past a lane's own count weigh 0.
    alignas(64) float counts[Floats::size];
    probes.store_aligned(counts);
    float most = 1.0f;
    for (float c : counts)
      most = c > most ? c : most;
    const Floats inverse = Floats(1.0f) / probes;
    const LevelPair levels = level_pair(lambda);  // every probe's
    const bool pairs = texture_.format == TexelFormat::rgba8;
    Sums pair_sums(texture_);
    Rgba<Arch> sum = zero_rgba<Arch>();
    for (int k = 0; k < static_cast<int>(most); ++k) {
      const Floats kf(static_cast<float>(k));
      const Floats offset = (kf + Floats(0.5f)) * inverse - Floats(0.5f);
      const auto used = kf < probes;
      const Floats s = q.s + offset * ds, t = q.t + offset * dt;
      if (pairs) {
        // Each probe at full weight, the mean taken once: fixed-point weights then round
        // relative to 1, not to 1 / probes.
        add_trilinear(pair_sums, levels, reduce_coordinate<Arch>(s, options_.wrap_s),
                      reduce_coordinate<Arch>(t, options_.wrap_t),
                      xsimd::select(used, Floats(1.0f), Floats(0.0f)));
      } else {
        accumulate<Arch>(sum, trilinear(s, t, lambda), xsimd::select(used, inverse, Floats(0.0f)));
      }
    }
    if (!pairs) return sum;
    Rgba<Arch> mean = pair_sums.total();
    for (int k = 0; k < 4; ++k)
      mean.c[k] = mean.c[k] * inverse;
    return mean;
  }

  Rgba<Arch> ripmap(const QueryLanes<Arch>& q) const {
    const Floats ux = q.dsdx * Floats(texture_.width), vx = q.dtdx * Floats(texture_.height);
    const Floats uy = q.dsdy * Floats(texture_.width), vy = q.dtdy * Floats(texture_.height);
    const Floats bias(options_.lod_bias);
    const Floats ls = fast_log2<Arch>(xsimd::max(xsimd::abs(ux), xsimd::abs(uy))) + bias;
    const Floats lt = fast_log2<Arch>(xsimd::max(xsimd::abs(vx), xsimd::abs(vy))) + bias;
    const Floats cs = xsimd::min(xsimd::max(ls, Floats(0.0f)),
                                 Floats(static_cast<float>(texture_.rip_columns - 1)));
    const Floats ct =
        xsimd::min(xsimd::max(lt, Floats(0.0f)), Floats(static_cast<float>(texture_.rip_rows - 1)));
    const Floats i0f = xsimd::floor(cs), j0f = xsimd::floor(ct);
    const Floats fs = cs - i0f, ft = ct - j0f;
    const Ints i0 = xsimd::to_int(i0f), j0 = xsimd::to_int(j0f);
    const Ints i1 = xsimd::min(i0 + Ints(1), Ints(texture_.rip_columns - 1));
    const Ints j1 = xsimd::min(j0 + Ints(1), Ints(texture_.rip_rows - 1));
    const Ints columns(texture_.rip_columns);
    const auto rip = [&](Ints i, Ints j) {
      return bilinear(level_lanes<Arch>(texture_.rips, j * columns + i), q.s, q.t);
    };
    const Rgba<Arch> top = weighted_sum<Arch>(rip(i0, j0), Floats(1.0f) - fs, rip(i1, j0), fs);
    const Rgba<Arch> bottom = weighted_sum<Arch>(rip(i0, j1), Floats(1.0f) - fs, rip(i1, j1), fs);
    return weighted_sum<Arch>(top, Floats(1.0f) - ft, bottom, ft);
  }

 private:
  // sums += weight * the bilinear filter of `level` at coordinates already reduced by the wrap
  // modes, for 8-bit texels: each tap row's two texels by one 64-bit load per lane where no lane's
  // row wraps between them (the usual case: a row wraps at one texel in w), else by a load per
  // texel; the same sums either way.
  [[gnu::always_inline]] void add_bilinear(Sums& sums, const LevelLanes<Arch>& level, Floats sr,
                                           Floats tr, Floats weight) const {
    const Floats u = sr * level.widthf - Floats(0.5f);
    const Floats v = tr * level.heightf - Floats(0.5f);
    const Floats u0 = xsimd::floor(u), v0 = xsimd::floor(v);
    const Floats fu = u - u0, fv = v - v0;
    const Ints x0 = xsimd::to_int(u0), y0 = xsimd::to_int(v0);
    // Named copies, not structured bindings: lambdas may capture the latter only from C++20
    // compilers that implement P1091 (clang 16 on), and the fuzz build uses clang 14.
    const auto columns = wrap_tap_pair<Arch>(x0, level.width, options_.wrap_s);
    const auto [ya, yb] = wrap_tap_pair<Arch>(y0, level.height, options_.wrap_t);
    const Ints xa = columns.first, xb = columns.second;
    const Floats gu = Floats(1.0f) - fu;
    const bool adjacent = xsimd::all(xb == xa + Ints(1));
    const auto add_row = [&](Ints row, Floats row_weight) EDGEWISE_INLINE_LAMBDA {
      sums.add(row + xa, row + xb, adjacent, gu * row_weight, fu * row_weight);
    };
    add_row(level.start + ya * level.width, (Floats(1.0f) - fv) * weight);
    add_row(level.start + yb * level.width, fv * weight);
  }

  // The two levels trilinear filtering blends at lambda, and the coarser one's weight f.
  struct LevelPair {
    LevelLanes<Arch> fine, coarse;
    Floats f;
    bool blends;  // some lane weighs the coarser level
  };
  [[gnu::always_inline]] LevelPair level_pair(Floats lambda) const {
    const Floats clamped = clamp_lambda(lambda);
    const Floats floor_level = xsimd::floor(clamped);
    const Ints l0 = xsimd::to_int(floor_level);
    LevelPair p;
    p.f = clamped - floor_level;
    p.fine = level_lanes<Arch>(texture_.mips, l0);
    // Where every lane magnifies or sits at the last level, the second level weighs nothing.
    p.blends = !xsimd::all(p.f == Floats(0.0f));
    p.coarse = p.blends ? level_lanes<Arch>(texture_.mips,
                                            xsimd::min(l0 + Ints(1), Ints(texture_.mips.count - 1)))
                        : p.fine;
    return p;
  }

  // sums += weight * the trilinear filter at reduced coordinates, for 8-bit texels.
  [[gnu::always_inline]] void add_trilinear(Sums& sums, const LevelPair& levels, Floats sr,
                                            Floats tr, Floats weight) const {
    add_bilinear(sums, levels.fine, sr, tr, weight * (Floats(1.0f) - levels.f));
    if (levels.blends) add_bilinear(sums, levels.coarse, sr, tr, weight * levels.f);
  }

  static void cubic_weights(Floats f, bool catmull_rom, Floats w[4]) {
    const Floats f2 = f * f, f3 = f2 * f;
    if (catmull_rom) {
      w[0] = Floats(0.5f) * (Floats(2.0f) * f2 - f3 - f);
      w[1] = Floats(0.5f) * (Floats(3.0f) * f3 - Floats(5.0f) * f2 + Floats(2.0f));
      w[2] = Floats(0.5f) * (Floats(4.0f) * f2 + f - Floats(3.0f) * f3);
      w[3] = Floats(0.5f) * (f3 - f2);
    } else {
      const Floats g = Floats(1.0f) - f;
      const Floats sixth(1.0f / 6.0f);
      w[0] = g * g * g * sixth;
      w[1] = (Floats(3.0f) * f3 - Floats(6.0f) * f2 + Floats(4.0f)) * sixth;
      w[2] = (Floats(3.0f) * (f2 - f3 + f) + Floats(1.0f)) * sixth;
      w[3] = f3 * sixth;
    }
  }

  const detail::TextureDescription& texture_;
  const SamplerOptions& options_;
  LevelLanes<Arch> level0_;
  float lod_offset_;  // lod_bias - log2(3) / 2 (level_of_detail.hpp), rounded once, per call
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
