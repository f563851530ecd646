// City/<isa>/<whole|culled>: the procedural city (testing/scene/city.hpp) at 1280x720 from its
// street-level camera, drawn whole and with occlusion culling (city_frame.hpp), one frame per
// iteration on all threads; the culled frame counts the objects it drew. BoxQueries/<isa>/city:
// its queries alone.
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

void city_frame(benchmark::State& state, Isa isa, bool culled) {
  const scene::City& city = bench_city();
  const Mat4 view = scene::city_view(city, static_cast<float>(kCityWidth) / kCityHeight);
  scene::CityFrameOptions options;
  options.isa = isa;
  Framebuffer target(kCityWidth, kCityHeight);
  OcclusionBuffer occlusion(kCityWidth, kCityHeight);
  scene::Mesh visible;
  scene::CityFrame frame;
  for (auto _ : state) {
    frame = culled ? scene::draw_city_culled(target, occlusion, city, view, options, visible)
                   : scene::draw_city(target, city, view, options);
    benchmark::DoNotOptimize(target.color_tiles());
  }
  state.counters["objects_drawn"] = static_cast<double>(frame.objects_drawn);
  state.counters["objects"] = static_cast<double>(city.objects.size());
}

// The culled frame's queries alone: every tree's box against the buildings' and ground's depth.
void city_box_queries(benchmark::State& state, Isa isa) {
  const scene::City& city = bench_city();
  const Mat4 view = scene::city_view(city, static_cast<float>(kCityWidth) / kCityHeight);
  scene::CityFrameOptions options;
  options.isa = isa;
  Framebuffer target(kCityWidth, kCityHeight);
  OcclusionBuffer occlusion(kCityWidth, kCityHeight);
  scene::Mesh visible;
  scene::draw_city_culled(target, occlusion, city, view, options, visible);
  std::vector<OcclusionBox> boxes;
  for (std::size_t i = city.first_prop(); i < city.objects.size(); ++i)
    boxes.push_back({city.objects[i].bounds.min, city.objects[i].bounds.max});
  std::vector<Visibility> answers(boxes.size());
  for (auto _ : state) {
    occlusion.test_boxes(boxes, view, answers, isa);
    benchmark::DoNotOptimize(answers.data());
  }
  state.counters["queries"] = benchmark::Counter(
      static_cast<double>(boxes.size() * state.iterations()), benchmark::Counter::kIsRate);
}

}  // namespace

void register_city_benchmarks() {
  for (Isa isa : supported_isas()) {
    const std::string name = "BoxQueries/" + std::string(name_of(isa)) + "/city";
    benchmark::RegisterBenchmark(name.c_str(), city_box_queries, isa)
        ->Unit(benchmark::kMillisecond);
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
