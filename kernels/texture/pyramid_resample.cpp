// A separable resampler for pyramid levels: each output texel of an axis is a weighted sum of
// source texels (its taps), computed once per axis and applied to every row or column.
//
// Alpha is filtered like any other channel, as a straight (not premultiplied) value: the texture
// stores straight alpha and the sampler filters it that way too, so a pyramid level is what the
// sampler would compute from the finer one.
#include "pyramid_resample.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <vector>

namespace edgewise::detail {
namespace {

struct Tap {
  std::int32_t index;  // source texel along the axis
  double weight;
};

// Output texel c of an axis reads taps[first[c] .. first[c + 1]).
struct AxisTaps {
  std::vector<std::size_t> first{0};
  std::vector<Tap> taps;
};

// The exact area average: coarse texel c of n_out covers the source interval
// [c n_in / n_out, (c + 1) n_in / n_out). In units of 1 / n_out that interval and the source
// texels' edges are integers, so each overlap is an exact integer and the weights are
// overlap / n_in. For n_in = 2 n_out this is the 2-tap box (1/2, 1/2); for n_in = 2n + 1,
// n_out = n, the 3-tap polyphase box (n - c, n, c + 1) / (2n + 1).
AxisTaps box_taps(std::int32_t n_in, std::int32_t n_out) {
  AxisTaps axis;
  for (std::int64_t c = 0; c < n_out; ++c) {
    const std::int64_t lo = c * n_in, hi = (c + 1) * n_in;
    for (std::int64_t k = lo / n_out; k * n_out < hi; ++k) {
      const std::int64_t overlap = std::min(hi, (k + 1) * n_out) - std::max(lo, k * n_out);
      axis.taps.push_back({static_cast<std::int32_t>(k), static_cast<double>(overlap) / n_in});
    }
    axis.first.push_back(axis.taps.size());
  }
  return axis;
}

// Lanczos a = 3: sinc(x) sinc(x / 3) on |x| < 3.
double lanczos3(double x) {
  if (x == 0.0) return 1.0;
  if (std::abs(x) >= 3.0) return 0.0;
  const double px = std::numbers::pi * x;
  return 3.0 * std::sin(px) * std::sin(px / 3.0) / (px * px);
}

// Lanczos 3 stretched to the coarse spacing: coarse texel c is centred at source position
// (c + 0.5) n_in / n_out - 0.5 and reads the source texels within 3 coarse texels of it, clamped
// to the edge; the weights are normalized to sum 1 (the sampled kernel's sum is not exactly 1).
AxisTaps lanczos3_taps(std::int32_t n_in, std::int32_t n_out) {
  AxisTaps axis;
  const double scale = static_cast<double>(n_in) / n_out;
  for (std::int32_t c = 0; c < n_out; ++c) {
    const double centre = (c + 0.5) * scale - 0.5;
    const auto first = static_cast<std::int64_t>(std::ceil(centre - 3.0 * scale));
    const auto last = static_cast<std::int64_t>(std::floor(centre + 3.0 * scale));
    double sum = 0.0;
    const std::size_t begin = axis.taps.size();
    for (std::int64_t k = first; k <= last; ++k) {
      const double weight = lanczos3((static_cast<double>(k) - centre) / scale);
      const auto index = static_cast<std::int32_t>(std::clamp<std::int64_t>(k, 0, n_in - 1));
      axis.taps.push_back({index, weight});
      sum += weight;
    }
    for (std::size_t i = begin; i < axis.taps.size(); ++i)
      axis.taps[i].weight /= sum;
    axis.first.push_back(axis.taps.size());
  }
  return axis;
}

AxisTaps axis_taps(PyramidFilter filter, std::int32_t n_in, std::int32_t n_out) {
  return filter == PyramidFilter::lanczos3 ? lanczos3_taps(n_in, n_out) : box_taps(n_in, n_out);
}

// Stored texels to linear doubles and back.
class TexelCodec {
 public:
  TexelCodec(TexelFormat format, ColorEncoding encoding) : format_(format), encoding_(encoding) {
    for (int code = 0; code < 256; ++code) {
      alpha_[code] = code / 255.0;
      colour_[code] = encoding == ColorEncoding::srgb ? srgb_to_linear(code / 255.0) : code / 255.0;
    }
  }

  void decode(const std::byte* texels, std::size_t index, double out[4]) const {
    if (format_ == TexelFormat::rgba32f) {
      float value[4];
      std::memcpy(value, texels + index * sizeof(value), sizeof(value));
      for (int ch = 0; ch < 4; ++ch)
        out[ch] = value[ch];
      return;
    }
    const auto* code = reinterpret_cast<const std::uint8_t*>(texels) + index * 4;
    for (int ch = 0; ch < 3; ++ch)
      out[ch] = colour_[code[ch]];
    out[3] = alpha_[code[3]];
  }

  void encode(const double in[4], std::byte* texels, std::size_t index) const {
    if (format_ == TexelFormat::rgba32f) {
      float value[4];
      for (int ch = 0; ch < 4; ++ch)
        value[ch] = to_float(in[ch]);
      std::memcpy(texels + index * sizeof(value), value, sizeof(value));
      return;
    }
    auto* code = reinterpret_cast<std::uint8_t*>(texels) + index * 4;
    for (int ch = 0; ch < 4; ++ch) {
      const bool srgb = encoding_ == ColorEncoding::srgb && ch < 3;
      code[ch] = to_code(srgb ? linear_to_srgb(in[ch]) : in[ch]);
    }
  }

 private:
  // Round to nearest float as IEEE does, overflow included, without converting an out-of-range
  // double (undefined behaviour): a Lanczos sum may overshoot the largest float.
  static float to_float(double v) {
    constexpr double kMax = std::numeric_limits<float>::max();
    constexpr double kOverflow = kMax + 0x1p103;  // halfway to the next power of two: rounds up
    if (std::isnan(v)) return std::numeric_limits<float>::quiet_NaN();
    if (std::abs(v) >= kOverflow) return std::copysign(std::numeric_limits<float>::infinity(), v);
    return static_cast<float>(std::clamp(v, -kMax, kMax));
  }

  // Nearest code, clamped (a Lanczos result may overshoot [0, 1]).
  static std::uint8_t to_code(double v) {
    const double scaled = std::clamp(v * 255.0, 0.0, 255.0);
    return static_cast<std::uint8_t>(std::lround(scaled));
  }

  TexelFormat format_;
  ColorEncoding encoding_;
  double colour_[256];
  double alpha_[256];
};

// Rows [first_row, first_row + height) of an image of linear RGBA doubles, `width` texels each.
struct LinearRows {
  std::int32_t width = 0;
  std::int32_t first_row = 0;
  std::int32_t height = 0;
  std::vector<double> rgba;
  double* texel(std::int32_t x, std::int32_t y) {
    return rgba.data() + (static_cast<std::size_t>(y - first_row) * width + x) * 4;
  }
};

// Output rows decoded and filtered per band: the band's rows, 32 bytes per texel, are the
// resampler's only large buffer, so building a level takes memory in proportion to a band of
// its source rather than to the whole of it.
constexpr std::int32_t kBandRows = 16;

// Horizontal pass over source rows [rows.first_row, rows.first_row + rows.height): decodes
// them and filters each to rows.width texels (decoding only, when the width stays).
void filter_rows(const TexelCodec& codec, const AxisTaps* axis, const LevelView& source,
                 LinearRows& rows, std::vector<double>& decoded) {
  const std::size_t row = static_cast<std::size_t>(source.width);
  const std::int32_t end = rows.first_row + rows.height;
  for (std::int32_t y = rows.first_row; y < end; ++y) {
    if (axis == nullptr) {
      for (std::int32_t x = 0; x < rows.width; ++x)
        codec.decode(source.texels, y * row + x, rows.texel(x, y));
      continue;
    }
    for (std::int32_t x = 0; x < source.width; ++x) {
      codec.decode(source.texels, y * row + x, decoded.data() + x * 4);
    }
    for (std::int32_t x = 0; x < rows.width; ++x) {
      double sum[4] = {0.0, 0.0, 0.0, 0.0};
      for (std::size_t i = axis->first[x]; i < axis->first[x + 1]; ++i) {
        const double* texel = decoded.data() + static_cast<std::size_t>(axis->taps[i].index) * 4;
        for (int ch = 0; ch < 4; ++ch)
          sum[ch] += axis->taps[i].weight * texel[ch];
      }
      std::copy(sum, sum + 4, rows.texel(x, y));
    }
  }
}

// Vertical pass for output rows [y0, y1): filters the columns of `rows` (which hold every source
// row those output rows read) and encodes (no filtering when the height stays: output row y is
// source row y).
void filter_columns_and_encode(const TexelCodec& codec, const AxisTaps* axis, LinearRows& rows,
                               std::byte* destination, std::int32_t y0, std::int32_t y1) {
  const std::size_t row = static_cast<std::size_t>(rows.width);
  for (std::int32_t y = y0; y < y1; ++y) {
    for (std::int32_t x = 0; x < rows.width; ++x) {
      if (axis == nullptr) {
        codec.encode(rows.texel(x, y), destination, y * row + x);
        continue;
      }
      double sum[4] = {0.0, 0.0, 0.0, 0.0};
      for (std::size_t i = axis->first[y]; i < axis->first[y + 1]; ++i) {
        const double* texel = rows.texel(x, axis->taps[i].index);
        for (int ch = 0; ch < 4; ++ch)
          sum[ch] += axis->taps[i].weight * texel[ch];
      }
      codec.encode(sum, destination, y * row + x);
    }
  }
}

}  // namespace

void resample_level(TexelFormat format, ColorEncoding encoding, PyramidFilter filter,
                    const LevelView& source, std::byte* destination, std::int32_t width,
                    std::int32_t height) {
  const TexelCodec codec(format, encoding);
  const AxisTaps horizontal = axis_taps(filter, source.width, width);
  const AxisTaps vertical = axis_taps(filter, source.height, height);
  const AxisTaps* h = width == source.width ? nullptr : &horizontal;
  const AxisTaps* v = height == source.height ? nullptr : &vertical;
  std::vector<double> decoded(static_cast<std::size_t>(source.width) * 4);
  LinearRows rows;
  rows.width = width;
  for (std::int32_t y0 = 0; y0 < height; y0 += kBandRows) {
    const std::int32_t y1 = std::min(height, y0 + kBandRows);
    // The source rows the band's output rows read (the band itself when the height stays).
    std::int32_t low = y0, high = y1;
    if (v != nullptr) {
      low = std::numeric_limits<std::int32_t>::max();
      high = 0;
      for (std::size_t i = v->first[y0]; i < v->first[y1]; ++i) {
        low = std::min(low, v->taps[i].index);
        high = std::max(high, v->taps[i].index + 1);
      }
    }
    rows.first_row = low;
    rows.height = high - low;
    rows.rgba.resize(static_cast<std::size_t>(rows.height) * width * 4);
    filter_rows(codec, h, source, rows, decoded);
    filter_columns_and_encode(codec, v, rows, destination, y0, y1);
  }
}

}  // namespace edgewise::detail
