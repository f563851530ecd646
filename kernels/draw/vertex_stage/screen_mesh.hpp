// What draw()'s vertex stage hands to the shading kernels: screen-space vertices and triangles.
// Screen vertex i (i below the mesh's vertex count) is the mesh's vertex i; the vertices that
// clipping makes follow them. Vertices that no drawn triangle uses are mapped like the others
// and never read. A range of an indexed mesh's triangles, assembled on its own, keeps the
// vertices its clipping makes in a screen mesh of its own, numbered on from the mesh's vertices
// (ScreenMesh::first_vertex_index).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

#include "edgewise/vector.hpp"
#include "../../core/growable_array.hpp"

namespace edgewise::detail {

// A vertex attribute of the screen mesh: the mesh's own array, read in place, until a clipped
// vertex is appended; the first append copies it, so that meshes drawn without clipping (the
// common case) never copy their attributes.
template <class T>
class ScreenAttribute {
 public:
  void borrow(std::span<const T> values) { borrowed_ = values; }
  // `count` owned values, left for the caller to write (a mesh without colours is opaque white,
  // written by the vertex ranges that map its vertices).
  T* own(std::size_t count) {
    owning_ = true;
    return owned_.extend(count);
  }
  T* owned_data() { return owned_.data(); }
  void push_back(T value) {
    if (!owning_) {
      std::copy_n(borrowed_.data(), borrowed_.size(), owned_.extend(borrowed_.size()));
      owning_ = true;
    }
    owned_.push_back(value);
  }

  const T* data() const { return owning_ ? owned_.data() : borrowed_.data(); }
  std::size_t size() const { return owning_ ? owned_.size() : borrowed_.size(); }
  const T& operator[](std::size_t i) const { return data()[i]; }

 private:
  std::span<const T> borrowed_;
  GrowableArray<T> owned_;
  bool owning_ = false;
};

struct ScreenMesh {
  GrowableArray<Vec2> positions;  // snapped to 1/256 px
  GrowableArray<float> depth;     // z/w, clamped to [0, 1] (to_screen())
  GrowableArray<float> clip_w;
  ScreenAttribute<Vec4> colors;
  ScreenAttribute<Vec3> normals;         // diffuse shading only
  ScreenAttribute<Vec2> uvs;             // textured draws only
  GrowableArray<std::uint32_t> indices;  // three per screen triangle, in the mesh's order
  // The index that positions[0] has in `indices`: 0, or the mesh's vertex count for a range's
  // screen mesh, which holds only the vertices its clipping makes.
  std::size_t first_vertex_index = 0;
};

}  // namespace edgewise::detail
