// Framebuffer clear: the memory-bound ceiling that coverage throughput is compared with.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "benchmarks.hpp"

namespace {

using edgewise::bench::kHeight;
using edgewise::bench::kWidth;

void clear_rgba8_depth32f(benchmark::State& state) {
  constexpr std::size_t kPixels = std::size_t{kWidth} * kHeight;
  std::vector<std::uint32_t> color(kPixels);
  std::vector<float> depth(kPixels);
  constexpr std::uint32_t kClearColor = 0xff302010;  // opaque; not zero, so no calloc shortcut
  constexpr float kClearDepth = 1.0f;
  for (auto _ : state) {
    std::fill(color.begin(), color.end(), kClearColor);
    std::fill(depth.begin(), depth.end(), kClearDepth);
    benchmark::DoNotOptimize(color.data());
    benchmark::DoNotOptimize(depth.data());
    benchmark::ClobberMemory();
  }
  const auto iterations = static_cast<std::int64_t>(state.iterations());
  state.SetBytesProcessed(iterations * std::int64_t{kPixels} *
                          (sizeof(std::uint32_t) + sizeof(float)));
  state.counters["pixels"] =
      benchmark::Counter(double(kPixels) * double(iterations), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK(clear_rgba8_depth32f)
    ->Name("Clear/rgba8+depth32f/1920x1080")
    ->Unit(benchmark::kMicrosecond);
