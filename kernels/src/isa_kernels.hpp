// The kernels every ISA defines in its own namespace, one translation unit per capability
// (kernels/isa/coverage.cpp, draw.cpp, resolve.cpp, sample.cpp), gathered into its table by
// kernels/isa/kernel_table.cpp. Included after isa_build.hpp.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kernel_table.hpp"
#include "sample_kernels.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// coverage.cpp
void rasterize(const detail::TriangleBatch& batch, CoverageSink& sink, RasterReport& report);
void count_coverage(const detail::TriangleBatch& batch, RasterReport& report,
                    std::uint64_t& pixels);
void rasterize_areas(const detail::TriangleBatch& batch, AreaSink& sink, RasterReport& report);

// draw.cpp
void transform_vertices(const Mat4& m, const Vec3* in, std::size_t count, Vec4* out);
void map_vertices(const detail::VertexStageCall& call, std::size_t first, std::size_t last,
                  detail::ScreenMesh& out, std::int32_t* codes);
void assemble_triangles(const detail::VertexStageCall& call, const std::int32_t* codes,
                        std::size_t first, std::size_t last, detail::ScreenMesh& out,
                        DrawReport& report);
detail::DroppedTriangles drop_culled_triangles(const Vec2* vertices, std::size_t vertex_count,
                                               std::uint32_t* indices, std::size_t triangles,
                                               CullMode cull, const detail::SampleWindow& window,
                                               const detail::BinOutput& output);
void shade(const detail::ShadeBatch& batch, RasterReport& report, detail::ShadeCounts& counts);

// resolve.cpp
void resolve_box(const detail::ResolveCall& call, std::int32_t first_tile_row,
                 std::int32_t last_tile_row);
void resolve_taps(const detail::ResolveCall& call, std::int32_t first_row, std::int32_t last_row);

// sample.cpp
void sample(const detail::TextureDescription& texture, const SamplerOptions& options,
            const TextureQuery* queries, std::size_t count, Vec4* out);
void sample_fields(const detail::TextureDescription& texture, const SamplerOptions& options,
                   const detail::QueryFields& queries, std::size_t count,
                   const detail::ResultChannels& out);

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
