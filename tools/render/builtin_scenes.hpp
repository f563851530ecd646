// The scenes edgewise-render draws without a file, each with the camera it is meant to be seen
// from (testing/scene/procedural.hpp builds the meshes).
#pragma once

#include <string>
#include <string_view>

#include "scene/procedural.hpp"

namespace edgewise::render_tool {

//   default  the demo scene: ground plane to the horizon, sphere, tilted torus around it
//   sphere   a finely tessellated sphere, seen from slightly above
//   torus    a torus tilted towards the camera
//   ground   the checkerboard plane receding to the horizon, seen from eye height
inline constexpr std::string_view kBuiltinSceneNames[] = {"default", "sphere", "torus", "ground"};

// Throws std::invalid_argument for a name not in kBuiltinSceneNames.
scene::Scene make_builtin_scene(std::string_view name);

}  // namespace edgewise::render_tool
