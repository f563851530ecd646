// A frame of the city (city.hpp) drawn whole, or with occlusion culling: the buildings and the
// ground drawn first, their depth taken as the occluders' (OcclusionBuffer::copy_depth()), every
// prop's box tested against it, and only the props found visible drawn. Objects are drawn in the
// city's order either way, so the two frames give the same image: a prop is culled only when no
// sample of it passes the depth test against the buildings and the ground, which are drawn
// before any prop in both.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "edgewise/draw.hpp"
#include "edgewise/occlusion.hpp"
#include "scene/city.hpp"

namespace edgewise::scene {

struct CityFrameOptions {
  std::optional<Isa> isa;
  std::size_t threads = 0;
};

struct CityFrame {
  double occluder_seconds = 0.0;  // culled frames: the buildings and ground, their depth copied
  double query_seconds = 0.0;     // culled frames: every prop's box tested
  double draw_seconds = 0.0;      // the objects drawn (culled frames: the visible props)
  std::size_t objects_drawn = 0;
  std::size_t triangles_drawn = 0;
  double seconds() const { return occluder_seconds + query_seconds + draw_seconds; }
};

// The city's camera as a transform to clip space, for a target of that aspect.
Mat4 city_view(const City& city, float aspect);

// Every object drawn (the framebuffer cleared first).
CityFrame draw_city(Framebuffer& target, const City& city, const Mat4& view,
                    const CityFrameOptions& options);

// The same frame, culled through `occlusion` (the target's size). The visible props are gathered
// into `visible` (scratch space) and drawn as one mesh: draw() maps every vertex of the mesh it is
// given, so the props' own vertices alone.
CityFrame draw_city_culled(Framebuffer& target, OcclusionBuffer& occlusion, const City& city,
                           const Mat4& view, const CityFrameOptions& options, Mesh& visible);

}  // namespace edgewise::scene
