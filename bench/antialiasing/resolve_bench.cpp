// resolve() of a 4x multisampled 1280x720 frame, per filter and ISA, against the time to read
// its samples once (the memory-bound floor a box resolve approaches).
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "../benchmarks.hpp"
#include "edgewise/framebuffer.hpp"
#include "edgewise/isa.hpp"
#include "edgewise/resolve.hpp"

namespace edgewise::bench {
namespace {

constexpr std::int32_t kResolveWidth = 1280, kResolveHeight = 720;
constexpr int kResolveSamples = 4;

// Every sample a different colour (a frame's edges mix far fewer; the kernels' work does not
// depend on the values).
Framebuffer multisampled_frame() {
  Framebuffer frame(kResolveWidth, kResolveHeight, kResolveSamples);
  const std::size_t count = static_cast<std::size_t>(frame.tiles_x()) * frame.tiles_y() * 64 *
                            static_cast<std::size_t>(kResolveSamples);
  std::uint32_t state = 12345;
  for (std::size_t i = 0; i < count; ++i) {
    state = state * 1664525u + 1013904223u;
    frame.color_tiles()[i] = state;
  }
  return frame;
}

std::size_t sample_bytes(const Framebuffer& frame) {
  return static_cast<std::size_t>(frame.tiles_x()) * frame.tiles_y() * 64 *
         static_cast<std::size_t>(frame.samples()) * sizeof(std::uint32_t);
}

void read_samples_once(benchmark::State& state) {
  const Framebuffer frame = multisampled_frame();
  const std::uint32_t* words = frame.color_tiles();
  const std::size_t count = sample_bytes(frame) / sizeof(std::uint32_t);
  for (auto _ : state) {
    std::uint32_t sum = std::accumulate(words, words + count, std::uint32_t{0});
    benchmark::DoNotOptimize(sum);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(sample_bytes(frame)));
}

void resolve_frame(benchmark::State& state, ResolveOptions options) {
  const Framebuffer frame = multisampled_frame();
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(kResolveWidth) * kResolveHeight * 4);
  for (auto _ : state) {
    resolve(frame, rgba, options);
    benchmark::DoNotOptimize(rgba.data());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(sample_bytes(frame)));
  state.counters["pixels"] =
      benchmark::Counter(double(kResolveWidth) * kResolveHeight * double(state.iterations()),
                         benchmark::Counter::kIsRate);
}

}  // namespace

void register_resolve_benchmarks() {
  const std::string frame =
      "msaa4/" + std::to_string(kResolveWidth) + "x" + std::to_string(kResolveHeight);
  benchmark::RegisterBenchmark(("Resolve/read_samples_once/" + frame).c_str(), read_samples_once)
      ->Unit(benchmark::kMicrosecond);
  struct Variant {
    ResolveFilter filter;
    bool srgb;
  };
  for (Isa isa : supported_isas()) {
    for (const Variant variant :
         {Variant{ResolveFilter::box, false}, Variant{ResolveFilter::box, true},
          Variant{ResolveFilter::tent, false}, Variant{ResolveFilter::mitchell, false}}) {
      for (std::size_t threads : {std::size_t{1}, std::size_t{0}}) {
        if (threads == 0 && isa == Isa::reference) continue;
        const std::string name = "Resolve/" + std::string(name_of(isa)) + "/" +
                                 std::string(name_of(variant.filter)) +
                                 (variant.srgb ? "/srgb/" : "/linear/") +
                                 (threads == 1 ? "threads:1/" : "threads:all/") + frame;
        const ResolveOptions options{variant.filter, 1, variant.srgb, isa, threads, {}};
        benchmark::internal::Benchmark* benchmark =
            benchmark::RegisterBenchmark(name.c_str(), resolve_frame, options)
                ->Unit(benchmark::kMicrosecond);
        if (threads != 1) benchmark->UseRealTime();  // the calling thread's CPU time is not it
      }
    }
  }
}

}  // namespace edgewise::bench
