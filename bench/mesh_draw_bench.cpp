// MeshDraw/<isa>/<mesh> and MeshDraw/<isa>/threads:all/<mesh>: draw() on real meshes
// (mesh_scenes.hpp: the OBJ files of EDGEWISE_BENCH_MESHES, per-pixel diffuse, back faces
// culled, perspective), on one thread and on every core (wall-clock time), for every vectorized
// ISA. One iteration is one draw() call of the whole mesh into a 1920x1080 target cleared before
// it with the timer paused. Counters: triangles (of the mesh), fragments (covered samples) and
// written (passing the depth test) as rates, and culled (the share of triangles culled: about
// half for a closed mesh).
#include <benchmark/benchmark.h>

#include <string>

#include "benchmarks.hpp"
#include "edgewise/edgewise.hpp"
#include "mesh_scenes.hpp"

namespace edgewise::bench {
namespace {

void mesh_draw(benchmark::State& state, Isa isa, const MeshScene* scene, std::size_t threads) {
  const DrawMesh mesh = draw_mesh(*scene);
  DrawOptions options = mesh_options(isa, *scene);
  options.threads = threads;
  Framebuffer target(kWidth, kHeight);
  DrawReport last;
  for (auto _ : state) {
    state.PauseTiming();
    target.clear(kMeshClearColor, kMeshClearDepth);
    state.ResumeTiming();
    last = draw(target, mesh, options);
    benchmark::DoNotOptimize(target.color_tiles());
    benchmark::ClobberMemory();
  }
  if (last.isa != isa) state.SkipWithError("draw() ran another ISA than the one asked for");
  if (last.errors != 0 || last.fragments_passed == 0)
    state.SkipWithError("the mesh has bad triangles or draws nothing");
  const double iterations = double(state.iterations());
  const auto rate = [&](double per_call) {
    return benchmark::Counter(per_call * iterations, benchmark::Counter::kIsRate);
  };
  state.counters["triangles"] = rate(double(last.triangles));
  state.counters["fragments"] = rate(double(last.fragments));
  state.counters["written"] = rate(double(last.fragments_passed));
  state.counters["culled"] =
      last.triangles > 0 ? double(last.culled) / double(last.triangles) : 0.0;
}

}  // namespace

void register_mesh_draw_benchmarks() {
  for (Isa isa : supported_isas()) {
    if (isa == Isa::reference) continue;
    for (const MeshScene& scene : mesh_scenes()) {
      const std::string name = "MeshDraw/" + std::string(name_of(isa)) + "/" + scene.name;
      benchmark::RegisterBenchmark(name.c_str(), mesh_draw, isa, &scene, std::size_t{1})
          ->Unit(benchmark::kMicrosecond);
      const std::string all =
          "MeshDraw/" + std::string(name_of(isa)) + "/threads:all/" + scene.name;
      benchmark::RegisterBenchmark(all.c_str(), mesh_draw, isa, &scene, std::size_t{0})
          ->Unit(benchmark::kMicrosecond)
          ->UseRealTime();
    }
  }
}

}  // namespace edgewise::bench
