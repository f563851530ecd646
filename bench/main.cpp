// edgewise-bench: every benchmark of the library in one binary.
#include <benchmark/benchmark.h>

#include <string>
#include <string_view>

#include "benchmarks.hpp"
#include "edgewise/edgewise.hpp"
#if defined(EDGEWISE_BENCH_LLVMPIPE)
#include "llvmpipe_peer.hpp"
#include "peer_process.hpp"
#endif

int main(int argc, char** argv) {
#if defined(EDGEWISE_BENCH_LLVMPIPE)
  // The binary started again as a DrawPeer/ benchmark's llvmpipe process (draw_peer_bench.cpp).
  if (argc == 2 && std::string_view(argv[1]) == edgewise::bench::kPeerChildFlag)
    return edgewise::bench::serve_llvmpipe_peer(edgewise::bench::kPeerChildFd);
#endif
  edgewise::bench::register_coverage_benchmarks();
  edgewise::bench::register_area_benchmarks();
  edgewise::bench::register_clip_benchmarks();
  edgewise::bench::register_draw_benchmarks();
  edgewise::bench::register_resolve_benchmarks();
  edgewise::bench::register_occlusion_benchmarks();
#if defined(EDGEWISE_BENCH_MOC)
  edgewise::bench::register_moc_peer_benchmarks();
#endif
#if defined(EDGEWISE_BENCH_SAMPLING)
  edgewise::bench::register_sample_benchmarks();
  edgewise::bench::register_textured_draw_benchmarks();
#endif
#if defined(EDGEWISE_BENCH_MESHES)
  edgewise::bench::register_mesh_draw_benchmarks();
  edgewise::bench::register_city_benchmarks();
#endif
#if defined(EDGEWISE_BENCH_BUDGET)
  edgewise::bench::register_budget_draw_benchmarks();
#endif
#if defined(EDGEWISE_BENCH_LLVMPIPE)
  edgewise::bench::register_draw_peer_benchmarks();
#endif

  std::string supported;
  for (edgewise::Isa isa : edgewise::supported_isas()) {
    if (!supported.empty()) supported += ",";
    supported += edgewise::name_of(isa);
  }
  benchmark::AddCustomContext("edgewise_supported_isas", supported);
  benchmark::AddCustomContext("edgewise_active_isa",
                              std::string(edgewise::name_of(edgewise::active_isa())));

  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
