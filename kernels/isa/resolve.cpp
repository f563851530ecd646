// The resolve kernels (resolve.hpp's resolve()), compiled once per ISA.
#include "../src/isa_build.hpp"

#include "../generic/resolve_box-inl.hpp"
#include "../generic/resolve_taps-inl.hpp"
#include "../src/isa_kernels.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

void resolve_box(const detail::ResolveCall& call, std::int32_t first_tile_row,
                 std::int32_t last_tile_row) {
  resolve_box_tiles<RowArch<EDGEWISE_ARCH>>(call, first_tile_row, last_tile_row);
}

void resolve_taps(const detail::ResolveCall& call, std::int32_t first_row, std::int32_t last_row) {
  resolve_taps_rows<RowArch<EDGEWISE_ARCH>>(call, first_row, last_row);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
