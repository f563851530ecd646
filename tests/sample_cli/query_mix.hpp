// Queries that reach every branch of the filters: deep magnification, isotropic and strongly
// anisotropic minification, coordinates far outside [0, 1), derivatives of 0, of 1e30 and not
// finite, and non-finite positions.
#pragma once

#include <cstdint>
#include <vector>

#include "edgewise/sample.hpp"

namespace edgewise::sample_cli_test {

// `count` queries for a width x height texture, the same for a given seed.
std::vector<TextureQuery> mixed_queries(std::uint64_t seed, std::size_t count, int width,
                                        int height);

// One query at each texel centre of level 0, with zero derivatives (the texel itself for
// nearest), row by row.
std::vector<TextureQuery> texel_centre_queries(int width, int height);

}  // namespace edgewise::sample_cli_test
