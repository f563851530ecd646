// Drawing shaded, depth-tested triangle meshes into a Framebuffer.
//
// The pipeline: vertices are transformed to clip space (camera.hpp), triangles are clipped
// (docs/design/vertex-stage.md, "Clipping") and mapped to the screen, snapped to 1/256 px like
// every coverage decision, culled by winding, rasterized with the exact coverage of coverage.hpp,
// depth-tested, shaded, written.
//
// Depth is z/w, interpolated linearly in screen space in float32 by one fixed formula (see
// docs/design/depth-and-interpolation.md, "Depth"), so depth-test outcomes are identical on every
// ISA and in the scalar reference. Colours and normals are interpolated by the chosen method,
// perspective- correct by default, within the bounds derived in the kernels.
//
// Texturing (DrawOptions::texture): texture coordinates are interpolated by plane equations of
// s/w, t/w and 1/w (of s and t under Perspective::affine), each pixel's (s, t) and derivatives go
// to the sampler (sample.hpp) with the chosen filter, and the filtered texel multiplies the
// shaded colour channel by channel (flat, Gouraud or diffuse, as without a texture). Coordinates
// and derivatives come from one fixed float32 formula (docs/design/textures.md), so every
// ISA and the scalar reference sample the texture at the same queries; the texture-coordinate
// planes do not depend on the interpolation method, which applies to colours and normals.
//
// Thread safety: draw() keeps no state between calls. Calls on different framebuffers may run at
// once, sharing meshes and textures (only read); two calls on the same framebuffer may not. With
// DrawOptions::threads other than 1, one call itself runs on several threads (threads.hpp): it
// sorts the triangles into screen bins, each drawn by one thread in submission order, and
// returns when all are done.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "edgewise/camera.hpp"
#include "edgewise/framebuffer.hpp"
#include "edgewise/interpolation.hpp"
#include "edgewise/isa.hpp"
#include "edgewise/coverage.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "edgewise/threads.hpp"
#include "edgewise/vector.hpp"
#include "edgewise/names.hpp"

namespace edgewise {

// Passes when (fragment depth) OP (stored depth).
enum class DepthTest : std::uint8_t { less, less_equal, greater, always, never };

enum class Shading : std::uint8_t {
  flat,     // every pixel takes the colour of the triangle's first vertex
  gouraud,  // vertex colours interpolated
  diffuse,  // interpolated colour times (ambient + (1 - ambient) max(0, n . l)), n the
            // interpolated normal renormalized per pixel
};

// Where the sampler's screen derivatives (dsdx, dtdx, dsdy, dtdy) come from.
enum class TextureDerivatives : std::uint8_t {
  // Differences within 2x2 pixel quads, as GPUs take them: dsdx at (x, y) is
  // s(x | 1, y) - s(x & ~1, y), dsdy is s(x, y | 1) - s(x, y & ~1) (each pixel's own row and
  // column of its quad), with s evaluated at every pixel of a quad the triangle touches, covered
  // or not. Exact for affine mappings up to rounding; a one-pixel secant under perspective.
  quad,
  // The exact derivatives of the projective mapping at the pixel centre, from the planes of
  // s/w, t/w and q = 1/w: ds/dx = (d(s/w)/dx - s dq/dx) / q, and likewise for t and y.
  analytic,
};

struct DrawTexture {
  const Texture* texture = nullptr;  // read during draw() only
  SamplerOptions sampler;
  TextureDerivatives derivatives = TextureDerivatives::quad;
};

// The mesh to draw; spans are read during draw() only.
struct DrawMesh {
  std::span<const Vec3> positions;
  std::span<const Vec4> colors;            // linear RGBA per vertex; empty: opaque white
  std::span<const Vec3> normals;           // per vertex; needed by Shading::diffuse
  std::span<const std::uint32_t> indices;  // three per triangle; empty: vertices 3t .. 3t + 2
  std::span<const Vec2> uvs{};             // texture coordinates (s, t) per vertex; needed with
                                           // a texture, ignored without one
};

struct DrawOptions {
  Mat4 transform = identity();     // object space to clip space
  CullMode cull = CullMode::none;  // winding on screen (y down), as coverage.hpp defines it
  DepthTest depth_test = DepthTest::less;
  bool depth_write = true;
  Shading shading = Shading::gouraud;
  InterpolationMethod interpolation = InterpolationMethod::plane_equations;
  Perspective perspective = Perspective::correct;
  // Towards the light, in the normals' space; any finite vector (its length does not matter),
  // zero for no direct light (ambient only). Throws for a NaN or infinite component.
  Vec3 light_direction{0.0f, 0.0f, 1.0f};
  // The light of a surface facing away from the light (Shading::diffuse): in [0, 1], so that
  // the light goes from it to 1 as the surface turns to the light. Throws outside [0, 1] or NaN.
  float ambient = 0.15f;
  // Multiplies the shaded colour by the filtered texel at each pixel (see the top of this file).
  std::optional<DrawTexture> texture;
  // The largest difference from the exact methods' colour allowed at any pixel, in linear units
  // of the written colour (1/255 is one 8-bit code); std::nullopt or 0 draw with the exact
  // methods. Within it, draw() replaces the plane-equation shading (Gouraud, diffuse) of a
  // triangle by one colour, and a textured triangle's filtered texels by one colour per 8x8
  // tile (nearest, bilinear, mip_nearest and trilinear filters), wherever a bound derived from
  // the triangle's vertices, the texture's ranges and the float32 rounding of the exact path
  // shows the written 8-bit codes to differ by at most floor(255 budget)
  // (docs/design/error-budget.md); a budget within 2^-20 of k/255 counts as k codes. Multisampled
  // targets are drawn exactly. Throws for a negative or NaN budget.
  std::optional<float> error_budget;
  // Skip 8x8 tiles whose stored depth the triangle cannot pass anywhere (less and less_equal
  // tests), from a per-tile depth bound the framebuffer keeps. Outcomes are the same either way.
  bool hierarchical_depth = true;
  std::optional<PixelRect> scissor;  // intersected with the framebuffer
  std::optional<Isa> isa;            // default: active_isa()
  // Threads (threads.hpp): 0 takes default_thread_count(), 1 draws on the calling thread alone.
  // The framebuffer and the report are the same bit for bit for every count.
  std::size_t threads = 0;
  // Runs the call's tasks on those threads; empty: oneTBB's (threads.hpp states the contract).
  TaskExecutor executor;
};

// What draw()'s shortcuts did, none of which changes the image beyond what DrawOptions allows:
// statistics for tuning a scene, apart from the report's results.
struct DrawStatistics {
  std::uint64_t tiles_skipped = 0;  // covered tiles rejected whole by hierarchical depth
  // Of DrawReport::fragments_passed, those written with one colour per triangle or per tile under
  // DrawOptions::error_budget.
  std::uint64_t fragments_constant = 0;
  // Of DrawReport::fragments_passed, textured ones whose texel was one value for their whole tile
  // under the budget (the filter not run; the shading still per pixel).
  std::uint64_t fragments_one_texel = 0;
};

// What became of the mesh's triangles. Each one is counted once: outside, culled or an error,
// as it is or after clipping; clipped, when clipping cut it into clip_triangles pieces; or
// rasterized. Each piece is in turn culled, an error or rasterized. So always
//   outside + culled + errors + rasterized == triangles - clipped + clip_triangles.
// Tiny coordinates are no error in themselves: a triangle too small to cover 1/256 px (1e-40
// under a camera whose clip-space w stays near 1) snaps to zero area and is culled. What is an
// error is a clip-space coordinate that float32 cannot project: non-finite, beyond 2^64, or a w
// in (0, 2^-125) at a vertex that clipping keeps (docs/design/vertex-stage.md, "Clipping").
struct DrawReport {
  std::uint64_t triangles = 0;  // in the mesh
  std::uint64_t clipped = 0;    // cut by the clipping planes into pieces, clip_triangles in all
  std::uint64_t clip_triangles = 0;  // the pieces of the clipped triangles
  std::uint64_t outside = 0;         // entirely outside the view volume
  std::uint64_t culled = 0;          // by winding, zero area after snapping, or degenerate in
                                     // clipping (docs/design/vertex-stage.md, "Clipping")
  std::uint64_t errors = 0;          // non-finite or out-of-range clip-space positions, bad indices
  // Screen triangles drawn: set up and walked, or found from their box alone to cover no sample.
  std::uint64_t rasterized = 0;
  std::uint64_t fragments = 0;         // covered samples
  std::uint64_t fragments_passed = 0;  // of those, passing the depth test (and so written)
  Isa isa = Isa::reference;
  DrawStatistics statistics;  // how the shortcuts fared: for tuning, not part of the result
};

// Throws std::invalid_argument for inconsistent spans (attribute counts, index count not a
// multiple of 3, diffuse without normals, a texture without uvs), a null texture, sampler
// options sample() refuses, an inverted scissor, an unsupported ISA, or a float option outside
// its domain (ambient, light_direction, error_budget; each states its own), whatever the
// shading. The transform is not checked: the vertices it makes non-finite or out of range are
// bad geometry, which is counted in the report (DrawReport::errors), never drawn. Non-finite
// uvs give the sampler's defined results (sample.hpp).
DrawReport draw(Framebuffer& target, const DrawMesh& mesh, const DrawOptions& options);

// Names of the values (names.hpp).
std::string_view name_of(DepthTest value);
template <>
std::span<const DepthTest> values_of<DepthTest>();
std::string_view name_of(Shading value);
template <>
std::span<const Shading> values_of<Shading>();
std::string_view name_of(TextureDerivatives value);
template <>
std::span<const TextureDerivatives> values_of<TextureDerivatives>();

}  // namespace edgewise
