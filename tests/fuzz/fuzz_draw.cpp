// Differential fuzz target for draw(): the input bytes become a small mesh (positions, colours,
// normals, indices), a transform, a target, a scissor and the draw options, and optionally a
// texture with its sampler options and per-vertex texture coordinates. Every supported ISA and the
// shading reference draw it into identically cleared framebuffers, first the whole mesh, then
// each triangle on its own. A finding prints the decoded input and every ISA's output, then
// aborts, when:
// - an ISA throws where the reference does not, or anything but the documented
//   std::invalid_argument (whose cases the input decoder predicts) escapes draw();
// - a DrawReport count differs from the reference's, or breaks its own invariants;
// - a depth buffer (every sample of a multisampled target) differs from the reference's in any
//   bit (padding included);
// - anything outside the scissor, outside the target (the tile padding) or outside every
//   triangle changes from the clear values, on any ISA or the reference;
// - (one triangle per draw, so that each pixel's writer is known) a colour differs from the
//   reference's by more than tests/draw/colour_bounds.hpp allows for that pixel;
// - (textured, one triangle per draw) a colour, the reference's included, lies outside the bound
//   of tests/draw/textured_bounds.hpp: the pixel's query recomputed by the kernels' formula
//   (kernels/draw/shading/texture_planes.hpp) from the writer's snapped corners, its untextured
//   colour from the reference's draw of the same triangle without the texture (whose depth must
//   equal the textured draw's), nothing checked where the untextured colour bound is unbounded.
//
// Input layout (missing bytes read as zero):
//   u8 width, u8 height          target size, each modulo kMaxTargetSide + 1 (0 is empty)
//   u8 flags                     bits 0-1 cull (3 = none); 2 no depth write; 3 indexed;
//                                4 scissor; 5 affine; 6 ragged corner count; 7 one colour short
//   u8 depth test, u8 model      depth test modulo 5; shading model % 3, method / 3 % 6
//   u8 attributes                bit 0 no colours, bit 1 no normals; bits 2-4 the target's
//                                samples per pixel: 1, 2, 4, 8, 16 for 0-4, 1 for 5-7
//   4 x i8 scissor               x0, y0, width, height (negative sides are inverted)
//   u8 (+ number) clear depth    < 64: 1, < 128: 0, < 192: 0.5, else a number
//   4 x u8 clear colour, u8 ambient (v / 255), 3 x i8 light direction (v / 64)
//   u8 camera kind % 5, then its numbers (see decode_transform)
//   u8 vertex count % (kMaxVertices + 1), u8 indexed triangle count % (kMaxTriangles + 1)
//   per vertex: 3 numbers position; 4 x u8 colour ((v - 16) / 223, slightly beyond [0, 1]);
//               3 x i8 normal (v / 32); u8 extra: >= 240 replaces component extra % 7 of the
//               colour (0-3) or normal (4-6) with a number
//   indexed: one u8 per corner, modulo (vertex count + 2), so some indices are past the end
// Then, optionally (an input that ends here, or whose next byte is even, draws untextured):
//   u8 texture                   bit 0 textured; bits 1-2 % 3 rgba8 linear, rgba8 sRGB, rgba32f;
//                                3 analytic derivatives (else quad); 4 Lanczos-3 pyramid (else
//                                box); 5 texels at random palette entries (else cycling through
//                                it); 6 LodFormula::max_axis; 7 one texture coordinate short
//   u8 width, u8 height          1 + v % kMaxTextureSide
//   u8 palette size, entries     1 + v % kMaxPalette entries of 4 x u8: the 8-bit codes, or for
//                                float texels 2^scale (4 v / 255 - 1), in 2^scale [-1, 3]
//   u32 seed, u8 float scale     of the random layout (tests/random.hpp); scale v % 21 - 10
//   u8 filter % 11, u8 wrap      wrap_s v % 3, wrap_t v / 3 % 3 (WrapMode's order)
//   i8 lod bias (v / 64), u8 max anisotropy (1 + v % 64), u8 supersample taps (1 + v % 16)
//   u8 variant                   < 247: ripmaps and a summed-area table built. 247: no texture
//                                (null pointer); 248: no ripmaps; 249: no summed-area table;
//                                250, 251: max_anisotropy 0, 65; 252, 253: supersample_taps 0,
//                                17; 254, 255: lod_bias inf, NaN
//   per vertex: 2 numbers        the texture coordinates (s, t)
// Texels are finite and within float texels' 2^10 [-1, 3], as tests/texture/sample_bounds.hpp
// assumes; coordinates take any number, NaN and infinities included.
// A number is a u8 tag: < 192 an i16 / 4096 (+-8 in 1/4096 steps), < 192 + 40 an entry of
// kSpecialValues (zeros, +-1, the clip range's ends, the guard band, float's extremes, NaN,
// infinities), else raw float bits from a u32.
//
// Replay: `fuzz_draw <input file>` runs one input; a finding prints it and aborts.
// EDGEWISE_FUZZ_PRINT=1 prints every input's description and per-ISA counts.
// EDGEWISE_FUZZ_SEEDS=DIR writes seed scenes (seed_inputs below) into DIR at start-up.
#include <algorithm>
#include <array>
#include <bit>
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <initializer_list>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "draw/vertex_stage/clip.hpp"
#include "core/framebuffer_access.hpp"
#include "edgewise/edgewise.hpp"
#include "edgewise/draw.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "random.hpp"
#include "interpolation/interpolation_reference.hpp"
#include "draw/colour_bounds.hpp"
#include "draw/textured_bounds.hpp"
#include "sampler_input.hpp"
#include "seed_files.hpp"
#include "draw/shading/texture_planes.hpp"

namespace {

using namespace edgewise;
using test::allowed_codes;
using test::Bounded;
using test::VertexAttributes;
using test::WeightErrors;

// Small targets keep the reference fast; sizes cross tile boundaries and include 0 and 1.
constexpr std::int32_t kMaxTargetSide = 72;
constexpr std::size_t kMaxTriangles = 6;
constexpr std::size_t kMaxVertices = 3 * kMaxTriangles;
// Textures cross the sampling kernels' batch sizes and the pyramids' odd sides; a small palette
// lets the input choose the texel values without paying for every texel.
constexpr std::int32_t kMaxTextureSide = 64;
constexpr std::uint32_t kMaxPalette = 8;
using fuzz::kFilterCount;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kFloatMax = std::numeric_limits<float>::max();
constexpr float kFloatMin = std::numeric_limits<float>::min();
constexpr float kDenormMin = std::numeric_limits<float>::denorm_min();
// One line per kind of value.
// clang-format off
constexpr float kSpecialValues[] = {
    0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 2.0f, 3.0f, -3.0f, 0.1f, 0.99999994f, 1.0000001f,  // ordinary
    1e-3f, -1e-3f, 1e-7f, -1e-7f, 1e-30f, kFloatMin, kDenormMin, -kDenormMin,  // near zero
    0x1p-32f, 0x1p-33f, 0x1p32f, 0x1p33f,  // the ends of [kMinClipW, kMaxClipW]
    32768.0f, -32768.0f, 65536.0f,         // the guard band
    1e10f, -1e10f, 1e19f, 1e30f, -1e30f, kFloatMax, -kFloatMax,  // huge
    kMaxClipCoordinate, -kMaxClipCoordinate, 0x1.000002p64f,     // the clipper's input range
    kNaN, -kNaN, kInf, -kInf};
// clang-format on
static_assert(std::size(kSpecialValues) == 40);

class FuzzInput {
 public:
  explicit FuzzInput(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  std::uint32_t u8() { return pos_ < bytes_.size() ? bytes_[pos_++] : 0; }
  std::int32_t i8() { return static_cast<std::int8_t>(u8()); }
  std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i)
      v |= u8() << (8 * i);
    return v;
  }
  float number() {
    const std::uint32_t tag = u8();
    if (tag < 192) {
      const std::uint32_t low = u8();
      const std::int32_t fixed = static_cast<std::int16_t>(low | u8() << 8);
      return static_cast<float>(fixed) / 4096.0f;
    }
    if (tag < 192 + std::size(kSpecialValues)) return kSpecialValues[tag - 192];
    return std::bit_cast<float>(u32());
  }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t pos_ = 0;
};

// The optional texture block of an input, decoded.
struct TextureInput {
  TexelFormat format = TexelFormat::rgba8;
  ColorEncoding encoding = ColorEncoding::linear;
  std::int32_t width = 1, height = 1;
  TextureBuild build{PyramidFilter::box, true, true};
  std::vector<std::array<std::uint8_t, 4>> palette;
  bool random_layout = false;
  std::uint32_t seed = 0;
  int scale_exponent = 0;  // float texels lie in 2^scale_exponent [-1, 3]
  std::uint32_t variant = 0;
};

// Everything one input decodes to.
struct Case {
  std::int32_t width = 0, height = 0;
  std::vector<Vec3> positions;
  std::vector<Vec4> colors;
  std::vector<Vec3> normals;
  std::vector<std::uint32_t> indices;
  std::vector<Vec2> uvs;  // textured inputs only
  bool indexed = false;
  std::optional<TextureInput> texture_input;
  std::shared_ptr<const Texture> texture;  // options.texture points to it (copies share it)
  DrawOptions options;
  Vec4 clear_color{};
  float clear_depth = 1.0f;
  int samples = 1;  // per pixel of the target
  const char* camera = "";
  std::string part = "the whole mesh";  // or one of its triangles, drawn alone
  bool expect_invalid = false;          // draw() documents std::invalid_argument for this input

  DrawMesh mesh() const { return {positions, colors, normals, indices, uvs}; }
  std::size_t triangle_count() const { return (indexed ? indices.size() : positions.size()) / 3; }
};

// Object space to clip space: the identity (positions are clip space with w = 1), a projective
// map with w = c z + d (w near and across 0), a perspective or orthographic camera behind a
// rotation and translation, or a raw matrix.
Mat4 decode_transform(FuzzInput& in, std::int32_t width, std::int32_t height, const char*& name) {
  const auto view = [&in] {
    const Vec3 offset{in.number(), in.number(), in.number()};
    const Vec3 axis{in.number(), in.number(), in.number()};
    return translate(offset) * rotate(axis, in.number());
  };
  switch (in.u8() % 5) {
    case 0:
      name = "identity";
      return identity();
    case 1: {
      name = "projective (z' = a z + b, w = c z + d)";
      Mat4 m = identity();
      m.m[2][2] = in.number();
      m.m[2][3] = in.number();
      m.m[3][2] = in.number();
      m.m[3][3] = in.number();
      return m;
    }
    case 2: {
      name = "perspective * translate * rotate";
      const float fovy = static_cast<float>(in.u8() + 1) / 256.0f * 3.1f;
      const float aspect = width > 0 && height > 0 ? static_cast<float>(width) / height : 1.0f;
      const float near = in.number(), far = in.number();
      return perspective(fovy, aspect, near, far) * view();
    }
    case 3: {
      name = "orthographic * translate * rotate";
      const float left = in.number(), right = in.number(), bottom = in.number(), top = in.number(),
                  near = in.number(), far = in.number();
      return orthographic(left, right, bottom, top, near, far) * view();
    }
    default: {
      name = "raw";
      Mat4 m;
      for (auto& row : m.m) {
        for (float& v : row)
          v = in.number();
      }
      return m;
    }
  }
}

// Level 0 from the palette: texel (x, y) is entry (x + y width) % n, or a random entry.
std::shared_ptr<const Texture> make_texture(const TextureInput& t) {
  test::Random random(t.seed);
  const std::size_t n = t.palette.size();
  const std::size_t count = static_cast<std::size_t>(t.width) * static_cast<std::size_t>(t.height);
  std::vector<std::uint8_t> codes;
  codes.reserve(4 * count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t entry =
        t.random_layout ? static_cast<std::size_t>(random.integer(0, std::int64_t(n) - 1)) : i % n;
    codes.insert(codes.end(), t.palette[entry].begin(), t.palette[entry].end());
  }
  if (t.format == TexelFormat::rgba8) {
    return std::make_shared<const Texture>(
        Texture::from_rgba8(t.width, t.height, codes, t.encoding, t.build));
  }
  std::vector<float> texels(codes.size());
  for (std::size_t i = 0; i < codes.size(); ++i)
    texels[i] = static_cast<float>(std::ldexp(4.0 * codes[i] / 255.0 - 1.0, t.scale_exponent));
  return std::make_shared<const Texture>(Texture::from_rgba32f(t.width, t.height, texels, t.build));
}

// The texture block (see the header); returns whether its options make draw() throw.
bool decode_texture(FuzzInput& in, Case& c) {
  const std::uint32_t flags = in.u8();
  if ((flags & 1) == 0) return false;
  TextureInput t;
  const std::uint32_t format = (flags >> 1 & 3) % 3;
  t.format = format == 2 ? TexelFormat::rgba32f : TexelFormat::rgba8;
  t.encoding = format == 1 ? ColorEncoding::srgb : ColorEncoding::linear;
  DrawTexture& d = c.options.texture.emplace();
  d.derivatives = (flags & 8) != 0 ? TextureDerivatives::analytic : TextureDerivatives::quad;
  t.build.filter = (flags & 16) != 0 ? PyramidFilter::lanczos3 : PyramidFilter::box;
  t.random_layout = (flags & 32) != 0;
  SamplerOptions& o = d.sampler;
  o.lod = (flags & 64) != 0 ? LodFormula::max_axis : LodFormula::exact;
  const bool uv_short = (flags & 128) != 0;
  t.width = 1 + static_cast<std::int32_t>(in.u8() % kMaxTextureSide);
  t.height = 1 + static_cast<std::int32_t>(in.u8() % kMaxTextureSide);
  t.palette.resize(1 + in.u8() % kMaxPalette);
  for (auto& entry : t.palette) {
    for (std::uint8_t& v : entry)
      v = static_cast<std::uint8_t>(in.u8());
  }
  t.seed = in.u32();
  t.scale_exponent = static_cast<int>(in.u8() % 21) - 10;
  t.variant = fuzz::decode_sampler(in, o, t.build).variant;
  for (std::size_t v = 0; v < c.positions.size(); ++v)
    c.uvs.push_back({in.number(), in.number()});
  if (uv_short && !c.uvs.empty()) c.uvs.pop_back();
  if (t.variant != 247) c.texture = make_texture(t);
  d.texture = c.texture.get();
  c.texture_input = std::move(t);
  // The cases draw.hpp documents as std::invalid_argument (sample.hpp's among them).
  return c.uvs.size() != c.positions.size() || d.texture == nullptr ||
         c.texture_input->variant >= 250 ||
         (o.filter == TextureFilter::ripmap && !c.texture_input->build.ripmaps) ||
         (o.filter == TextureFilter::summed_area && !c.texture_input->build.summed_area_table);
}

Case decode(std::span<const std::uint8_t> bytes) {
  FuzzInput in(bytes);
  Case c;
  c.width = static_cast<std::int32_t>(in.u8() % (kMaxTargetSide + 1));
  c.height = static_cast<std::int32_t>(in.u8() % (kMaxTargetSide + 1));
  const std::uint32_t flags = in.u8();
  DrawOptions& o = c.options;
  o.cull = (flags & 3) == 3 ? CullMode::none : static_cast<CullMode>(flags & 3);
  o.depth_write = (flags & 4) == 0;
  c.indexed = (flags & 8) != 0;
  const bool scissor = (flags & 16) != 0;
  o.perspective = (flags & 32) != 0 ? Perspective::affine : Perspective::correct;
  const bool ragged = (flags & 64) != 0;
  const bool color_short = (flags & 128) != 0;
  o.depth_test = static_cast<DepthTest>(in.u8() % 5);
  const std::uint32_t model = in.u8();
  o.shading = static_cast<Shading>(model % 3);
  o.interpolation = kInterpolationMethods[model / 3 % 6];
  const std::uint32_t attributes = in.u8();
  constexpr int kSampleCounts[8] = {1, 2, 4, 8, 16, 1, 1, 1};
  c.samples = kSampleCounts[attributes >> 2 & 7];
  PixelRect s;
  s.x0 = in.i8();
  s.y0 = in.i8();
  s.x1 = s.x0 + in.i8();
  s.y1 = s.y0 + in.i8();
  if (scissor) o.scissor = s;
  const std::uint32_t depth_choice = in.u8();
  c.clear_depth = depth_choice < 64    ? 1.0f
                  : depth_choice < 128 ? 0.0f
                  : depth_choice < 192 ? 0.5f
                                       : in.number();
  c.clear_color = {static_cast<float>(in.u8()) / 255.0f, static_cast<float>(in.u8()) / 255.0f,
                   static_cast<float>(in.u8()) / 255.0f, static_cast<float>(in.u8()) / 255.0f};
  o.ambient = static_cast<float>(in.u8()) / 255.0f;
  o.light_direction = {static_cast<float>(in.i8()) / 64.0f, static_cast<float>(in.i8()) / 64.0f,
                       static_cast<float>(in.i8()) / 64.0f};
  o.transform = decode_transform(in, c.width, c.height, c.camera);

  std::size_t vertices = in.u8() % (kMaxVertices + 1);
  const std::size_t indexed_triangles = in.u8() % (kMaxTriangles + 1);
  if (!c.indexed && !ragged) vertices -= vertices % 3;
  for (std::size_t v = 0; v < vertices; ++v) {
    c.positions.push_back({in.number(), in.number(), in.number()});
    Vec4 color;
    for (float* k : {&color.x, &color.y, &color.z, &color.w})
      *k = (static_cast<float>(in.u8()) - 16.0f) / 223.0f;
    Vec3 normal{static_cast<float>(in.i8()) / 32.0f, static_cast<float>(in.i8()) / 32.0f,
                static_cast<float>(in.i8()) / 32.0f};
    const std::uint32_t extra = in.u8();
    if (extra >= 240) {
      float* component[7] = {&color.x,  &color.y,  &color.z, &color.w,
                             &normal.x, &normal.y, &normal.z};
      *component[extra % 7] = in.number();
    }
    c.colors.push_back(color);
    c.normals.push_back(normal);
  }
  if (c.indexed) {
    const std::size_t corners = 3 * indexed_triangles + (ragged ? 1 : 0);
    for (std::size_t i = 0; i < corners; ++i)
      c.indices.push_back(in.u8() % static_cast<std::uint32_t>(vertices + 2));
  }
  c.indexed = !c.indices.empty();  // draw() reads an empty index span as unindexed
  if ((attributes & 1) != 0) c.colors.clear();
  if ((attributes & 2) != 0) c.normals.clear();
  if (color_short && !c.colors.empty()) c.colors.pop_back();
  const bool bad_texture = decode_texture(in, c);

  // The cases draw.hpp documents as std::invalid_argument.
  const std::size_t n = c.positions.size();
  const std::size_t corners = c.indexed ? c.indices.size() : n;
  c.expect_invalid =
      bad_texture || (!c.colors.empty() && c.colors.size() != n) ||
      (!c.normals.empty() && c.normals.size() != n) ||
      (o.shading == Shading::diffuse && c.normals.empty()) || corners % 3 != 0 ||
      (o.scissor && (o.scissor->x0 > o.scissor->x1 || o.scissor->y0 > o.scissor->y1));
  return c;
}

// Seed inputs: scenes in the layout above that draw something, so that fuzzing starts from
// covered pixels rather than from empty meshes, and textured with every filter. Written by
// LLVMFuzzerInitialize into the directory EDGEWISE_FUZZ_SEEDS names (tools/check passes its
// corpus).
class InputWriter : public fuzz::SeedWriter<InputWriter> {
 public:
  InputWriter& vertex(Vec3 p, std::uint32_t r, std::uint32_t g, std::uint32_t b, Vec3 n) {
    numbers({p.x, p.y, p.z}).u8(r).u8(g).u8(b).u8(239);
    return i8(static_cast<std::int32_t>(n.x * 32))
        .i8(static_cast<std::int32_t>(n.y * 32))
        .i8(static_cast<std::int32_t>(n.z * 32))
        .u8(0);
  }
};

struct SeedHeader {
  std::int32_t width, height;
  std::uint32_t flags;  // as decoded: cull, depth write, indexed, scissor, affine, ...
  DepthTest test;
  Shading shading;
  InterpolationMethod method;
  PixelRect scissor{0, 0, 0, 0};
  std::uint32_t sample_code = 0;  // samples per pixel: 1, 2, 4, 8, 16 for 0-4
};

InputWriter seed_header(const SeedHeader& h) {
  std::uint32_t method = 0;
  while (kInterpolationMethods[method] != h.method)
    ++method;
  InputWriter w;
  w.u8(static_cast<std::uint32_t>(h.width)).u8(static_cast<std::uint32_t>(h.height)).u8(h.flags);
  w.u8(static_cast<std::uint32_t>(h.test));
  w.u8(static_cast<std::uint32_t>(h.shading) + 3 * method).u8(h.sample_code << 2);
  w.i8(h.scissor.x0)
      .i8(h.scissor.y0)
      .i8(h.scissor.x1 - h.scissor.x0)
      .i8(h.scissor.y1 - h.scissor.y0);
  w.u8(0);                                // clear depth 1
  w.u8(10).u8(20).u8(30).u8(255).u8(38);  // clear colour, ambient 0.15
  w.i8(16).i8(24).i8(48);                 // light direction
  return w;
}

// A texture block: `flags` as decoded (bit 0 set), a four-colour palette, everything built.
void seed_texture(InputWriter& w, std::uint32_t flags, std::int32_t width, std::int32_t height,
                  TextureFilter filter, std::initializer_list<Vec2> uvs) {
  w.u8(flags | 1)
      .u8(static_cast<std::uint32_t>(width - 1))
      .u8(static_cast<std::uint32_t>(height - 1));
  w.u8(3).u8(250).u8(40).u8(40).u8(255).u8(40).u8(220).u8(60).u8(255);
  w.u8(20).u8(30).u8(240).u8(128).u8(235).u8(235).u8(235).u8(0);
  w.u8(7).u8(0).u8(0).u8(0).u8(12);  // seed, float scale 2^2
  w.u8(static_cast<std::uint32_t>(filter)).u8(static_cast<std::uint32_t>(filter) % 9);
  w.u8(0).u8(15).u8(3).u8(0);  // bias 0, max_anisotropy 16, 4 x 4 taps, everything built
  for (const Vec2& uv : uvs)
    w.numbers({uv.x, uv.y});
}

std::vector<std::vector<std::uint8_t>> seed_inputs() {
  constexpr std::uint32_t kNoCull = 3, kNoDepthWrite = 4, kIndexed = 8, kScissor = 16;
  const Vec3 facing{0, 0, 1}, tilted{0.5f, 0.25f, 0.75f};
  std::vector<std::vector<std::uint8_t>> seeds;
  // clip space (w = 1): two triangles crossing in depth, into 1x, 4x and 16x targets
  for (std::uint32_t sample_code : {0u, 2u, 4u}) {
    InputWriter w = seed_header({37,
                                 29,
                                 kNoCull,
                                 DepthTest::less,
                                 Shading::gouraud,
                                 InterpolationMethod::plane_equations,
                                 {0, 0, 0, 0},
                                 sample_code});
    w.u8(0).u8(6).u8(0);
    w.vertex({-0.9f, -0.8f, 0.2f}, 240, 16, 16, facing)
        .vertex({0.8f, -0.6f, 0.7f}, 16, 240, 16, facing);
    w.vertex({-0.2f, 0.9f, 0.4f}, 16, 16, 240, facing)
        .vertex({-0.7f, 0.7f, 0.9f}, 200, 100, 50, facing);
    w.vertex({0.9f, 0.3f, 0.1f}, 50, 200, 100, facing)
        .vertex({0.1f, -0.9f, 0.5f}, 100, 50, 200, facing);
    seeds.push_back(w.bytes);
  }
  {  // a perspective camera: a triangle through the near plane and a ground plane to far away
    InputWriter w = seed_header(
        {64, 48, kNoCull, DepthTest::less, Shading::diffuse, InterpolationMethod::scanline});
    w.u8(2).u8(85).numbers({0.5f, 40.0f, 0, 0, 0, 0, 0, 0, 0}).u8(6).u8(0);
    w.vertex({-1, -0.5f, -0.1f}, 240, 16, 16, tilted).vertex({1, -0.25f, -5}, 16, 240, 16, facing);
    w.vertex({0, 1, -3}, 16, 16, 240, tilted).vertex({-20, -1, -0.25f}, 200, 200, 16, {0, 1, 0});
    w.vertex({20, -1, -0.25f}, 16, 200, 200, {0, 1, 0}).vertex({0, -1, -60}, 200, 16, 200, tilted);
    seeds.push_back(w.bytes);
  }
  {  // w = z: vertices behind, at and in front of the eye; scissor; clockwise triangles culled
    InputWriter w = seed_header({40,
                                 40,
                                 1 | kScissor,
                                 DepthTest::less,
                                 Shading::gouraud,
                                 InterpolationMethod::inverse_distance,
                                 {5, 4, 35, 24}});
    w.u8(1).numbers({0.5f, 0, 1, 0}).u8(6).u8(0);
    w.vertex({-0.5f, -0.5f, 0.001f}, 240, 16, 16, facing)
        .vertex({0.5f, -0.5f, 2}, 16, 240, 16, facing);
    w.vertex({0, 0.5f, -0.5f}, 16, 16, 240, facing).vertex({-1, 1, 1}, 240, 16, 16, facing);
    w.vertex({1, 1, 0.25f}, 16, 240, 16, facing).vertex({0, -1, 4}, 16, 16, 240, facing);
    seeds.push_back(w.bytes);
  }
  {  // an orthographic view in pixels, indexed: a quad and a zero-area triangle, no depth write
    InputWriter w = seed_header({24, 18, kNoCull | kIndexed | kNoDepthWrite, DepthTest::less_equal,
                                 Shading::gouraud, InterpolationMethod::edge_functions});
    w.u8(3).numbers({0, 24, 18, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0}).u8(4).u8(3);
    w.vertex({1.5f, 2, -0.3f}, 240, 16, 16, facing).vertex({22, 1, -0.5f}, 16, 240, 16, facing);
    w.vertex({23, 17, -0.7f}, 16, 16, 240, facing)
        .vertex({0.25f, 16, -0.4f}, 200, 200, 200, facing);
    w.u8(0).u8(1).u8(2).u8(0).u8(2).u8(3).u8(0).u8(2).u8(2);
    seeds.push_back(w.bytes);
  }
  {  // a 1x1 target, nearest vertex
    InputWriter w = seed_header(
        {1, 1, kNoCull, DepthTest::always, Shading::diffuse, InterpolationMethod::nearest_vertex});
    w.u8(0).u8(3).u8(0);
    w.vertex({-1, -1, 0.5f}, 240, 16, 16, facing).vertex({1, -1, 0.5f}, 16, 240, 16, tilted);
    w.vertex({0, 1, 0.25f}, 16, 16, 240, facing);
    seeds.push_back(w.bytes);
  }
  {  // flat shading and sub-triangle areas on a target of partial tiles, and a sliver
    InputWriter w = seed_header(
        {9, 7, kNoCull, DepthTest::greater, Shading::flat, InterpolationMethod::subtriangle_areas});
    w.u8(0).u8(6).u8(0);
    w.vertex({-1, -1, 0.5f}, 240, 16, 16, facing).vertex({1, -0.9f, 0.6f}, 16, 240, 16, facing);
    w.vertex({0.3f, 1, 0.7f}, 16, 16, 240, facing).vertex({-1, -0.5f, 0.2f}, 240, 16, 16, facing);
    w.vertex({1, 0.5f, 0.3f}, 16, 240, 16, facing).vertex({0, 0.001f, 0.9f}, 16, 16, 240, facing);
    seeds.push_back(w.bytes);
  }
  // A perspective camera over a ground plane and a triangle through the near plane, textured
  // with each filter in turn: every format, both derivative methods, random and cycling texels.
  for (int f = 0; f < kFilterCount; ++f) {
    InputWriter w = seed_header({64, 48, kNoCull, DepthTest::less,
                                 f % 3 == 0 ? Shading::flat : Shading::gouraud,
                                 InterpolationMethod::plane_equations});
    w.u8(2).u8(85).numbers({0.5f, 40.0f, 0, 0, 0, 0, 0, 0, 0}).u8(6).u8(0);
    w.vertex({-20, -1, -0.25f}, 239, 239, 239, {0, 1, 0})
        .vertex({20, -1, -0.25f}, 239, 239, 239, {0, 1, 0});
    w.vertex({0, -1, -60}, 200, 239, 150, tilted).vertex({-1, -0.5f, -0.1f}, 240, 16, 16, tilted);
    w.vertex({1, -0.25f, -5}, 16, 240, 16, facing).vertex({0, 1, -3}, 16, 16, 240, tilted);
    const std::uint32_t flags =
        static_cast<std::uint32_t>(f % 3) << 1 | (f % 2 == 1 ? 8u : 0u) | (f % 4 == 2 ? 32u : 0u);
    seed_texture(w, flags, 37 + f, 29 - f, static_cast<TextureFilter>(f),
                 {{-3, 0}, {4, 0}, {0.5f, 7.5f}, {0, 0}, {1, 0.25f}, {0.5f, 1}});
    seeds.push_back(w.bytes);
  }
  {  // an orthographic view in pixels: a textured quad, about one texel per pixel
    InputWriter w = seed_header({24, 18, kNoCull | kIndexed, DepthTest::less, Shading::gouraud,
                                 InterpolationMethod::edge_functions});
    w.u8(3).numbers({0, 24, 18, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0}).u8(4).u8(2);
    w.vertex({0, 0, -0.5f}, 239, 239, 239, facing).vertex({24, 0, -0.5f}, 200, 239, 239, facing);
    w.vertex({24, 18, -0.5f}, 239, 200, 239, facing).vertex({0, 18, -0.5f}, 239, 239, 200, facing);
    w.u8(0).u8(1).u8(2).u8(0).u8(2).u8(3);
    seed_texture(w, 32, 24, 18, TextureFilter::nearest, {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    seeds.push_back(w.bytes);
  }
  return seeds;
}

void print_vec(const char* name, const float* v, int n) {
  std::fprintf(stderr, " %s (", name);
  for (int k = 0; k < n; ++k)
    std::fprintf(stderr, "%s%.9g", k ? ", " : "", static_cast<double>(v[k]));
  std::fprintf(stderr, ")");
}

const char* format_name(const TextureInput& t) {
  if (t.format == TexelFormat::rgba32f) return "rgba32f";
  return t.encoding == ColorEncoding::srgb ? "rgba8 sRGB" : "rgba8 linear";
}

void print_texture(const Case& c) {
  const TextureInput& t = *c.texture_input;
  const DrawTexture& d = *c.options.texture;
  const SamplerOptions& o = d.sampler;
  std::fprintf(stderr,
               "texture %s %dx%d, %s pyramid, ripmaps %s, summed-area table %s, texels %s "
               "(seed %" PRIu32 ", float scale 2^%d), palette",
               format_name(t), t.width, t.height, std::string(name_of(t.build.filter)).c_str(),
               t.build.ripmaps ? "yes" : "no", t.build.summed_area_table ? "yes" : "no",
               t.random_layout ? "at random palette entries" : "cycling through the palette",
               t.seed, t.scale_exponent);
  for (const auto& entry : t.palette)
    std::fprintf(stderr, " %02x%02x%02x%02x", entry[0], entry[1], entry[2], entry[3]);
  std::fprintf(stderr,
               "%s\nfilter %s, wrap %s/%s, lod %s, lod_bias %.9g, max_anisotropy %d, "
               "supersample_taps %d (variant %" PRIu32 "), derivatives %s\n",
               c.texture ? "" : " (not passed: a null texture)",
               std::string(name_of(o.filter)).c_str(), std::string(name_of(o.wrap_s)).c_str(),
               std::string(name_of(o.wrap_t)).c_str(), std::string(name_of(o.lod)).c_str(),
               static_cast<double>(o.lod_bias), o.max_anisotropy, o.supersample_taps, t.variant,
               std::string(name_of(d.derivatives)).c_str());
}

void print_case(const Case& c) {
  const DrawOptions& o = c.options;
  std::fprintf(stderr, "drawing %s\ntarget %dx%d, %d sample%s per pixel", c.part.c_str(), c.width,
               c.height, c.samples, c.samples == 1 ? "" : "s");
  if (o.scissor) {
    std::fprintf(stderr, ", scissor [%d, %d) x [%d, %d)", o.scissor->x0, o.scissor->x1,
                 o.scissor->y0, o.scissor->y1);
  }
  std::fprintf(stderr,
               ", clear depth %.9g (%a), clear colour (%.9g, %.9g, %.9g, %.9g)\n"
               "cull %d, depth test %s, depth write %s, shading %s, interpolation %s, "
               "perspective %s, ambient %.9g, light (%.9g, %.9g, %.9g)%s\n",
               static_cast<double>(c.clear_depth), static_cast<double>(c.clear_depth),
               static_cast<double>(c.clear_color.x), static_cast<double>(c.clear_color.y),
               static_cast<double>(c.clear_color.z), static_cast<double>(c.clear_color.w),
               static_cast<int>(o.cull), std::string(name_of(o.depth_test)).c_str(),
               o.depth_write ? "on" : "off", std::string(name_of(o.shading)).c_str(),
               std::string(name_of(o.interpolation)).c_str(),
               std::string(name_of(o.perspective)).c_str(), static_cast<double>(o.ambient),
               static_cast<double>(o.light_direction.x), static_cast<double>(o.light_direction.y),
               static_cast<double>(o.light_direction.z),
               c.expect_invalid ? "; expected: std::invalid_argument" : "");
  std::fprintf(stderr, "transform: %s\n", c.camera);
  for (const auto& row : o.transform.m) {
    std::fprintf(stderr, "  [%.9g, %.9g, %.9g, %.9g]\n", static_cast<double>(row[0]),
                 static_cast<double>(row[1]), static_cast<double>(row[2]),
                 static_cast<double>(row[3]));
  }
  if (c.texture_input) print_texture(c);
  std::fprintf(stderr, "%zu positions, %zu colours, %zu normals, %zu texture coordinates\n",
               c.positions.size(), c.colors.size(), c.normals.size(), c.uvs.size());
  for (std::size_t v = 0; v < c.positions.size(); ++v) {
    std::fprintf(stderr, "  vertex %zu:", v);
    print_vec("position", &c.positions[v].x, 3);
    std::fprintf(stderr, " = (%a, %a, %a)", static_cast<double>(c.positions[v].x),
                 static_cast<double>(c.positions[v].y), static_cast<double>(c.positions[v].z));
    if (v < c.colors.size()) print_vec("colour", &c.colors[v].x, 4);
    if (v < c.normals.size()) print_vec("normal", &c.normals[v].x, 3);
    if (v < c.uvs.size()) {
      print_vec("uv", &c.uvs[v].x, 2);
      std::fprintf(stderr, " = (%a, %a)", static_cast<double>(c.uvs[v].x),
                   static_cast<double>(c.uvs[v].y));
    }
    const Vec4 clip = transform(o.transform, c.positions[v]);
    print_vec("clip", &clip.x, 4);
    std::fprintf(stderr, "\n");
  }
  if (c.indexed) {
    std::fprintf(stderr, "indices:");
    for (std::uint32_t i : c.indices)
      std::fprintf(stderr, " %u", i);
    std::fprintf(stderr, "\n");
  }
}

// One ISA's draw of one mesh.
struct Output {
  Isa isa;
  bool threw = false;
  std::string error;
  DrawReport report;
  Framebuffer target;
};

void print_outputs(std::span<const Output> outputs) {
  std::fprintf(stderr, "%-10s %9s %7s %8s %7s %6s %6s %10s %9s %9s\n", "isa", "triangles",
               "clipped", "clip_tri", "outside", "culled", "errors", "rasterized", "fragments",
               "passed");
  for (const Output& o : outputs) {
    if (o.threw) {
      std::fprintf(stderr, "%-10s threw: %s\n", std::string(name_of(o.isa)).c_str(),
                   o.error.c_str());
      continue;
    }
    const DrawReport& r = o.report;
    std::fprintf(stderr,
                 "%-10s %9" PRIu64 " %7" PRIu64 " %8" PRIu64 " %7" PRIu64 " %6" PRIu64 " %6" PRIu64
                 " %10" PRIu64 " %9" PRIu64 " %9" PRIu64 "\n",
                 std::string(name_of(o.isa)).c_str(), r.triangles, r.clipped, r.clip_triangles,
                 r.outside, r.culled, r.errors, r.rasterized, r.fragments, r.fragments_passed);
  }
}

[[noreturn]] void fail(const Case& c, const char* what, std::span<const Output> outputs,
                       const std::string& detail) {
  std::fprintf(stderr, "edgewise fuzz_draw: %s\n", what);
  print_case(c);
  if (!detail.empty()) std::fprintf(stderr, "%s\n", detail.c_str());
  print_outputs(outputs);
  std::abort();
}

std::string pixel_text(std::int32_t x, std::int32_t y) {
  return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
}

std::string hex(std::uint32_t v) {
  char text[16];
  std::snprintf(text, sizeof text, "%08x", v);
  return text;
}

std::string float_text(float v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.9g (%a)", static_cast<double>(v), static_cast<double>(v));
  return text;
}

std::vector<Output> draw_on(const Case& c, const DrawMesh& mesh, std::span<const Isa> isas) {
  std::vector<Output> outputs;
  for (Isa isa : isas) {
    Output out{isa, false, {}, {}, Framebuffer(c.width, c.height, c.samples)};
    out.target.clear(c.clear_color, c.clear_depth);
    DrawOptions options = c.options;
    options.isa = isa;
    try {
      out.report = draw(out.target, mesh, options);
    } catch (const std::invalid_argument& e) {
      out.threw = true;
      out.error = e.what();
    } catch (const std::exception& e) {
      outputs.push_back(std::move(out));
      fail(c, "draw() threw something other than std::invalid_argument", outputs, e.what());
    } catch (...) {
      outputs.push_back(std::move(out));
      fail(c, "draw() threw a non-standard exception", outputs, "");
    }
    outputs.push_back(std::move(out));
  }
  return outputs;
}

std::vector<Output> draw_every_isa(const Case& c, const DrawMesh& mesh) {
  return draw_on(c, mesh, supported_isas());  // the reference first
}

bool same_counts(const DrawReport& a, const DrawReport& b) {
  return a.triangles == b.triangles && a.clipped == b.clipped &&
         a.clip_triangles == b.clip_triangles && a.outside == b.outside && a.culled == b.culled &&
         a.errors == b.errors && a.rasterized == b.rasterized && a.fragments == b.fragments &&
         a.fragments_passed == b.fragments_passed;
}

// The screen triangles draw() hands to the shading kernels for one mesh triangle: the vertex
// stage (kernels/draw/vertex_stage/vertex_stage.cpp) replayed through the public clipper (identical
// on every ISA, so this only has to name the writer of each pixel and its attributes).
struct Piece {
  Vec2 snapped[3];
  ScreenTriangle screen;
  VertexAttributes attributes;
  Vec2 uvs[3];  // (0, 0) untextured, as the vertex stage passes them
};

float snap(float v) {
  return static_cast<float>(std::nearbyint(static_cast<double>(v) * 256.0) / 256.0);
}

void append_pieces(const Case& c, const std::uint32_t corner[3], std::vector<Piece>& pieces) {
  const Viewport viewport{c.width, c.height};
  const bool diffuse = c.options.shading == Shading::diffuse;
  const bool textured = c.options.texture.has_value();
  Vec4 clip[3], color[3];
  Vec3 normal[3];
  Vec2 uv[3];
  for (int i = 0; i < 3; ++i) {
    clip[i] = transform(c.options.transform, c.positions[corner[i]]);
    color[i] = c.colors.empty() ? Vec4{1, 1, 1, 1} : c.colors[corner[i]];
    normal[i] = diffuse ? c.normals[corner[i]] : Vec3{0, 0, 0};
    uv[i] = textured ? c.uvs[corner[i]] : Vec2{0, 0};
  }
  const ClippedPolygon polygon =
      clip_triangle(clip[0], clip[1], clip[2], guard_band_planes(viewport));
  struct Vertex {
    Vec4 clip;
    Vec4 color;
    Vec3 normal;
    Vec2 uv;
  };
  std::vector<Vertex> fan;
  if (polygon.status == ClipStatus::inside) {
    for (int i = 0; i < 3; ++i)
      fan.push_back({clip[i], color[i], normal[i], uv[i]});
  } else if (polygon.status == ClipStatus::clipped) {
    for (int k = 0; k < polygon.count; ++k) {
      const ClipVertex& v = polygon.vertices[k];
      // The vertex stage's blend of clipped attributes, operation for operation.
      const auto blend = [&v](float a, float b, float d) { return v.b0 * a + v.b1 * b + v.b2 * d; };
      fan.push_back(
          {v.position,
           {blend(color[0].x, color[1].x, color[2].x), blend(color[0].y, color[1].y, color[2].y),
            blend(color[0].z, color[1].z, color[2].z), blend(color[0].w, color[1].w, color[2].w)},
           {blend(normal[0].x, normal[1].x, normal[2].x),
            blend(normal[0].y, normal[1].y, normal[2].y),
            blend(normal[0].z, normal[1].z, normal[2].z)},
           {blend(uv[0].x, uv[1].x, uv[2].x), blend(uv[0].y, uv[1].y, uv[2].y)}});
    }
  }
  for (std::size_t k = 0; k + 2 < fan.size(); ++k) {
    Piece p;
    const std::size_t chosen[3] = {0, k + 1, k + 2};
    for (int i = 0; i < 3; ++i) {
      const Vertex& v = fan[chosen[i]];
      const ScreenVertex s = to_screen(v.clip, viewport);
      p.snapped[i] = {snap(s.x), snap(s.y)};
      p.screen.x[i] = p.snapped[i].x;
      p.screen.y[i] = p.snapped[i].y;
      p.screen.w[i] = v.clip.w;
      p.attributes.colors[i] = v.color;
      p.attributes.normals[i] = v.normal;
      p.uvs[i] = v.uv;
    }
    pieces.push_back(p);
  }
}

// Per pixel of the target (row-major), the set of pieces covering it, from the reference
// rasterizer with draw()'s clip rectangle and cull mode.
class CoverageMap final : public CoverageSink {
 public:
  CoverageMap(const Case& c, std::span<const Piece> pieces)
      : width_(c.width),
        height_(c.height),
        masks_(static_cast<std::size_t>(c.width) * static_cast<std::size_t>(c.height) *
                   static_cast<std::size_t>(c.samples),
               0) {
    std::vector<Vec2> vertices;
    for (const Piece& p : pieces)
      vertices.insert(vertices.end(), p.snapped, p.snapped + 3);
    RasterOptions options;
    options.cull = c.options.cull;
    options.isa = Isa::reference;
    options.samples = c.samples;
    rasterize(vertices, {}, RasterTarget{c.width, c.height, c.options.scissor}, options, *this);
  }
  void consume(std::span<const TileCoverage> tiles) override {
    for (const TileCoverage& t : tiles) {
      for (std::uint64_t m = t.mask; m != 0; m &= m - 1) {
        const int bit = std::countr_zero(m);
        const std::size_t x = t.tile_x * 8u + static_cast<unsigned>(bit % 8);
        const std::size_t y = t.tile_y * 8u + static_cast<unsigned>(bit / 8);
        masks_[(t.sample * static_cast<std::size_t>(height_) + y) *
                   static_cast<std::size_t>(width_) +
               x] |= std::uint64_t{1} << (t.triangle % 64);
      }
    }
  }
  // The pieces covering sample k of pixel (x, y), a bit each.
  std::uint64_t at(std::int32_t x, std::int32_t y, int k) const {
    return masks_[(static_cast<std::size_t>(k) * static_cast<std::size_t>(height_) +
                   static_cast<std::size_t>(y)) *
                      static_cast<std::size_t>(width_) +
                  static_cast<std::size_t>(x)];
  }

 private:
  std::int32_t width_, height_;
  std::vector<std::uint64_t> masks_;
};

bool finite_attributes(const VertexAttributes& a) {
  for (int i = 0; i < 3; ++i) {
    for (float v : {a.colors[i].x, a.colors[i].y, a.colors[i].z, a.colors[i].w, a.normals[i].x,
                    a.normals[i].y, a.normals[i].z}) {
      if (!std::isfinite(v)) return false;
    }
  }
  return true;
}

// What the colour checks covered, printed at exit with EDGEWISE_FUZZ_PRINT.
struct Stats {
  std::uint64_t inputs = 0, invalid = 0, colour_draws = 0, pixels = 0, bounded = 0,
                nearest_ties = 0, non_finite = 0, widest = 0;
  std::uint64_t textured_draws = 0, textured_pixels = 0, textured_differing = 0,
                textured_checked = 0, textured_unbounded = 0, non_finite_queries = 0;
  std::uint64_t per_filter[kFilterCount] = {};  // textured pixels checked against their bound
  double closest = -std::numeric_limits<double>::infinity();  // the largest excess (<= 0)
} stats;

// The shaded colour's bound at one pixel: in codes (255: any colour) and as a linear channel
// difference.
struct ColourBound {
  int codes;
  double error;
};

// The bound of the fast colour at pixel (x, y) if `piece` wrote it; nullopt where the method has
// no single right answer (nearest vertex at a tie) or the attributes are not finite.
std::optional<ColourBound> colour_bound_for(const Case& c, const Piece& piece, std::int32_t x,
                                            std::int32_t y) {
  const DrawOptions& o = c.options;
  if (!finite_attributes(piece.attributes)) {
    ++stats.non_finite;
    return std::nullopt;
  }
  const double px = x + 0.5, py = y + 0.5;
  const ScreenTriangle& t = piece.screen;
  WeightErrors e;
  if (o.shading == Shading::flat) {
    e = {{1, 0, 0}, {0, 0, 0}};  // vertex 0's colour, packed: no interpolation at all
  } else if (o.interpolation == InterpolationMethod::nearest_vertex) {
    // The reference's choice, unless the fast path's squared distances tie with it within their
    // rounding bounds (the test of tests/interpolation/fast_interpolation_test.cpp).
    const reference::Weights ref = reference::screen_weights(o.interpolation, t, px, py);
    const int chosen = static_cast<int>(std::max_element(ref.b, ref.b + 3) - ref.b);
    Bounded squared[3];
    test::squared_distance_bounds(test::Evaluator::float32, t, std::floor(t.x[0]),
                                  std::floor(t.y[0]), px, py, squared);
    for (int i = 0; i < 3; ++i) {
      if (i != chosen && std::abs(squared[i].value - squared[chosen].value) <=
                             squared[i].error + squared[chosen].error) {
        ++stats.nearest_ties;
        return std::nullopt;
      }
    }
    e = test::one_hot_weight_errors(chosen, o.perspective, t);
  } else if (o.interpolation == InterpolationMethod::plane_equations) {
    // Gouraud or diffuse by plane equations: the kernels' plane path.
    return ColourBound{
        test::plane_shading_codes(t, piece.attributes, o.perspective, o.shading, o.ambient, px, py),
        test::plane_shading_error(t, piece.attributes, o.perspective, o.shading, o.ambient, px,
                                  py)};
  } else {
    e = test::weight_errors(o.interpolation, o.perspective, t, px, py);
  }
  const Shading shading = o.shading == Shading::flat ? Shading::gouraud : o.shading;
  return ColourBound{allowed_codes(piece.attributes, e, shading, o.ambient),
                     test::colour_error(piece.attributes, e, shading, o.ambient)};
}

std::uint32_t clear_code(const Case& c) {
  return pack_rgba8(c.clear_color);
}

int code_difference(std::uint32_t a, std::uint32_t b) {
  int widest = 0;
  for (int k = 0; k < 4; ++k) {
    const int da = static_cast<int>((a >> (8 * k)) & 0xFF);
    const int db = static_cast<int>((b >> (8 * k)) & 0xFF);
    widest = std::max(widest, std::abs(da - db));
  }
  return widest;
}

// The checks that need no knowledge of the writer: exceptions, counts and their invariants,
// depth bits, and nothing written outside the clip rectangle or outside every piece.
void check_draw(const Case& c, std::span<const Output> outputs, std::span<const Piece> pieces) {
  const Output& ref = outputs.front();
  for (const Output& o : outputs) {
    if (o.threw != c.expect_invalid) {
      fail(c, o.threw ? "draw() threw for a valid input" : "draw() accepted an invalid input",
           outputs, std::string(name_of(o.isa)));
    }
  }
  const std::uint32_t clear = clear_code(c);
  const std::uint32_t clear_depth = std::bit_cast<std::uint32_t>(c.clear_depth);
  const std::size_t storage = static_cast<std::size_t>(ref.target.tiles_x()) *
                              static_cast<std::size_t>(ref.target.tiles_y()) * 64 *
                              static_cast<std::size_t>(c.samples);
  if (c.expect_invalid) {
    for (const Output& o : outputs) {
      for (std::size_t i = 0; i < storage; ++i) {
        if (o.target.color_tiles()[i] != clear ||
            std::bit_cast<std::uint32_t>(o.target.depth_tiles()[i]) != clear_depth) {
          fail(c, "a rejected draw changed the framebuffer", outputs, std::string(name_of(o.isa)));
        }
      }
    }
    return;
  }
  const DrawOptions& opt = c.options;
  for (const Output& o : outputs) {
    const DrawReport& r = o.report;
    const std::string name(name_of(o.isa));
    if (r.isa != o.isa) fail(c, "DrawReport names another ISA", outputs, name);
    if (!same_counts(r, ref.report)) fail(c, "DrawReport counts differ", outputs, name);
    if (r.triangles != c.triangle_count() || r.fragments_passed > r.fragments ||
        (opt.depth_test == DepthTest::never && r.fragments_passed != 0) ||
        (opt.depth_test == DepthTest::always && r.fragments_passed != r.fragments)) {
      fail(c, "DrawReport counts break their invariants", outputs, name);
    }
  }
  const PixelRect clip =
      clip_rect(RasterTarget{c.width, c.height, opt.scissor});  // valid: not expect_invalid
  const CoverageMap coverage(c, pieces);
  for (int k = 0; k < c.samples; ++k) {
    for (std::int32_t y = 0; y < ref.target.tiles_y() * 8; ++y) {
      for (std::int32_t x = 0; x < ref.target.tiles_x() * 8; ++x) {
        const std::size_t i = detail::FramebufferAccess::index(ref.target, x, y, k);
        const bool inside = x >= clip.x0 && x < clip.x1 && y >= clip.y0 && y < clip.y1;
        const bool covered = inside && coverage.at(x, y, k) != 0;
        const std::uint32_t ref_depth = std::bit_cast<std::uint32_t>(ref.target.depth_tiles()[i]);
        for (const Output& o : outputs) {
          const float z = o.target.depth_tiles()[i];
          const std::uint32_t depth = std::bit_cast<std::uint32_t>(z);
          const bool untouched = o.target.color_tiles()[i] == clear && depth == clear_depth;
          const char* problem = nullptr;
          if (depth != ref_depth) {
            problem = "depth differs from the reference";
          } else if (!covered && !untouched) {
            problem = inside ? "a pixel no triangle covers changed"
                             : "a pixel outside the scissor or the target changed";
          } else if (depth != clear_depth && (!opt.depth_write || !(z >= 0.0f && z <= 1.0f))) {
            problem = "a depth was written that draw() may not write";
          }
          if (problem != nullptr) {
            fail(c, problem, outputs,
                 std::string(name_of(o.isa)) + " " + pixel_text(x, y) + " sample " +
                     std::to_string(k) + ": colour " + hex(o.target.color_tiles()[i]) + " depth " +
                     float_text(z) + "; reference colour " + hex(ref.target.color_tiles()[i]) +
                     " depth " + float_text(ref.target.depth_tiles()[i]));
          }
        }
      }
    }
  }
}

// One mesh triangle alone: each covered pixel's writer is one of its pieces, so each fast colour
// is held to the bound of that piece (of any covering piece where rounding made the clipped
// polygon's fan overlap itself).
void check_colours(const Case& c, std::span<const Output> outputs, std::span<const Piece> pieces) {
  const Output& ref = outputs.front();
  const PixelRect clip = clip_rect(RasterTarget{c.width, c.height, c.options.scissor});
  const CoverageMap coverage(c, pieces);
  ++stats.colour_draws;
  // Each pixel is shaded once, at its centre: every sample's colour is held to the writer's
  // bound at the centre.
  for (int sample = 0; sample < c.samples; ++sample) {
    for (std::int32_t y = clip.y0; y < clip.y1; ++y) {
      for (std::int32_t x = clip.x0; x < clip.x1; ++x) {
        const std::uint64_t writers = coverage.at(x, y, sample);
        if (writers == 0) continue;  // check_draw: unchanged
        ++stats.pixels;
        const std::size_t i = detail::FramebufferAccess::index(ref.target, x, y, sample);
        const std::uint32_t expected = ref.target.color_tiles()[i];
        for (const Output& o : outputs) {
          const std::uint32_t actual = o.target.color_tiles()[i];
          const int difference = code_difference(actual, expected);
          if (difference <= 1) continue;  // every bound allows one code
          ++stats.bounded;
          int allowed = -1;
          bool unchecked = false;
          for (std::uint64_t m = writers; m != 0; m &= m - 1) {
            const std::optional<ColourBound> a =
                colour_bound_for(c, pieces[std::countr_zero(m)], x, y);
            unchecked = unchecked || !a;
            if (a) allowed = std::max(allowed, a->codes);
          }
          if (unchecked) continue;
          stats.widest =
              std::max<std::uint64_t>(stats.widest, static_cast<std::uint64_t>(difference));
          if (difference > allowed) {
            std::string detail = std::string(name_of(o.isa)) + " " + pixel_text(x, y) +
                                 ": colour " + hex(actual) + ", reference " + hex(expected) +
                                 " (ABGR), " + std::to_string(difference) + " codes apart, " +
                                 std::to_string(allowed) + " allowed; written by one of:";
            for (std::uint64_t m = writers; m != 0; m &= m - 1) {
              const Piece& p = pieces[std::countr_zero(m)];
              char text[256];
              for (int k = 0; k < 3; ++k) {
                std::snprintf(text, sizeof text, "\n  (%a, %a) w %a", p.screen.x[k], p.screen.y[k],
                              p.screen.w[k]);
                detail += text;
              }
            }
            fail(c, "a colour is outside the derived bound", outputs, detail);
          }
        }
      }
    }
  }
}

std::array<std::uint8_t, 4> channels_of(std::uint32_t code) {
  return {static_cast<std::uint8_t>(code), static_cast<std::uint8_t>(code >> 8),
          static_cast<std::uint8_t>(code >> 16), static_cast<std::uint8_t>(code >> 24)};
}

// What one writer of a textured pixel allows there (tests/draw/textured_bounds.hpp).
struct WriterBound {
  TextureQuery query;
  double texel_bound, colour_error;
  std::vector<test::CodeRanges> allowed;
};

std::string describe_writer(const Piece& p, const WriterBound& w) {
  std::string text;
  char line[320];
  for (int k = 0; k < 3; ++k) {
    std::snprintf(line, sizeof line, "\n  (%a, %a) w %a uv (%a, %a)", p.screen.x[k], p.screen.y[k],
                  p.screen.w[k], static_cast<double>(p.uvs[k].x), static_cast<double>(p.uvs[k].y));
    text += line;
  }
  const TextureQuery& q = w.query;
  std::snprintf(line, sizeof line,
                "\n  query s %a t %a dsdx %a dtdx %a dsdy %a dtdy %a; texel bound %.9g, colour "
                "error %.9g; allowed codes per accepted texel:",
                static_cast<double>(q.s), static_cast<double>(q.t), static_cast<double>(q.dsdx),
                static_cast<double>(q.dtdx), static_cast<double>(q.dsdy),
                static_cast<double>(q.dtdy), w.texel_bound, w.colour_error);
  text += line;
  for (const test::CodeRanges& r : w.allowed) {
    std::snprintf(line, sizeof line, "\n    [%.6g, %.6g] [%.6g, %.6g] [%.6g, %.6g] [%.6g, %.6g]",
                  r.lo[0], r.hi[0], r.lo[1], r.hi[1], r.lo[2], r.hi[2], r.lo[3], r.hi[3]);
    text += line;
  }
  return text;
}

// One mesh triangle alone, textured: where any ISA's colour differs from the reference's, every
// colour (the reference's too) is held to the textured bound of a piece that covers the pixel,
// from the pixel's query on that piece and its colour in the reference's untextured draw.
void check_textured_colours(const Case& c, const test::TexturedPixelCheck& check,
                            std::span<const Output> outputs, const Framebuffer& untextured,
                            std::span<const Piece> pieces) {
  const Output& ref = outputs.front();
  const PixelRect clip = clip_rect(RasterTarget{c.width, c.height, c.options.scissor});
  const CoverageMap coverage(c, pieces);
  const DrawTexture& d = *c.options.texture;
  std::vector<detail::TexturePlanes> planes;
  std::vector<test::ShadedRange> shaded;
  for (const Piece& p : pieces) {
    planes.push_back(
        detail::make_texture_planes(p.snapped, p.uvs, p.screen.w, c.options.perspective));
    shaded.push_back(test::shaded_range(p.attributes, c.options.shading, c.options.ambient));
  }
  ++stats.textured_draws;
  for (int sample = 0; sample < c.samples; ++sample) {
    for (std::int32_t y = clip.y0; y < clip.y1; ++y) {
      for (std::int32_t x = clip.x0; x < clip.x1; ++x) {
        const std::uint64_t writers = coverage.at(x, y, sample);
        if (writers == 0) continue;  // check_draw: unchanged
        ++stats.textured_pixels;
        const std::size_t i = detail::FramebufferAccess::index(ref.target, x, y, sample);
        const std::uint32_t expected = ref.target.color_tiles()[i];
        if (std::all_of(outputs.begin(), outputs.end(),
                        [&](const Output& o) { return o.target.color_tiles()[i] == expected; })) {
          continue;
        }
        ++stats.textured_differing;
        const std::array<std::uint8_t, 4> plain = channels_of(untextured.color_tiles()[i]);
        std::vector<std::pair<std::size_t, WriterBound>> bounds;
        bool unbounded = false;
        for (std::uint64_t m = writers; m != 0 && !unbounded; m &= m - 1) {
          const std::size_t k = static_cast<std::size_t>(std::countr_zero(m));
          const std::optional<ColourBound> a = colour_bound_for(c, pieces[k], x, y);
          unbounded = !a || a->codes >= 255;
          if (unbounded) break;
          WriterBound w;
          w.query = detail::texture_query(planes[k], d.derivatives, x, y);
          w.texel_bound = check.texel_bound(w.query);
          w.colour_error = a->error;
          w.allowed = check.allowed(w.query, plain.data(), shaded[k], a->error);
          stats.non_finite_queries += std::isfinite(w.query.s) && std::isfinite(w.query.t) ? 0 : 1;
          bounds.emplace_back(k, std::move(w));
        }
        if (unbounded) {
          ++stats.textured_unbounded;
          continue;
        }
        ++stats.textured_checked;
        ++stats.per_filter[static_cast<int>(d.sampler.filter)];
        for (const Output& o : outputs) {
          const std::array<std::uint8_t, 4> got = channels_of(o.target.color_tiles()[i]);
          double excess = std::numeric_limits<double>::infinity();
          for (const auto& [k, w] : bounds)
            excess = std::min(excess, test::TexturedPixelCheck::excess(w.allowed, got.data()));
          stats.closest = std::max(stats.closest, excess);
          if (excess <= 0.0) continue;
          std::string detail = std::string(name_of(o.isa)) + " " + pixel_text(x, y) + ": colour " +
                               hex(o.target.color_tiles()[i]) + ", reference " + hex(expected) +
                               ", untextured reference " + hex(untextured.color_tiles()[i]) +
                               " (ABGR), " + std::to_string(excess) +
                               " codes outside the bound; written by one of:";
          for (const auto& [k, w] : bounds)
            detail += describe_writer(pieces[k], w);
          fail(c,
               o.isa == Isa::reference
                   ? "the reference's textured colour is outside its own bound (a gap in the bound)"
                   : "a textured colour is outside the derived bound",
               outputs, detail);
        }
      }
    }
  }
}

// The reference's draw of a textured case without its texture (each pixel's shaded colour before
// the texture), whose depth must equal the textured draw's: texturing changes no depth test.
Framebuffer untextured_reference(const Case& c, std::span<const Output> outputs) {
  Case plain = c;
  plain.options.texture.reset();
  const Isa reference[] = {Isa::reference};
  std::vector<Output> drawn = draw_on(plain, plain.mesh(), reference);
  const Framebuffer& textured = outputs.front().target;
  const std::size_t storage = static_cast<std::size_t>(textured.tiles_x()) *
                              static_cast<std::size_t>(textured.tiles_y()) * 64 *
                              static_cast<std::size_t>(c.samples);
  for (std::size_t i = 0; i < storage; ++i) {
    if (std::bit_cast<std::uint32_t>(drawn.front().target.depth_tiles()[i]) !=
        std::bit_cast<std::uint32_t>(textured.depth_tiles()[i])) {
      fail(c, "the reference's depth differs with and without the texture", outputs, "");
    }
  }
  return std::move(drawn.front().target);
}

void print_counts(const char* what, std::span<const Output> outputs) {
  std::fprintf(stderr, "%s\n", what);
  print_outputs(outputs);
}

void print_stats() {
  std::fprintf(stderr,
               "fuzz_draw: %" PRIu64 " inputs (%" PRIu64 " invalid), %" PRIu64
               " one-triangle draws, %" PRIu64 " covered pixels compared, %" PRIu64
               " more than one code apart checked against their bound (widest %" PRIu64
               " codes), %" PRIu64 " unchecked nearest-vertex ties, %" PRIu64
               " unchecked non-finite attributes\n",
               stats.inputs, stats.invalid, stats.colour_draws, stats.pixels, stats.bounded,
               stats.widest, stats.nearest_ties, stats.non_finite);
  std::fprintf(
      stderr,
      "fuzz_draw textured: %" PRIu64 " one-triangle draws, %" PRIu64 " covered pixels, %" PRIu64
      " where an ISA differs from the reference: %" PRIu64 " checked against their bound (%" PRIu64
      " at non-finite s or t; largest excess %.3g codes), %" PRIu64
      " unchecked (colour bound unbounded or unknown)\n",
      stats.textured_draws, stats.textured_pixels, stats.textured_differing, stats.textured_checked,
      stats.non_finite_queries, stats.closest, stats.textured_unbounded);
  for (int f = 0; f < kFilterCount; ++f) {
    std::fprintf(stderr, "  %-20s %10" PRIu64 " pixels checked\n",
                 std::string(name_of(static_cast<TextureFilter>(f))).c_str(), stats.per_filter[f]);
  }
}

bool printing() {
  static const bool print = [] {
    const char* value = std::getenv("EDGEWISE_FUZZ_PRINT");
    const bool on = value != nullptr && value[0] != '\0' && value[0] != '0';
    if (on) std::atexit(print_stats);
    return on;
  }();
  return print;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  edgewise::fuzz::write_seed_files("fuzz_draw", "draw", seed_inputs());
  return 0;
}

// DrawOptions::error_budget of two codes: every ISA within two codes of its own exact image at
// every sample, with the same depth, and the reference's choices (its counts of fragments given
// one colour and one texel value per tile).
void check_budget(const Case& c, std::span<const Output> exact) {
  Case budgeted = c;
  budgeted.options.error_budget = 2.0f / 255.0f;
  const std::vector<Output> outputs = draw_every_isa(budgeted, budgeted.mesh());
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const Output& got = outputs[i];
    const Output& want = exact[i];
    if (got.threw) fail(budgeted, "draw() threw under an error budget", outputs, got.error);
    if (got.report.statistics.fragments_constant !=
            outputs.front().report.statistics.fragments_constant ||
        got.report.statistics.fragments_one_texel !=
            outputs.front().report.statistics.fragments_one_texel) {
      fail(budgeted, "an ISA's error-budget choices differ from the reference's", outputs,
           std::string(name_of(got.isa)));
    }
    const std::size_t values = static_cast<std::size_t>(got.target.tiles_x()) *
                               static_cast<std::size_t>(got.target.tiles_y()) * 64 *
                               static_cast<std::size_t>(got.target.samples());
    for (std::size_t v = 0; v < values; ++v) {
      const std::uint32_t a = got.target.color_tiles()[v], b = want.target.color_tiles()[v];
      for (int k = 0; k < 4; ++k) {
        const int da =
            static_cast<int>(a >> (8 * k) & 0xFF) - static_cast<int>(b >> (8 * k) & 0xFF);
        if (da > 2 || da < -2) {
          fail(budgeted, "the error budget's image leaves the budget", outputs,
               std::string(name_of(got.isa)) + ": " + hex(a) + " against " + hex(b) +
                   " at storage index " + std::to_string(v));
        }
      }
      const float za = got.target.depth_tiles()[v], zb = want.target.depth_tiles()[v];
      if (!(za == zb || (std::isnan(za) && std::isnan(zb)))) {
        fail(budgeted, "the error budget changed depth", outputs,
             std::string(name_of(got.isa)) + " at storage index " + std::to_string(v));
      }
    }
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Case c = decode({data, size});
  ++stats.inputs;
  if (printing()) print_case(c);

  // The triangles whose corners are all in range (the others are counted as errors, not drawn).
  std::vector<std::vector<Piece>> pieces_of;
  std::vector<std::array<std::uint32_t, 3>> corners_of;
  if (!c.expect_invalid && c.width > 0 && c.height > 0) {
    for (std::size_t t = 0; t < c.triangle_count(); ++t) {
      std::array<std::uint32_t, 3> corner;
      bool in_range = true;
      for (int i = 0; i < 3; ++i) {
        corner[i] = c.indexed ? c.indices[3 * t + i] : static_cast<std::uint32_t>(3 * t + i);
        in_range = in_range && corner[i] < c.positions.size();
      }
      if (!in_range) continue;
      corners_of.push_back(corner);
      pieces_of.emplace_back();
      append_pieces(c, corner.data(), pieces_of.back());
    }
  }

  std::vector<Piece> all_pieces;
  for (const auto& p : pieces_of)
    all_pieces.insert(all_pieces.end(), p.begin(), p.end());
  const std::vector<Output> whole = draw_every_isa(c, c.mesh());
  if (printing()) print_counts("whole mesh:", whole);
  check_draw(c, whole, all_pieces);
  if (c.expect_invalid) {
    ++stats.invalid;
    return 0;
  }
  if (c.width > 0 && c.height > 0) check_budget(c, whole);

  // The texture's extremes, scanned once (the options are valid here).
  std::optional<test::TexturedPixelCheck> textured_check;
  if (c.options.texture) textured_check.emplace(*c.texture, c.options.texture->sampler);
  for (std::size_t k = 0; k < corners_of.size(); ++k) {
    Case one = c;
    one.part = "triangle " + std::to_string(k) + " of the mesh (corners " +
               std::to_string(corners_of[k][0]) + ", " + std::to_string(corners_of[k][1]) + ", " +
               std::to_string(corners_of[k][2]) + ")";
    one.indexed = false;
    one.indices.clear();
    one.positions.clear();
    one.colors.clear();
    one.normals.clear();
    one.uvs.clear();
    for (std::uint32_t v : corners_of[k]) {
      one.positions.push_back(c.positions[v]);
      if (!c.colors.empty()) one.colors.push_back(c.colors[v]);
      if (!c.normals.empty()) one.normals.push_back(c.normals[v]);
      if (!c.uvs.empty()) one.uvs.push_back(c.uvs[v]);
    }
    const std::vector<Output> outputs = draw_every_isa(one, one.mesh());
    if (printing()) print_counts(one.part.c_str(), outputs);
    check_draw(one, outputs, pieces_of[k]);
    if (one.options.texture) {
      check_textured_colours(one, *textured_check, outputs, untextured_reference(one, outputs),
                             pieces_of[k]);
    } else {
      check_colours(one, outputs, pieces_of[k]);
    }
  }
  return 0;
}
