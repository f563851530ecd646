// One batch of mesh vertices through the whole per-vertex work of draw()'s vertex stage: the
// transform, the clip classification, the screen mapping and the snapping, from the object-space
// records to the screen mesh's arrays. Every result equals the scalar functions' bit for bit
// (transform(), classify_clip_vertex(), to_screen(), snap()): the same float operations in the
// same order, never fused (the kernels are compiled with -ffp-contract=off), on every lane.
#pragma once

#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "clip.hpp"
#include "edgewise/camera.hpp"
#include "edgewise/vector.hpp"
#include "../../simd/interleave-inl.hpp"
#include "../../simd/simd_ops-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// A vertex's class (classify_clip_vertex()) in one int32 lane. Bits 0 to 5 (kFrustumBits): the
// view-frustum planes the vertex is beyond (near, far, left, right, bottom, top), set only for
// a checked vertex, so that three codes share a bit exactly when clip_triangle() rejects the
// triangle outright. kNotInside: unchecked, at w < kMinProjectedW or beyond a guard-band plane.
// The vertex is inside every clipping plane, at w >= kMinProjectedW, exactly when its code is 0.
inline constexpr std::int32_t kFrustumBits = 0x3f;
inline constexpr std::int32_t kNotInside = 1 << 6;

template <class Arch>
class ScreenMapping {
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  using FloatMask = xsimd::batch_bool<float, Arch>;

 public:
  static constexpr std::size_t kLanes = Floats::size;

  ScreenMapping(const Mat4& m, const Viewport& viewport, const GuardBandPlanes& planes)
      : matrix_(m),
        half_width_(0.5f * static_cast<float>(viewport.width)),
        half_height_(0.5f * static_cast<float>(viewport.height)),
        planes_(planes) {}

  // A batch of vertices through the stage, one per lane.
  struct Lanes {
    Floats x, y;      // the snapped screen position
    Floats depth, w;  // z/w clamped to [0, 1], and the clip-space w
    Ints code;        // the clip class, as above
  };

  // Vertices (p[0], p[1], p[2]) = (x, y, z) of object space, one per lane.
  [[gnu::always_inline]] Lanes map_lanes(const Floats (&p)[3]) const {
    Floats clip[4];
    for (int r = 0; r < 4; ++r) {  // transform(): ((m0 x + m1 y) + m2 z) + m3 (w = 1)
      clip[r] = ((Floats(matrix_.m[r][0]) * p[0] + Floats(matrix_.m[r][1]) * p[1]) +
                 Floats(matrix_.m[r][2]) * p[2]) +
                Floats(matrix_.m[r][3]);
    }
    const Floats x = clip[0], y = clip[1], z = clip[2], w = clip[3];
    Lanes out;
    out.code = code(x, y, z, w);
    out.w = w;

    // to_screen()
    const Floats one(1.0f), zero(0.0f);
    const Floats inv_w = divide_exactly(one, w);
    Floats z_over_w = z * inv_w;
    z_over_w = xsimd::select(z_over_w > one, one, z_over_w);
    out.depth = xsimd::select(z_over_w < zero, zero, z_over_w);
    out.x = snap((x * inv_w + one) * Floats(half_width_));
    out.y = snap((one - y * inv_w) * Floats(half_height_));
    return out;
  }

  // Vertices in[0 .. kLanes) to positions, depth, clip_w and codes [0 .. kLanes).
  [[gnu::always_inline]] void map(const Vec3* in, Vec2* positions, float* depth, float* clip_w,
                                  std::int32_t* codes) const {
    static_assert(sizeof(Vec3) == 3 * sizeof(float) && sizeof(Vec2) == 2 * sizeof(float));
    Floats p[3];
    load_interleaved3<Arch>(&in->x, p);
    const Lanes mapped = map_lanes(p);
    mapped.code.store_unaligned(codes);
    mapped.w.store_unaligned(clip_w);
    mapped.depth.store_unaligned(depth);
    store_interleaved2<Arch>(mapped.x, mapped.y, &positions->x);
  }

 private:
  // classify_clip_vertex() as a code (above).
  [[gnu::always_inline]] Ints code(Floats x, Floats y, Floats z, Floats w) const {
    // Checked: every coordinate finite and within kMaxClipCoordinate. The largest magnitude is
    // taken on the bits, as integers, in which NaN lies above infinity: a NaN stays a NaN, which
    // fails the comparison.
    const Ints magnitude_mask(0x7fffffff);
    const auto magnitude = [&](Floats c) { return xsimd::bitwise_cast<Ints>(c) & magnitude_mask; };
    const Ints largest =
        xsimd::max(xsimd::max(magnitude(x), magnitude(y)), xsimd::max(magnitude(z), magnitude(w)));
    const Ints checked =
        mask_lanes(xsimd::bitwise_cast<Floats>(largest) <= Floats(kMaxClipCoordinate));

    // outcode() (clip.cpp). For a checked vertex every distance is finite, so "not >= 0" is
    // "< 0"; the lanes of other vertices are overwritten below.
    const Floats zero(0.0f), minus_w = -w;
    const auto bit = [](FloatMask m, std::int32_t value) { return mask_lanes(m) & Ints(value); };
    const Ints frustum = (bit(z < zero, 1) | bit((w - z) < zero, 2)) |
                         (bit(x < minus_w, 4) | bit(x > w, 8)) |
                         (bit(y < minus_w, 16) | bit(y > w, 32));
    const Floats nearest_band_plane =
        xsimd::min(xsimd::min(x - Floats(planes_.x_min) * w, Floats(planes_.x_max) * w - x),
                   xsimd::min(y - Floats(planes_.y_min) * w, Floats(planes_.y_max) * w - y));
    // Not inside: beyond a guard-band plane, at w < kMinProjectedW, or unchecked. (Beyond a
    // frustum plane shows in the frustum bits.)
    const Ints not_inside =
        mask_lanes((nearest_band_plane < zero) | (w < Floats(kMinProjectedW))) | ~checked;
    return (frustum & checked) | (not_inside & Ints(kNotInside));
  }

  // snap() (vertex_stage.cpp) in float: v * 256 is exact, and below 2^23 in magnitude it rounds
  // (ties to even) to an integer exactly representable in int32 and in float, so dividing it by
  // 256 again is exact too: the double computation's result. A rounded 0 is +0, as there. From
  // 2^15 px on (and for infinities and NaN) snap() returns v itself.
  [[gnu::always_inline]] static Floats snap(Floats v) {
    const Floats rounded =
        xsimd::to_float(xsimd::nearbyint_as_int(v * Floats(256.0f))) * Floats(1.0f / 256.0f);
    return xsimd::select(xsimd::abs(v) < Floats(0x1p15f), rounded, v);
  }

  Mat4 matrix_;
  float half_width_, half_height_;
  GuardBandPlanes planes_;
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
