// resolve(): the filtered mean of the samples around each output pixel (resolve.hpp).
//
// The source's samples repeat with the output pixels: the output pixel at (x, y) sees source
// pixel (f x + i, f y + j), sample k, at the same distance for every (x, y). So the filter's
// taps, each (i, j, k) with its normalized weight, are found once per call, and the kernels
// (resolve_call.hpp) sum over them, bands of output rows on the call's threads.
#include "edgewise/resolve.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "edgewise/multisample.hpp"
#include "../core/kernel_table.hpp"
#include "../core/parallel.hpp"
#include "resolve_call.hpp"

namespace edgewise {
namespace {

using detail::KernelTable;
using detail::ResolveTap;

// The taps of every output pixel, weights summing to 1.
std::vector<ResolveTap> filter_taps(ResolveFilter filter, int factor,
                                    std::span<const SampleOffset> pattern) {
  const double radius = filter_radius(filter);
  // Source pixels whose samples may lie within the radius: their centres within radius + 1/2
  // output pixels (a sample is at most half a source pixel from its centre).
  const auto reach = static_cast<std::int32_t>(std::ceil((radius + 0.5) * factor)) + 1;
  std::vector<ResolveTap> taps;
  double total = 0.0;
  for (std::int32_t j = -reach; j < factor + reach; ++j) {
    for (std::int32_t i = -reach; i < factor + reach; ++i) {
      for (std::size_t k = 0; k < pattern.size(); ++k) {
        const double dx = (i + 0.5 + pattern[k].x / 16.0) / factor - 0.5;
        const double dy = (j + 0.5 + pattern[k].y / 16.0) / factor - 0.5;
        const double weight = filter_weight(filter, dx) * filter_weight(filter, dy);
        if (weight == 0.0) continue;
        taps.push_back({i, j, static_cast<std::int32_t>(k), static_cast<float>(weight)});
        total += weight;
      }
    }
  }
  for (ResolveTap& tap : taps)
    tap.weight = static_cast<float>(tap.weight / total);
  return taps;
}

// The box filter with supersampling: every output pixel is the plain mean of the f x f x samples
// samples of its own source block (each standard offset lies inside its pixel: weights equal,
// none outside), summed exactly in integers, two channels per 64-bit word (each sum at most
// 255 f^2 samples, far below 2^32 for any target that fits in memory), and rounded to nearest.
// Output rows [first_row, last_row).
void resolve_box_blocks(const detail::ResolveCall& call, std::int32_t first_row,
                        std::int32_t last_row) {
  const std::int32_t f = call.factor;
  const auto count = static_cast<std::uint64_t>(f) * static_cast<std::uint64_t>(f) *
                     static_cast<std::uint64_t>(call.samples);
  const float scale = 1.0f / (255.0f * static_cast<float>(count));
  const double inverse = 1.0 / static_cast<double>(count);
  for (std::int32_t y = first_row; y < last_row; ++y) {
    for (std::int32_t x = 0; x < call.width; ++x) {
      // Channels R and B in the low and high 32 bits of `even`, G and A of `odd`.
      std::uint64_t even = 0, odd = 0;
      for (std::int32_t j = 0; j < f; ++j) {
        for (std::int32_t i = 0; i < f; ++i) {
          for (std::int32_t k = 0; k < call.samples; ++k) {
            const std::uint64_t c = call.color(x * f + i, y * f + j, k);
            even += (c & 0xFF) | (c & 0xFF0000) << 16;
            odd += (c >> 8 & 0xFF) | (c >> 24 & 0xFF) << 32;
          }
        }
      }
      const std::uint64_t sums[4] = {even & 0xFFFFFFFF, odd & 0xFFFFFFFF, even >> 32, odd >> 32};
      // The mean rounded to nearest (within 2^-40 of the exact quotient: only a mean of exactly a
      // half may round either way), or sRGB-encoded.
      std::uint8_t* out = call.rgba + (static_cast<std::size_t>(y) * call.width + x) * 4;
      for (int k = 0; k < 4; ++k) {
        out[k] = call.srgb && k < 3
                     ? detail::encode_resolved(static_cast<float>(sums[k]) * scale, true)
                     : static_cast<std::uint8_t>(static_cast<double>(sums[k]) * inverse + 0.5);
      }
    }
  }
}

// The code of every channel sum of a pixel's samples under the box filter (factor 1), as the
// reference encodes it (the sRGB codes by the constant-time cells, equal to its search).
std::vector<std::uint8_t> box_colour_codes(int samples, bool srgb) {
  const float scale = 1.0f / (255.0f * static_cast<float>(samples));
  const double inverse = 1.0 / static_cast<double>(samples);
  const detail::SrgbCodeCells& cells = detail::srgb_code_cells();
  std::vector<std::uint8_t> codes(static_cast<std::size_t>(255 * samples + 1));
  for (std::size_t sum = 0; sum < codes.size(); ++sum) {
    codes[sum] = srgb ? cells.code(std::min(1.0f, static_cast<float>(sum) * scale))
                      : static_cast<std::uint8_t>(static_cast<double>(sum) * inverse + 0.5);
  }
  return codes;
}

// Bands of output rows per task: whole tile rows (the box reads a tile row's samples at once),
// enough per band that the filtered kernels' plane rows are mostly made once.
constexpr std::int32_t kBandRows = 32;

}  // namespace

double filter_radius(ResolveFilter filter) {
  switch (filter) {
    case ResolveFilter::box:
      return 0.5;
    case ResolveFilter::tent:
      return 1.0;
    case ResolveFilter::mitchell:
      return 2.0;
  }
  return 0.5;
}

double filter_weight(ResolveFilter filter, double d) {
  const double a = std::fabs(d);
  switch (filter) {
    case ResolveFilter::box:
      return d >= -0.5 && d < 0.5 ? 1.0 : 0.0;
    case ResolveFilter::tent:
      return a < 1.0 ? 1.0 - a : 0.0;
    case ResolveFilter::mitchell: {
      // Mitchell and Netravali (1988), B = C = 1/3.
      constexpr double b = 1.0 / 3.0, c = 1.0 / 3.0;
      if (a < 1.0) {
        return ((12 - 9 * b - 6 * c) * a * a * a + (-18 + 12 * b + 6 * c) * a * a + (6 - 2 * b)) /
               6;
      }
      if (a < 2.0) {
        return ((-b - 6 * c) * a * a * a + (6 * b + 30 * c) * a * a + (-12 * b - 48 * c) * a +
                (8 * b + 24 * c)) /
               6;
      }
      return 0.0;
    }
  }
  return 0.0;
}

void resolve(const Framebuffer& source, std::span<std::uint8_t> rgba,
             const ResolveOptions& options) {
  const int f = options.supersampling;
  if (f < 1 || source.width() % f != 0 || source.height() % f != 0) {
    throw std::invalid_argument("resolve: supersampling factor " + std::to_string(f) +
                                " does not divide the source's " + std::to_string(source.width()) +
                                "x" + std::to_string(source.height()) + " pixels");
  }
  const std::int32_t width = source.width() / f, height = source.height() / f;
  const std::size_t bytes = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
  if (rgba.size() != bytes) {
    throw std::invalid_argument("resolve: the span holds " + std::to_string(rgba.size()) +
                                " bytes, not " + std::to_string(bytes));
  }
  const KernelTable& kernels = detail::kernel_table(resolve_isa(options.isa));
  const detail::Workers workers =
      detail::resolve_workers(options.threads, options.executor, "resolve");
  detail::ResolveCall call{source.color_tiles(),
                           source.tiles_x(),
                           source.width(),
                           source.height(),
                           source.samples(),
                           f,
                           width,
                           height,
                           rgba.data(),
                           options.srgb,
                           &detail::srgb_code_cells(),
                           {},
                           {}};
  const std::size_t bands = static_cast<std::size_t>((height + kBandRows - 1) / kBandRows);
  const auto band_rows = [&](std::size_t band) {
    const auto first = static_cast<std::int32_t>(band) * kBandRows;
    return std::pair{first, std::min(first + kBandRows, height)};
  };
  if (options.filter == ResolveFilter::box) {
    if (f > 1) {
      workers.run(bands, [&](std::size_t band) {
        const auto [first, last] = band_rows(band);
        resolve_box_blocks(call, first, last);
      });
      return;
    }
    const std::vector<std::uint8_t> codes = box_colour_codes(source.samples(), options.srgb);
    call.colour_codes = codes;
    workers.run(bands, [&](std::size_t band) {
      const auto [first, last] = band_rows(band);
      kernels.resolve_box(call, first / 8, (last + 7) / 8);
    });
    return;
  }
  const std::vector<ResolveTap> taps =
      filter_taps(options.filter, f, standard_sample_pattern(source.samples()));
  call.taps = taps;
  workers.run(bands, [&](std::size_t band) {
    const auto [first, last] = band_rows(band);
    kernels.resolve_taps(call, first, last);
  });
}

}  // namespace edgewise
