// Every wrap mode of the sampler (edgewise/sample.hpp), for the tests that check each.
#pragma once

#include "edgewise/sample.hpp"

namespace edgewise::texture_scene {

inline constexpr WrapMode kWrapModes[] = {WrapMode::repeat, WrapMode::clamp_to_edge,
                                          WrapMode::mirror};

}  // namespace edgewise::texture_scene
