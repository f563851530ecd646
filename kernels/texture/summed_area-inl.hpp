// The summed-area-table box filter (sample.hpp, summed_area), in double precision as the table
// is: each query's box, moved exactly by whole periods, becomes at most eight weighted table
// entries per axis (kernels/texture/sample_reference.cpp derives the same terms), and the 64
// products are summed with all four channels of an entry in one double batch (two on SSE and
// NEON). The box's corners are exact in double, so the result matches the reference up to the
// order of the double sums and the final rounding to float.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "sample_kernels.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
class SummedAreaBox {
 public:
  using Doubles = xsimd::batch<double, Arch>;
  static constexpr std::size_t kParts = 4 / Doubles::size;  // batches per RGBA entry

  SummedAreaBox(const detail::TextureDescription& texture, const SamplerOptions& options)
      : texture_(texture), options_(options) {}

  // The box average at one query (finite s, t and derivatives), linear RGBA.
  void average(double s, double t, double dsdx, double dtdx, double dsdy, double dtdy,
               float out[4]) const {
    const SummedAreaTable& table = *texture_.summed_area_table;
    const double width = table.width, height = table.height;
    const double hu = half_extent((std::fabs(dsdx) + std::fabs(dsdy)) * width);
    const double hv = half_extent((std::fabs(dtdx) + std::fabs(dtdy)) * height);
    const double cu = centre(s, table.width, hu, options_.wrap_s);
    const double cv = centre(t, table.height, hv, options_.wrap_t);
    Terms xs, ys;
    add_prefix(cu + hu, table.width, options_.wrap_s, 1.0, xs);
    add_prefix(cu - hu, table.width, options_.wrap_s, -1.0, xs);
    add_prefix(cv + hv, table.height, options_.wrap_t, 1.0, ys);
    add_prefix(cv - hv, table.height, options_.wrap_t, -1.0, ys);
    const std::size_t stride = static_cast<std::size_t>(table.width) + 1;
    Doubles sum[kParts];
    for (Doubles& part : sum)
      part = Doubles(0.0);
    for (int j = 0; j < kTerms; ++j) {
      const double* row = table.sums.data() + 4 * static_cast<std::size_t>(ys.index[j]) * stride;
      Doubles row_sum[kParts];
      for (Doubles& part : row_sum)
        part = Doubles(0.0);
      for (int i = 0; i < kTerms; ++i) {
        const double* entry = row + 4 * static_cast<std::size_t>(xs.index[i]);
        for (std::size_t p = 0; p < kParts; ++p) {
          row_sum[p] = xsimd::fma(Doubles(xs.weight[i]),
                                  Doubles::load_unaligned(entry + p * Doubles::size), row_sum[p]);
        }
      }
      for (std::size_t p = 0; p < kParts; ++p)
        sum[p] = xsimd::fma(Doubles(ys.weight[j]), row_sum[p], sum[p]);
    }
    const double scale = table.scale / (4.0 * hu * hv);
    alignas(64) double rgba[4];
    for (std::size_t p = 0; p < kParts; ++p)
      (sum[p] * Doubles(scale)).store_aligned(rgba + p * Doubles::size);
    for (int k = 0; k < 4; ++k)
      out[k] = static_cast<float>(rgba[k]);
  }

 private:
  // Two lattice points per corner, two terms per lattice point (weight 0 where one suffices),
  // two corners per axis.
  static constexpr int kTerms = 8;
  struct Terms {
    std::int64_t index[kTerms] = {};
    double weight[kTerms] = {};
    int count = 0;
    void add(std::int64_t i, double w) {
      index[count] = i;
      weight[count] = w;
      ++count;
    }
  };

  static double half_extent(double footprint) {
    const double half = 0.5 * footprint;
    return half < 0.5 ? 0.5 : (half > 0x1p20 ? 0x1p20 : half);
  }

  // The box centre in level-0 texels, moved by whole periods (repeat, mirror) or, for clamp, by
  // whole texels to at most ceil(half extent + 1) beyond the border: the box then covers the
  // same values. Exact: s has 24 significant bits and the size at most 15.
  static double centre(double s, std::int64_t n, double half, WrapMode mode) {
    const double size = static_cast<double>(n);
    switch (mode) {
      case WrapMode::repeat:
        return (s - std::floor(s)) * size;
      case WrapMode::mirror:
        return (s - 2.0 * std::floor(0.5 * s)) * size;
      case WrapMode::clamp_to_edge:
        break;
    }
    const double x = s * size;
    const double bound = size + std::ceil(half + 1.0);
    const double within = (s - std::floor(s)) * size;
    const double fraction = within - std::floor(within);
    if (x > bound) return bound + fraction;
    if (x < -bound) return -bound - 1.0 + fraction;
    return x;
  }

  static std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    const std::int64_t q = a / b;
    return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
  }

  // S_ext at the integer X, times w, as two table entries on this axis.
  static void add_lattice(std::int64_t X, std::int64_t n, WrapMode mode, double w, Terms& out) {
    switch (mode) {
      case WrapMode::repeat: {
        const std::int64_t k = floor_div(X, n);
        out.add(n, w * static_cast<double>(k));
        out.add(X - k * n, w);
        return;
      }
      case WrapMode::mirror: {
        const std::int64_t k = floor_div(X, 2 * n);
        const std::int64_t r = X - 2 * k * n;
        if (r <= n) {
          out.add(n, 2.0 * w * static_cast<double>(k));
          out.add(r, w);
        } else {
          out.add(n, 2.0 * w * static_cast<double>(k + 1));
          out.add(2 * n - r, -w);
        }
        return;
      }
      case WrapMode::clamp_to_edge:
        break;
    }
    if (X < 0) {  // column 0 continues to the left; S(0) = 0
      out.add(1, w * static_cast<double>(X));
      out.add(0, -w * static_cast<double>(X));
    } else if (X > n) {  // column n - 1 continues to the right
      const double beyond = static_cast<double>(X - n);
      out.add(n, w * (1.0 + beyond));
      out.add(n - 1, -w * beyond);
    } else {
      out.add(X, w);
      out.add(0, 0.0);
    }
  }

  // S_ext at a real x: linear between its lattice neighbours.
  static void add_prefix(double x, std::int64_t n, WrapMode mode, double w, Terms& out) {
    const double X = std::floor(x);
    const double f = x - X;
    const auto lattice = static_cast<std::int64_t>(X);
    add_lattice(lattice, n, mode, w * (1.0 - f), out);
    add_lattice(lattice + 1, n, mode, w * f, out);
  }

  const detail::TextureDescription& texture_;
  const SamplerOptions& options_;
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
