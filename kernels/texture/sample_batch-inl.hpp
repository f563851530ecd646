// The sampling entry point for one ISA: queries in batches of lanes (records transposed to one
// batch per field), the filter, the defined results for bad input, results transposed back.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "sample_kernels.hpp"
#include "ewa_filter-inl.hpp"
#include "fixed_taps-inl.hpp"
#include "../simd/interleave-inl.hpp"
#include "../simd/lane_arch-inl.hpp"
#include "summed_area-inl.hpp"
#include "texture_filters-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

namespace sample_detail {

// The filters made of bilinear taps in float run on the ISA's full width (16 lanes on AVX-512:
// half the instructions per query of 8 lanes, docs/design/textures.md); the others, and the
// fixed-point taps, on 8 lanes at most.
using Arch = RowArch<EDGEWISE_ARCH>;
using TapArch = WideArch<Arch>;

// Where queries come from and results go: records (TextureQuery, Vec4) or one array per field
// (QueryFields, ResultChannels). load(first, n) returns queries [first, first + n) as batches,
// lanes past n repeating the last query; store(rgba, first, n) writes n results.
template <class Arch>
struct RecordQueries {
  using Floats = xsimd::batch<float, Arch>;
  static constexpr std::size_t kLanes = Floats::size;
  const TextureQuery* queries;

  [[gnu::always_inline]] QueryLanes<Arch> load(std::size_t first, std::size_t count) const {
    static_assert(sizeof(TextureQuery) == 6 * sizeof(float));
    const float* fields = &queries[first].s;
    if (count == kLanes) {  // a whole batch: transposed in registers
      Floats lanes[6];
      load_records6<Arch>(fields, lanes);
      return {lanes[0], lanes[1], lanes[2], lanes[3], lanes[4], lanes[5]};
    }
    alignas(64) float lanes[6][kLanes];
    for (std::size_t l = 0; l < kLanes; ++l) {
      const TextureQuery& q = queries[first + (l < count ? l : count - 1)];
      const float values[6] = {q.s, q.t, q.dsdx, q.dtdx, q.dsdy, q.dtdy};
      for (int f = 0; f < 6; ++f)
        lanes[f][l] = values[f];
    }
    return {Floats::load_aligned(lanes[0]), Floats::load_aligned(lanes[1]),
            Floats::load_aligned(lanes[2]), Floats::load_aligned(lanes[3]),
            Floats::load_aligned(lanes[4]), Floats::load_aligned(lanes[5])};
  }
};

template <class Arch>
struct RecordResults {
  static constexpr std::size_t kLanes = xsimd::batch<float, Arch>::size;
  Vec4* out;

  [[gnu::always_inline]] void store(const Rgba<Arch>& rgba, std::size_t first,
                                    std::size_t count) const {
    static_assert(sizeof(Vec4) == 4 * sizeof(float));
    if (count == kLanes) {
      store_interleaved<Arch>(rgba.c, &out[first].x);
      return;
    }
    alignas(64) float channels[4][kLanes];
    for (int k = 0; k < 4; ++k)
      rgba.c[k].store_aligned(channels[k]);
    for (std::size_t l = 0; l < count; ++l)
      out[first + l] = {channels[0][l], channels[1][l], channels[2][l], channels[3][l]};
  }
};

// Lanes [0, count) of `field + first`, the rest repeating the last.
template <class Arch>
[[gnu::always_inline]] inline xsimd::batch<float, Arch> load_field(const float* field,
                                                                   std::size_t first,
                                                                   std::size_t count) {
  using Floats = xsimd::batch<float, Arch>;
  constexpr std::size_t kLanes = Floats::size;
  if (count == kLanes) return Floats::load_unaligned(field + first);
  alignas(64) float lanes[kLanes];
  for (std::size_t l = 0; l < kLanes; ++l)
    lanes[l] = field[first + (l < count ? l : count - 1)];
  return Floats::load_aligned(lanes);
}

template <class Arch>
struct FieldQueries {
  detail::QueryFields fields;

  [[gnu::always_inline]] QueryLanes<Arch> load(std::size_t first, std::size_t count) const {
    return {
        load_field<Arch>(fields.s, first, count),    load_field<Arch>(fields.t, first, count),
        load_field<Arch>(fields.dsdx, first, count), load_field<Arch>(fields.dtdx, first, count),
        load_field<Arch>(fields.dsdy, first, count), load_field<Arch>(fields.dtdy, first, count)};
  }
};

template <class Arch>
struct ChannelResults {
  static constexpr std::size_t kLanes = xsimd::batch<float, Arch>::size;
  detail::ResultChannels channels;

  [[gnu::always_inline]] void store(const Rgba<Arch>& rgba, std::size_t first,
                                    std::size_t count) const {
    if (count == kLanes) {
      for (int k = 0; k < 4; ++k)
        rgba.c[k].store_unaligned(channels.c[k] + first);
      return;
    }
    for (int k = 0; k < 4; ++k) {
      alignas(64) float lanes[kLanes];
      rgba.c[k].store_aligned(lanes);
      for (std::size_t l = 0; l < count; ++l)
        channels.c[k][first + l] = lanes[l];
    }
  }
};

// Every query through `filter` (one loop per filter, the filter inlined), with the defined
// results for bad input: lanes with a non-finite position or (when the filter reads them) a
// non-finite derivative are computed from harmless values, so every index stays in range, and
// then replaced by (0, 0, 0, 0) or the coarsest texel.
// kStoredUnits: the filter returns the texture's stored units (texel_fetch-inl.hpp), scaled to
// linear here; otherwise it returns linear values.
template <bool kReadsDerivatives, bool kStoredUnits = true, class Arch,
          template <class> class Queries, template <class> class Results, class Filter>
[[gnu::always_inline]] inline void sample_all(const detail::TextureDescription& texture,
                                              const Queries<Arch>& queries, std::size_t count,
                                              const Results<Arch>& out, Filter filter) {
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  constexpr std::size_t kLanes = Floats::size;
  const detail::LevelTable& mips = texture.mips;
  const Rgba<Arch> coarsest = fetch_texels<Arch>(texture, Ints(mips.start[mips.count - 1]));
  const Floats largest(std::numeric_limits<float>::max());
  Floats scale[4];
  Floats coarsest_linear[4];
  for (int k = 0; k < 4; ++k) {
    scale[k] = Floats(texture.channel_scale[k]);
    coarsest_linear[k] = coarsest.c[k] * scale[k];
  }
  for (std::size_t first = 0; first < count; first += kLanes) {
    const std::size_t n = count - first < kLanes ? count - first : kLanes;
    QueryLanes<Arch> q = queries.load(first, n);
    const auto position_ok = (xsimd::abs(q.s) <= largest) & (xsimd::abs(q.t) <= largest);
    auto derivatives_ok = position_ok;
    Floats* derivatives[4] = {&q.dsdx, &q.dtdx, &q.dsdy, &q.dtdy};
    if constexpr (kReadsDerivatives) {
      for (Floats* d : derivatives)
        derivatives_ok = derivatives_ok & (xsimd::abs(*d) <= largest);
    }
    // The usual batch has no bad lane: it skips the replacements (a branch per batch).
    const bool all_ok = xsimd::all(derivatives_ok);
    if (!all_ok) {
      q.s = xsimd::select(position_ok, q.s, Floats(0.0f));
      q.t = xsimd::select(position_ok, q.t, Floats(0.0f));
      if constexpr (kReadsDerivatives) {
        for (Floats* d : derivatives)
          *d = xsimd::select(derivatives_ok, *d, Floats(0.0f));
      }
    }
    Rgba<Arch> rgba = filter(q);
    for (int k = 0; k < 4; ++k) {
      if constexpr (kStoredUnits) rgba.c[k] = rgba.c[k] * scale[k];
    }
    if (!all_ok) {
      for (int k = 0; k < 4; ++k) {
        if constexpr (kReadsDerivatives) {
          rgba.c[k] = xsimd::select(derivatives_ok, rgba.c[k], coarsest_linear[k]);
        }
        rgba.c[k] = xsimd::select(position_ok, rgba.c[k], Floats(0.0f));
      }
    }
    out.store(rgba, first, n);
  }
}

// The summed-area box per lane: its table is double and its terms differ per query, so lanes
// are taken one at a time, each query's four channels summed together in double batches.
inline Rgba<Arch> summed_area_lanes(const SummedAreaBox<Arch>& box, const QueryLanes<Arch>& q) {
  using Floats = xsimd::batch<float, Arch>;
  constexpr std::size_t kLanes = Floats::size;
  alignas(64) float fields[6][kLanes];
  const Floats* values[6] = {&q.s, &q.t, &q.dsdx, &q.dtdx, &q.dsdy, &q.dtdy};
  for (int f = 0; f < 6; ++f)
    values[f]->store_aligned(fields[f]);
  alignas(64) float channels[4][kLanes];
  for (std::size_t l = 0; l < kLanes; ++l) {
    float rgba[4];
    box.average(fields[0][l], fields[1][l], fields[2][l], fields[3][l], fields[4][l], fields[5][l],
                rgba);
    for (int k = 0; k < 4; ++k)
      channels[k][l] = rgba[k];
  }
  Rgba<Arch> out;
  for (int k = 0; k < 4; ++k)
    out.c[k] = Floats::load_aligned(channels[k]);
  return out;
}

// Every query through `options`' filter, one made of bilinear taps, which `Sums` weighs and sums,
// in batches of Sums' lanes.
template <template <class> class Sums, class Arch, template <class> class Queries,
          template <class> class Results>
void sample_taps(const detail::TextureDescription& texture, const SamplerOptions& options,
                 const Queries<Arch>& queries, std::size_t count, const Results<Arch>& out) {
  const TextureFilters<Arch, Sums<Arch>> f(texture, options);
  using Q = QueryLanes<Arch>;
  switch (options.filter) {
    case TextureFilter::bilinear:
      return sample_all<false>(texture, queries, count, out,
                               [&](const Q& q)
                                   EDGEWISE_INLINE_LAMBDA { return f.bilinear0(q.s, q.t); });
    case TextureFilter::mip_nearest:
      return sample_all<true>(texture, queries, count, out, [&](const Q& q) EDGEWISE_INLINE_LAMBDA {
        return f.mip_nearest(q.s, q.t, f.level_of_detail(q));
      });
    case TextureFilter::trilinear:
      return sample_all<true>(texture, queries, count, out, [&](const Q& q) EDGEWISE_INLINE_LAMBDA {
        return f.trilinear(q.s, q.t, f.level_of_detail(q));
      });
    case TextureFilter::supersample:
      return sample_all<true>(texture, queries, count, out,
                              [&](const Q& q) EDGEWISE_INLINE_LAMBDA { return f.supersample(q); });
    case TextureFilter::ripmap:
      return sample_all<true>(texture, queries, count, out,
                              [&](const Q& q) EDGEWISE_INLINE_LAMBDA { return f.ripmap(q); });
    case TextureFilter::anisotropic:
      return sample_all<true>(texture, queries, count, out,
                              [&](const Q& q) EDGEWISE_INLINE_LAMBDA { return f.anisotropic(q); });
    default:
      return;  // not reached: the callers check reads_bilinear_taps()
  }
}

// Every query through the filter `options` names, in the precision they carry.
template <template <class> class Queries, template <class> class Results, class Source,
          class Target>
void sample_with(const detail::TextureDescription& texture, const SamplerOptions& options,
                 const Source& source, std::size_t count, const Target& target) {
  const Queries<Arch> queries{source};
  const Results<Arch> out{target};
  if (reads_bilinear_taps(options.filter)) {
    if (detail::fixed_point_taps(texture, options)) {
      return sample_taps<FixedTapSums>(texture, options, queries, count, out);
    }
    return sample_taps<FloatTapSums>(texture, options, Queries<TapArch>{source}, count,
                                     Results<TapArch>{target});
  }
  const TextureFilters<Arch> f(texture, options);
  using Q = QueryLanes<Arch>;
  switch (options.filter) {
    case TextureFilter::nearest:
      return sample_all<false>(texture, queries, count, out,
                               [&](const Q& q)
                                   EDGEWISE_INLINE_LAMBDA { return f.nearest(q.s, q.t); });
    case TextureFilter::bicubic_catmull_rom:
      return sample_all<false>(texture, queries, count, out,
                               [&](const Q& q)
                                   EDGEWISE_INLINE_LAMBDA { return f.bicubic(q.s, q.t, true); });
    case TextureFilter::bicubic_bspline:
      return sample_all<false>(texture, queries, count, out,
                               [&](const Q& q)
                                   EDGEWISE_INLINE_LAMBDA { return f.bicubic(q.s, q.t, false); });
    case TextureFilter::ewa: {
      const EwaFilter<Arch> ewa(f, texture, options);
      return sample_all<true>(texture, queries, count, out,
                              [&](const Q& q) EDGEWISE_INLINE_LAMBDA { return ewa.filter(q); });
    }
    case TextureFilter::summed_area: {
      const SummedAreaBox<Arch> box(texture, options);
      return sample_all<true, false>(
          texture, queries, count, out,
          [&](const Q& q) EDGEWISE_INLINE_LAMBDA { return summed_area_lanes(box, q); });
    }
    default:
      return;  // the filters made of taps, above
  }
}

}  // namespace sample_detail

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
