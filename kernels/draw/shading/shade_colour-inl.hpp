// The colour part of shading: where a fragment's colour comes from. Flat shading takes the first
// vertex's colour; Gouraud and diffuse colour either come from the group's colour planes
// (plane_setup-inl.hpp: one add per channel and pixel) or from the interpolation method's weights
// (method_interpolator-inl.hpp); a triangle whose three vertices share one colour uses it as it
// is. Diffuse shading then lights R, G and B by the interpolated normal.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include <xsimd/xsimd.hpp>

#include "edgewise/framebuffer.hpp"
#include "../../interpolation/screen_triangle.hpp"
#include "shade_batch.hpp"
#include "../../simd/simd_ops-inl.hpp"
#include "../../interpolation/interpolation-inl.hpp"
#include "../../interpolation/method_interpolator-inl.hpp"
#include "plane_setup-inl.hpp"
#include "../../coverage/tile_masks-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// The dx terms of the depth formula and of the colour planes for a tile's columns, per batch of
// lanes.
template <class Arch>
struct TileColumnTerms {
  using Floats = xsimd::batch<float, Arch>;
  static constexpr std::size_t kParts = kTileSize / Floats::size;
  Floats depth[kParts];
  Floats colour[kShadingPlanes][kParts];
};

// Writes lanes h of `row` of a tile's colours where `write` is set. Blended as floats: a blend
// moves bits without arithmetic, so every colour survives as is.
template <class Arch>
[[gnu::always_inline]] inline void write_colour(std::uint32_t* color, int row, std::size_t h,
                                                xsimd::batch_bool<float, Arch> write,
                                                xsimd::batch<std::int32_t, Arch> new_color) {
  using Floats = xsimd::batch<float, Arch>;
  float* at = reinterpret_cast<float*>(color + static_cast<std::size_t>(row) * kTileSize +
                                       h * Floats::size);
  const Floats old_color = Floats::load_aligned(at);
  xsimd::select(write, xsimd::bitwise_cast<Floats>(new_color), old_color).store_aligned(at);
}

template <class Arch>
class ColourSource {
 public:
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  static constexpr std::size_t kLanes = Floats::size;
  static constexpr int kPlanes = kShadingPlanes;
  using Columns = TileColumnTerms<Arch>;
  using RowTerms = float[kTileSize];  // a plane's row terms for a tile's rows

  explicit ColourSource(const detail::ShadeBatch& batch)
      : batch_(batch),
        interpolator_(batch.method, ScreenTriangle{{0, 1, 0}, {0, 0, 1}, {1, 1, 1}}, 0.0, 0.0),
        divide_(ScreenTriangle{{0, 1, 0}, {0, 0, 1}, {1, 1, 1}}),
        planar_(batch.method == InterpolationMethod::plane_equations &&
                (batch.shading == Shading::gouraud || batch.shading == Shading::diffuse)),
        lit_planes_(planar_ && batch.shading == Shading::diffuse) {}

  // Colour from the group's planes (Gouraud or diffuse by plane equations); lit_planes(): the
  // normal from them too (diffuse).
  bool planar() const { return planar_; }
  bool lit_planes() const { return lit_planes_; }
  // The current triangle's vertices share one colour, used as it is.
  bool uniform() const { return uniform_; }
  bool perspective() const { return perspective_; }
  const ColourPlane& plane(int k) const { return plane_[k]; }
  float uniform_channel(int k) const { return uniform_channel_[k]; }
  float min_inverse_w() const { return min_inverse_w_; }
  const Vec4* vertex_colours() const { return color_; }
  const Vec3* vertex_normals() const { return normal_; }

  // Gathers the normals and colours of a group's lanes into `in` for its planes, and finds the
  // lanes whose three vertices share one colour; returns whether all of them do (the planes
  // then need no colour values). `colours_for_budget`: the colours are needed anyway.
  bool read_group(const GroupCorners<Arch>& corners, PlaneGroupInput<Arch>& in,
                  bool colours_for_budget) {
    // One colour at all three vertices (a mesh without colours, a material's colour): its
    // planes would interpolate that colour, so it is used as it is, as flat shading uses it.
    // Not on a multisampled target: there a pixel is shaded at its centre, which may lie outside
    // the triangle, where the plane of 1 / w can fall below its smallest vertex value and the
    // reference's weights, kept from falling below it, scale the colour down.
    const bool may_be_uniform = planar_ && batch_.coverage.samples.size() <= 1;
    bool all_uniform = may_be_uniform;
    for (std::size_t l = 0; l < kSetupLanes<Arch>; ++l) {
      const bool valid = corners.valid[l];  // a bad index reads nothing; the lane is not drawn
      if (lit_planes_) {
        for (int i = 0; i < 3; ++i) {
          const Vec3 normal = valid ? batch_.normals[corners.vertex[l][i]] : Vec3{};
          in.normal[i][0][l] = normal.x;
          in.normal[i][1][l] = normal.y;
          in.normal[i][2][l] = normal.z;
        }
      }
      // Compared as bits: one load and compare per vertex.
      group_uniform_[l] = may_be_uniform;
      if (group_uniform_[l] && valid) {
        const Vec4* colors = batch_.colors;
        const Vec4& first = colors[corners.vertex[l][0]];
        group_uniform_colour_[l] = first;
        group_uniform_[l] = same_bits(colors[corners.vertex[l][1]], first) &&
                            same_bits(colors[corners.vertex[l][2]], first);
      } else {
        group_uniform_colour_[l] = Vec4{};
      }
      all_uniform = all_uniform && group_uniform_[l];
    }
    // The colours themselves, for the planes of a group with a colour that varies, and for the
    // budget's bounds.
    if (planar_ && (!all_uniform || colours_for_budget)) {
      for (std::size_t l = 0; l < kSetupLanes<Arch>; ++l) {
        for (int i = 0; i < 3; ++i) {
          const Vec4 colour = corners.valid[l] ? batch_.colors[corners.vertex[l][i]] : Vec4{};
          in.colour[i][0][l] = colour.x;
          in.colour[i][1][l] = colour.y;
          in.colour[i][2][l] = colour.z;
          in.colour[i][3][l] = colour.w;
        }
      }
    }
    return all_uniform;
  }

  // Lane l of the group's planes, before begin_triangle_from_vertices() if that is called.
  void begin_triangle(const PlaneGroup<Arch>& group, std::size_t l) {
    row_bases_tile_y_ = kNoTileRow;
    uniform_ = group_uniform_[l];
    if (planar_) {
      perspective_ = group.perspective[l];
      min_inverse_w_ = group.min_inverse_w[l];
      for (int k = 0; k < kColourPlanes && !uniform_; ++k)
        plane_[k] = group.colour[k][l];
      if (lit_planes_) {
        for (int k = kFirstNormalPlane; k < kShadingPlanes; ++k)
          plane_[k] = group.colour[k][l];
      }
    }
    if (uniform_) {
      // The colour scaled to 0 .. 255 at every pixel, exactly: its planes would have zero slopes
      // (and give the same packed colour), and there is nothing to divide.
      for (int k = 0; k < 4; ++k)
        uniform_channel_[k] = 255.0f * (&group_uniform_colour_[l].x)[k];
      perspective_ = false;
    }
  }

  // The colours (and normals) of the vertices `corner`.
  void read_vertices(const std::size_t (&corner)[3]) {
    for (int i = 0; i < 3; ++i) {
      color_[i] = batch_.colors[corner[i]];
      if (batch_.normals != nullptr) normal_[i] = batch_.normals[corner[i]];
    }
  }

  // What the group's planes leave out, from the vertices read_vertices() read: flat colour and
  // the other interpolation methods' set-up.
  void begin_triangle_from_vertices(const Vec2 (&p)[3], const ScreenTriangle& screen) {
    // Interpolation coordinates from a pixel corner near the triangle keep float32 exact.
    origin_x_ = static_cast<std::int32_t>(std::floor(p[0].x));
    origin_y_ = static_cast<std::int32_t>(std::floor(p[0].y));
    // Equal w (orthographic views, or a triangle facing the camera) makes perspective-correct
    // weights equal the affine ones; flat shading needs no weights. w outside
    // [kMinClipW, kMaxClipW] (or NaN) makes the triangle affine, as in the reference. A uniform
    // colour has nothing to divide.
    bool usable_w = true;
    for (double w : screen.w)
      usable_w = usable_w && w >= kMinClipW && w <= kMaxClipW;
    perspective_ = !uniform_ && batch_.perspective == Perspective::correct && usable_w &&
                   !(screen.w[0] == screen.w[1] && screen.w[1] == screen.w[2]);
    if (batch_.normals != nullptr && !lit_planes_) scale_normals();
    if (batch_.shading == Shading::flat) flat_color_ = pack_rgba8(color_[0]);
    if (!planar_ && batch_.shading != Shading::flat) {
      interpolator_ = MethodInterpolator<Arch>(batch_.method, screen, origin_x_, origin_y_);
      if (perspective_) divide_ = PerspectiveDivide<Arch>(screen);
    }
  }

  // Planes in use: the fifth, 1 / w, only for perspective-correct colour (it is set up, as a
  // constant, when diffuse shading needs the normal planes after it).
  int planes_used() const { return lit_planes_ ? kShadingPlanes : perspective_ ? 5 : 4; }
  // The first of them: a uniform triangle's colour needs no planes.
  int first_plane() const { return uniform_ ? kFirstNormalPlane : 0; }

  // The colour planes' dx terms for lanes h of a tile's columns, whose exact dx is `dx`.
  [[gnu::always_inline]] void set_up_column(Floats dx, std::size_t h, Columns& columns) const {
    for (int k = first_plane(); k < planes_used(); ++k)
      columns.colour[k][h] = Floats(plane_[k].dx) * dx;
  }

  // Each colour plane's at_vertex + dy_slope * dy for the tile's rows from pixel row py, a batch
  // at a time (y0: the depth plane's, which the colour planes share).
  [[gnu::always_inline]] void set_up_rows(float y0, std::int32_t py,
                                          float (*row_bases)[kTileSize]) const {
    for (std::size_t h = 0; h < kTileSize / kLanes; ++h) {
      const Floats dy =
          interpolation_detail::lane_centers<Arch>(py + static_cast<std::int32_t>(h * kLanes)) -
          Floats(y0);
      for (int k = first_plane(); k < planes_used(); ++k) {
        (Floats(plane_[k].at_vertex) + Floats(plane_[k].dy) * dy)
            .store_aligned(&row_bases[k][h * kLanes]);
      }
    }
  }

  // Sets up row_bases() for the tile row from pixel row py (tile row tile_y) unless the last call
  // did: the walks deliver a triangle's tiles row by row.
  [[gnu::always_inline]] void set_up_tile_row(float y0, std::int32_t py, std::uint32_t tile_y) {
    if (tile_y != row_bases_tile_y_) {
      set_up_rows(y0, py, row_bases_);
      row_bases_tile_y_ = tile_y;
    }
  }
  // The row terms set_up_tile_row() set up (a member's address, which the loops keep for free).
  const RowTerms* row_bases() const { return row_bases_; }

  // The shaded colour of lanes h of `row`, each channel scaled to 0 .. 255, before packing.
  [[gnu::always_inline]] void channels(const float (*row_bases)[kTileSize], const Columns& columns,
                                       std::int32_t px, std::int32_t py, int row, std::size_t h,
                                       Floats channel[4]) const {
    if (planar_) return planar_channels(row_bases, columns, row, h, channel);
    if (batch_.shading == Shading::flat) {
      for (int k = 0; k < 4; ++k)
        channel[k] = Floats(255.0f * (&color_[0].x)[k]);
      return;
    }
    weighted_channels(px + static_cast<std::int32_t>(h * kLanes) - origin_x_, py + row - origin_y_,
                      channel);
  }

  // Packed RGBA8 of lanes h of `row`.
  [[gnu::always_inline]] Ints packed(const float (*row_bases)[kTileSize], const Columns& columns,
                                     std::int32_t px, std::int32_t py, int row,
                                     std::size_t h) const {
    if (!planar_ && batch_.shading == Shading::flat)
      return Ints(static_cast<std::int32_t>(flat_color_));
    Floats channel[4];
    channels(row_bases, columns, px, py, row, h, channel);
    return pack_rgba8_lanes<Arch>(channel);
  }

  // Colour by its own plane equations (model no more than the scene needs: one add per channel
  // and pixel instead of weights, then colours). Each channel, scaled to 0 .. 255, is
  // value(px, py) = (at_vertex + dy_slope * dy) + dx_slope * dx with the depth formula's exact dx,
  // dy; perspective-correct, channels are planes of value / w, divided per pixel by the plane of
  // 1 / w (the fifth), kept from falling below the smallest vertex 1 / w as the reference's
  // weights keep it. Slopes come from the snapped positions in double, rounded to float once.
  [[gnu::always_inline]] void planar_channels(const float (*row_bases)[kTileSize],
                                              const Columns& columns, int row, std::size_t h,
                                              Floats channel[4]) const {
    for (int k = 0; k < 4; ++k) {
      channel[k] =
          uniform_ ? Floats(uniform_channel_[k]) : Floats(row_bases[k][row]) + columns.colour[k][h];
    }
    if (perspective_) {
      const Floats w = Floats(1.0f) / xsimd::max(Floats(row_bases[4][row]) + columns.colour[4][h],
                                                 Floats(min_inverse_w_));
      for (int k = 0; k < 4; ++k)
        channel[k] = channel[k] * w;
    }
    if (lit_planes_) {
      Floats normal[kNormalPlanes];
      for (int k = 0; k < kNormalPlanes; ++k) {
        normal[k] = Floats(row_bases[kFirstNormalPlane + k][row]) +
                    columns.colour[kFirstNormalPlane + k][h];
      }
      apply_light(normal, channel);
    }
  }

  // Diffuse light on R, G and B: ambient + (1 - ambient) max(0, n . l / |n|), with `n` the
  // interpolated normal or its planes' value (any positive multiple gives the same light).
  template <class F>
  [[gnu::always_inline]] void apply_light(const F (&n)[kNormalPlanes], F* channel) const {
    const F length = xsimd::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const F facing = n[0] * F(batch_.light.x) + n[1] * F(batch_.light.y) + n[2] * F(batch_.light.z);
    // A zero normal gives no direct light, not NaN.
    const F lambert =
        xsimd::select(length > F(0.0f), xsimd::max(facing / length, F(0.0f)), F(0.0f));
    const F light = F(batch_.ambient) + F(1.0f - batch_.ambient) * lambert;
    for (int k = 0; k < 3; ++k)
      channel[k] = channel[k] * light;
  }

 private:
  // Gouraud or diffuse by the interpolation method's weights at (column, row) relative to the
  // interpolation origin, each channel scaled to 0 .. 255.
  [[gnu::always_inline]] void weighted_channels(std::int32_t column, std::int32_t row,
                                                Floats rgba[4]) const {
    WeightRow<Arch> w = interpolator_.row(column, row);
    if (perspective_) w = divide_.apply(w);
    const float* c0 = &color_[0].x;
    const float* c1 = &color_[1].x;
    const float* c2 = &color_[2].x;
    for (int k = 0; k < 4; ++k)
      rgba[k] = w.b[0] * Floats(c0[k]) + w.b[1] * Floats(c1[k]) + w.b[2] * Floats(c2[k]);
    if (batch_.shading == Shading::diffuse) {
      Floats n[kNormalPlanes];
      const float* n0 = &normal_[0].x;
      const float* n1 = &normal_[1].x;
      const float* n2 = &normal_[2].x;
      for (int k = 0; k < 3; ++k)
        n[k] = w.b[0] * Floats(n0[k]) + w.b[1] * Floats(n1[k]) + w.b[2] * Floats(n2[k]);
      apply_light(n, rgba);
    }
    for (int k = 0; k < 4; ++k)
      rgba[k] = rgba[k] * Floats(255.0f);
  }

  // Scales the three normals by one power of two (exact, and n / |n| is unchanged) so that the
  // largest component is near 1: float32 squared lengths then neither overflow (components
  // above ~1.8e19) nor underflow (below ~1e-19).
  void scale_normals() {
    float largest = 0.0f;
    for (const Vec3& n : normal_) {
      for (float c : {n.x, n.y, n.z})
        largest = std::fmax(largest, std::fabs(c));
    }
    if (!(largest > 0.0f) || !std::isfinite(largest)) return;
    const float scale = std::ldexp(1.0f, -std::ilogb(largest));
    for (Vec3& n : normal_) {
      n.x *= scale;
      n.y *= scale;
      n.z *= scale;
    }
  }

  // Equal bit patterns (equal colours as stored; +0 and -0, or two NaNs, count as different).
  static bool same_bits(const Vec4& a, const Vec4& b) {
    std::uint64_t x[2], y[2];
    std::memcpy(x, &a, sizeof x);
    std::memcpy(y, &b, sizeof y);
    return ((x[0] ^ y[0]) | (x[1] ^ y[1])) == 0;
  }

  const detail::ShadeBatch& batch_;
  MethodInterpolator<Arch> interpolator_;
  PerspectiveDivide<Arch> divide_;
  const bool planar_;      // Gouraud or diffuse colour from the group's planes
  const bool lit_planes_;  // diffuse: the normal from the group's planes
  // Of the current group: the lanes whose vertices share one colour, and that colour.
  bool group_uniform_[kSetupLanes<Arch>]{};
  Vec4 group_uniform_colour_[kSetupLanes<Arch>]{};
  // The current triangle.
  Vec4 color_[3]{};
  Vec3 normal_[3]{};
  std::uint32_t flat_color_ = 0;
  std::int32_t origin_x_ = 0, origin_y_ = 0;
  bool perspective_ = false;
  float min_inverse_w_ = 1.0f;    // the plane of 1 / w's floor (PlaneGroup::min_inverse_w)
  ColourPlane plane_[kPlanes]{};  // those from first_plane() to planes_used() set
  bool uniform_ = false;
  float uniform_channel_[4]{};  // the uniform colour, scaled to 0 .. 255
  // The planes' row terms for the tile row row_bases_tile_y_ (set_up_tile_row()).
  static constexpr std::uint32_t kNoTileRow = UINT32_MAX;
  std::uint32_t row_bases_tile_y_ = kNoTileRow;
  alignas(64) float row_bases_[kPlanes][kTileSize];
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
