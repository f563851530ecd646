// Building a Texture takes little memory beyond what the Texture keeps: the pyramid's resampler
// works in bands of rows, so a large texture never needs a whole level in double precision
// beside it (32 bytes a texel, eight times an 8-bit level).
//
// This program replaces the global operator new and delete to count the bytes live on the heap
// (malloc_usable_size on both sides, so the two agree) and their peak.
#include <gtest/gtest.h>
#include <malloc.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <vector>

#include "edgewise/texture.hpp"

namespace {

std::atomic<std::size_t> live_bytes{0};
std::atomic<std::size_t> peak_bytes{0};

void* counted(void* p) {
  if (p == nullptr) throw std::bad_alloc();
  const std::size_t now = live_bytes += malloc_usable_size(p);
  std::size_t peak = peak_bytes.load();
  while (now > peak && !peak_bytes.compare_exchange_weak(peak, now)) {
  }
  return p;
}

void uncounted(void* p) {
  if (p == nullptr) return;
  live_bytes -= malloc_usable_size(p);
  std::free(p);
}

}  // namespace

void* operator new(std::size_t n) {
  return counted(std::malloc(n == 0 ? 1 : n));
}
void* operator new[](std::size_t n) {
  return counted(std::malloc(n == 0 ? 1 : n));
}
void* operator new(std::size_t n, std::align_val_t a) {
  const auto alignment = static_cast<std::size_t>(a);
  return counted(std::aligned_alloc(alignment, (n + alignment - 1) / alignment * alignment));
}
void* operator new[](std::size_t n, std::align_val_t a) {
  return operator new(n, a);
}
void operator delete(void* p) noexcept {
  uncounted(p);
}
void operator delete[](void* p) noexcept {
  uncounted(p);
}
void operator delete(void* p, std::size_t) noexcept {
  uncounted(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  uncounted(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
  uncounted(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
  uncounted(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  uncounted(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  uncounted(p);
}

namespace edgewise {
namespace {

struct Footprint {
  std::size_t kept = 0;   // live after the build, beyond what was live before it
  std::size_t extra = 0;  // the build's peak beyond that
};

template <class Build>
Footprint measure(Build build) {
  const std::size_t before = live_bytes.load();
  peak_bytes = before;
  const Texture texture = build();
  const std::size_t after = live_bytes.load();
  return {after - before, peak_bytes.load() - after};
}

// What the build may hold beyond the Texture: one band of the resampler, at most
// 2 kBandRows + 12 source rows (16 output rows read 2 x 16 source rows for the box filter, and
// Lanczos 3 reaches 3 coarse texels, 6 source rows, beyond each end) of the level being halved,
// filtered to half its width at 32 bytes a texel, and one decoded source row at 32 bytes a
// texel; plus the texel ranges' per-level scratch (two bytes per channel per 8x8 block), and
// 64 KiB for small vectors. For a 2048-texel-wide level 0: 44 x 1024 x 32 + 2048 x 32 +
// 2 x 4 x 65536 + 65536 bytes, about 2 MiB; a whole level in doubles would be 64 MiB.
std::size_t allowed_extra(std::int32_t width, std::int32_t height) {
  const auto w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height);
  return 44 * (w / 2) * 32 + w * 32 + 2 * 4 * (w / 8) * (h / 8) + 65536;
}

TEST(TextureMemory, BuildPeaksNearWhatTheTextureKeeps) {
  constexpr std::int32_t kWidth = 2048, kHeight = 2048;
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(kWidth) * kHeight * 4);
  for (std::size_t i = 0; i < texels.size(); ++i)
    texels[i] = static_cast<std::uint8_t>(i * 2654435761u >> 13);
  for (const PyramidFilter filter : {PyramidFilter::box, PyramidFilter::lanczos3}) {
    for (const ColorEncoding encoding : {ColorEncoding::linear, ColorEncoding::srgb}) {
      const Footprint f = measure([&] {
        return Texture::from_rgba8(kWidth, kHeight, texels, encoding, {.filter = filter});
      });
      EXPECT_GE(f.kept, texels.size()) << "level 0 at least";
      EXPECT_LE(f.extra, allowed_extra(kWidth, kHeight))
          << name_of(filter) << ": the build took " << f.extra << " bytes beyond the " << f.kept
          << " the texture keeps";
    }
  }
}

TEST(TextureMemory, FloatAndRipmapBuildsPeakNearWhatTheTextureKeeps) {
  constexpr std::int32_t kWidth = 1024, kHeight = 512;
  std::vector<float> texels(static_cast<std::size_t>(kWidth) * kHeight * 4);
  for (std::size_t i = 0; i < texels.size(); ++i)
    texels[i] = static_cast<float>(i % 977) / 977.0f;
  const Footprint f =
      measure([&] { return Texture::from_rgba32f(kWidth, kHeight, texels, {.ripmaps = true}); });
  EXPECT_LE(f.extra, allowed_extra(kWidth, kHeight))
      << "the build took " << f.extra << " bytes beyond the " << f.kept << " the texture keeps";
}

}  // namespace
}  // namespace edgewise
