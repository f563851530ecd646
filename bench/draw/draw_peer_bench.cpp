// DrawPeer/llvmpipe/<threads>/<workload>/manual_time: Mesa's llvmpipe drawing the same work as
// Shading/<isa>/area:<px> (workload area:<px>), Multisample/<isa>/samples:<n>/area:<px>
// (area:<px>/samples:<n>, n = 4 or 8), TexturedDraw/<isa>/trilinear/quad (workload
// ground_plane/trilinear), TexturedDraw/<isa>/anisotropic/quad (ground_plane/anisotropic16) and
// MeshDraw/<isa>/<mesh> (workload mesh/<mesh>): draw_peer_workloads.hpp names the draw() calls,
// llvmpipe_peer.hpp says how OpenGL reproduces them.
//
// Threads: threads:1 runs llvmpipe with LP_NUM_THREADS=0, which makes it rasterize on the thread
// that draws (no rasterizer threads: one thread does everything, as in edgewise's benchmarks);
// threads:default leaves LP_NUM_THREADS unset (one rasterizer thread per CPU, fed by the drawing
// thread). llvmpipe reads the variable once, when EGL creates its screen, so each setting runs in
// a process of its own: the first benchmark of a setting starts this binary again
// (peer_process.hpp) with the variable set or removed, and that process serves the setting's
// benchmarks for the rest of the run. The child times each draw itself and the benchmark reports
// those times (UseManualTime), so the exchange between the processes is not counted: with
// threads:1 the process's CPU time, the measure of edgewise's one-thread benchmarks (Google
// Benchmark's CPU time), which a busy machine's other work does not inflate; with
// threads:default the wall-clock time, which is what the extra threads shorten. The counter
// cpu_per_wall is the CPU time of all the process's threads over the wall-clock time: about 1
// for threads:1, up to the number of CPUs when the rasterizer threads keep them busy.
//
// Same work, checked before timing: llvmpipe's covered and written samples (occlusion queries)
// against the fragments and fragments_passed of one edgewise draw() call of the workload.
// Covered counts must be equal, except by a few in 10^5 under a perspective transform (the
// meshes: see kPerspectiveCoveredTolerance). Written counts may differ by a few samples in a
// million: llvmpipe (Mesa 22.3) evaluates depth from a plane anchored at the window origin,
// edgewise from the triangle's first vertex (kernels/draw/shading/depth_plane.hpp), so the two
// depths of a pixel differ in their last bits (up to 4e-5 on the 8 px triangles), and where two
// triangles are that close at a pixel the depth test can go either way. A larger difference, or any
// error (no EGL, no surfaceless platform, a GL_RENDERER that is not llvmpipe), fails the benchmark
// with SkipWithError instead of timing other work.
//
// Multisampled workloads (area:<px>/samples:<n>): llvmpipe draws into multisampled renderbuffers
// of n samples, edgewise into a Framebuffer of n samples, and both count samples: GL's
// GL_SAMPLES_PASSED counts each sample of a multisampled target that passes, and llvmpipe tests
// depth at each sample's own position, as edgewise does. The covered counts must be equal: in the
// peer's frame (y negated) llvmpipe's 4x positions are the standard pattern and its fill rule is
// the top-left rule, so every sample is decided alike (tests/peer/llvmpipe_multisample_test.cpp
// shows it sample for sample); the peer refuses a sample count the driver does not offer
// (GL_MAX_SAMPLES is 4 in Mesa 22.3's llvmpipe, so samples:8 fails with that reason) or offers at
// other positions. Written counts differ for the reason above, per sample.
//
// One iteration is one draw and glFinish(); the target is cleared (and the clear finished)
// before each, untimed, as edgewise's benchmarks clear with the timer paused. Counters as
// Shading/'s: triangles, fragments (covered) and written as rates, with written_difference and
// covered_difference (llvmpipe's samples minus edgewise's, per draw); the textured workload reports
// pixels as items, as TexturedDraw/ does.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <thread>

#include "../benchmarks.hpp"
#include "draw_peer_workloads.hpp"
#include "edgewise/edgewise.hpp"
#include "../llvmpipe_peer.hpp"
#include "../peer_process.hpp"

namespace edgewise::bench {
namespace {

enum class PeerThreads { one, default_count };

std::string_view threads_label(PeerThreads threads) {
  return threads == PeerThreads::one ? "threads:1" : "threads:default";
}

// The llvmpipe settings a process gets: software rendering with llvmpipe (not a GPU driver the
// surfaceless platform might find first, nor softpipe), and the thread count.
PeerProcess::EnvironmentChanges environment_for(PeerThreads threads) {
  return {{"LIBGL_ALWAYS_SOFTWARE", "1"},
          {"GALLIUM_DRIVER", "llvmpipe"},
          {"LP_NUM_THREADS",
           threads == PeerThreads::one ? std::optional<std::string>("0") : std::nullopt}};
}

// Written samples may differ by this share (see the top of this file); the most seen is 2e-6 with
// one sample per pixel and 3.6e-6 with four.
constexpr double kWrittenTolerance = 1e-5;
// Covered samples under a perspective transform (the meshes) may differ by this share: a vertex's
// x/w and y/w, mapped to the screen and rounded to 1/256 px, land on the other side of a rounding
// boundary when llvmpipe multiplies by 1/w where edgewise divides (one ulp apart), which moves an
// edge by 1/256 px and flips the pixels whose centres lie within that distance of it. The most
// seen on the meshes is 1.4e-5 (one sample in 72784). Orthographic workloads (w = 1) must agree
// exactly.
constexpr double kPerspectiveCoveredTolerance = 1e-4;

bool is_perspective(const Mat4& transform) {
  return transform.m[3][0] != 0.0f || transform.m[3][1] != 0.0f || transform.m[3][2] != 0.0f;
}

struct Comparison {
  std::string problem;  // why the workload cannot be timed, or empty
  std::int64_t written_difference = 0;
  std::int64_t covered_difference = 0;
};

struct PeerSession {
  std::unique_ptr<PeerProcess> process;
  std::string failure;  // why this setting cannot run, or empty
  std::string label;
  std::string loaded;                             // the workload the process holds
  std::map<std::string, Comparison> comparisons;  // per loaded workload
};

PeerSession& session(PeerThreads threads) {
  static std::map<PeerThreads, PeerSession> sessions;
  auto [it, inserted] = sessions.try_emplace(threads);
  PeerSession& s = it->second;
  if (!inserted) return s;
  std::string error;
  s.process = PeerProcess::start(environment_for(threads), error);
  const std::optional<std::string> greeting = s.process ? s.process->greeting() : std::nullopt;
  if (greeting && greeting->rfind("ready ", 0) == 0) {
    s.label = greeting->substr(6) +
              (threads == PeerThreads::one
                   ? ", LP_NUM_THREADS=0"
                   : ", default threads (" + std::to_string(std::thread::hardware_concurrency()) +
                         " CPUs)");
  } else {
    if (greeting && greeting->rfind("error ", 0) == 0) error = greeting->substr(6);
    if (error.empty()) error = "the peer process ended before greeting";
    s.failure = "llvmpipe is not available: " + error;
    s.process.reset();
  }
  return s;
}

// Covered and written samples of one edgewise draw() call of the workload.
PeerCounts edgewise_counts(const PeerWorkload& workload) {
  static std::map<std::string, PeerCounts> cache;
  auto it = cache.find(workload.name);
  if (it != cache.end()) return it->second;
  Framebuffer target(kWidth, kHeight, workload.samples);
  target.clear(workload.clear_color, workload.clear_depth);
  const DrawReport report = draw(target, workload.mesh, workload.options);
  return cache[workload.name] = {report.fragments, report.fragments_passed};
}

// Loads the workload into the peer process and compares its counts with edgewise's.
Comparison prepare(PeerSession& s, const PeerWorkload& workload) {
  if (s.loaded == workload.name) return s.comparisons[workload.name];
  s.loaded.clear();
  const std::optional<std::string> reply = s.process->request("load " + workload.name);
  if (!reply) {
    s.failure = "the llvmpipe process ended";
    return {s.failure};
  }
  unsigned long long covered = 0, written = 0;
  if (std::sscanf(reply->c_str(), "counts %llu %llu", &covered, &written) != 2)
    return {reply->rfind("error ", 0) == 0 ? reply->substr(6) : *reply};
  s.loaded = workload.name;
  const PeerCounts expected = edgewise_counts(workload);
  Comparison& result = s.comparisons[workload.name];
  result.written_difference = std::int64_t(written) - std::int64_t(expected.written);
  result.covered_difference = std::int64_t(covered) - std::int64_t(expected.covered);
  const double covered_tolerance =
      is_perspective(workload.options.transform) ? kPerspectiveCoveredTolerance : 0.0;
  const double written_tolerance = kWrittenTolerance + covered_tolerance;
  if (double(std::llabs(result.covered_difference)) >
          covered_tolerance * double(expected.covered) ||
      double(std::llabs(result.written_difference)) >
          written_tolerance * double(expected.written)) {
    result.problem = "not the same work: llvmpipe covered " + std::to_string(covered) +
                     " and wrote " + std::to_string(written) + " samples, edgewise " +
                     std::to_string(expected.covered) + " and " + std::to_string(expected.written);
  }
  return result;
}

void draw_peer(benchmark::State& state, PeerThreads threads, std::string_view workload_name) {
  PeerSession& s = session(threads);
  const PeerWorkload* workload = find_peer_workload(workload_name);
  const Comparison comparison = s.failure.empty() ? prepare(s, *workload) : Comparison{s.failure};
  if (!comparison.problem.empty()) {
    state.SkipWithError(comparison.problem.c_str());
    return;
  }
  state.SetLabel(s.label);
  double total_wall = 0.0, total_cpu = 0.0;
  for (auto _ : state) {
    const std::optional<std::string> reply = s.process->request("draw");
    double wall = 0.0, cpu = 0.0;
    if (!reply || std::sscanf(reply->c_str(), "seconds %lf %lf", &wall, &cpu) != 2) {
      if (!reply) s.failure = "the llvmpipe process ended";
      state.SkipWithError(reply ? reply->c_str() : s.failure.c_str());
      break;
    }
    state.SetIterationTime(threads == PeerThreads::one ? cpu : wall);
    total_wall += wall;
    total_cpu += cpu;
  }
  state.counters["cpu_per_wall"] = total_wall > 0.0 ? total_cpu / total_wall : 0.0;
  const PeerCounts counts = edgewise_counts(*workload);
  const double iterations = double(state.iterations());
  const auto rate = [&](double per_call) {
    return benchmark::Counter(per_call * iterations, benchmark::Counter::kIsRate);
  };
  state.counters["written_difference"] = double(comparison.written_difference);
  state.counters["covered_difference"] = double(comparison.covered_difference);
  if (workload->options.texture) {
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(counts.written));
    return;
  }
  state.counters["triangles"] = rate(double(workload->triangles));
  state.counters["fragments"] = rate(double(counts.covered));
  state.counters["written"] = rate(double(counts.written));
}

}  // namespace

void register_draw_peer_benchmarks() {
  for (PeerThreads threads : {PeerThreads::one, PeerThreads::default_count}) {
    for (std::string_view workload : peer_workload_names()) {
      const std::string name =
          "DrawPeer/llvmpipe/" + std::string(threads_label(threads)) + "/" + std::string(workload);
      benchmark::RegisterBenchmark(name.c_str(), draw_peer, threads, workload)
          ->UseManualTime()
          ->Unit(workload.rfind("area:", 0) == 0 ? benchmark::kMicrosecond
                                                 : benchmark::kMillisecond);
    }
  }
}

}  // namespace edgewise::bench
