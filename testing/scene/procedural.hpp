// Built-in shapes with normals, uvs and per-vertex colours, and the demo scene made of them.
// Conventions are mesh.hpp's: right-handed, y up, counter-clockwise front faces, t down.
//
// Vertices along a texture seam (and at the sphere's poles) are repeated with their own uvs but
// bit-identical positions, normals and colours, so the surfaces are closed once positions are
// welded, and compute_smooth_normals would give the same normals.
#pragma once

#include "scene/mesh.hpp"

namespace edgewise::scene {

// Counts below these are raised to them; counts above kMaxSubdivisions are lowered to it.
inline constexpr int kMinSphereRings = 2;
inline constexpr int kMinSegments = 3;
inline constexpr int kMaxSubdivisions = 4096;

struct SphereOptions {
  Vec3 center{0.0f, 0.0f, 0.0f};
  float radius = 1.0f;
  int rings = 24;                             // bands from pole to pole
  int segments = 48;                          // slices around the y axis
  Vec4 color_top{1.0f, 1.0f, 1.0f, 1.0f};     // at the +y pole, blended linearly in latitude
  Vec4 color_bottom{1.0f, 1.0f, 1.0f, 1.0f};  // at the -y pole
};

// A sphere around the y axis: uv s follows longitude (0 to 1 around), t latitude (0 at the +y
// pole). Each pole is `segments` vertices (one per slice, s at the slice's middle), each other
// ring `segments + 1` (the seam repeated at s = 1):
//   2 * segments + (rings - 1) * (segments + 1) vertices, 2 * segments * (rings - 1) triangles.
Mesh make_uv_sphere(const SphereOptions& options = {});

struct TorusOptions {
  Vec3 center{0.0f, 0.0f, 0.0f};
  float major_radius = 1.0f;   // from the centre to the middle of the tube
  float minor_radius = 0.25f;  // of the tube
  int major_segments = 48;     // around the y axis
  int minor_segments = 24;     // around the tube
  // Rotation about the x axis through the centre; positive lowers the +z side.
  float tilt_radians = 0.0f;
  Vec4 color_a{1.0f, 1.0f, 1.0f, 1.0f};  // at major angle 0 (+x side)
  Vec4 color_b{1.0f, 1.0f, 1.0f, 1.0f};  // at major angle pi, blended by (1 - cos) / 2
};

// A torus lying in the xz plane (before the tilt): uv s around the y axis, t around the tube.
//   (major_segments + 1) * (minor_segments + 1) vertices, 2 * major * minor triangles.
Mesh make_torus(const TorusOptions& options = {});

struct GroundOptions {
  float height = 0.0f;         // y of the plane
  float half_extent = 250.0f;  // the plane spans [-half_extent, half_extent] in x and z
  int cells_per_side = 125;
  // World units per texture repeat: uv = (x, z) / texture_tile, so a texture tiles the plane.
  float texture_tile = 4.0f;
  Vec4 color_a{1.0f, 1.0f, 1.0f, 1.0f};  // checkerboard by cell: cell (0, 0) has color_a
  Vec4 color_b{0.0f, 0.0f, 0.0f, 1.0f};
};

// A square facing +y, cut into cells_per_side^2 cells of a colour checkerboard. Each cell has its
// own 4 vertices (so its colour stays flat under Gouraud shading):
//   4 * cells^2 vertices, 2 * cells^2 triangles.
Mesh make_ground_plane(const GroundOptions& options = {});

// The camera a scene is meant to be seen from: a look-at camera with a vertical field of view
// (the aspect ratio is the image's) and the clip distances that hold the whole scene.
struct SceneCamera {
  Vec3 eye;
  Vec3 target;
  Vec3 up;
  float vertical_fov_degrees;
  float near_plane;
  float far_plane;
};

struct Scene {
  Mesh mesh;
  SceneCamera camera;
};

// The demo scene: a checkerboard ground plane reaching far enough that, from the camera, it
// nearly meets the horizon (its far edge ~0.5 degrees below it: the region where cells shrink to
// less than a pixel), a sphere (radius 1, centre (0, 1.3, 0)) floating above it, and a torus
// circling the sphere, its front tilted down so that it passes in front of the sphere low and
// behind it high (depth overlap both ways). The camera:
//   eye (0, 2.4, 6.5), target (0, 1.1, 0), up (0, 1, 0), 45 degrees vertical field of view,
//   near 0.1, far 500.
Scene default_scene();

// The ground plane alone to the horizon, as the demo textures it: the eye 1.7 units above a plane
// reaching 250 units out (its far edge 0.4 degrees below the horizon, where the cells shrink
// below a pixel), uv = (x, z) / 4.
Scene ground_scene();

}  // namespace edgewise::scene
