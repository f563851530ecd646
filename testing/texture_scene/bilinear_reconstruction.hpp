// Level 0 as a continuous function of (s, t): bilinear interpolation between texel centres,
// with the wrap rules of the sampler (texture_spec.md, "Texel addressing"). This is the signal
// the ground truth integrates (ground_truth.hpp says why).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "edgewise/sample.hpp"
#include "texture_scene/linear_image.hpp"

namespace edgewise::texture_scene {

// Integer texel index i wrapped onto an axis of n texels (n >= 1):
//   repeat: ((i mod n) + n) mod n;  clamp_to_edge: clamp(i, 0, n - 1);
//   mirror: m = ((i mod 2n) + 2n) mod 2n, then m < n ? m : 2n - 1 - m.
inline std::int64_t wrap_texel_index(std::int64_t i, std::int64_t n, WrapMode mode) {
  switch (mode) {
    case WrapMode::repeat:
      return ((i % n) + n) % n;
    case WrapMode::clamp_to_edge:
      return i < 0 ? 0 : (i > n - 1 ? n - 1 : i);
    case WrapMode::mirror: {
      const std::int64_t m = ((i % (2 * n)) + 2 * n) % (2 * n);
      return m < n ? m : 2 * n - 1 - m;
    }
  }
  return 0;
}

// One axis of the texture: finds the two texels either side of a texel-space coordinate u
// (texel centres at integers), wrapped, and the fraction between them. u is first brought into
// [0, period] by whole periods (repeat: n, mirror: 2n), or clamped to [-1, n] for clamp_to_edge
// (which changes neither the clamped texels nor their blend).
//
// The ground truth calls this billions of times with coordinates of both signs, so it avoids
// integer division, std::floor (a library call on baseline x86-64) and branches that depend on
// the sign: floors are truncations of numbers made non-negative, with fix-ups that are rarely
// taken.
class WrappedAxis {
 public:
  WrappedAxis(std::int64_t n, WrapMode mode)
      : n_(n),
        mode_(mode),
        period_(mode == WrapMode::mirror ? 2.0 * double(n) : double(n)),
        inverse_period_(1.0 / period_) {}

  // u must be finite.
  void locate(double u, std::int64_t& i0, std::int64_t& i1, double& fraction) const {
    if (mode_ == WrapMode::clamp_to_edge) {
      u = std::min(std::max(u, -1.0), double(n_));
      // u + 1 >= 0, so truncation is its floor, unless u + 1 rounded up to an integer.
      std::int64_t i = static_cast<std::int64_t>(u + 1.0) - 1;
      if (double(i) > u) --i;
      fraction = u - double(i);
      i0 = std::min(std::max(i, std::int64_t{0}), n_ - 1);
      i1 = std::min(i + 1, n_ - 1);
      return;
    }
    double r;
    if (std::abs(u) < 0x1.0p40) {
      // k is within one of floor(u / period) (the biased sum is positive, and its rounding
      // may cross an integer). u - k period is then exact: both are multiples of ulp(u), and
      // the remainder is below 2^53 ulp(u).
      constexpr double kBias = 0x1.0p41;
      const std::int64_t k =
          static_cast<std::int64_t>(u * inverse_period_ + kBias) - static_cast<std::int64_t>(kBias);
      r = u - period_ * double(k);
    } else {
      r = std::fmod(u, period_);  // exact
    }
    // Only adding the period back to a small negative remainder rounds: within half an ulp of
    // the period, and possibly to the period itself, whose index wraps like 0.
    if (r < 0.0) {
      r += period_;
    } else if (r >= period_) {
      r -= period_;
    }
    std::int64_t i = static_cast<std::int64_t>(r);  // in [0, period]
    fraction = r - double(i);
    const auto p = static_cast<std::int64_t>(period_);
    if (i >= p) i -= p;
    const std::int64_t next = i + 1 == p ? 0 : i + 1;
    if (mode_ == WrapMode::repeat) {
      i0 = i;
      i1 = next;
    } else {  // mirror: the second half of each period runs backwards
      i0 = i < n_ ? i : 2 * n_ - 1 - i;
      i1 = next < n_ ? next : 2 * n_ - 1 - next;
    }
  }

 private:
  std::int64_t n_;
  WrapMode mode_;
  double period_;
  double inverse_period_;
};

class BilinearReconstruction {
 public:
  // Keeps a reference to `image`, which must outlive this object. Throws std::invalid_argument
  // for an empty image or an rgba size that does not match width x height.
  BilinearReconstruction(const LinearImage& image, WrapMode wrap_s, WrapMode wrap_t)
      : image_(checked(image)), s_axis_(image.width, wrap_s), t_axis_(image.height, wrap_t) {}

  // The bilinear value at (s, t): u = s W - 0.5, i0 = floor(u), fu = u - i0 (v likewise), the
  // texels (i0, j0) .. (i0 + 1, j0 + 1) wrapped. Written as three lerps, which equal the
  // spec's four weights in exact arithmetic and reproduce a constant image exactly in floating
  // point. Non-finite s or t gives 0 (as the sampler does).
  void evaluate(double s, double t, double out[4]) const {
    if (!std::isfinite(s) || !std::isfinite(t)) {
      out[0] = out[1] = out[2] = out[3] = 0.0;
      return;
    }
    std::int64_t i0, i1, j0, j1;
    double fu, fv;
    s_axis_.locate(s * image_.width - 0.5, i0, i1, fu);
    t_axis_.locate(t * image_.height - 0.5, j0, j1, fv);
    const float* p00 = texel(i0, j0);
    const float* p10 = texel(i1, j0);
    const float* p01 = texel(i0, j1);
    const float* p11 = texel(i1, j1);
    for (int c = 0; c < 4; ++c) {
      const double top = p00[c] + fu * (double(p10[c]) - p00[c]);
      const double bottom = p01[c] + fu * (double(p11[c]) - p01[c]);
      out[c] = top + fv * (bottom - top);
    }
  }

  const LinearImage& image() const { return image_; }

 private:
  static const LinearImage& checked(const LinearImage& image) {
    if (image.width < 1 || image.height < 1 ||
        image.rgba.size() != image.texel_index(0, image.height))
      throw std::invalid_argument("BilinearReconstruction: empty or inconsistent image");
    return image;
  }

  const float* texel(std::int64_t x, std::int64_t y) const {
    return image_.rgba.data() + 4 * (y * image_.width + x);
  }

  const LinearImage& image_;
  WrappedAxis s_axis_;
  WrappedAxis t_axis_;
};

}  // namespace edgewise::texture_scene
