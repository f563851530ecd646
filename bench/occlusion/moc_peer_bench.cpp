// Intel's Masked Occlusion Culling (MOC) on the workloads of occlusion_bench.cpp, in the same
// binary: OccluderPeer/moc/<isa>/size:<px>[/threads:all] renders the fill-rate triangles as
// MOC's FillrateTest does (clip-space vertices whose w orders them nearest last, no clipping, a
// CullingThreadpool of one thread fewer than the cores, two bins by as many as threads), and
// RectQueryPeer/moc/<isa> tests the same rectangles against the same occluders. Built only
// against a MOC library given to CMake (EDGEWISE_MOC_DIR, bench/README.md).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "../benchmarks.hpp"
#include "CullingThreadpool.h"
#include "MaskedOcclusionCulling.h"
#include "fillrate_triangles.hpp"
#include "occlusion_workloads.hpp"

namespace edgewise::bench {
namespace {

struct MocDeleter {
  void operator()(MaskedOcclusionCulling* moc) const { MaskedOcclusionCulling::Destroy(moc); }
};
using Moc = std::unique_ptr<MaskedOcclusionCulling, MocDeleter>;

Moc make_moc(MaskedOcclusionCulling::Implementation simd) {
  Moc moc(MaskedOcclusionCulling::Create(simd));
  moc->SetResolution(kWidth, kHeight);
  moc->SetNearClipPlane(0.0f);
  moc->ClearBuffer();
  return moc;
}

// MOC's vertices: (x, y, z, w) in clip space with w the triangle's order, so that 1/w, MOC's
// depth, orders the triangles as z/w orders them for edgewise; indices 0, 1, 2, ...
struct MocMesh {
  std::vector<float> vertices;
  std::vector<unsigned> indices;
};

MocMesh moc_mesh(const FillrateTriangles& t) {
  MocMesh mesh;
  for (std::size_t i = 0; i < t.ndc.size(); ++i) {
    const float w = t.clip_w[i];
    mesh.vertices.insert(mesh.vertices.end(), {t.ndc[i].x * w, t.ndc[i].y * w, t.ndc[i].z * w, w});
    mesh.indices.push_back(static_cast<unsigned>(i));
  }
  return mesh;
}

bool implementation_matches(MaskedOcclusionCulling& moc,
                            MaskedOcclusionCulling::Implementation simd) {
  return moc.GetImplementation() == simd;
}

void moc_occluders(benchmark::State& state, MaskedOcclusionCulling::Implementation simd, int size,
                   bool all_threads) {
  const FillrateTriangles& triangles = fillrate_triangles(size, fillrate_count(size));
  const MocMesh mesh = moc_mesh(triangles);
  const Moc moc = make_moc(simd);
  if (!implementation_matches(*moc, simd)) {
    state.SkipWithError("this CPU runs another MOC implementation than the one asked for");
    return;
  }
  const int count = static_cast<int>(triangles.triangles());
  if (!all_threads) {
    for (auto _ : state) {
      state.PauseTiming();
      moc->ClearBuffer();
      state.ResumeTiming();
      moc->RenderTriangles(mesh.vertices.data(), mesh.indices.data(), count, nullptr,
                           MaskedOcclusionCulling::BACKFACE_NONE,
                           MaskedOcclusionCulling::CLIP_PLANE_NONE);
    }
  } else {
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency() - 1);
    CullingThreadpool pool(threads, 2, threads);
    pool.SetBuffer(moc.get());
    pool.WakeThreads();
    for (auto _ : state) {
      state.PauseTiming();
      pool.ClearBuffer();
      pool.Flush();
      state.ResumeTiming();
      pool.RenderTriangles(mesh.vertices.data(), mesh.indices.data(), count,
                           MaskedOcclusionCulling::BACKFACE_NONE,
                           MaskedOcclusionCulling::CLIP_PLANE_NONE);
      pool.Flush();
    }
    pool.SuspendThreads();
  }
  state.counters["triangles"] =
      benchmark::Counter(static_cast<double>(count) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

void moc_rect_queries(benchmark::State& state, MaskedOcclusionCulling::Implementation simd) {
  const Moc moc = make_moc(simd);
  if (!implementation_matches(*moc, simd)) {
    state.SkipWithError("this CPU runs another MOC implementation than the one asked for");
    return;
  }
  const MocMesh mesh = moc_mesh(fillrate_triangles(kQuerySceneSize, kQuerySceneTriangles));
  moc->RenderTriangles(
      mesh.vertices.data(), mesh.indices.data(), static_cast<int>(kQuerySceneTriangles), nullptr,
      MaskedOcclusionCulling::BACKFACE_NONE, MaskedOcclusionCulling::CLIP_PLANE_NONE);
  // The rectangles in NDC (y up), each depth z as the w of the triangle at that depth.
  struct NdcRect {
    float xmin, ymin, xmax, ymax, wmin;
  };
  std::vector<NdcRect> rects;
  for (const OcclusionRect& r : query_rects()) {
    rects.push_back({r.x0 / kWidth * 2.0f - 1.0f, 1.0f - r.y1 / kHeight * 2.0f,
                     r.x1 / kWidth * 2.0f - 1.0f, 1.0f - r.y0 / kHeight * 2.0f,
                     r.depth * static_cast<float>(kQuerySceneTriangles)});
  }
  std::size_t occluded = 0;
  for (auto _ : state) {
    occluded = 0;
    for (const NdcRect& r : rects) {
      occluded +=
          moc->TestRect(r.xmin, r.ymin, r.xmax, r.ymax, r.wmin) == MaskedOcclusionCulling::OCCLUDED;
    }
    benchmark::DoNotOptimize(occluded);
  }
  state.counters["queries"] = benchmark::Counter(
      static_cast<double>(rects.size()) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
  state.counters["occluded_share"] = static_cast<double>(occluded) / rects.size();
}

}  // namespace

void register_moc_peer_benchmarks() {
  const std::pair<MaskedOcclusionCulling::Implementation, const char*> kSimd[] = {
      {MaskedOcclusionCulling::AVX2, "avx2"}, {MaskedOcclusionCulling::AVX512, "avx512"}};
  for (const auto& [simd, name] : kSimd) {
    for (const int size : kFillrateSizes) {
      for (const bool all : {false, true}) {
        const std::string bench = "OccluderPeer/moc/" + std::string(name) +
                                  "/size:" + std::to_string(size) + (all ? "/threads:all" : "");
        benchmark::RegisterBenchmark(bench.c_str(), moc_occluders, simd, size, all)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
      }
    }
    const std::string bench = "RectQueryPeer/moc/" + std::string(name);
    benchmark::RegisterBenchmark(bench.c_str(), moc_rect_queries, simd)
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace edgewise::bench
