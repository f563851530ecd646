// Textured drawing throughput through draw(): the sampling benchmarks' ground-plane view drawn as
// geometry (texture_scene::view_mesh(): two screen-filling triangles whose perspective-correct
// interpolation is the view's mapping) at 1920 x 1080 with the same 1024 x 1024 checkerboard,
// for every filter and both derivative methods. With analytic derivatives the sampler sees the
// same queries as Sample/<isa>/<filter>/ground_plane (up to float rounding), so the two rates
// side by side show what drawing adds to sampling: coverage, depth, the texture coordinates and
// derivatives, the colour write.
//
// TexturedDraw/<isa>/<filter>/<derivatives>, and /<precision> after it for the common filters
// made of bilinear taps: the FilterPrecision the default does not use. One iteration is one
// draw() call (white flat shading, depth test less; the framebuffer cleared with the timer
// paused); items are pixels; rmse and psnr_db against ground truth when it is stored
// (bench_texture.hpp).
// AVX2 (or NEON) runs every filter with both methods; the other ISAs bilinear, trilinear and
// anisotropic with quad derivatives; the reference bilinear and trilinear on a quarter of the
// screen (its scissor), as it takes about a second per full frame.
// TexturedDraw/<isa>/threads:all/<filter>/quad: bilinear, trilinear and anisotropic on every
// core (wall-clock time), for every vectorized ISA, with model16 and model64: the speed-ups the
// draw's schedule allows on 16 and 64 threads (schedule_model.hpp).
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "bench_texture.hpp"
#include "../benchmarks.hpp"
#include "edgewise/edgewise.hpp"
#include "../draw/schedule_model.hpp"

namespace edgewise::bench {
namespace {

void textured_draw(benchmark::State& state, Isa isa, TextureFilter filter,
                   TextureDerivatives derivatives, std::size_t threads, FilterPrecision precision) {
  const texture_scene::ViewMesh& mesh = ground_plane_mesh();
  DrawOptions options = ground_plane_options(isa, filter, derivatives);
  options.threads = threads;
  options.texture->sampler.precision = precision;
  std::uint64_t pixels = static_cast<std::uint64_t>(kWidth) * kHeight;
  if (isa == Isa::reference) {
    options.scissor = PixelRect{0, 0, kWidth / 2, kHeight / 2};
    pixels /= 4;
  }
  Framebuffer target(kWidth, kHeight);
  for (auto _ : state) {
    state.PauseTiming();
    target.clear(kGroundPlaneClearColor, kGroundPlaneClearDepth);
    state.ResumeTiming();
    const DrawReport report = draw(target, mesh.mesh(), options);
    if (report.fragments_passed != pixels) {
      state.SkipWithError("the view did not cover every pixel exactly once");
      return;
    }
    benchmark::DoNotOptimize(target.color_tiles());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(pixels));
  if (threads != 1) {  // the speed-ups the draw's schedule allows on 16 and 64 threads
    const auto prepare = [&] { target.clear(kGroundPlaneClearColor, kGroundPlaneClearDepth); };
    const auto draw_with = [&](const DrawOptions& with) { draw(target, mesh.mesh(), with); };
    DrawOptions one = options;
    one.threads = 1;
    const double one_thread = median_seconds(prepare, [&] { draw_with(one); });
    state.counters["model16"] = one_thread / modelled_seconds(options, 16, prepare, draw_with);
    state.counters["model64"] = one_thread / modelled_seconds(options, 64, prepare, draw_with);
  }
  if (isa == Isa::reference) return;  // a quarter of the screen
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(pixels) * 4);
  target.read_rgba8(rgba);
  std::vector<Vec4> colours(static_cast<std::size_t>(pixels));
  for (std::size_t i = 0; i < colours.size(); ++i) {
    colours[i] = {rgba[4 * i] / 255.0f, rgba[4 * i + 1] / 255.0f, rgba[4 * i + 2] / 255.0f,
                  rgba[4 * i + 3] / 255.0f};
  }
  report_error(state, "ground_plane", ground_plane(), colours);
}

}  // namespace

void register_textured_draw_benchmarks() {
  for (Isa isa : supported_isas()) {
    for (int f = 0; f <= static_cast<int>(TextureFilter::ewa); ++f) {
      const auto filter = static_cast<TextureFilter>(f);
      for (TextureDerivatives derivatives :
           {TextureDerivatives::quad, TextureDerivatives::analytic}) {
        const bool widest = isa == compiled_isas().back();  // the best ISA compiled
        const bool common = filter == TextureFilter::bilinear ||
                            filter == TextureFilter::trilinear ||
                            (filter == TextureFilter::anisotropic && isa != Isa::reference);
        if (!widest && !(common && derivatives == TextureDerivatives::quad)) continue;
        const std::string name = "TexturedDraw/" + std::string(name_of(isa)) + "/" +
                                 std::string(name_of(filter)) + "/" +
                                 std::string(name_of(derivatives));
        benchmark::RegisterBenchmark(name.c_str(), textured_draw, isa, filter, derivatives,
                                     std::size_t{1}, FilterPrecision::automatic)
            ->Unit(benchmark::kMillisecond);
        if (isa == Isa::reference || !common || derivatives != TextureDerivatives::quad) continue;
        // The other precision of the taps beside the default, named by a suffix.
        if (reads_bilinear_taps(filter)) {
          const FilterPrecision other = other_precision(filter);
          benchmark::RegisterBenchmark((name + "/" + std::string(name_of(other))).c_str(),
                                       textured_draw, isa, filter, derivatives, std::size_t{1},
                                       other)
              ->Unit(benchmark::kMillisecond);
        }
        const std::string all = "TexturedDraw/" + std::string(name_of(isa)) + "/threads:all/" +
                                std::string(name_of(filter)) + "/quad";
        benchmark::RegisterBenchmark(all.c_str(), textured_draw, isa, filter, derivatives,
                                     std::size_t{0}, FilterPrecision::automatic)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
      }
    }
  }
}

}  // namespace edgewise::bench
