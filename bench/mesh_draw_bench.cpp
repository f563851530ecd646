// MeshDraw/<isa>/<mesh> and MeshDraw/<isa>/threads:all/<mesh>: draw() on real meshes
// (mesh_scenes.hpp: the OBJ files of EDGEWISE_BENCH_MESHES, per-pixel diffuse, back faces
// culled, perspective), on one thread and on every core (wall-clock time), for every vectorized
// ISA. One iteration is one draw() call of the whole mesh into a 1920x1080 target cleared before
// it with the timer paused. Counters: triangles (of the mesh), fragments (covered samples) and
// written (passing the depth test) as rates, and culled (the share of triangles culled: about
// half for a closed mesh). On every core, also serial_share: the calling thread's time outside
// the draw's tasks (the built-in executor, wrapped to time its runs) over the time of a draw on
// one thread, and the speed-ups that Amdahl's law allows with that share on 16 and 64 threads
// (amdahl16, amdahl64), so that a machine of few cores shows what would stop many from scaling;
// and model16, model64: the speed-up on 16 and 64 threads of the draw's own schedule (its serial
// part, its phases' task counts and their balance), from its tasks timed one by one
// (schedule_model.hpp).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "benchmarks.hpp"
#include "edgewise/edgewise.hpp"
#include "mesh_scenes.hpp"
#include "schedule_model.hpp"

namespace edgewise::bench {
namespace {

using Clock = std::chrono::steady_clock;

// The speed-up on `threads` threads that a serial share `s` of the one-thread time allows.
double amdahl_bound(double s, double threads) {
  return 1.0 / (s + (1.0 - s) / threads);
}

void mesh_draw(benchmark::State& state, Isa isa, const MeshScene* scene, std::size_t threads) {
  const DrawMesh mesh = draw_mesh(*scene);
  DrawOptions options = mesh_options(isa, *scene);
  options.threads = threads;
  // On several threads, the time the draw's tasks take, from the calling thread's side.
  Clock::duration in_tasks{}, drawing{};
  if (threads != 1) {
    const TaskExecutor builtin = builtin_executor(threads);
    options.executor = [&in_tasks, builtin](std::size_t count,
                                            const std::function<void(std::size_t)>& task) {
      const Clock::time_point start = Clock::now();
      builtin(count, task);
      in_tasks += Clock::now() - start;
    };
  }
  Framebuffer target(kWidth, kHeight);
  DrawReport last;
  for (auto _ : state) {
    state.PauseTiming();
    target.clear(kMeshClearColor, kMeshClearDepth);
    state.ResumeTiming();
    const Clock::time_point start = Clock::now();
    last = draw(target, mesh, options);
    drawing += Clock::now() - start;
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
  if (threads != 1 && iterations > 0) {
    const double serial_seconds =
        std::chrono::duration<double>(drawing - in_tasks).count() / iterations;
    const auto prepare = [&] { target.clear(kMeshClearColor, kMeshClearDepth); };
    const auto draw_with = [&](const DrawOptions& with) { draw(target, mesh, with); };
    DrawOptions one = options;
    one.threads = 1;
    one.executor = {};
    const double one_thread = median_seconds(prepare, [&] { draw_with(one); });
    const double share = serial_seconds / one_thread;
    state.counters["serial_share"] = share;
    state.counters["amdahl16"] = amdahl_bound(share, 16.0);
    state.counters["amdahl64"] = amdahl_bound(share, 64.0);
    state.counters["model16"] = one_thread / modelled_seconds(options, 16, prepare, draw_with);
    state.counters["model64"] = one_thread / modelled_seconds(options, 64, prepare, draw_with);
  }
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
