// Shading of covered tiles: depth test, attribute interpolation and colour writes, 8 pixels per
// AVX2 step (4 with SSE and NEON), into the Framebuffer's tiled storage. The tile walks deliver
// masks to ShadingVisitor exactly as they deliver them to the coverage visitors.
//
// Per row of a tile: depth from the shared plane formula (kernels/src/depth_plane.hpp, the same
// float operations as the reference, so outcomes match it exactly), the depth compare, then the
// interpolation method's weights, the perspective step when w varies across the triangle, and
// the shading model. Writes are blends under the covered-and-passed lane mask: no branch per
// pixel. Rows without covered samples are skipped.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>

#include <xsimd/xsimd.hpp>

#include "../src/depth_plane.hpp"
#include "../src/shade_batch.hpp"
#include "../src/shading_budget.hpp"
#include "interpolation-inl.hpp"
#include "method_interpolator-inl.hpp"
#include "plane_setup-inl.hpp"
#include "budget_prefilter-inl.hpp"
#include "sample_walk-inl.hpp"
#include "../simd/row_pairs-inl.hpp"
#include "../simd/simd_ops-inl.hpp"
#include "texture_tile-inl.hpp"
#include "tile_masks-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
class ShadingVisitor {
 public:
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  using Mask = xsimd::batch_bool<float, Arch>;
  static constexpr std::size_t kLanes = Floats::size;
  static constexpr std::size_t kParts = kTileSize / kLanes;
  static constexpr int kPlanes = kShadingPlanes;
#if defined(EDGEWISE_HAS_AVX512_256)
  // Colour from planes with depth writes steps two tile rows per batch (shade_planar_row_pairs).
  static constexpr bool kRowPairs = std::is_same_v<Arch, avx512_256>;
#else
  static constexpr bool kRowPairs = false;
#endif

  explicit ShadingVisitor(const detail::ShadeBatch& batch)
      : batch_(batch),
        interpolator_(batch.method, ScreenTriangle{{0, 1, 0}, {0, 0, 1}, {1, 1, 1}}, 0.0, 0.0),
        divide_(ScreenTriangle{{0, 1, 0}, {0, 0, 1}, {1, 1, 1}}),
        colour_planes_(batch.method == InterpolationMethod::plane_equations &&
                       (batch.shading == Shading::gouraud || batch.shading == Shading::diffuse)),
        normal_planes_(colour_planes_ && batch.shading == Shading::diffuse),
        keep_bounds_(batch.tile_max_depth != nullptr && batch.depth_write),
        reject_hidden_(
            batch.tile_max_depth != nullptr && batch.hierarchical_depth &&
            (batch.depth_test == DepthTest::less || batch.depth_test == DepthTest::less_equal)),
        textured_(batch.texture_description != nullptr),
        // Model no more than the scene needs: Gouraud colour by plane equations interpolates the
        // colours (and diffuse the normals) directly, and then, untextured, needs nothing per
        // triangle beyond the planes.
        needs_vertices_(textured_ || !colour_planes_),
        // Under an error budget (shading_budget.hpp): the triangles whose shading it bounds.
        budget_shading_(detail::budget_shades(batch)),
        pattern_(batch.coverage.samples),
        sample_reach_(sample_reach(pattern_)) {
    for (std::size_t k = 0; k < pattern_.size() && k < kMaxSamples; ++k) {
      sample_dx_[k] = detail::sixteenths(pattern_[k].x);
      sample_dy_[k] = detail::sixteenths(pattern_[k].y);
    }
  }

  // The depth and colour planes of a group of triangles (plane_setup-inl.hpp), before
  // begin_triangle() for each.
  void begin_group(const GroupCorners<Arch>& corners, const TriangleGroup<Arch>& positions) {
    PlaneGroupInput<Arch> in;
    // One colour at all three vertices (a mesh without colours, a material's colour): its
    // planes would interpolate that colour, so it is used as it is, as flat shading uses it.
    // Not on a multisampled target: there a pixel is shaded at its centre, which may lie outside
    // the triangle, where the plane of 1 / w can fall below its smallest vertex value and the
    // reference's weights, kept from falling below it, scale the colour down.
    const bool may_be_uniform = colour_planes_ && pattern_.size() <= 1;
    bool all_uniform = may_be_uniform;
    for (std::size_t l = 0; l < kSetupLanes<Arch>; ++l) {
      const bool valid = corners.valid[l];  // a bad index reads nothing; the lane is not drawn
      for (int i = 0; i < 3; ++i) {
        in.x[i][l] = positions.x[i][l];
        in.y[i][l] = positions.y[i][l];
        const std::size_t v = corners.vertex[l][i];
        in.z[i][l] = valid ? batch_.depth[v] : 0.0f;
        in.w[i][l] = valid ? batch_.clip_w[v] : 1.0f;
        if (normal_planes_) {
          const Vec3 normal = valid ? batch_.normals[v] : Vec3{};
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
    const bool budget_bounds = budget_shading_ && !textured_;
    if (colour_planes_ && (!all_uniform || budget_bounds)) {
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
    set_up_plane_group(in, colour_planes_, normal_planes_,
                       batch_.perspective == Perspective::correct, group_,
                       /*colour_values=*/!all_uniform);
    if (budget_bounds) {
      mark_beyond_budget(in, normal_planes_, batch_.light, batch_.ambient,
                         detail::untextured_width_limit(batch_.budget_codes), beyond_budget_);
    }
  }

  // Starts fetching what run_batch() and begin_group() will read of the vertices `corners`
  // (an index past the end fetches the last vertex). A plain loop: the compiler may drop the
  // prefetches of a generic lambda that takes each array in turn.
  [[gnu::always_inline]] void prefetch_vertices(const std::uint32_t* corners,
                                                std::size_t count) const {
    const std::size_t vertices = batch_.coverage.vertex_count;
    if (vertices == 0) return;
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t v = std::min<std::size_t>(corners[i], vertices - 1);
      __builtin_prefetch(batch_.coverage.vertices + v);
      __builtin_prefetch(batch_.depth + v);
      __builtin_prefetch(batch_.clip_w + v);
      if (normal_planes_) __builtin_prefetch(batch_.normals + v);
      if (colour_planes_) __builtin_prefetch(batch_.colors + v);
    }
  }

  // Triangle t, lane l of the last begin_group().
  void begin_triangle(std::uint32_t t, std::size_t l) {
    row_bases_tile_y_ = kNoTileRow;
    sample_rows_tile_y_ = kNoTileRow;
    depth_ = {group_.z0[l], group_.dzdx[l], group_.dzdy[l], group_.x0[l], group_.y0[l]};
    max_vertex_depth_ = group_.max_depth[l];
    uniform_ = group_uniform_[l];
    if (colour_planes_) {
      perspective_ = group_.perspective[l];
      min_inverse_w_ = group_.min_inverse_w[l];
      for (int k = 0; k < kColourPlanes && !uniform_; ++k)
        plane_[k] = group_.colour[k][l];
      if (normal_planes_) {
        for (int k = kFirstNormalPlane; k < kShadingPlanes; ++k)
          plane_[k] = group_.colour[k][l];
      }
    }
    // Under a budget, an untextured triangle is looked at closer unless its vertices already
    // rule one colour out.
    constant_ = tile_choices_ = false;
    if (needs_vertices_ || (budget_shading_ && !beyond_budget_[l])) begin_triangle_from_vertices(t);
    if (uniform_) {
      // The colour scaled to 0 .. 255 at every pixel, exactly: its planes would have zero slopes
      // (and give the same packed colour), and there is nothing to divide.
      for (int k = 0; k < 4; ++k)
        uniform_channel_[k] = 255.0f * (&group_uniform_colour_[l].x)[k];
      perspective_ = false;
    }
  }

  // What the group's planes leave out: normals, texture planes, flat colour and the other
  // interpolation methods' set-up.
  void begin_triangle_from_vertices(std::uint32_t t) {
    std::size_t corner[3] = {3 * std::size_t{t}, 3 * std::size_t{t} + 1, 3 * std::size_t{t} + 2};
    if (batch_.coverage.indices != nullptr) {
      for (int i = 0; i < 3; ++i)
        corner[i] = batch_.coverage.indices[corner[i]];
    }
    Vec2 p[3];
    Vec2 uv[3]{};
    ScreenTriangle screen;
    for (int i = 0; i < 3; ++i) {
      p[i] = batch_.coverage.vertices[corner[i]];
      screen.x[i] = p[i].x;
      screen.y[i] = p[i].y;
      screen.w[i] = batch_.clip_w[corner[i]];
      color_[i] = batch_.colors[corner[i]];
      if (batch_.normals != nullptr) normal_[i] = batch_.normals[corner[i]];
      if (textured_) uv[i] = batch_.uvs[corner[i]];
    }
    if (textured_)
      texture_planes_ = detail::make_texture_planes(p, uv, screen.w, batch_.perspective);
    if (budget_shading_) choose_within_budget(p, screen);
    // Interpolation coordinates from a pixel corner near the triangle keep float32 exact.
    origin_x_ = static_cast<std::int32_t>(std::floor(p[0].x));
    origin_y_ = static_cast<std::int32_t>(std::floor(p[0].y));
    // Equal w (orthographic views, or a triangle facing the camera) makes perspective-correct
    // weights equal the affine ones; flat shading needs no weights. w outside
    // [kMinClipW, kMaxClipW] (or NaN) makes the triangle affine, as in the reference.
    bool usable_w = true;
    for (double w : screen.w)
      usable_w = usable_w && w >= kMinClipW && w <= kMaxClipW;
    perspective_ = batch_.perspective == Perspective::correct && usable_w &&
                   !(screen.w[0] == screen.w[1] && screen.w[1] == screen.w[2]);
    if (batch_.normals != nullptr && !normal_planes_) scale_normals();
    if (batch_.shading == Shading::flat) flat_color_ = pack_rgba8(color_[0]);
    if (textured_) texture_.begin_triangle(texture_planes_, batch_.derivatives);
    if (!colour_planes_ && batch_.shading != Shading::flat) {
      interpolator_ = MethodInterpolator<Arch>(batch_.method, screen, origin_x_, origin_y_);
      if (perspective_) divide_ = PerspectiveDivide<Arch>(screen);
    }
  }

  void tile(std::uint32_t tile_x, std::uint32_t tile_y, std::uint64_t mask) {
    const std::size_t tile_index =
        static_cast<std::size_t>(tile_y) * static_cast<std::size_t>(batch_.tiles_x) + tile_x;
    const std::size_t base = tile_index * 64;
    float* depth = batch_.depth_tiles + base;
    std::uint32_t* color = batch_.color_tiles + base;
    const std::int32_t px = static_cast<std::int32_t>(tile_x) * kTileSize;
    const std::int32_t py = static_cast<std::int32_t>(tile_y) * kTileSize;
    fragments_ += static_cast<std::uint64_t>(std::popcount(mask));
    // A tile whose bound lies above every vertex depth holds a stored depth the triangle beats
    // (hidden() could only succeed within its rounding margin of the vertices' largest depth, and
    // not skipping a tile is always correct): the cheap comparison spares most tiles the test.
    if (skips_hidden_tile(tile_index, px, py)) return;
    Floats stored_max(-std::numeric_limits<float>::infinity());  // depth after the writes
    ColumnTerms columns;
    set_up_tile_columns(px, columns);
    // The walks deliver a triangle's tiles row by row: the row terms serve a whole tile row.
    if (needs_row_bases() && tile_y != row_bases_tile_y_) {
      set_up_colour_rows(py, row_bases_);
      row_bases_tile_y_ = tile_y;
    }
    const float(*colour_row_bases)[kTileSize] = row_bases_;
    const std::uint32_t rows = covered_rows(mask);
    if (textured_) {
      shade_textured_rows(mask, rows, depth, color, px, py, columns, colour_row_bases, stored_max);
    } else {
      // Inlined: as a call, its captures go through memory for every tile.
      with_depth_test([&](auto test) EDGEWISE_INLINE_LAMBDA {
        shade_rows<decltype(test)::value>(mask, rows, depth, color, px, py, columns,
                                          colour_row_bases, stored_max);
      });
    }
    if (keep_bounds_) tighten_bound(tile_index, depth, rows, stored_max);
  }

  // The dx terms of the depth formula and of the colour planes for the columns of the tiles
  // starting at pixel column px.
  struct ColumnTerms {
    Floats depth[kParts];
    Floats colour[kPlanes][kParts];
  };

  // A tile of a multisampled target (walk_sample_tiles): masks[k] is sample k's coverage, and
  // sample k of the tile is the 64 values from (tile * samples + k) * 64 (framebuffer.hpp). Each
  // covered sample's depth is tested, and written, at its own position; each pixel with a
  // covered sample is shaded once, at its centre, and that colour written to the samples that
  // passed.
  void sample_tile(std::uint32_t tile_x, std::uint32_t tile_y,
                   std::span<const std::uint64_t> masks) {
    const std::size_t samples = masks.size();
    const std::size_t tile_index =
        static_cast<std::size_t>(tile_y) * static_cast<std::size_t>(batch_.tiles_x) + tile_x;
    float* depth = batch_.depth_tiles + tile_index * samples * 64;
    std::uint32_t* color = batch_.color_tiles + tile_index * samples * 64;
    const std::int32_t px = static_cast<std::int32_t>(tile_x) * kTileSize;
    const std::int32_t py = static_cast<std::int32_t>(tile_y) * kTileSize;
    std::uint64_t covered = 0, fragments = 0;
    for (std::uint64_t mask : masks) {
      fragments += static_cast<std::uint64_t>(std::popcount(mask));
      covered |= mask;
    }
    fragments_ += fragments;
    if (skips_hidden_tile(tile_index, px, py)) return;
    ColumnTerms columns;
    set_up_tile_columns(px, columns);
    if (colour_planes_ && tile_y != row_bases_tile_y_) {
      set_up_colour_rows(py, row_bases_);
      row_bases_tile_y_ = tile_y;
    }
    SampleDepthTerms terms;
    set_up_sample_depth(px, samples, terms);
    if (tile_y != sample_rows_tile_y_) {
      set_up_sample_rows(py, samples);
      sample_rows_tile_y_ = tile_y;
    }
    std::uint64_t tile_passed = 0;
    if (textured_) {
      tile_passed = shade_textured_samples(masks, depth, color, px, py, columns, terms);
    } else {
      // Inlined: as a call, its captures go through memory for every tile.
      with_depth_test([&](auto test) EDGEWISE_INLINE_LAMBDA {
        tile_passed = shade_samples_as<decltype(test)::value>(batch_.depth_write, masks, covered,
                                                              depth, color, px, py, columns, terms);
      });
    }
    passed_ += tile_passed;
    // The tile's bound anew from every sample's depth where the writes may have raised it
    // (tests other than less and less_equal), or where they replaced every sample (a tile the
    // triangle covers whole): then the lower bound lets hierarchical depth skip the tile for the
    // triangles behind. Elsewhere the old bound stays an upper bound, looser (as the 1x path
    // leaves it for small triangles): the recount would cost more than the depth test itself.
    const bool may_raise =
        batch_.depth_test != DepthTest::less && batch_.depth_test != DepthTest::less_equal;
    if (keep_bounds_ && tile_passed != 0 && (may_raise || tile_passed == 64 * samples)) {
      Floats stored_max(-std::numeric_limits<float>::infinity());
      for (std::size_t k = 0; k < samples; ++k) {
        for (int row = 0; row < kTileSize; ++row)
          keep_row_bound(depth + k * 64, row, stored_max);
      }
      batch_.tile_max_depth[tile_index] = horizontal_max(stored_max);
    }
  }

  // Each sample's dx terms of the depth formula over a tile column, per batch of lanes (its row
  // terms are sample_row_base_): depth_at() with the sample's offset, the same float operations.
  struct SampleDepthTerms {
    Floats column[kMaxSamples][kParts];
  };

  [[gnu::always_inline]] void set_up_sample_depth(std::int32_t px, std::size_t samples,
                                                  SampleDepthTerms& terms) const {
    for (std::size_t h = 0; h < kParts; ++h) {
      const Floats centre_x =
          interpolation_detail::lane_centers<Arch>(px + static_cast<std::int32_t>(h * kLanes));
      for (std::size_t k = 0; k < samples; ++k)
        terms.column[k][h] =
            Floats(depth_.dzdx) * ((centre_x + Floats(sample_dx_[k])) - Floats(depth_.x0));
    }
  }

  // Each sample's row terms of the depth formula for the tile row from pixel row py.
  [[gnu::always_inline]] void set_up_sample_rows(std::int32_t py, std::size_t samples) {
    for (std::size_t h = 0; h < kParts; ++h) {
      const auto first = static_cast<std::int32_t>(h * kLanes);
      const Floats centre_y = interpolation_detail::lane_centers<Arch>(py + first);
      for (std::size_t k = 0; k < samples; ++k) {
        const Floats dy = (centre_y + Floats(sample_dy_[k])) - Floats(depth_.y0);
        (Floats(depth_.z0) + Floats(depth_.dzdy) * dy).store_aligned(sample_row_base_[k] + first);
      }
    }
  }

  // shade_samples() with depth writes or not.
  template <DepthTest Test>
  [[gnu::always_inline]] std::uint64_t shade_samples_as(bool write,
                                                        std::span<const std::uint64_t> masks,
                                                        std::uint64_t covered, float* depth,
                                                        std::uint32_t* color, std::int32_t px,
                                                        std::int32_t py, const ColumnTerms& columns,
                                                        const SampleDepthTerms& terms) {
    return write ? shade_samples<Test, true>(masks, covered, depth, color, px, py, columns, terms)
                 : shade_samples<Test, false>(masks, covered, depth, color, px, py, columns, terms);
  }

  // Untextured multisampled tiles in one pass over the covered rows: per batch of lanes, the
  // colour at the pixel centres, then per sample with covered lanes the depth test and the
  // writes. Returns the samples that passed.
  template <DepthTest Test, bool WriteDepth>
  [[gnu::always_inline]] std::uint64_t shade_samples(std::span<const std::uint64_t> masks,
                                                     std::uint64_t covered, float* depth,
                                                     std::uint32_t* color, std::int32_t px,
                                                     std::int32_t py, const ColumnTerms& columns,
                                                     const SampleDepthTerms& terms) {
    const std::size_t samples = masks.size();
    constexpr std::uint32_t kLaneBits = (1u << kLanes) - 1;
    Floats passed(0.0f);  // per lane, the samples that passed (exact: at most 128 per tile)
    for (std::uint32_t rows = covered_rows(covered); rows != 0; rows &= rows - 1) {
      const int row = std::countr_zero(rows);
      for (std::size_t h = 0; h < kParts; ++h) {
        const std::size_t at = static_cast<std::size_t>(row) * kTileSize + h * kLanes;
        Floats channel[4];
        colour_channels(row_bases_, columns, px, py, row, h, channel);
        const Ints packed = pack_rgba8_lanes<Arch>(channel);
        for (std::size_t k = 0; k < samples; ++k) {
          const std::uint32_t lanes = static_cast<std::uint32_t>(masks[k] >> at) & kLaneBits;
          if (lanes == 0) continue;
          float* sample_depth = depth + k * 64;
          const Floats z = clamp01(Floats(sample_row_base_[k][row]) + terms.column[k][h]);
          const Floats stored = Floats::load_aligned(sample_depth + at);
          const Mask write = lanes_of_bits<Arch>(lanes) && passes<Test>(z, stored);
          if constexpr (WriteDepth)
            xsimd::select(write, z, stored).store_aligned(sample_depth + at);
          write_colour(color + k * 64, row, h, write, packed);
          passed += xsimd::select(write, Floats(1.0f), Floats(0.0f));
        }
      }
    }
    return static_cast<std::uint64_t>(xsimd::hadd(passed));  // exact: at most 1024
  }

  // Textured multisampled tiles: every sample's depth test first, then the texels of the rows
  // with a sample that passed, and the colour written to those samples. Returns the samples
  // that passed.
  std::uint64_t shade_textured_samples(std::span<const std::uint64_t> masks, float* depth,
                                       std::uint32_t* color, std::int32_t px, std::int32_t py,
                                       const ColumnTerms& columns, const SampleDepthTerms& terms) {
    const std::size_t samples = masks.size();
    // Per sample, the rows with a sample that passed (bit `row`) and each row's lanes to write.
    std::uint32_t passed_rows[kMaxSamples];
    Mask writes[kMaxSamples][kTileSize][kParts];
    std::uint32_t written_rows = 0;
    std::uint64_t tile_passed = 0;
    with_depth_test([&](auto test) {
      for (std::size_t k = 0; k < samples; ++k) {
        const std::uint64_t passed = sample_depth_test<decltype(test)::value>(
            masks[k], depth + k * 64, terms, k, writes[k], passed_rows[k]);
        tile_passed += static_cast<std::uint64_t>(std::popcount(passed));
        written_rows |= passed_rows[k];
      }
    });
    if (written_rows == 0) return 0;
    texture_.sample_rows(batch_, px, py, std::countr_zero(written_rows),
                         31 - std::countl_zero(written_rows));
    for (std::uint32_t rows = written_rows; rows != 0; rows &= rows - 1) {
      const int row = std::countr_zero(rows);
      for (std::size_t h = 0; h < kParts; ++h) {
        Floats channel[4];
        colour_channels(row_bases_, columns, px, py, row, h, channel);
        for (int k = 0; k < 4; ++k)
          channel[k] = channel[k] * texture_.texel(k, row, h);
        const Ints packed = pack_rgba8_lanes<Arch>(channel);
        for (std::size_t k = 0; k < samples; ++k) {
          if ((passed_rows[k] >> row) & 1u)
            write_colour(color + k * 64, row, h, writes[k][row][h], packed);
        }
      }
    }
    return tile_passed;
  }

  // One sample's depth test over a tile (`depth` its plane of the tile, `terms` its depth
  // formula's terms), the depth written where it passes. Fills `writes` for the rows of
  // `passed_rows` (the rows where some lane passed) and returns the samples that passed (bit
  // y * 8 + x).
  template <DepthTest Test>
  [[gnu::always_inline]] std::uint64_t sample_depth_test(std::uint64_t mask, float* depth,
                                                         const SampleDepthTerms& terms,
                                                         std::size_t k, Mask (*writes)[kParts],
                                                         std::uint32_t& passed_rows) {
    std::uint64_t passed = 0;
    for (std::uint32_t rows = covered_rows(mask); rows != 0; rows &= rows - 1) {
      const int row = std::countr_zero(rows);
      const std::uint32_t row_mask = static_cast<std::uint32_t>(mask >> (8 * row)) & 0xFF;
      const Floats base(sample_row_base_[k][row]);
      for (std::size_t h = 0; h < kParts; ++h) {
        const std::size_t at = static_cast<std::size_t>(row) * kTileSize + h * kLanes;
        const Floats z = clamp01(base + terms.column[k][h]);
        const Floats stored = Floats::load_aligned(depth + at);
        const Mask write = lanes_of_bits<Arch>(row_mask >> (h * kLanes)) && passes<Test>(z, stored);
        if (batch_.depth_write) xsimd::select(write, z, stored).store_aligned(depth + at);
        writes[row][h] = write;
        passed |= std::uint64_t{bits_of_lanes<Arch>(write)} << at;
      }
    }
    passed_rows = covered_rows(passed);
    return passed;
  }

  // Whether hierarchical depth rejects the tile at (px, py) whole, counted when it does.
  [[gnu::always_inline]] bool skips_hidden_tile(std::size_t tile_index, std::int32_t px,
                                                std::int32_t py) {
    if (reject_hidden_ && !(batch_.tile_max_depth[tile_index] > max_vertex_depth_) &&
        hidden(batch_.tile_max_depth[tile_index], px, py)) {
      ++tiles_skipped_;
      return true;
    }
    return false;
  }

  // The masks of a small triangle (walk_block, walk_block_16) in the N x N tiles from
  // (tile_x, tile_y): masks[row][column] for tile (tile_x + column, tile_y + row), any of them
  // empty. The small-triangle path: the column and row terms are set up once per tile column
  // and row, and only rows with covered samples are touched.
  template <std::size_t N>
  void tile_grid(std::uint32_t tile_x, std::uint32_t tile_y, const std::uint64_t (&masks)[N][N]) {
    if (textured_) {
      for (std::uint32_t row = 0; row < N; ++row) {
        for (std::uint32_t column = 0; column < N; ++column) {
          if (masks[row][column] != 0) tile(tile_x + column, tile_y + row, masks[row][column]);
        }
      }
      return;
    }
    with_depth_test([&](auto test) { shade_grid<decltype(test)::value>(tile_x, tile_y, masks); });
  }

  template <DepthTest Test, std::size_t N>
  [[gnu::always_inline]] void shade_grid(std::uint32_t tile_x, std::uint32_t tile_y,
                                         const std::uint64_t (&masks)[N][N]) {
    const std::int32_t px = static_cast<std::int32_t>(tile_x) * kTileSize;
    const std::int32_t py = static_cast<std::int32_t>(tile_y) * kTileSize;
    // Bit k of each: tile row or column k holds a covered sample. Flags rather than the masks
    // ORed together: the compiler turned those ORs into vector loads of masks the walk had just
    // stored as 64-bit values, which cannot be forwarded from the stores and stalled each call.
    std::uint32_t rows_in = 0, columns_in = 0;
    for (std::uint32_t row = 0; row < N; ++row) {
      for (std::uint32_t column = 0; column < N; ++column) {
        if (masks[row][column] != 0) {
          rows_in |= 1u << row;
          columns_in |= 1u << column;
        }
      }
    }
    ColumnTerms columns[N];
    for (std::uint32_t column = 0; column < N; ++column) {
      if ((columns_in >> column) & 1u) {
        set_up_tile_columns(px + static_cast<std::int32_t>(column) * kTileSize, columns[column]);
      }
    }
    alignas(64) float colour_row_bases[kPlanes][kTileSize];
    std::uint32_t set_up_row = N;  // the tile row colour_row_bases holds
    for (std::uint32_t row = 0; row < N; ++row) {
      if (((rows_in >> row) & 1u) == 0) continue;
      const std::int32_t tile_py = py + static_cast<std::int32_t>(row) * kTileSize;
      for (std::uint32_t column = 0; column < N; ++column) {
        const std::uint64_t mask = masks[row][column];
        if (mask == 0) continue;
        const std::size_t tile_index =
            static_cast<std::size_t>(tile_y + row) * static_cast<std::size_t>(batch_.tiles_x) +
            tile_x + column;
        const std::int32_t tile_px = px + static_cast<std::int32_t>(column) * kTileSize;
        fragments_ += static_cast<std::uint64_t>(std::popcount(mask));
        if (skips_hidden_tile(tile_index, tile_px, tile_py)) continue;
        float* depth = batch_.depth_tiles + tile_index * 64;
        std::uint32_t* color = batch_.color_tiles + tile_index * 64;
        Floats stored_max(-std::numeric_limits<float>::infinity());
        const std::uint32_t rows = covered_rows(mask);
        // A box of at most 8x8 pixels covers at most 8 rows in all: its row terms are computed
        // per row; larger boxes set them up per tile row.
        if constexpr (N == 2) {
          shade_rows<Test, true>(mask, rows, depth, color, tile_px, tile_py, columns[column],
                                 nullptr, stored_max);
        } else {
          if (needs_row_bases() && set_up_row != row) {
            set_up_colour_rows(tile_py, colour_row_bases);
            set_up_row = row;
          }
          shade_rows<Test>(mask, rows, depth, color, tile_px, tile_py, columns[column],
                           colour_row_bases, stored_max);
        }
        // Under less and less_equal a write only lowers a stored depth, so the bound stays an
        // upper bound without a look at the tile's other rows (it may be left looser than the
        // largest depth: such a tile is skipped less often, never wrongly). Small triangles take
        // this path whichever bin they are drawn in (triangle_batch-inl.hpp), so the skipped
        // tiles are the same for every thread count.
        if constexpr (Test != DepthTest::less && Test != DepthTest::less_equal) {
          if (keep_bounds_) tighten_bound(tile_index, depth, rows, stored_max);
        }
      }
    }
  }

  // Whether a tile's shading reads the colour planes' row terms from set_up_colour_rows(): not
  // the row pairs of AVX-512 (untextured, depth written), which compute their own.
  bool needs_row_bases() const {
    if (!colour_planes_ || constant_) return false;
    return textured_ || !(kRowPairs && batch_.depth_write);
  }

  // The tile's largest depth, over all 64 values after the writes, as its new bound:
  // `stored_max` holds the largest of the covered rows `rows`; the others kept their depths.
  [[gnu::always_inline]] void tighten_bound(std::size_t tile_index, const float* depth,
                                            std::uint32_t rows, Floats stored_max) const {
    for (std::uint32_t other = ~rows & 0xFFu; other != 0; other &= other - 1)
      keep_row_bound(depth, std::countr_zero(other), stored_max);
    batch_.tile_max_depth[tile_index] = horizontal_max(stored_max);
  }

  // The dx terms for tile columns from px (exact dx, one rounding each); the colour planes'
  // only when colour comes from planes.
  [[gnu::always_inline]] void set_up_tile_columns(std::int32_t px, ColumnTerms& columns) const {
    for (std::size_t h = 0; h < kParts; ++h) {
      const Floats dx =
          interpolation_detail::lane_centers<Arch>(px + static_cast<std::int32_t>(h * kLanes)) -
          Floats(depth_.x0);
      columns.depth[h] = Floats(depth_.dzdx) * dx;
      if (colour_planes_ && !constant_) {
        for (int k = first_plane(); k < planes_used(); ++k)
          columns.colour[k][h] = Floats(plane_[k].dx) * dx;
      }
    }
  }

  // Each colour plane's at_vertex + dy_slope * dy for the tile's rows, a batch at a time.
  [[gnu::always_inline]] void set_up_colour_rows(std::int32_t py,
                                                 float (*colour_row_bases)[kTileSize]) const {
    for (std::size_t h = 0; h < kParts; ++h) {
      const Floats dy =
          interpolation_detail::lane_centers<Arch>(py + static_cast<std::int32_t>(h * kLanes)) -
          Floats(depth_.y0);
      for (int k = first_plane(); k < planes_used(); ++k) {
        (Floats(plane_[k].at_vertex) + Floats(plane_[k].dy) * dy)
            .store_aligned(&colour_row_bases[k][h * kLanes]);
      }
    }
  }

  // Untextured tiles: per covered row and batch of lanes, the depth test, then the colour
  // written where it passed. Gouraud colour from planes with depth writes, the common case,
  // has a loop of its own. The colour planes' row terms come from `colour_row_bases`, or, with
  // RowTermsPerRow (small triangles, which cover few of a tile's rows), are computed per
  // covered row with the same float operations.
  template <DepthTest Test, bool RowTermsPerRow = false>
  [[gnu::always_inline]] void shade_rows(std::uint64_t mask, std::uint32_t rows, float* depth,
                                         std::uint32_t* color, std::int32_t px, std::int32_t py,
                                         const ColumnTerms& columns,
                                         const float (*colour_row_bases)[kTileSize],
                                         Floats& stored_max) {
    if (colour_planes_ && batch_.depth_write && !constant_) {
      if (normal_planes_) {
        return shade_planar_choice<Test, RowTermsPerRow, true>(
            mask, rows, depth, color, py, columns, colour_row_bases, stored_max);
      }
      return shade_planar_choice<Test, RowTermsPerRow, false>(mask, rows, depth, color, py, columns,
                                                              colour_row_bases, stored_max);
    }
    alignas(64) float row_bases[kPlanes][kTileSize];
    if constexpr (RowTermsPerRow) {
      if (colour_planes_ && !constant_) set_up_colour_rows(py, row_bases);
      colour_row_bases = row_bases;
    }
    shade_rows_generic<Test>(mask, rows, depth, color, px, py, columns, colour_row_bases,
                             stored_max);
  }

  // shade_planar_rows() for the tile's division (perspective) and coverage (full or not).
  template <DepthTest Test, bool RowTermsPerRow, bool Lit>
  [[gnu::always_inline]] void shade_planar_choice(std::uint64_t mask, std::uint32_t rows,
                                                  float* depth, std::uint32_t* color,
                                                  std::int32_t py, const ColumnTerms& columns,
                                                  const float (*colour_row_bases)[kTileSize],
                                                  Floats& stored_max) {
    if (uniform_) {
      if (mask == ~std::uint64_t{0}) {
        return shade_planar_rows<Test, false, true, RowTermsPerRow, Lit, true>(
            mask, rows, depth, color, py, columns, colour_row_bases, stored_max);
      }
      return shade_planar_rows<Test, false, false, RowTermsPerRow, Lit, true>(
          mask, rows, depth, color, py, columns, colour_row_bases, stored_max);
    }
    if (mask == ~std::uint64_t{0}) {
      if (perspective_) {
        return shade_planar_rows<Test, true, true, RowTermsPerRow, Lit>(
            mask, rows, depth, color, py, columns, colour_row_bases, stored_max);
      }
      return shade_planar_rows<Test, false, true, RowTermsPerRow, Lit>(
          mask, rows, depth, color, py, columns, colour_row_bases, stored_max);
    }
    if (perspective_) {
      return shade_planar_rows<Test, true, false, RowTermsPerRow, Lit>(
          mask, rows, depth, color, py, columns, colour_row_bases, stored_max);
    }
    return shade_planar_rows<Test, false, false, RowTermsPerRow, Lit>(
        mask, rows, depth, color, py, columns, colour_row_bases, stored_max);
  }

  // shade_rows() for colour from planes (Gouraud, or diffuse when Lit), depth written: the same
  // operations as the generic loop, with the choices made once per tile and the counts kept in
  // registers. A full tile (every sample covered) runs all eight rows without lane masks; a
  // Uniform triangle's colour is the same at every pixel.
  template <DepthTest Test, bool Divide, bool Full, bool RowTermsPerRow, bool Lit,
            bool Uniform = false>
  [[gnu::always_inline]] void shade_planar_rows(std::uint64_t mask, std::uint32_t rows,
                                                float* depth, std::uint32_t* color, std::int32_t py,
                                                const ColumnTerms& columns,
                                                const float (*colour_row_bases)[kTileSize],
                                                Floats& stored_max) {
#if defined(EDGEWISE_HAS_AVX512_256)
    if constexpr (kRowPairs) {
      return shade_planar_row_pairs<Test, Divide, Full, Lit, Uniform>(mask, rows, depth, color, py,
                                                                      columns, stored_max);
    }
#endif
    std::uint64_t passed = 0;
    Floats largest = stored_max;
    for (int next = 0; Full ? next < kTileSize : rows != 0; ++next, rows &= rows - 1) {
      const int row = Full ? next : std::countr_zero(rows);
      const std::uint32_t row_mask = static_cast<std::uint32_t>(mask >> (8 * row)) & 0xFF;
      const Floats row_base(detail::depth_row_base(depth_, py + row));
      for (std::size_t h = 0; h < kParts; ++h) {
        const std::size_t offset = static_cast<std::size_t>(row) * kTileSize + h * kLanes;
        const Floats z = clamp01(row_base + columns.depth[h]);
        const Floats stored = Floats::load_aligned(depth + offset);
        Mask write = passes<Test>(z, stored);
        if constexpr (!Full) write = write && lanes_of_bits<Arch>(row_mask >> (h * kLanes));
        const Floats updated = xsimd::select(write, z, stored);
        updated.store_aligned(depth + offset);
        largest = xsimd::max(largest, updated);
        passed += static_cast<std::uint64_t>(std::popcount(bits_of_lanes<Arch>(write)));
        float row_term[kPlanes];
        for (int k = Uniform ? kFirstNormalPlane : 0; k < kPlanes; ++k) {
          if (k == 4 && !Divide) continue;
          if (k >= kFirstNormalPlane && !Lit) break;
          if constexpr (RowTermsPerRow) {
            // set_up_colour_rows()'s operations for this one row.
            const float dy = (static_cast<float>(py + row) + 0.5f) - depth_.y0;
            row_term[k] = plane_[k].at_vertex + plane_[k].dy * dy;
          } else {
            row_term[k] = colour_row_bases[k][row];
          }
        }
        Floats channel[4];
        for (int k = 0; k < 4; ++k) {
          if constexpr (Uniform) {
            channel[k] = Floats(uniform_channel_[k]);
          } else {
            channel[k] = Floats(row_term[k]) + columns.colour[k][h];
          }
        }
        if constexpr (Divide) {
          const Floats w = Floats(1.0f) / xsimd::max(Floats(row_term[4]) + columns.colour[4][h],
                                                     Floats(min_inverse_w_));
          for (int k = 0; k < 4; ++k)
            channel[k] = channel[k] * w;
        }
        if constexpr (Lit) {
          Floats normal[kNormalPlanes];
          for (int k = 0; k < kNormalPlanes; ++k) {
            normal[k] =
                Floats(row_term[kFirstNormalPlane + k]) + columns.colour[kFirstNormalPlane + k][h];
          }
          apply_light(normal, channel);
        }
        write_colour(color, row, h, write, pack_rgba8_lanes<Arch>(channel));
      }
    }
    passed_ += passed;
    stored_max = largest;
  }

#if defined(EDGEWISE_HAS_AVX512_256)
  // shade_planar_rows() on AVX-512, two tile rows per 512-bit batch: a small triangle covers
  // about two pixels of each tile row it touches, so pairs of rows halve the steps (their row
  // terms, mask handling and loop) for the same lanes of work. Each lane takes the same float
  // operations on the same dx and dy as in the 8-lane loop (row r + 1's centre, r + 1.5, is exact),
  // so the results are identical.
  // (PairFloats and the other row-pair operations: simd/row_pairs-inl.hpp.)
  template <DepthTest Test, bool Divide, bool Full, bool Lit, bool Uniform>
  [[gnu::always_inline]] void shade_planar_row_pairs(std::uint64_t mask, std::uint32_t rows,
                                                     float* depth, std::uint32_t* color,
                                                     std::int32_t py, const ColumnTerms& columns,
                                                     Floats& stored_max) {
    static_assert(kParts == 1, "one batch per tile row");
    // Bit r set for each pair of rows r and r + 1 (r even) with a covered sample.
    std::uint32_t pairs = Full ? 0x55u : (rows | rows >> 1) & 0x55u;
    alignas(64) static constexpr float kPairRowCentre[16] = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f,
                                                             0.5f, 0.5f, 1.5f, 1.5f, 1.5f, 1.5f,
                                                             1.5f, 1.5f, 1.5f, 1.5f};
    const PairFloats row_centre = PairFloats::load_aligned(kPairRowCentre);
    const PairFloats depth_column = both_halves(columns.depth[0]);
    PairFloats colour_column[kPlanes];
    for (int k = Uniform ? kFirstNormalPlane : 0; k < kPlanes; ++k) {
      if (k == 4 && !Divide) continue;
      if (k >= kFirstNormalPlane && !Lit) break;
      colour_column[k] = both_halves(columns.colour[k][0]);
    }
    std::uint64_t passed = 0;
    PairFloats largest(-std::numeric_limits<float>::infinity());
    for (; pairs != 0; pairs &= pairs - 1) {
      const int row = std::countr_zero(pairs);
      // depth_row_base()'s dy, the colour planes' too.
      const PairFloats dy =
          (PairFloats(static_cast<float>(py + row)) + row_centre) - PairFloats(depth_.y0);
      const PairFloats z =
          clamp01((PairFloats(depth_.z0) + PairFloats(depth_.dzdy) * dy) + depth_column);
      float* depth_at = depth + static_cast<std::size_t>(row) * kTileSize;
      const PairFloats stored = PairFloats::load_aligned(depth_at);
      PairMask write = passes<Test>(z, stored);
      if constexpr (!Full) write = write && pair_mask_of_bits(mask >> (8 * row));
      const PairFloats updated = xsimd::select(write, z, stored);
      updated.store_aligned(depth_at);
      largest = xsimd::max(largest, updated);
      passed += static_cast<std::uint64_t>(std::popcount(bits_of_pair_mask(write)));
      const auto plane_at = [&](int k) {
        return (PairFloats(plane_[k].at_vertex) + PairFloats(plane_[k].dy) * dy) + colour_column[k];
      };
      PairFloats channel[4];
      for (int k = 0; k < 4; ++k)
        channel[k] = Uniform ? PairFloats(uniform_channel_[k]) : plane_at(k);
      if constexpr (Divide) {
        const PairFloats w = PairFloats(1.0f) / xsimd::max(plane_at(4), PairFloats(min_inverse_w_));
        for (int k = 0; k < 4; ++k)
          channel[k] = channel[k] * w;
      }
      if constexpr (Lit) {
        PairFloats normal[kNormalPlanes];
        for (int k = 0; k < kNormalPlanes; ++k)
          normal[k] = plane_at(kFirstNormalPlane + k);
        apply_light(normal, channel);
      }
      std::uint32_t* color_at = color + static_cast<std::size_t>(row) * kTileSize;
      store_masked(color_at, write, pack_rgba8_lanes<xsimd::avx512bw>(channel));
    }
    passed_ += passed;
    stored_max = xsimd::max(stored_max, Floats(max_of_halves(largest)));
  }
#endif

  template <DepthTest Test>
  [[gnu::always_inline]] void shade_rows_generic(std::uint64_t mask, std::uint32_t rows,
                                                 float* depth, std::uint32_t* color,
                                                 std::int32_t px, std::int32_t py,
                                                 const ColumnTerms& columns,
                                                 const float (*colour_row_bases)[kTileSize],
                                                 Floats& stored_max) {
    for (; rows != 0; rows &= rows - 1) {
      const int row = std::countr_zero(rows);
      const std::uint32_t row_mask = static_cast<std::uint32_t>(mask >> (8 * row)) & 0xFF;
      const Floats row_base(detail::depth_row_base(depth_, py + row));
      for (std::size_t h = 0; h < kParts; ++h) {
        const Mask write =
            depth_step<Test>(depth, row, h, row_base, columns.depth[h], row_mask, stored_max);
        if (constant_) {
          // One colour under the error budget.
          write_colour(color, row, h, write, Ints(static_cast<std::int32_t>(constant_colour_)));
          constant_fragments_ +=
              static_cast<std::uint64_t>(std::popcount(bits_of_lanes<Arch>(write)));
          continue;
        }
        const Ints new_color = colour_planes_
                                   ? planar_colour(colour_row_bases, columns, row, h)
                                   : shade(px + static_cast<std::int32_t>(h * kLanes) - origin_x_,
                                           py + row - origin_y_);
        write_colour(color, row, h, write, new_color);
      }
    }
  }

  // Textured tiles: depth first, so that only rows with pixels to write are textured; then
  // colour.
  [[gnu::always_inline]] void shade_textured_rows(std::uint64_t mask, std::uint32_t rows,
                                                  float* depth, std::uint32_t* color,
                                                  std::int32_t px, std::int32_t py,
                                                  const ColumnTerms& columns,
                                                  const float (*colour_row_bases)[kTileSize],
                                                  Floats& stored_max) {
    Mask writes[kTileSize][kParts];
    const std::uint32_t written_rows =
        depth_test_rows(mask, rows, depth, py, columns, stored_max, writes);
    if (written_rows != 0 && constant_) {
      return write_constant_rows(written_rows, color, writes, constant_colour_);
    }
    if (written_rows != 0) {
      const int first_row = std::countr_zero(written_rows);
      const int last_row = 31 - std::countl_zero(written_rows);
      texture_.query_rows(px, py, first_row, last_row);
      detail::TileTexture choice;
      if (tile_choices_) {
        choice = detail::measured_texture_tile(shade_interval_,
                                               texture_.measure(written_rows, writes), batch_);
      }
      if (choice.colour) return write_constant_rows(written_rows, color, writes, *choice.colour);
      if (choice.one_texel) {
        texture_.fill_rows(choice.texel, first_row, last_row);
        one_texel_fragments_ += written_fragments(written_rows, writes);
      } else {
        texture_.filter_rows(batch_, first_row, last_row);
      }
    }
    write_textured_rows(written_rows, color, px, py, columns, colour_row_bases, writes);
  }

  // The lanes of `writes` in the rows of `written_rows`.
  [[gnu::always_inline]] static std::uint64_t written_fragments(std::uint32_t written_rows,
                                                                const Mask (*writes)[kParts]) {
    std::uint64_t written = 0;
    for (; written_rows != 0; written_rows &= written_rows - 1) {
      const int row = std::countr_zero(written_rows);
      for (std::size_t h = 0; h < kParts; ++h)
        written += static_cast<std::uint64_t>(std::popcount(bits_of_lanes<Arch>(writes[row][h])));
    }
    return written;
  }

  // A tile the budget gives one colour: written under `writes` in the rows of `written_rows`.
  [[gnu::always_inline]] void write_constant_rows(std::uint32_t written_rows, std::uint32_t* color,
                                                  const Mask (*writes)[kParts],
                                                  std::uint32_t constant) {
    const Ints packed(static_cast<std::int32_t>(constant));
    std::uint64_t written = 0;
    for (; written_rows != 0; written_rows &= written_rows - 1) {
      const int row = std::countr_zero(written_rows);
      for (std::size_t h = 0; h < kParts; ++h) {
        write_colour(color, row, h, writes[row][h], packed);
        written += static_cast<std::uint64_t>(std::popcount(bits_of_lanes<Arch>(writes[row][h])));
      }
    }
    constant_fragments_ += written;
  }

  // The depth pass of a textured tile: `writes` gets the lanes to write of each covered row;
  // returns the rows with any such lane (bit `row` for row `row`).
  [[gnu::always_inline]] std::uint32_t depth_test_rows(std::uint64_t mask, std::uint32_t rows,
                                                       float* depth, std::int32_t py,
                                                       const ColumnTerms& columns,
                                                       Floats& stored_max, Mask (*writes)[kParts]) {
    std::uint32_t written_rows = 0;
    for (; rows != 0; rows &= rows - 1) {
      const int row = std::countr_zero(rows);
      const std::uint32_t row_mask = static_cast<std::uint32_t>(mask >> (8 * row)) & 0xFF;
      const Floats row_base(detail::depth_row_base(depth_, py + row));
      std::uint32_t any = 0;
      for (std::size_t h = 0; h < kParts; ++h) {
        writes[row][h] =
            depth_step_any_test(depth, row, h, row_base, columns.depth[h], row_mask, stored_max);
        any |= bits_of_lanes<Arch>(writes[row][h]);
      }
      if (any != 0) written_rows |= 1u << row;
    }
    return written_rows;
  }

  // The colour pass of a textured tile: shaded colour times the sampled texel, written under
  // `writes` in the rows of `written_rows`.
  [[gnu::always_inline]] void write_textured_rows(std::uint32_t written_rows, std::uint32_t* color,
                                                  std::int32_t px, std::int32_t py,
                                                  const ColumnTerms& columns,
                                                  const float (*colour_row_bases)[kTileSize],
                                                  const Mask (*writes)[kParts]) const {
    for (; written_rows != 0; written_rows &= written_rows - 1) {
      const int row = std::countr_zero(written_rows);
      for (std::size_t h = 0; h < kParts; ++h) {
        Floats channel[4];
        colour_channels(colour_row_bases, columns, px, py, row, h, channel);
        for (int k = 0; k < 4; ++k)
          channel[k] = channel[k] * texture_.texel(k, row, h);
        write_colour(color, row, h, writes[row][h], pack_rgba8_lanes<Arch>(channel));
      }
    }
  }

  // A row without covered samples: its stored depths still count towards the tile's bound.
  [[gnu::always_inline]] void keep_row_bound(const float* depth, int row,
                                             Floats& stored_max) const {
    for (std::size_t h = 0; h < kParts; ++h) {
      stored_max = xsimd::max(
          stored_max,
          Floats::load_aligned(depth + static_cast<std::size_t>(row) * kTileSize + h * kLanes));
    }
  }

  // The depth test of lanes h of `row`, the depth written where it passes; returns the lanes
  // to write.
  template <DepthTest Test>
  [[gnu::always_inline]] Mask depth_step(float* depth, int row, std::size_t h, Floats row_base,
                                         Floats depth_column, std::uint32_t row_mask,
                                         Floats& stored_max) {
    const std::size_t offset = static_cast<std::size_t>(row) * kTileSize + h * kLanes;
    const Floats z = clamp01(row_base + depth_column);
    const Floats stored = Floats::load_aligned(depth + offset);
    const Mask write = lanes_of_bits<Arch>(row_mask >> (h * kLanes)) && passes<Test>(z, stored);
    if (batch_.depth_write) {
      const Floats updated = xsimd::select(write, z, stored);
      updated.store_aligned(depth + offset);
      stored_max = xsimd::max(stored_max, updated);
    }
    passed_ += static_cast<std::uint64_t>(std::popcount(bits_of_lanes<Arch>(write)));
    return write;
  }

  // f(std::integral_constant<DepthTest, test>) for the batch's test: the one place a test chosen
  // at run time becomes a template argument.
  template <class F>
  [[gnu::always_inline]] decltype(auto) with_depth_test(F&& f) const {
    switch (batch_.depth_test) {
      case DepthTest::less:
        return f(std::integral_constant<DepthTest, DepthTest::less>{});
      case DepthTest::less_equal:
        return f(std::integral_constant<DepthTest, DepthTest::less_equal>{});
      case DepthTest::greater:
        return f(std::integral_constant<DepthTest, DepthTest::greater>{});
      case DepthTest::always:
        return f(std::integral_constant<DepthTest, DepthTest::always>{});
      case DepthTest::never:
        break;
    }
    return f(std::integral_constant<DepthTest, DepthTest::never>{});
  }

  // Planes in use: the fifth, 1 / w, only for perspective-correct colour (it is set up, as a
  // constant, when diffuse shading needs the normal planes after it).
  int planes_used() const {
    return normal_planes_ ? kShadingPlanes : perspective_ ? 5 : 4;
  }
  // The first of them: a uniform triangle's colour needs no planes.
  int first_plane() const {
    return uniform_ ? kFirstNormalPlane : 0;
  }

  // Equal bit patterns (equal colours as stored; +0 and -0, or two NaNs, count as different).
  static bool same_bits(const Vec4& a, const Vec4& b) {
    std::uint64_t x[2], y[2];
    std::memcpy(x, &a, sizeof x);
    std::memcpy(y, &b, sizeof y);
    return ((x[0] ^ y[0]) | (x[1] ^ y[1])) == 0;
  }

  // depth_step() with the test chosen per call.
  [[gnu::always_inline]] Mask depth_step_any_test(float* depth, int row, std::size_t h,
                                                  Floats row_base, Floats depth_column,
                                                  std::uint32_t row_mask, Floats& stored_max) {
    return with_depth_test([&](auto test) {
      return depth_step<decltype(test)::value>(depth, row, h, row_base, depth_column, row_mask,
                                               stored_max);
    });
  }

  // Blended as floats: a blend moves bits without arithmetic, so every colour survives as is.
  [[gnu::always_inline]] static void write_colour(std::uint32_t* color, int row, std::size_t h,
                                                  Mask write, Ints new_color) {
    float* at =
        reinterpret_cast<float*>(color + static_cast<std::size_t>(row) * kTileSize + h * kLanes);
    const Floats old_color = Floats::load_aligned(at);
    xsimd::select(write, xsimd::bitwise_cast<Floats>(new_color), old_color).store_aligned(at);
  }

  // The shaded colour of lanes h of `row`, each channel scaled to 0 .. 255, before packing.
  [[gnu::always_inline]] void colour_channels(const float (*row_bases)[kTileSize],
                                              const ColumnTerms& columns, std::int32_t px,
                                              std::int32_t py, int row, std::size_t h,
                                              Floats channel[4]) const {
    if (colour_planes_) return planar_channels(row_bases, columns, row, h, channel);
    if (batch_.shading == Shading::flat) {
      for (int k = 0; k < 4; ++k)
        channel[k] = Floats(255.0f * (&color_[0].x)[k]);
      return;
    }
    shade_channels(px + static_cast<std::int32_t>(h * kLanes) - origin_x_, py + row - origin_y_,
                   channel);
  }

  void full_tiles(std::uint32_t begin, std::uint32_t end, std::uint32_t tile_y,
                  std::uint64_t mask) {
    for (std::uint32_t tile_x = begin; tile_x < end; ++tile_x)
      tile(tile_x, tile_y, mask);
  }

  void add_counts(detail::ShadeCounts& counts) const {
    counts.tiles_skipped += tiles_skipped_;
    counts.fragments += fragments_;
    counts.passed += passed_;
    counts.constant += constant_fragments_;
    counts.one_texel += one_texel_fragments_;
  }

 private:
  // The budget's choice for the triangle whose vertices begin_triangle_from_vertices() read:
  // its shade interval, and one colour for it when untextured and within the budget.
  void choose_within_budget(const Vec2 (&p)[3], const ScreenTriangle& screen) {
    detail::BudgetTriangle triangle;
    for (int i = 0; i < 3; ++i) {
      triangle.position[i] = p[i];
      triangle.w[i] = screen.w[i];
      triangle.colour[i] = color_[i];
      triangle.normal[i] = normal_[i];
    }
    shade_interval_ = detail::shade_interval(triangle, batch_);
    std::optional<std::uint32_t> colour;
    tile_choices_ = false;
    if (!textured_) {
      colour = detail::constant_colour(shade_interval_, batch_.budget_codes);
    } else {
      const detail::TexturePlan plan =
          detail::texture_plan(shade_interval_, texture_planes_, batch_, p);
      colour = plan.colour;
      tile_choices_ = plan.tiles;
    }
    constant_ = colour.has_value();
    constant_colour_ = colour.value_or(0u);
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

  static float horizontal_max(Floats v) {
    return lane_max<Arch>(v);
  }

  // Whether the depth test fails at every sample of the tile at (px, py). The samples lie in the
  // rectangle from the first pixel centre moved by the pattern's least offsets to the last one
  // moved by its largest (the centres alone with one sample), and the plane's exact value over
  // it is smallest at the corner its slopes point away from. Each computed depth
  // (depth_plane.hpp: three roundings) lies within 3 u M of the exact plane, u = 2^-24,
  // M = |z0| + |dzdy| max|dy| + |dzdx| max|dx| over the rectangle; `corner` (the computed row base
  // plus the rounded dx term, summed exactly) is within u M of the computed corner depth. So
  // every computed depth in the tile is at least corner - 7 u M; clamping to [0, 1] keeps the
  // order. The margin below is 8 u M: M is itself computed from float differences (the reaches,
  // each within a factor 1 +- u of the exact one), so the computed 7 u M could fall short of the
  // exact one by about 7 u^2 M; the extra u M covers that many times over. A NaN bound compares
  // false: such a tile is never skipped.
  bool hidden(float bound, std::int32_t px, std::int32_t py) const {
    const SampleReach& r = sample_reach_;
    // The pattern's reach in sixteenths of a pixel, as the depth formula takes offsets (16
    // fixed-point units each), and in pixels.
    const auto sixteenths = [](std::int32_t fixed) { return fixed / 16; };
    const auto px_of = [&](std::int32_t fixed) { return detail::sixteenths(sixteenths(fixed)); };
    const bool low_x = depth_.dzdx >= 0.0f, low_y = depth_.dzdy >= 0.0f;
    const std::int32_t cx = low_x ? px : px + kTileSize - 1;
    const std::int32_t cy = low_y ? py : py + kTileSize - 1;
    const float corner_dx =
        ((static_cast<float>(cx) + 0.5f) + px_of(low_x ? r.x_min : r.x_max)) - depth_.x0;
    const double corner = static_cast<double>(detail::depth_row_base(
                              depth_, cy, sixteenths(low_y ? r.y_min : r.y_max))) +
                          depth_.dzdx * corner_dx;
    // Plain comparisons rather than std::fmax/fmin, which compile to library calls; they give
    // the same values here (the reaches are finite, and a NaN corner becomes 0 either way).
    const double reach_x =
        larger(std::fabs(((static_cast<float>(px) + 0.5f) + px_of(r.x_min)) - depth_.x0),
               std::fabs(((static_cast<float>(px) + 7.5f) + px_of(r.x_max)) - depth_.x0));
    const double reach_y =
        larger(std::fabs(((static_cast<float>(py) + 0.5f) + px_of(r.y_min)) - depth_.y0),
               std::fabs(((static_cast<float>(py) + 7.5f) + px_of(r.y_max)) - depth_.y0));
    const double margin = 8.0 * 0x1p-24 *
                          (std::fabs(depth_.z0) + std::fabs(depth_.dzdy) * reach_y +
                           std::fabs(depth_.dzdx) * reach_x);
    const double above_zero = corner - margin > 0.0 ? corner - margin : 0.0;
    const double lowest = above_zero < 1.0 ? above_zero : 1.0;
    return batch_.depth_test == DepthTest::less ? lowest >= bound : lowest > bound;
  }

  static double larger(double a, double b) {
    return a > b ? a : b;
  }
  template <class F>
  static F clamp01(F z) {
    return xsimd::min(xsimd::max(z, F(0.0f)), F(1.0f));
  }
  template <DepthTest Test, class F>
  [[gnu::always_inline]] static typename F::batch_bool_type passes(F z, F stored) {
    using Bools = typename F::batch_bool_type;
    if constexpr (Test == DepthTest::less) return z < stored;
    if constexpr (Test == DepthTest::less_equal) return z <= stored;
    if constexpr (Test == DepthTest::greater) return z > stored;
    if constexpr (Test == DepthTest::always) return Bools(true);
    return Bools(false);
  }

  // Gouraud colour by its own plane equations (model no more than the scene needs: one add per
  // channel and pixel instead of weights, then colours). Each channel, scaled to 0 .. 255, is
  // value(px, py) = (at_vertex + dy_slope * dy) + dx_slope * dx with the depth formula's exact dx,
  // dy; perspective-correct, channels are planes of value / w, divided per pixel by the plane of
  // 1 / w (the fifth), kept from falling below the smallest vertex 1 / w as the reference's
  // weights keep it. Slopes come from the snapped positions in double, rounded to float once.
  [[gnu::always_inline]] Ints planar_colour(const float (*row_bases)[kTileSize],
                                            const ColumnTerms& columns, int row,
                                            std::size_t h) const {
    Floats channel[4];
    planar_channels(row_bases, columns, row, h, channel);
    return pack_rgba8_lanes<Arch>(channel);
  }
  [[gnu::always_inline]] void planar_channels(const float (*row_bases)[kTileSize],
                                              const ColumnTerms& columns, int row, std::size_t h,
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
    if (normal_planes_) {
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

  // Packed RGBA8 of kLanes pixels from (column, row) relative to the interpolation origin.
  [[gnu::always_inline]] Ints shade(std::int32_t column, std::int32_t row) const {
    if (batch_.shading == Shading::flat) return Ints(static_cast<std::int32_t>(flat_color_));
    Floats rgba[4];
    shade_channels(column, row, rgba);
    return pack_rgba8_lanes<Arch>(rgba);
  }
  // Gouraud or diffuse, each channel scaled to 0 .. 255.
  [[gnu::always_inline]] void shade_channels(std::int32_t column, std::int32_t row,
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

  const detail::ShadeBatch& batch_;
  MethodInterpolator<Arch> interpolator_;
  PerspectiveDivide<Arch> divide_;
  // Fixed for the batch.
  const bool colour_planes_;  // Gouraud or diffuse colour from the group's planes
  const bool normal_planes_;  // diffuse: the normal from the group's planes
  const bool keep_bounds_, reject_hidden_;
  const bool textured_;
  const bool needs_vertices_;  // begin_triangle() reads the vertices for more than the planes
  const bool budget_shading_;
  // The current group's planes and triangle.
  PlaneGroup<Arch> group_{};
  detail::DepthPlane depth_{};
  float max_vertex_depth_ = 0.0f;
  Vec4 color_[3]{};
  Vec3 normal_[3]{};
  std::uint32_t flat_color_ = 0;
  // The budget's choices for the current triangle.
  detail::ShadeInterval shade_interval_{};
  bool constant_ = false;      // drawn in one colour
  bool tile_choices_ = false;  // textured: each tile decided (measured_texture_tile())
  std::uint32_t constant_colour_ = 0;
  detail::TexturePlanes texture_planes_{};
  bool beyond_budget_[kSetupLanes<Arch>]{};  // of the current group (mark_beyond_budget())
  // Of the current group: the lanes whose vertices share one colour, and that colour.
  bool group_uniform_[kSetupLanes<Arch>]{};
  Vec4 group_uniform_colour_[kSetupLanes<Arch>]{};
  std::int32_t origin_x_ = 0, origin_y_ = 0;
  bool perspective_ = false;
  float min_inverse_w_ = 1.0f;    // the plane of 1 / w's floor (PlaneGroup::min_inverse_w)
  ColourPlane plane_[kPlanes]{};  // those from first_plane() to planes_used() set
  // The current triangle's vertices share one colour: uniform_channel_, scaled to 0 .. 255.
  bool uniform_ = false;
  float uniform_channel_[4]{};
  // The colour planes' row terms for the tile row row_bases_tile_y_ (set_up_colour_rows()).
  static constexpr std::uint32_t kNoTileRow = UINT32_MAX;
  std::uint32_t row_bases_tile_y_ = kNoTileRow;
  alignas(64) float row_bases_[kPlanes][kTileSize];
  // Counts.
  std::uint64_t fragments_ = 0;
  std::uint64_t tiles_skipped_ = 0;
  std::uint64_t passed_ = 0;
  std::uint64_t constant_fragments_ = 0;
  std::uint64_t one_texel_fragments_ = 0;
  TextureTile<Arch> texture_;
  // The target's sample pattern (empty: pixel centres) and its reach (sample_walk-inl.hpp).
  std::span<const SampleOffset> pattern_;
  SampleReach sample_reach_;
  float sample_dx_[kMaxSamples]{}, sample_dy_[kMaxSamples]{};  // the pattern's offsets in pixels
  // Each sample's depth row terms for the tile row sample_rows_tile_y_ (set_up_sample_rows()).
  std::uint32_t sample_rows_tile_y_ = kNoTileRow;
  alignas(64) float sample_row_base_[kMaxSamples][kTileSize];
};

// The shading visitor of a multisampled target: the walks deliver every sample's masks
// (sample_tile).
template <class Arch>
class MultisampleShadingVisitor : public ShadingVisitor<Arch> {
 public:
  static constexpr bool kMultisample = true;
  using ShadingVisitor<Arch>::ShadingVisitor;
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
