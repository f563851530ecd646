// Benchmarks that depend on the CPU (one per supported ISA) are registered at run time.
#pragma once

namespace edgewise::bench {

// The target every benchmark draws into (full HD).
inline constexpr int kWidth = 1920, kHeight = 1080;

// Coverage/<isa>/area:<px> for every supported ISA, the reference included.
void register_coverage_benchmarks();

// Area/<isa>/area:<px>: rasterize_areas() (exact-area coverage) for every supported ISA and the
// reference (the reference up to 1000 px).
void register_area_benchmarks();

// Clip/<float32|reference>/<inside|near|guard_band>: clip_triangle() against its reference.
void register_clip_benchmarks();

// Shading/<isa>/area:<px> (the peer-comparable draw() workload) and
// ShadingMethod/<isa>/<method>/<perspective>/area:<px>, for every supported ISA and the reference.
void register_draw_benchmarks();

// Resolve/<isa>/<filter>/<linear|srgb>/<threads:1|threads:all>/msaa4/1280x720[/real_time]:
// resolve() of a 4x multisampled frame, and Resolve/read_samples_once/msaa4/1280x720, the time to
// read its samples once.
void register_resolve_benchmarks();

// Sample/<isa>/<filter>/<stream> for every supported ISA and the reference, and
// SamplePeer/oiio/<mode>/<stream> (OpenImageIO's TextureSystem) when it is built in.
void register_sample_benchmarks();

// TexturedDraw/<isa>/<filter>/<derivatives>: the ground-plane view drawn textured.
void register_textured_draw_benchmarks();

// MeshDraw/<isa>/[threads:all/]<mesh>: draw() on the real meshes of EDGEWISE_BENCH_MESHES
// (mesh_scenes.hpp), when built with the OBJ loader.
void register_mesh_draw_benchmarks();

// BudgetDraw/<isa>/<scene>/<exact|budget:1/255>: the demo's scenes drawn exactly and within an
// error budget of one code, when built with the procedural scenes and the texture scenes.
void register_budget_draw_benchmarks();

// DrawPeer/llvmpipe/<threads:1|threads:default>/<workload>: Mesa's llvmpipe drawing the Shading/
// workloads (also into 4- and 8-sample targets, as Multisample/), the trilinear TexturedDraw/ one
// and the MeshDraw/ meshes, when built with EGL and OpenGL.
void register_draw_peer_benchmarks();

// Occluders/<isa>/size:<px>[/threads:all]: OcclusionBuffer::draw_occluders() on Masked Occlusion
// Culling's fill-rate protocol; RectQueries/<isa>: test_rects() against a screen of occluders.
void register_occlusion_benchmarks();

// City/<isa>/<whole|culled>: the procedural city drawn whole and with occlusion culling, when
// built with the procedural scenes.
void register_city_benchmarks();

// OccluderPeer/moc/... and RectQueryPeer/moc/...: Masked Occlusion Culling on the same workloads,
// when built against it (EDGEWISE_MOC_DIR, bench/README.md).
void register_moc_peer_benchmarks();

}  // namespace edgewise::bench
