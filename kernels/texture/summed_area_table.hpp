// Building a texture's summed-area table from level 0 (texture.hpp, SummedAreaTable).
#pragma once

#include "edgewise/texture.hpp"
#include "pyramid_resample.hpp"

namespace edgewise::detail {

// The prefix sums of `level0`'s linear values, laid out and scaled as SummedAreaTable says.
// A NaN or infinite float texel makes every entry whose rectangle contains it non-finite.
SummedAreaTable build_summed_area_table(TexelFormat format, ColorEncoding encoding,
                                        const LevelView& level0);

}  // namespace edgewise::detail
