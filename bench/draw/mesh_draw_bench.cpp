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
// (schedule_model.hpp), and model_serial16, the calling thread's share in that 16-thread draw.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "../benchmarks.hpp"
#include "edgewise/edgewise.hpp"
#include "mesh_scenes.hpp"
#include "phase_profile.hpp"
#include "schedule_model.hpp"

namespace edgewise::bench {
namespace {

// The speed-up on `threads` threads that a serial share `s` of the one-thread time allows.
double amdahl_bound(double s, double threads) {
  return 1.0 / (s + (1.0 - s) / threads);
}

// Draws profiled after the timed ones.
constexpr int kProfiledDraws = 20;

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
  if (threads != 1 && iterations > 0) {
    const auto prepare = [&] { target.clear(kMeshClearColor, kMeshClearDepth); };
    const auto draw_with = [&](const DrawOptions& with) { draw(target, mesh, with); };
    DrawOptions one = options;
    one.threads = 1;
    const double one_thread = median_seconds(prepare, [&] { draw_with(one); });
    // Where each thread's time goes (phase_profile.hpp), over draws of their own: the built-in
    // executor wrapped to time each task (so these draws do not call its threads up early).
    PhaseProfile profile(threads != 0 ? threads : default_thread_count());
    DrawOptions profiled = options;
    profiled.executor = profile.executor();
    for (int i = 0; i < kProfiledDraws; ++i) {
      prepare();
      profile.begin_draw();
      draw_with(profiled);
      profile.end_draw();
    }
    const PhaseProfile::Shares shares = profile.shares();
    const double share = shares.serial * shares.wall / one_thread;
    state.counters["serial_share"] = share;
    state.counters["amdahl16"] = amdahl_bound(share, 16.0);
    state.counters["amdahl64"] = amdahl_bound(share, 64.0);
    state.counters["share_busy"] = shares.busy;
    state.counters["share_waking"] = shares.waking;
    state.counters["share_between"] = shares.between;
    state.counters["share_tail"] = shares.tail;
    state.counters["share_serial"] = shares.serial;
    state.counters["work_ratio"] = shares.work / one_thread;
    state.counters["phases"] = shares.phases;
    state.counters["tasks"] = shares.tasks;
    std::vector<double> model_work;
    double model_serial = 0.0;
    state.counters["model16"] =
        one_thread / modelled_seconds(options, 16, prepare, draw_with, &model_work, &model_serial);
    state.counters["model_serial16"] = model_serial / one_thread;
    state.counters["model64"] = one_thread / modelled_seconds(options, 64, prepare, draw_with);
    double model_total = 0.0;
    for (double work : model_work)
      model_total += work;
    state.counters["model_work_ratio"] = model_total / one_thread;
    // Each phase's wall-clock share, and its tasks' time on these threads over their time one
    // after the other (the model's, made for 16 threads: only when the draw ran its phases).
    const bool same_phases = model_work.size() == shares.phase_walls.size();
    for (std::size_t p = 0; p < shares.phase_walls.size(); ++p) {
      const std::string phase = "phase" + std::to_string(p + 1);
      state.counters[phase] = shares.phase_walls[p];
      if (same_phases && model_work[p] > 0.0)
        state.counters[phase + "_work"] = shares.phase_work[p] / model_work[p];
    }
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
