// DrawOptions::error_budget: on every ISA and the scalar reference, an image drawn with a budget
// differs from the same ISA's exact image by at most floor(255 budget) codes at every pixel, its
// depth is the same, and every ISA makes the reference's choices (the same counts of fragments
// given one colour and given one texel value per tile). Random scenes, and adversarial ones:
// slivers, w ratios up to the frustum's, colours outside [0, 1], normals far apart, textures with
// sharp edges under every wrap mode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "edgewise/draw.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "draw/draw_scenes.hpp"

namespace edgewise::test {
namespace {

constexpr std::int32_t kWidth = 96, kHeight = 72;

// A quarter of the triangles keep their random colours and normals, a quarter get colours within
// a few codes of each other, the others one colour (and half of those one normal) at all three
// vertices, some of them outside [0, 1].
Scene budget_scene(Random& random, int triangles, double min_size, double max_size) {
  Scene scene =
      random_scene(random, triangles, static_cast<double>(kWidth) / kHeight, min_size, max_size);
  for (std::size_t t = 0; 3 * t < scene.positions.size(); ++t) {
    const int kind = random.integer(0, 3);
    if (kind == 0) continue;
    if (kind == 1) {  // colours within a few codes of each other
      for (int i = 1; i < 3; ++i) {
        Vec4& c = scene.colors[3 * t + i];
        c = scene.colors[3 * t];
        c.x += static_cast<float>(random.uniform(-2.5, 2.5) / 255.0);
        c.z += static_cast<float>(random.uniform(-2.5, 2.5) / 255.0);
      }
      continue;
    }
    for (int i = 1; i < 3; ++i) {
      scene.colors[3 * t + i] = scene.colors[3 * t];
      if (kind >= 2) scene.normals[3 * t + i] = scene.normals[3 * t];
    }
    if (kind == 3) {  // out of range: clamped when written
      for (int i = 0; i < 3; ++i)
        scene.colors[3 * t + i].x = 1.5f;
    }
  }
  return scene;
}

// Slivers along random directions, nearly flat colours, and triangles reaching from near the
// near plane to the far one.
Scene adversarial_scene(Random& random) {
  Scene scene;
  const auto vertex = [&](double x, double y, double z, Vec4 colour, Vec3 normal) {
    scene.positions.push_back(
        {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)});
    scene.colors.push_back(colour);
    scene.normals.push_back(normal);
  };
  for (int t = 0; t < 24; ++t) {
    const Vec4 colour{static_cast<float>(random.uniform(0.0, 1.0)),
                      static_cast<float>(random.uniform(0.0, 1.0)),
                      static_cast<float>(random.uniform(0.0, 1.0)), 1.0f};
    // A colour within a fraction of a code of the first.
    Vec4 near = colour;
    near.y += static_cast<float>(random.uniform(-1.5, 1.5) / 255.0);
    const Vec3 normal{static_cast<float>(random.uniform(-0.3, 0.3)),
                      static_cast<float>(random.uniform(-0.3, 0.3)), 1.0f};
    const double z0 = -random.log_uniform(0.55, 39.0), z1 = -random.log_uniform(0.55, 39.0);
    const double x = random.uniform(-0.3, 0.3), y = random.uniform(-0.3, 0.3);
    if (t % 3 == 0) {
      // A sliver: long, a fraction of a pixel wide at its middle.
      const double angle = random.uniform(0.0, 6.283185307179586);
      const double length = random.uniform(0.5, 1.5), thickness = random.log_uniform(1e-4, 1e-2);
      const double dx = std::cos(angle) * length, dy = std::sin(angle) * length;
      vertex((x - dx) * -z0, (y - dy) * -z0, z0, colour, normal);
      vertex((x + dx) * -z1, (y + dy) * -z1, z1, colour, normal);
      vertex((x + thickness * -dy) * -z0, (y + thickness * dx) * -z0, z0, near, normal);
    } else {
      // Deep: from near the near plane into the distance, one colour, normals apart or equal.
      const Vec3 other{-normal.x, normal.y, 0.2f};
      const Vec3 second = t % 3 == 1 ? normal : other;
      vertex((x - 0.2) * 0.6, (y - 0.2) * 0.6, -0.6, colour, normal);
      vertex((x + 0.3) * -z1, (y - 0.1) * -z1, z1, colour, second);
      vertex((x - 0.1) * -z0, (y + 0.3) * -z0, z0, near, normal);
    }
  }
  return scene;
}

struct Difference {
  int largest = 0;  // codes
  bool same_depth = true;
};

Difference compare(const Rendered& a, const Rendered& b) {
  Difference d;
  for (std::size_t i = 0; i < a.rgba.size(); ++i)
    d.largest = std::max(d.largest, std::abs(int{a.rgba[i]} - int{b.rgba[i]}));
  d.same_depth = a.depth == b.depth;
  return d;
}

// The fragments the budget gave one colour, and one texel value per tile.
struct Chosen {
  std::uint64_t constant = 0, one_texel = 0;
  bool operator==(const Chosen&) const = default;
  Chosen& operator+=(const Chosen& other) {
    constant += other.constant;
    one_texel += other.one_texel;
    return *this;
  }
};

// Draws `scene` exactly and within `budget` on every ISA: the budgeted image within the budget's
// codes of the exact one, the same depth, and the reference's counts of chosen fragments.
// Returns the reference's counts.
Chosen check_budget(const Scene& scene, DrawOptions options, float budget,
                    const std::string& label) {
  // The library's rule (shading_budget.hpp): within 2^-20 of k/255 counts as k codes.
  const int codes = static_cast<int>(std::floor(255.0 * budget * (1.0 + 0x1p-20)));
  Chosen reference_chosen;
  std::vector<std::pair<Isa, Chosen>> chosen;
  for (Isa isa : every_isa()) {
    options.error_budget.reset();
    const Rendered exact = render(isa, scene, options, kWidth, kHeight);
    options.error_budget = budget;
    const Rendered budgeted = render(isa, scene, options, kWidth, kHeight);
    const Difference d = compare(exact, budgeted);
    EXPECT_LE(d.largest, codes) << label << " on " << name_of(isa);
    EXPECT_TRUE(d.same_depth) << label << " on " << name_of(isa);
    EXPECT_EQ(budgeted.report.fragments_passed, exact.report.fragments_passed) << label;
    if (codes == 0) {
      EXPECT_EQ(budgeted.report.statistics.fragments_constant, 0u) << label;
      EXPECT_EQ(budgeted.report.statistics.fragments_one_texel, 0u) << label;
    }
    const Chosen counts{budgeted.report.statistics.fragments_constant,
                        budgeted.report.statistics.fragments_one_texel};
    if (isa == Isa::reference) reference_chosen = counts;
    chosen.emplace_back(isa, counts);
  }
  for (const auto& [isa, counts] : chosen) {
    EXPECT_TRUE(counts == reference_chosen)
        << label << " on " << name_of(isa) << ": not the reference's choices (" << counts.constant
        << " constant and " << counts.one_texel << " one-texel fragments against "
        << reference_chosen.constant << " and " << reference_chosen.one_texel << ")";
  }
  return reference_chosen;
}

TEST(ErrorBudget, RefusesNegativeAndNaNBudgets) {
  Random random(3);
  const Scene scene = budget_scene(random, 4, 0.1, 0.4);
  Framebuffer target(16, 16);
  DrawOptions options = perspective_options(16, 16);
  options.shading = Shading::diffuse;
  for (float bad : {-1.0f / 255, std::numeric_limits<float>::quiet_NaN()}) {
    options.error_budget = bad;
    EXPECT_THROW(draw(target, mesh_of(scene), options), std::invalid_argument);
  }
  options.error_budget = std::numeric_limits<float>::infinity();  // any colour: allowed
  EXPECT_NO_THROW(draw(target, mesh_of(scene), options));
}

TEST(ErrorBudget, RandomScenesWithinBudgetWithTheReferencesChoices) {
  Random random(17);
  std::uint64_t constant = 0;
  for (int round = 0; round < 3; ++round) {
    const Scene scene = budget_scene(random, 24, 0.05, 0.7);
    for (Shading shading : {Shading::gouraud, Shading::diffuse}) {
      for (Perspective perspective : {Perspective::correct, Perspective::affine}) {
        DrawOptions options = perspective_options(kWidth, kHeight);
        options.shading = shading;
        options.perspective = perspective;
        options.ambient = 0.2f;
        options.light_direction = {0.3f, 0.5f, 0.8f};
        for (float budget : {1.0f / 255, 3.0f / 255, 0.5f / 255}) {
          const std::string label = "round " + std::to_string(round) + " " +
                                    std::string(name_of(shading)) + " " +
                                    std::string(name_of(perspective)) + " budget " +
                                    std::to_string(budget * 255) + "/255";
          constant += check_budget(scene, options, budget, label).constant;
        }
      }
    }
  }
  EXPECT_GT(constant, 10000u) << "the budget chose nothing: the test checks nothing";
}

TEST(ErrorBudget, AdversarialScenesWithinBudget) {
  Random random(23);
  std::uint64_t constant = 0;
  for (int round = 0; round < 3; ++round) {
    const Scene scene = adversarial_scene(random);
    for (Shading shading : {Shading::gouraud, Shading::diffuse}) {
      DrawOptions options = perspective_options(kWidth, kHeight);
      options.shading = shading;
      options.cull = CullMode::none;
      options.depth_test = DepthTest::always;  // every layer reaches the image
      constant += check_budget(scene, options, 1.0f / 255,
                               "adversarial round " + std::to_string(round) + " " +
                                   std::string(name_of(shading)))
                      .constant;
    }
  }
  EXPECT_GT(constant, 0u);
}

// Sharp-edged textures: a checkerboard (power-of-two size) and random blocks (not a power of
// two), and a nearly flat one, magnified and minified, every wrap mode, both derivative kinds, the
// filters the budget bounds and one it does not.
Texture checker_texture(std::int32_t width, std::int32_t height, std::int32_t square) {
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(width) * height * 4);
  for (std::int32_t y = 0; y < height; ++y) {
    for (std::int32_t x = 0; x < width; ++x) {
      const bool light = ((x / square) + (y / square)) % 2 == 0;
      for (int k = 0; k < 4; ++k)
        texels[4 * (static_cast<std::size_t>(y) * width + x) + k] =
            k == 3 ? 255 : (light ? 230 : static_cast<std::uint8_t>(20 + 40 * k));
    }
  }
  return Texture::from_rgba8(width, height, texels, ColorEncoding::srgb);
}

// Nearly flat: every texel within 3 codes of one colour, so that a tile's texels span a few codes
// and the choice of one texel value turns on the shade it is multiplied by.
Texture nearly_flat_texture(Random& random, std::int32_t width, std::int32_t height) {
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(width) * height * 4);
  for (std::size_t i = 0; i < texels.size(); ++i) {
    const int base[4] = {150, 110, 70, 255};
    texels[i] = static_cast<std::uint8_t>(base[i % 4] - (i % 4 == 3 ? 0 : random.integer(0, 3)));
  }
  return Texture::from_rgba8(width, height, texels, ColorEncoding::linear);
}

TEST(ErrorBudget, TexturedTilesWithinBudget) {
  Random random(29);
  const Texture textures[] = {checker_texture(64, 64, 16), checker_texture(52, 36, 13),
                              nearly_flat_texture(random, 40, 24)};
  Chosen chosen, anisotropic_chosen;
  for (const Texture& texture : textures) {
    Scene scene = budget_scene(random, 12, 0.3, 1.0);
    add_uvs(random, scene, 0.05, 6.0);
    for (Vec4& c : scene.colors)
      c = {1.0f, 1.0f, 1.0f, 1.0f};
    for (TextureFilter filter :
         {TextureFilter::nearest, TextureFilter::bilinear, TextureFilter::mip_nearest,
          TextureFilter::trilinear, TextureFilter::anisotropic}) {
      for (WrapMode wrap : {WrapMode::repeat, WrapMode::clamp_to_edge, WrapMode::mirror}) {
        for (TextureDerivatives derivatives :
             {TextureDerivatives::quad, TextureDerivatives::analytic}) {
          for (Shading shading : {Shading::flat, Shading::diffuse}) {
            DrawOptions options = perspective_options(kWidth, kHeight);
            options.shading = shading;
            options.texture = DrawTexture{&texture, {}, derivatives};
            options.texture->sampler.filter = filter;
            options.texture->sampler.wrap_s = options.texture->sampler.wrap_t = wrap;
            const std::string label =
                std::string(name_of(filter)) + " " + std::string(name_of(wrap)) + " " +
                std::string(name_of(derivatives)) + " " + std::string(name_of(shading));
            (filter == TextureFilter::anisotropic ? anisotropic_chosen : chosen) +=
                check_budget(scene, options, 1.0f / 255, label);
          }
        }
      }
    }
  }
  EXPECT_GT(chosen.constant, 10000u) << "no tile took one colour: the test checks nothing";
  EXPECT_GT(chosen.one_texel, 1000u) << "no tile took one texel value: the test checks nothing";
  EXPECT_EQ(anisotropic_chosen, Chosen{}) << "a filter without a bound took the budget";
}

// Multisampled targets and methods other than plane equations are drawn exactly.
TEST(ErrorBudget, ExactWhereNoBoundHolds) {
  Random random(31);
  const Scene scene = budget_scene(random, 12, 0.2, 0.8);
  DrawOptions options = perspective_options(kWidth, kHeight);
  options.shading = Shading::gouraud;
  options.error_budget = 4.0f / 255;
  const Rendered multisampled = render(Isa::reference, scene, options, kWidth, kHeight, 4);
  EXPECT_EQ(multisampled.report.statistics.fragments_constant, 0u);
  options.interpolation = InterpolationMethod::edge_functions;
  const Rendered other_method = render(Isa::reference, scene, options, kWidth, kHeight);
  EXPECT_EQ(other_method.report.statistics.fragments_constant, 0u);
  options.interpolation = InterpolationMethod::plane_equations;
  const Rendered planes = render(Isa::reference, scene, options, kWidth, kHeight);
  EXPECT_GT(planes.report.statistics.fragments_constant, 0u);
}

}  // namespace
}  // namespace edgewise::test
