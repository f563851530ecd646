// The sampler options a fuzz input chooses, as fuzz_sample and fuzz_draw both decode them:
// filter, wrap byte (s: % 3, t: / 3 % 3; the caller may read its high bit), lod bias in 1/64,
// max_anisotropy and supersample_taps within their ranges, then a variant byte whose values 248
// to 255 make the texture or options ones sample() and draw() must refuse (no ripmaps, no
// summed-area table, each integer option just outside its range, an infinite or NaN bias).
#pragma once

#include <cstdint>
#include <limits>

#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"

namespace edgewise::fuzz {

inline constexpr int kFilterCount = static_cast<int>(TextureFilter::ewa) + 1;

struct SamplerInput {
  std::uint32_t wrap_byte = 0;
  std::uint32_t variant = 0;
};

// Input: any reader with u8() and i8(). Sets options.filter, wraps, lod_bias, max_anisotropy,
// supersample_taps and build.ripmaps, build.summed_area_table.
template <class Input>
SamplerInput decode_sampler(Input& in, SamplerOptions& o, TextureBuild& build) {
  SamplerInput s;
  o.filter = static_cast<TextureFilter>(in.u8() % kFilterCount);
  s.wrap_byte = in.u8();
  o.wrap_s = static_cast<WrapMode>(s.wrap_byte % 3);
  o.wrap_t = static_cast<WrapMode>(s.wrap_byte / 3 % 3);
  o.lod_bias = static_cast<float>(in.i8()) / 64.0f;
  o.max_anisotropy = 1 + static_cast<int>(in.u8() % kMaxAnisotropyLimit);
  o.supersample_taps = 1 + static_cast<int>(in.u8() % kMaxSupersampleTaps);
  s.variant = in.u8();
  build.ripmaps = s.variant != 248;
  build.summed_area_table = s.variant != 249;
  switch (s.variant) {
    case 250:
      o.max_anisotropy = 0;
      break;
    case 251:
      o.max_anisotropy = kMaxAnisotropyLimit + 1;
      break;
    case 252:
      o.supersample_taps = 0;
      break;
    case 253:
      o.supersample_taps = kMaxSupersampleTaps + 1;
      break;
    case 254:
      o.lod_bias = std::numeric_limits<float>::infinity();
      break;
    case 255:
      o.lod_bias = std::numeric_limits<float>::quiet_NaN();
      break;
    default:
      break;
  }
  return s;
}

}  // namespace edgewise::fuzz
