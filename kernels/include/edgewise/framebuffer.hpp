// A render target: RGBA8 colour and float32 depth, stored in 8x8 tiles.
//
// Layout: the target is padded to whole tiles; tile (tx, ty) holds 64 consecutive pixels, row by
// row, at index (ty * tiles_x + tx) * 64, and pixel (x, y) of the target is element
// ((y / 8) * tiles_x + x / 8) * 64 + (y % 8) * 8 + x % 8 of both the colour and the depth array.
// A tile is exactly one coverage mask (coverage.hpp): a row of 8 pixels is 32 bytes of colour and
// 32 of depth, one AVX2 register each, and a tile's 512 bytes stay together in cache. Padding
// pixels are never drawn. read_rgba8() and read_depth() convert to the usual row-major order.
//
// Colour is packed R | G << 8 | B << 16 | A << 24 (bytes R, G, B, A in memory on little-endian
// machines), linear values v / 255.
//
// Multisampled targets (samples() of 2, 4, 8 or 16, the standard patterns of multisample.hpp)
// hold a colour and a depth per sample: tile t's sample k is the 64 values from index
// (t * samples() + k) * 64, in the pixel order above, so a tile's samples stay together in
// memory and one sample of a tile is still one coverage mask. With one sample the layout is the
// one above. draw() writes every sample a triangle covers; resolve() (resolve.hpp) filters the
// samples to the anti-aliased image.
//
// Thread safety: a Framebuffer is an ordinary object. Its const members may be called from many
// threads at once; clear(), draw() into it, or any other change needs it to itself.
#pragma once

#include <cstddef>
#include <cstdint>
#include <new>
#include <span>
#include <vector>

#include "edgewise/vector.hpp"

namespace edgewise {

namespace detail {
struct FramebufferAccess;

// Storage aligned to 64 bytes, so that every tile row is one aligned SIMD load on every ISA.
template <class T>
struct TileAlignedAllocator {
  using value_type = T;
  static constexpr std::align_val_t kAlignment{64};
  TileAlignedAllocator() = default;
  template <class U>
  TileAlignedAllocator(const TileAlignedAllocator<U>&) {}
  T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), kAlignment)); }
  void deallocate(T* p, std::size_t) { ::operator delete(p, kAlignment); }
  friend bool operator==(const TileAlignedAllocator&, const TileAlignedAllocator&) { return true; }
};
}  // namespace detail

class Framebuffer {
 public:
  // Throws std::invalid_argument for a side outside 0 .. kMaxTargetSize (coverage.hpp), or for
  // a sample count without a standard pattern (multisample.hpp).
  Framebuffer(std::int32_t width, std::int32_t height, int samples = 1);

  std::int32_t width() const { return width_; }
  std::int32_t height() const { return height_; }
  std::int32_t tiles_x() const { return tiles_x_; }
  std::int32_t tiles_y() const { return tiles_y_; }
  int samples() const { return samples_; }

  // Colour components are clamped to [0, 1] and rounded to 8 bits; depth is stored as given.
  void clear(const Vec4& color, float depth);

  // Sample `sample` (0 .. samples() - 1, unchecked) of pixel (x, y).
  std::uint32_t color(std::int32_t x, std::int32_t y, int sample = 0) const {
    return color_[index(x, y, sample)];
  }
  float depth(std::int32_t x, std::int32_t y, int sample = 0) const {
    return depth_[index(x, y, sample)];
  }

  // Row-major copies of one sample of every pixel: 4 bytes (R, G, B, A) per pixel, and one float
  // per pixel. Throw std::invalid_argument when the span's size is not width * height * 4 (or
  // width * height), or the sample is not one of the target's.
  void read_rgba8(std::span<std::uint8_t> rgba, int sample = 0) const;
  void read_depth(std::span<float> depth, int sample = 0) const;

  // The tiled storage (see the layout above). Depth may be written through depth_tiles(): the
  // per-tile depth bounds that draw() keeps for hierarchical depth rejection are then rebuilt
  // from the depth values at the next draw().
  std::uint32_t* color_tiles() { return color_.data(); }
  float* depth_tiles() {
    depth_bounds_valid_ = false;
    return depth_.data();
  }
  const std::uint32_t* color_tiles() const { return color_.data(); }
  const float* depth_tiles() const { return depth_.data(); }

 private:
  void check_sample(int sample, const char* what) const;
  // Where sample `sample` of pixel (x, y) is in the tiled storage (the layout above).
  std::size_t index(std::int32_t x, std::int32_t y, int sample = 0) const {
    return ((static_cast<std::size_t>(y >> 3) * static_cast<std::size_t>(tiles_x_) +
             static_cast<std::size_t>(x >> 3)) *
                static_cast<std::size_t>(samples_) +
            static_cast<std::size_t>(sample)) *
               64 +
           static_cast<std::size_t>((y & 7) * 8 + (x & 7));
  }

  std::int32_t width_, height_, tiles_x_, tiles_y_;
  int samples_;
  friend struct detail::FramebufferAccess;
  std::vector<std::uint32_t, detail::TileAlignedAllocator<std::uint32_t>> color_;
  std::vector<float, detail::TileAlignedAllocator<float>> depth_;
  // For each tile, an upper bound on its depth values, every sample's (when depth_bounds_valid_).
  std::vector<float> tile_max_depth_;
  bool depth_bounds_valid_ = true;
};

// Linear [0, 1] colour to the packed RGBA8 value: each component clamped, scaled by 255 and
// rounded to nearest (NaN becomes 0).
std::uint32_t pack_rgba8(const Vec4& color);

}  // namespace edgewise
