// resolve() in plain scalar code, a pixel at a time: the reference's kernel-table entries and the
// oracle of every ISA's kernels (kernels/antialiasing/resolve_box-inl.hpp, resolve_taps-inl.hpp).
#pragma once

#include <cstdint>

#include "resolve_call.hpp"

namespace edgewise::reference {

// Box filter at factor 1, output rows [8 first_tile_row, 8 last_tile_row): each channel's sum over
// the pixel's samples, its mean rounded to nearest (half up), or its sRGB code.
void resolve_box(const detail::ResolveCall& call, std::int32_t first_tile_row,
                 std::int32_t last_tile_row);

// Tent and Mitchell, output rows [first_row, last_row): each channel's weighted sum over the
// taps in their order, source coordinates clamped to the image, then encoded.
void resolve_taps(const detail::ResolveCall& call, std::int32_t first_row, std::int32_t last_row);

}  // namespace edgewise::reference
