// City/<isa>/<whole|culled>: the procedural city (testing/scene/city.hpp) at 1280x720 from its
// street-level camera, drawn whole and with occlusion culling (city_frame.hpp), one frame per
// iteration on all threads; the culled frame counts the objects it drew. BoxQueries/<isa>/city
// [/threads:all]: its queries alone, on one thread or all.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "../benchmarks.hpp"
#include "edgewise/edgewise.hpp"
#include "scene/city.hpp"
#include "scene/city_frame.hpp"

namespace edgewise::bench {
namespace {

constexpr std::int32_t kCityWidth = 1280, kCityHeight = 720;

const scene::City& bench_city() {
  static const scene::City city = scene::make_city();
  return city;
}

// What a frame of the city needs, for one ISA.
struct CityRun {
  explicit CityRun(Isa isa)
      : city(bench_city()),
        view(scene::city_view(city, static_cast<float>(kCityWidth) / kCityHeight)),
        target(kCityWidth, kCityHeight),
        occlusion(kCityWidth, kCityHeight) {
    options.isa = isa;
  }
  scene::CityFrame culled_frame() {
    return scene::draw_city_culled(target, occlusion, city, view, options, visible);
  }

  const scene::City& city;
  Mat4 view;
  scene::CityFrameOptions options;
  Framebuffer target;
  OcclusionBuffer occlusion;
  scene::Mesh visible;
};

void city_frame(benchmark::State& state, Isa isa, bool culled) {
  CityRun run(isa);
  scene::CityFrame frame;
  for (auto _ : state) {
    frame =
        culled ? run.culled_frame() : scene::draw_city(run.target, run.city, run.view, run.options);
    benchmark::DoNotOptimize(run.target.color_tiles());
  }
  state.counters["objects_drawn"] = static_cast<double>(frame.objects_drawn);
  state.counters["objects"] = static_cast<double>(run.city.objects.size());
}

// The culled frame's queries alone: every tree's box against the buildings' and ground's depth,
// on `threads` (0: all).
void city_box_queries(benchmark::State& state, Isa isa, std::size_t threads) {
  CityRun run(isa);
  run.culled_frame();
  std::vector<OcclusionBox> boxes;
  for (std::size_t i = run.city.first_prop(); i < run.city.objects.size(); ++i)
    boxes.push_back({run.city.objects[i].bounds.min, run.city.objects[i].bounds.max});
  std::vector<Visibility> answers(boxes.size());
  OcclusionOptions options;
  options.transform = run.view;
  options.isa = isa;
  options.threads = threads;
  for (auto _ : state) {
    run.occlusion.test_boxes(boxes, answers, options);
    benchmark::DoNotOptimize(answers.data());
  }
  state.counters["queries"] = benchmark::Counter(
      static_cast<double>(boxes.size() * state.iterations()), benchmark::Counter::kIsRate);
}

}  // namespace

void register_city_benchmarks() {
  for (Isa isa : supported_isas()) {
    for (const std::size_t threads : {std::size_t{1}, std::size_t{0}}) {
      const std::string name = "BoxQueries/" + std::string(name_of(isa)) + "/city" +
                               (threads == 1 ? "" : "/threads:all");
      benchmark::RegisterBenchmark(name.c_str(), city_box_queries, isa, threads)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
  }
  for (Isa isa : supported_isas()) {
    if (isa == Isa::reference) continue;  // the whole city takes the reference seconds a frame
    for (const bool culled : {false, true}) {
      const std::string name =
          "City/" + std::string(name_of(isa)) + (culled ? "/culled" : "/whole");
      benchmark::RegisterBenchmark(name.c_str(), city_frame, isa, culled)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
  }
}

}  // namespace edgewise::bench
