// OBJ texts the loader tests start from.
#pragma once

#include <string_view>

namespace edgewise::scene::test {

// The cube [-1, 1]^3 with one normal per face and the unit square's uvs on each face; quads,
// counter-clockwise from outside.
inline constexpr std::string_view kCubeObj = R"(# a cube
o cube
v -1 -1 -1
v  1 -1 -1
v -1  1 -1
v  1  1 -1
v -1 -1  1
v  1 -1  1
v -1  1  1
v  1  1  1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 -1
vn 0 0 1
vn -1 0 0
vn 1 0 0
vn 0 -1 0
vn 0 1 0
s off
f 1/1/1 3/4/1 4/3/1 2/2/1
f 5/1/2 6/2/2 8/3/2 7/4/2
f 1/1/3 5/2/3 7/3/3 3/4/3
f 2/1/4 4/2/4 8/3/4 6/4/4
f 1/1/5 2/2/5 6/3/5 5/4/5
f 3/1/6 7/2/6 8/3/6 4/4/6
)";

// Two triangles of two materials sharing an edge, and the MTL file they name.
inline constexpr std::string_view kTwoMaterialsObj = R"(mtllib colours.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
usemtl red
f 1 2 3
usemtl glass
f 1 3 4
)";
inline constexpr std::string_view kColoursMtl = R"(newmtl red
Kd 1 0 0
newmtl glass
Kd 0.25 0.5 0.75
d 0.5
)";

}  // namespace edgewise::scene::test
