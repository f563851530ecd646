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
// (modelled_seconds()).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>
#include <queue>
#include <string>
#include <vector>

#include "benchmarks.hpp"
#include "edgewise/edgewise.hpp"
#include "mesh_scenes.hpp"

namespace edgewise::bench {
namespace {

using Clock = std::chrono::steady_clock;

// The median time of one-thread draws of `mesh`, in seconds.
double one_thread_seconds(const DrawMesh& mesh, DrawOptions options, Framebuffer& target) {
  options.threads = 1;
  options.executor = {};
  std::vector<double> seconds;
  for (int i = 0; i < 5; ++i) {
    target.clear(kMeshClearColor, kMeshClearDepth);
    const Clock::time_point start = Clock::now();
    draw(target, mesh, options);
    seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  std::nth_element(seconds.begin(), seconds.begin() + 2, seconds.end());
  return seconds[2];
}

// The speed-up on `threads` threads that a serial share `s` of the one-thread time allows.
double amdahl_bound(double s, double threads) {
  return 1.0 / (s + (1.0 - s) / threads);
}

// The time `tasks` (seconds each) take when dealt, in order, each to whichever of `workers`
// workers is free first: how a dynamic scheduler spreads them.
double makespan(const std::vector<double>& tasks, std::size_t workers) {
  std::priority_queue<double, std::vector<double>, std::greater<>> free_at;
  for (std::size_t w = 0; w < workers; ++w)
    free_at.push(0.0);
  double end = 0.0;
  for (double task : tasks) {
    const double finish = free_at.top() + task;
    free_at.pop();
    free_at.push(finish);
    end = std::max(end, finish);
  }
  return end;
}

// The time of a draw made for `threads` threads (their bins and ranges) on as many cores, as its
// schedule allows: the draw's tasks are run one after the other on the calling thread, each
// timed, and every phase (one executor call) then takes its makespan() on `threads` workers,
// added to the calling thread's time outside the tasks. The median of five draws. What the
// cores would share (memory bandwidth, the last-level cache) is not in it: it models the
// schedule (serial parts, task counts, balance), as Amdahl's bound models the serial share.
double modelled_seconds(const DrawMesh& mesh, DrawOptions options, Framebuffer& target,
                        std::size_t threads) {
  std::vector<std::vector<double>> phases;
  options.threads = threads;
  options.executor = [&phases](std::size_t count, const std::function<void(std::size_t)>& task) {
    std::vector<double>& times = phases.emplace_back(count);
    for (std::size_t i = 0; i < count; ++i) {
      const Clock::time_point start = Clock::now();
      task(i);
      times[i] = std::chrono::duration<double>(Clock::now() - start).count();
    }
  };
  std::vector<double> seconds;
  for (int i = 0; i < 5; ++i) {
    target.clear(kMeshClearColor, kMeshClearDepth);
    phases.clear();
    const Clock::time_point start = Clock::now();
    draw(target, mesh, options);
    double modelled = std::chrono::duration<double>(Clock::now() - start).count();
    for (const std::vector<double>& phase : phases) {
      for (double task : phase)
        modelled -= task;
      modelled += makespan(phase, threads);
    }
    seconds.push_back(modelled);
  }
  std::nth_element(seconds.begin(), seconds.begin() + 2, seconds.end());
  return seconds[2];
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
    const double one_thread = one_thread_seconds(mesh, options, target);
    const double share = serial_seconds / one_thread;
    state.counters["serial_share"] = share;
    state.counters["amdahl16"] = amdahl_bound(share, 16.0);
    state.counters["amdahl64"] = amdahl_bound(share, 64.0);
    state.counters["model16"] = one_thread / modelled_seconds(mesh, options, target, 16);
    state.counters["model64"] = one_thread / modelled_seconds(mesh, options, target, 64);
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
