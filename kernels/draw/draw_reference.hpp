// The shading reference, draw()'s oracle: depth test, double-precision interpolation and shading
// of every covered sample (draw_reference.cpp).
#pragma once

#include "edgewise/coverage.hpp"

namespace edgewise::detail {
struct ShadeBatch;
struct ShadeCounts;
}  // namespace edgewise::detail

namespace edgewise::reference {

void shade(const detail::ShadeBatch& batch, RasterReport& report, detail::ShadeCounts& counts);

}  // namespace edgewise::reference
