// Textured draw()'s contract, on every ISA and the reference: argument checks, the texel
// convention (texel (a, b) centred at ((a + 0.5) / W, (b + 0.5) / H)), and perspective-correct
// coordinates through near-plane clipping, against the exact projective mapping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "edgewise/camera.hpp"
#include "edgewise/draw.hpp"
#include "isa_params.hpp"
#include "random.hpp"

namespace edgewise::test {
namespace {

using TexturedApi = IsaTest;

Texture random_texture(std::int32_t width, std::int32_t height, const TextureBuild& build = {}) {
  Random random(5);
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(width) * height * 4);
  for (std::uint8_t& v : texels)
    v = static_cast<std::uint8_t>(random.integer(0, 255));
  return Texture::from_rgba8(width, height, texels, ColorEncoding::linear, build);
}

// A screen-filling quad in an orthographic view of [0, width] x [0, height] pixels, uv (0, 0) at
// the top-left corner and (1, 1) at the bottom-right.
struct ScreenQuad {
  std::vector<Vec3> positions;
  std::vector<Vec2> uvs;
  ScreenQuad(float width, float height) {
    const Vec3 corners[4] = {
        {0, 0, -0.5f}, {width, 0, -0.5f}, {0, height, -0.5f}, {width, height, -0.5f}};
    const Vec2 uv[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    for (int i : {0, 1, 2, 1, 3, 2}) {
      positions.push_back(corners[i]);
      uvs.push_back(uv[i]);
    }
  }
  DrawMesh mesh() const { return {positions, {}, {}, {}, uvs}; }
};

DrawOptions screen_options(Isa isa, float width, float height, const Texture& texture,
                           TextureFilter filter) {
  DrawOptions options;
  options.transform = orthographic(0.0f, width, height, 0.0f, 0.0f, 1.0f);
  options.isa = isa;
  options.shading = Shading::flat;  // white: the texel alone
  options.texture = DrawTexture{&texture, {}, TextureDerivatives::quad};
  options.texture->sampler.filter = filter;
  return options;
}

TEST_P(TexturedApi, ArgumentErrorsThrow) {
  const Texture texture = random_texture(8, 8);
  const ScreenQuad quad(8, 8);
  Framebuffer target(8, 8);
  DrawOptions options = screen_options(isa(), 8, 8, texture, TextureFilter::bilinear);
  EXPECT_NO_THROW(draw(target, quad.mesh(), options));

  DrawMesh no_uvs = quad.mesh();
  no_uvs.uvs = {};
  EXPECT_THROW(draw(target, no_uvs, options), std::invalid_argument);
  DrawMesh short_uvs = quad.mesh();
  short_uvs.uvs = short_uvs.uvs.first(5);
  EXPECT_THROW(draw(target, short_uvs, options), std::invalid_argument);

  DrawOptions null_texture = options;
  null_texture.texture->texture = nullptr;
  EXPECT_THROW(draw(target, quad.mesh(), null_texture), std::invalid_argument);
  for (TextureFilter needs_more : {TextureFilter::ripmap, TextureFilter::summed_area}) {
    DrawOptions bad = options;
    bad.texture->sampler.filter = needs_more;  // the texture has neither
    EXPECT_THROW(draw(target, quad.mesh(), bad), std::invalid_argument);
  }
  DrawOptions bad_aniso = options;
  bad_aniso.texture->sampler.max_anisotropy = 0;
  EXPECT_THROW(draw(target, quad.mesh(), bad_aniso), std::invalid_argument);

  // Without a texture, uvs are ignored whatever their count.
  DrawOptions untextured = options;
  untextured.texture.reset();
  EXPECT_NO_THROW(draw(target, short_uvs, untextured));
}

// One texel per pixel: pixel (x, y) samples at ((x + 0.5) / W, (y + 0.5) / H), the centre of
// texel (x, y). Nearest returns that texel; bilinear and trilinear weigh it by 1 up to float
// rounding (far below half a code), so every pixel shows exactly its texel's code.
TEST_P(TexturedApi, OneTexelPerPixelShowsEachTexel) {
  const std::int32_t width = 40, height = 24;  // not whole tiles, not powers of two
  const Texture texture = random_texture(width, height);
  const ScreenQuad quad(width, height);
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(width) * height * 4);
  const auto* level0 =
      reinterpret_cast<const std::uint8_t*>(texture.texels(texture.mip_levels()[0]));
  texels.assign(level0, level0 + texels.size());
  for (TextureFilter filter :
       {TextureFilter::nearest, TextureFilter::bilinear, TextureFilter::trilinear}) {
    for (TextureDerivatives derivatives :
         {TextureDerivatives::quad, TextureDerivatives::analytic}) {
      DrawOptions options = screen_options(isa(), width, height, texture, filter);
      options.texture->derivatives = derivatives;
      Framebuffer target(width, height);
      target.clear({0, 0, 0, 0}, 1.0f);
      draw(target, quad.mesh(), options);
      std::vector<std::uint8_t> rgba(texels.size());
      target.read_rgba8(rgba);
      ASSERT_EQ(rgba, texels) << name_of(filter) << " " << name_of(derivatives);
    }
  }
}

// A floor from behind the camera to far ahead, clipped at the near plane, with uv an affine
// function of the floor position and a float texture whose red and green channels ramp with s
// and t: bilinear filtering reproduces the ramp exactly inside the texture (texel centres
// 0.5 / 256 .. 255.5 / 256; clamp to edge outside), so each pixel's red and green codes are
// round(255 s) and round(255 t) at the exact (s, t) the pixel's ray hits.
// Tolerance: one code. Rows at least 4 pixels below the horizon keep 1/w and the planes'
// cancellations small (terms at most ~100 times the result): float errors stay below 1e-4 of
// the result, far inside the half code (0.002) each side's rounding leaves.
TEST_P(TexturedApi, ClippedFloorIsPerspectiveCorrect) {
  const std::int32_t size = 64, ramp = 256;
  std::vector<float> texels(static_cast<std::size_t>(ramp) * ramp * 4);
  for (std::int32_t j = 0; j < ramp; ++j) {
    for (std::int32_t i = 0; i < ramp; ++i) {
      float* texel = &texels[(static_cast<std::size_t>(j) * ramp + i) * 4];
      texel[0] = (static_cast<float>(i) + 0.5f) / ramp;
      texel[1] = (static_cast<float>(j) + 0.5f) / ramp;
      texel[2] = 0.0f;
      texel[3] = 1.0f;
    }
  }
  const Texture texture = Texture::from_rgba32f(ramp, ramp, texels);
  // The floor y = -1; s = (x + 50) / 100, t = (z + 60) / 70.
  const std::vector<Vec3> positions = {{-50, -1, 10}, {50, -1, 10}, {0, -1, -60}};
  std::vector<Vec2> uvs;
  for (const Vec3& p : positions)
    uvs.push_back({(p.x + 50.0f) / 100.0f, (p.z + 60.0f) / 70.0f});
  const float fov = 1.2f;
  for (Perspective mode : {Perspective::correct, Perspective::affine}) {
    DrawOptions options;
    options.transform = perspective(fov, 1.0f, 0.1f, 100.0f);
    options.isa = isa();
    options.shading = Shading::flat;
    options.perspective = mode;
    options.texture = DrawTexture{&texture, {}, TextureDerivatives::analytic};
    options.texture->sampler.filter = TextureFilter::bilinear;
    options.texture->sampler.wrap_s = options.texture->sampler.wrap_t = WrapMode::clamp_to_edge;
    Framebuffer target(size, size);
    target.clear({0, 0, 0, 1}, 1.0f);
    const DrawReport report = draw(target, {positions, {}, {}, {}, uvs}, options);
    EXPECT_EQ(report.clipped, 1u);
    int worst = 0;
    for (std::int32_t y = size / 2 + 4; y < size; ++y) {
      for (std::int32_t x = 0; x < size; ++x) {
        ASSERT_LT(target.depth(x, y), 1.0f) << x << "," << y;  // the floor fills the bottom
        // The pixel's ray: direction (ndc_x tan(fov/2), ndc_y tan(fov/2), -1), meeting y = -1.
        const double half = std::tan(static_cast<double>(fov) / 2.0);
        const double ndc_x = (x + 0.5) / size * 2.0 - 1.0, ndc_y = 1.0 - (y + 0.5) / size * 2.0;
        const double distance = 1.0 / (-ndc_y * half);
        const double wx = ndc_x * half * distance, wz = -distance;
        const double st[2] = {(wx + 50.0) / 100.0, (wz + 60.0) / 70.0};
        const std::uint32_t color = target.color(x, y);
        for (int k = 0; k < 2; ++k) {
          const double clamped = std::clamp(st[k], 0.5 / ramp, (ramp - 0.5) / ramp);
          const int code = static_cast<int>(color >> (8 * k) & 0xFF);
          const int difference = std::abs(code - static_cast<int>(std::lrint(255.0 * clamped)));
          worst = std::max(worst, difference);
          if (mode == Perspective::correct) {
            ASSERT_LE(difference, 1) << x << "," << y << " channel " << k;
          }
        }
      }
    }
    // Affine interpolation of the same floor is visibly wrong: the test can tell them apart.
    if (mode == Perspective::affine) {
      EXPECT_GT(worst, 20);
    }
  }
}

EDGEWISE_INSTANTIATE_PER_ISA(TexturedApi, every_isa());

}  // namespace
}  // namespace edgewise::test
