// resolve(): the filtered mean of the samples around each output pixel (resolve.hpp).
//
// The source's samples repeat with the output pixels: the output pixel at (x, y) sees source
// pixel (f x + i, f y + j), sample k, at the same distance for every (x, y). So the filter's
// taps, each (i, j, k) with its normalized weight, are found once per call, and each output
// pixel is a sum over them; only pixels near the image's edges clamp the source coordinates.
#include "edgewise/resolve.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "edgewise/multisample.hpp"
#include "edgewise/texture.hpp"

namespace edgewise {
namespace {

struct Tap {
  std::int32_t i, j;  // source pixel offset from the output pixel's first source pixel
  std::int32_t sample;
  float weight;
};

// The taps of every output pixel, weights summing to 1.
std::vector<Tap> filter_taps(ResolveFilter filter, int factor,
                             std::span<const SampleOffset> pattern) {
  const double radius = filter_radius(filter);
  // Source pixels whose samples may lie within the radius: their centres within radius + 1/2
  // output pixels (a sample is at most half a source pixel from its centre).
  const auto reach = static_cast<std::int32_t>(std::ceil((radius + 0.5) * factor)) + 1;
  std::vector<Tap> taps;
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
  for (Tap& tap : taps)
    tap.weight = static_cast<float>(tap.weight / total);
  return taps;
}

// The 8-bit code of a linear value in [0, 1]: linear, or its sRGB encoding, rounded to nearest.
class Encoder {
 public:
  explicit Encoder(bool srgb) : srgb_(srgb) {
    // Code c is the nearest when the value's encoding lies in [(c - 1/2) / 255, (c + 1/2) / 255):
    // thresholds[c] is the linear value where code c + 1 begins.
    for (int c = 0; c < 255 && srgb; ++c)
      thresholds_[c] = static_cast<float>(srgb_to_linear((c + 0.5) / 255.0));
  }
  bool srgb() const { return srgb_; }
  std::uint8_t operator()(float v, bool colour) const {
    const float clamped = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // NaN: 0
    if (!srgb_ || !colour) return static_cast<std::uint8_t>(std::lrint(clamped * 255.0f));
    return static_cast<std::uint8_t>(
        std::upper_bound(thresholds_.begin(), thresholds_.end(), clamped) - thresholds_.begin());
  }

 private:
  bool srgb_;
  std::array<float, 255> thresholds_{};
};

// The box filter: every output pixel is the plain mean of the f x f x samples samples of its own
// source block (each standard offset lies inside its pixel: weights equal, none outside), summed
// exactly in integers, two channels per 64-bit word (each sum at most 255 f^2 samples, far below
// 2^32 for any target that fits in memory), and rounded to nearest.
void resolve_box(const Framebuffer& source, int f, std::span<std::uint8_t> rgba,
                 const Encoder& encode) {
  const std::int32_t width = source.width() / f, height = source.height() / f;
  const auto count = static_cast<std::uint64_t>(f) * static_cast<std::uint64_t>(f) *
                     static_cast<std::uint64_t>(source.samples());
  const float scale = 1.0f / (255.0f * static_cast<float>(count));
  const double inverse = 1.0 / static_cast<double>(count);
  // The mean rounded to nearest (within 2^-40 of the exact quotient: only a mean of exactly a
  // half may round either way), or sRGB-encoded.
  const auto write = [&](std::int32_t x, std::int32_t y, const std::uint64_t(&sums)[4]) {
    std::uint8_t* out = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
    for (int k = 0; k < 4; ++k) {
      out[k] = encode.srgb() && k < 3
                   ? encode(static_cast<float>(sums[k]) * scale, true)
                   : static_cast<std::uint8_t>(static_cast<double>(sums[k]) * inverse + 0.5);
    }
  };
  if (f == 1) {
    // A tile at a time: its samples' planes are consecutive (framebuffer.hpp), so the sums run
    // over contiguous pixels, R and B in the two 16-bit halves of one lane, G and A of another
    // (at most 16 samples of 255 each: below 2^16).
    const std::uint32_t* tiles = source.color_tiles();
    const auto samples = static_cast<std::size_t>(source.samples());
    for (std::int32_t ty = 0; ty < source.tiles_y(); ++ty) {
      for (std::int32_t tx = 0; tx < source.tiles_x(); ++tx) {
        const std::uint32_t* tile =
            tiles + (static_cast<std::size_t>(ty) * source.tiles_x() + tx) * samples * 64;
        std::uint32_t red_blue[64] = {}, green_alpha[64] = {};
        for (std::size_t k = 0; k < samples; ++k) {
          for (std::size_t p = 0; p < 64; ++p) {
            const std::uint32_t c = tile[k * 64 + p];
            red_blue[p] += c & 0x00FF00FFu;
            green_alpha[p] += (c >> 8) & 0x00FF00FFu;
          }
        }
        for (std::int32_t p = 0; p < 64; ++p) {
          const std::int32_t x = tx * 8 + p % 8, y = ty * 8 + p / 8;
          if (x >= width || y >= height) continue;
          const std::uint64_t sums[4] = {red_blue[p] & 0xFFFFu, green_alpha[p] & 0xFFFFu,
                                         red_blue[p] >> 16, green_alpha[p] >> 16};
          write(x, y, sums);
        }
      }
    }
    return;
  }
  for (std::int32_t y = 0; y < height; ++y) {
    for (std::int32_t x = 0; x < width; ++x) {
      // Channels R and B in the low and high 32 bits of `even`, G and A of `odd`.
      std::uint64_t even = 0, odd = 0;
      for (std::int32_t j = 0; j < f; ++j) {
        for (std::int32_t i = 0; i < f; ++i) {
          for (int k = 0; k < source.samples(); ++k) {
            const std::uint64_t c = source.color(x * f + i, y * f + j, k);
            even += (c & 0xFF) | (c & 0xFF0000) << 16;
            odd += (c >> 8 & 0xFF) | (c >> 24 & 0xFF) << 32;
          }
        }
      }
      const std::uint64_t sums[4] = {even & 0xFFFFFFFF, odd & 0xFFFFFFFF, even >> 32, odd >> 32};
      write(x, y, sums);
    }
  }
}

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
  const Encoder encode(options.srgb);
  if (options.filter == ResolveFilter::box) return resolve_box(source, f, rgba, encode);
  const std::vector<Tap> taps =
      filter_taps(options.filter, f, standard_sample_pattern(source.samples()));
  std::int32_t reach = 0;  // the farthest tap from the output pixel's own source pixels
  for (const Tap& tap : taps)
    reach = std::max({reach, -tap.i, -tap.j, tap.i - (f - 1), tap.j - (f - 1)});
  for (std::int32_t y = 0; y < height; ++y) {
    for (std::int32_t x = 0; x < width; ++x) {
      const bool interior = x * f - reach >= 0 && y * f - reach >= 0 &&
                            x * f + f - 1 + reach < source.width() &&
                            y * f + f - 1 + reach < source.height();
      float sum[4] = {0.0f, 0.0f, 0.0f, 0.0f};
      for (const Tap& tap : taps) {
        std::int32_t sx = x * f + tap.i, sy = y * f + tap.j;
        if (!interior) {
          sx = std::clamp(sx, 0, source.width() - 1);
          sy = std::clamp(sy, 0, source.height() - 1);
        }
        const std::uint32_t c = source.color(sx, sy, tap.sample);
        for (int k = 0; k < 4; ++k)
          sum[k] += tap.weight * static_cast<float>((c >> (8 * k)) & 0xFF);
      }
      std::uint8_t* out = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
      for (int k = 0; k < 4; ++k)
        out[k] = encode(sum[k] * (1.0f / 255.0f), k < 3);
    }
  }
}

}  // namespace edgewise
