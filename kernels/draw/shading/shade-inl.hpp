// Shading of covered tiles: depth test, attribute interpolation and colour writes, 8 pixels per
// AVX2 step (4 with SSE and NEON), into the Framebuffer's tiled storage. The tile walks deliver
// masks to ShadingVisitor exactly as they deliver them to the coverage visitors.
//
// Per row of a tile: depth from the shared plane formula, the depth compare (shade_depth-inl.hpp),
// then the colour (shade_colour-inl.hpp: planes, the interpolation method's weights, the
// perspective step when w varies across the triangle, and the shading model), times the texels
// when textured (shade_textured-inl.hpp), or one colour where the error budget allows it
// (shade_budget-inl.hpp). Writes are blends under the covered-and-passed lane mask: no branch per
// pixel. Rows without covered samples are skipped. A multisampled target has a visitor of its
// own (shade_multisample-inl.hpp).
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>

#include <xsimd/xsimd.hpp>

#include "depth_plane.hpp"
#include "shade_batch.hpp"
#include "../../simd/simd_ops-inl.hpp"
#include "plane_setup-inl.hpp"
#include "shade_budget-inl.hpp"
#include "shade_colour-inl.hpp"
#include "shade_depth-inl.hpp"
#include "shade_planar_rows-inl.hpp"
#include "shade_textured-inl.hpp"
#include "../../coverage/tile_masks-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
class ShadingVisitor {
 public:
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  using Mask = xsimd::batch_bool<float, Arch>;
  using Columns = TileColumnTerms<Arch>;
  static constexpr std::size_t kLanes = Floats::size;
  static constexpr std::size_t kParts = kTileSize / kLanes;
  static constexpr int kPlanes = kShadingPlanes;

  explicit ShadingVisitor(const detail::ShadeBatch& batch)
      : batch_(batch),
        depth_(batch),
        colour_(batch),
        budget_(batch),
        texture_(batch),
        textured_(batch.texture_description != nullptr),
        // Model no more than the scene needs: Gouraud colour by plane equations interpolates the
        // colours (and diffuse the normals) directly, and then, untextured, needs nothing per
        // triangle beyond the planes.
        needs_vertices_(textured_ || !colour_.planar()) {}

  // The depth and colour planes of a group of triangles (plane_setup-inl.hpp), before
  // begin_triangle() for each.
  void begin_group(const GroupCorners<Arch>& corners, const TriangleGroup<Arch>& positions) {
    PlaneGroupInput<Arch> in;
    for (std::size_t l = 0; l < kSetupLanes<Arch>; ++l) {
      const bool valid = corners.valid[l];  // a bad index reads nothing; the lane is not drawn
      for (int i = 0; i < 3; ++i) {
        in.x[i][l] = positions.x[i][l];
        in.y[i][l] = positions.y[i][l];
        const std::size_t v = corners.vertex[l][i];
        in.z[i][l] = valid ? batch_.depth[v] : 0.0f;
        in.w[i][l] = valid ? batch_.clip_w[v] : 1.0f;
      }
    }
    // The budget's bounds need the colours.
    const bool budget_bounds = budget_.active() && !textured_;
    const bool all_uniform = colour_.read_group(corners, in, budget_bounds);
    set_up_plane_group(in, colour_.planar(), colour_.lit_planes(),
                       batch_.perspective == Perspective::correct, group_,
                       /*colour_values=*/!all_uniform);
    if (budget_bounds) budget_.mark_group(in, colour_.lit_planes());
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
      if (colour_.lit_planes()) __builtin_prefetch(batch_.normals + v);
      if (colour_.planar()) __builtin_prefetch(batch_.colors + v);
    }
  }

  // Triangle t, lane l of the last begin_group().
  void begin_triangle(std::uint32_t t, std::size_t l) {
    depth_.begin_triangle(
        {group_.z0[l], group_.dzdx[l], group_.dzdy[l], group_.x0[l], group_.y0[l]},
        group_.max_depth[l]);
    colour_.begin_triangle(group_, l);
    budget_.begin_triangle();
    // Under a budget, an untextured triangle is looked at closer unless its vertices already
    // rule one colour out.
    if (needs_vertices_ || budget_.looks_at(l)) begin_triangle_from_vertices(t);
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
    if (depth_.skips_hidden_tile(tile_index, px, py)) return;
    Floats stored_max(-std::numeric_limits<float>::infinity());  // depth after the writes
    Columns columns;
    set_up_tile_columns(px, columns);
    if (needs_row_bases()) colour_.set_up_tile_row(depth_.plane().y0, py, tile_y);
    const float(*colour_row_bases)[kTileSize] = colour_.row_bases();
    const std::uint32_t rows = covered_rows(mask);
    if (textured_) {
      texture_.shade_rows(depth_, colour_, budget_, mask, rows, depth, color, px, py, columns,
                          colour_row_bases, stored_max);
    } else {
      // Inlined: as a call, its captures go through memory for every tile.
      depth_.with_test([&](auto test) EDGEWISE_INLINE_LAMBDA {
        shade_rows<decltype(test)::value>(mask, rows, depth, color, px, py, columns,
                                          colour_row_bases, stored_max);
      });
    }
    if (depth_.keeps_bounds()) depth_.tighten_bound(tile_index, depth, rows, stored_max);
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
    depth_.with_test([&](auto test) { shade_grid<decltype(test)::value>(tile_x, tile_y, masks); });
  }

  void full_tiles(std::uint32_t begin, std::uint32_t end, std::uint32_t tile_y,
                  std::uint64_t mask) {
    for (std::uint32_t tile_x = begin; tile_x < end; ++tile_x)
      tile(tile_x, tile_y, mask);
  }

  void add_counts(detail::ShadeCounts& counts) const {
    counts.fragments += fragments_;
    depth_.add_counts(counts);
    budget_.add_counts(counts);
    texture_.add_counts(counts);
  }

 protected:
  // What the group's planes leave out: normals, texture planes, flat colour, the budget's choice
  // and the other interpolation methods' set-up.
  void begin_triangle_from_vertices(std::uint32_t t) {
    std::size_t corner[3] = {3 * std::size_t{t}, 3 * std::size_t{t} + 1, 3 * std::size_t{t} + 2};
    if (batch_.coverage.indices != nullptr) {
      for (int i = 0; i < 3; ++i)
        corner[i] = batch_.coverage.indices[corner[i]];
    }
    Vec2 p[3];
    ScreenTriangle screen;
    for (int i = 0; i < 3; ++i) {
      p[i] = batch_.coverage.vertices[corner[i]];
      screen.x[i] = p[i].x;
      screen.y[i] = p[i].y;
      screen.w[i] = batch_.clip_w[corner[i]];
    }
    colour_.read_vertices(corner);
    if (textured_) {
      Vec2 uv[3];
      for (int i = 0; i < 3; ++i)
        uv[i] = batch_.uvs[corner[i]];
      texture_.begin_triangle(p, uv, screen.w);
    }
    if (budget_.active()) {
      budget_.choose(p, screen, colour_.vertex_colours(), colour_.vertex_normals(),
                     textured_ ? &texture_.planes() : nullptr);
    }
    colour_.begin_triangle_from_vertices(p, screen);
  }

  // Whether a tile's shading reads the colour planes' row terms from ColourSource::row_bases():
  // not the row pairs of AVX-512 (untextured, depth written), which compute their own.
  bool needs_row_bases() const {
    if (!colour_.planar() || budget_.constant()) return false;
    return textured_ || !(kPlanarRowPairs<Arch> && batch_.depth_write);
  }

  // The dx terms for tile columns from px (exact dx, one rounding each); the colour planes'
  // only when colour comes from planes.
  [[gnu::always_inline]] void set_up_tile_columns(std::int32_t px, Columns& columns) const {
    for (std::size_t h = 0; h < kParts; ++h) {
      const Floats dx = depth_.column_dx(px, h);
      columns.depth[h] = Floats(depth_.plane().dzdx) * dx;
      if (colour_.planar() && !budget_.constant()) colour_.set_up_column(dx, h, columns);
    }
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
    Columns columns[N];
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
        if (depth_.skips_hidden_tile(tile_index, tile_px, tile_py)) continue;
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
            colour_.set_up_rows(depth_.plane().y0, tile_py, colour_row_bases);
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
          if (depth_.keeps_bounds()) depth_.tighten_bound(tile_index, depth, rows, stored_max);
        }
      }
    }
  }

  // Untextured tiles: per covered row and batch of lanes, the depth test, then the colour
  // written where it passed. Colour from planes with depth writes, the common case, has loops of
  // its own (shade_planar_rows-inl.hpp). The colour planes' row terms come from
  // `colour_row_bases`, or, with RowTermsPerRow, are computed here.
  template <DepthTest Test, bool RowTermsPerRow = false>
  [[gnu::always_inline]] void shade_rows(std::uint64_t mask, std::uint32_t rows, float* depth,
                                         std::uint32_t* color, std::int32_t px, std::int32_t py,
                                         const Columns& columns,
                                         const float (*colour_row_bases)[kTileSize],
                                         Floats& stored_max) {
    if (colour_.planar() && batch_.depth_write && !budget_.constant()) {
      if (colour_.lit_planes()) {
        return shade_planar_choice<Test, RowTermsPerRow, true>(
            depth_, colour_, mask, rows, depth, color, py, columns, colour_row_bases, stored_max);
      }
      return shade_planar_choice<Test, RowTermsPerRow, false>(
          depth_, colour_, mask, rows, depth, color, py, columns, colour_row_bases, stored_max);
    }
    alignas(64) float row_bases[kPlanes][kTileSize];
    if constexpr (RowTermsPerRow) {
      if (colour_.planar() && !budget_.constant())
        colour_.set_up_rows(depth_.plane().y0, py, row_bases);
      colour_row_bases = row_bases;
    }
    for (; rows != 0; rows &= rows - 1) {
      const int row = std::countr_zero(rows);
      const std::uint32_t row_mask = static_cast<std::uint32_t>(mask >> (8 * row)) & 0xFF;
      const Floats row_base(detail::depth_row_base(depth_.plane(), py + row));
      for (std::size_t h = 0; h < kParts; ++h) {
        const Mask write = depth_.template step<Test>(depth, row, h, row_base, columns.depth[h],
                                                      row_mask, stored_max);
        if (budget_.constant()) {
          budget_.write_constant(color, row, h, write);  // one colour under the error budget
          continue;
        }
        write_colour<Arch>(color, row, h, write,
                           colour_.packed(colour_row_bases, columns, px, py, row, h));
      }
    }
  }

  const detail::ShadeBatch& batch_;
  DepthStage<Arch> depth_;
  ColourSource<Arch> colour_;
  ShadingBudget<Arch> budget_;
  TexturedShading<Arch> texture_;
  const bool textured_;
  const bool needs_vertices_;  // begin_triangle() reads the vertices for more than the planes
  PlaneGroup<Arch> group_{};   // the current group's planes
  std::uint64_t fragments_ = 0;
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
