// Real meshes for the drawing benchmarks: the built-in default scene (edgewise-render's, seen
// through its own camera), then every OBJ file in the folder named by the environment variable
// EDGEWISE_BENCH_MESHES (none when it is unset or holds none), loaded through the project's OBJ
// loader (testing/scene/obj_loader.hpp: polygons triangulated, smooth normals where the file has
// none), each drawn as a user's mesh is drawn:
// - through a perspective camera (45 degree vertical field of view, 1920x1080) looking at the
//   centre of the mesh's box from a fixed oblique direction, far enough that the box's bounding
//   sphere just fits the screen's height, near and far planes around that sphere;
// - per-pixel diffuse shading (Shading::diffuse, white vertices, a fixed light direction),
//   back faces culled, depth test less with writes, plane equations, perspective-correct.
// Triangle counts, sizes on screen and overdraw are those of the meshes: the mix of small and
// large triangles a renderer actually meets, unlike the one-size sets of shading_scene.hpp.
// Then, for each loaded mesh named in EDGEWISE_BENCH_GRIDS (comma-separated names without
// ".obj"), grid27-<mesh>: 27 copies of it in a 3x3x3 lattice (a fifth of the mesh's box apart),
// one indexed mesh framed as a whole, so that a frame holds millions of triangles (27 ogres hold
// 3.35 M): the draws whose front end and bins must scale to many cores.
#pragma once

#include <span>
#include <string>

#include "edgewise/edgewise.hpp"
#include "scene/mesh.hpp"

namespace edgewise::bench {

struct MeshScene {
  std::string name;  // the file's name without ".obj", or default_scene
  scene::Mesh mesh;  // indexed, with normals
  Mat4 transform;    // object space to clip space
};

// The copies per axis of a grid scene.
inline constexpr int kGridSide = 3;

// The default scene, then the meshes sorted by name, then the grids, loaded on first use. Files
// that do not load are reported on standard error and left out.
std::span<const MeshScene> mesh_scenes();

// The meshes' draw() settings (see the top of this file) on `isa`, one thread.
DrawOptions mesh_options(Isa isa, const MeshScene& scene);

// The mesh's spans, for draw().
DrawMesh draw_mesh(const MeshScene& scene);

// Cleared to alpha 0 (as the shading workload) and depth 1.
inline constexpr Vec4 kMeshClearColor{0.1f, 0.2f, 0.3f, 0.0f};
inline constexpr float kMeshClearDepth = 1.0f;

}  // namespace edgewise::bench
