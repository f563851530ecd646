// BudgetDraw/<isa>/<scene>/<exact|budget:1/255|floor>[/threads:all]: draw() on the demo's
// scenes with the exact methods and with DrawOptions::error_budget = 1/255, side by side, at
// 1280 x 720:
//   default   scene::default_scene() (ground plane, sphere, torus), per-pixel diffuse, back faces
//             culled, perspective-correct;
//   ground    scene::ground_scene() textured with the 1024 x 1024 checkerboard of 8 x 8 squares
//             (trilinear, quad derivatives), white diffuse.
// A third variant, `floor`, draws the same mesh flat, affine and untextured: every fragment one
// colour with no interpolation and no texture, the least any shading choice can cost with
// coverage and depth left exact. exact / floor is the most any budget can gain on the scene.
// One iteration is one draw() call into a target cleared with the timer paused. The budgeted runs
// also report `constant` (the share of written fragments given one colour), `one_texel` (the
// share given one texel value per tile, their shading still per pixel) and `largest_codes`
// (the largest 8-bit difference from the exact image, which the budget holds to 1).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "../benchmarks.hpp"
#include "edgewise/edgewise.hpp"
#include "scene/procedural.hpp"
#include "texture_scene/procedural_textures.hpp"

namespace edgewise::bench {
namespace {

constexpr std::int32_t kBudgetWidth = 1280, kBudgetHeight = 720;
constexpr Vec4 kClearColour{0.1f, 0.1f, 0.12f, 1.0f};
constexpr float kBudget = 1.0f / 255.0f;

struct BudgetScene {
  std::string name;
  scene::Scene scene;
  std::optional<Texture> texture;
};

Mat4 camera_transform(const scene::SceneCamera& c) {
  const float fov = c.vertical_fov_degrees * std::numbers::pi_v<float> / 180.0f;
  return perspective(fov, float(kBudgetWidth) / float(kBudgetHeight), c.near_plane, c.far_plane) *
         look_at(c.eye, c.target, c.up);
}

const std::vector<BudgetScene>& budget_scenes() {
  static const std::vector<BudgetScene> scenes = [] {
    std::vector<BudgetScene> list;
    list.push_back({"default", scene::default_scene(), std::nullopt});
    const std::vector<std::uint8_t> texels =
        texture_scene::to_rgba8(texture_scene::checkerboard(1024, 8));
    BudgetScene ground{"ground", scene::ground_scene(),
                       Texture::from_rgba8(1024, 1024, texels, ColorEncoding::linear)};
    for (Vec4& c : ground.scene.mesh.colors)
      c = {1.0f, 1.0f, 1.0f, 1.0f};
    list.push_back(std::move(ground));
    return list;
  }();
  return scenes;
}

DrawMesh mesh_of(const scene::Mesh& mesh, bool textured) {
  DrawMesh m{mesh.positions, mesh.colors, mesh.normals, mesh.indices};
  if (textured) m.uvs = mesh.uvs;
  return m;
}

enum class Variant { exact, budget, floor };

DrawOptions options_of(const BudgetScene& s, Isa isa, Variant variant, std::size_t threads) {
  DrawOptions options;
  options.transform = camera_transform(s.scene.camera);
  options.cull = CullMode::clockwise;
  options.shading = Shading::diffuse;
  options.light_direction = {-0.45f, 0.8f, 0.55f};
  options.isa = isa;
  options.threads = threads;
  if (variant == Variant::floor) {
    options.shading = Shading::flat;
    options.perspective = Perspective::affine;
    return options;
  }
  if (s.texture) options.texture = DrawTexture{&*s.texture, {}, TextureDerivatives::quad};
  if (variant == Variant::budget) options.error_budget = kBudget;
  return options;
}

std::vector<std::uint8_t> image_of(const Framebuffer& target) {
  std::vector<std::uint8_t> rgba(std::size_t{4} * kBudgetWidth * kBudgetHeight);
  target.read_rgba8(rgba);
  return rgba;
}

void budget_draw(benchmark::State& state, Isa isa, const BudgetScene* s, Variant variant,
                 std::size_t threads) {
  const DrawMesh mesh = mesh_of(s->scene.mesh, s->texture.has_value() && variant != Variant::floor);
  const DrawOptions options = options_of(*s, isa, variant, threads);
  Framebuffer target(kBudgetWidth, kBudgetHeight);
  DrawReport last;
  for (auto _ : state) {
    state.PauseTiming();
    target.clear(kClearColour, 1.0f);
    state.ResumeTiming();
    last = draw(target, mesh, options);
    benchmark::DoNotOptimize(target.color_tiles());
    benchmark::ClobberMemory();
  }
  if (last.fragments_passed == 0) state.SkipWithError("the scene draws nothing");
  const double written = double(last.fragments_passed == 0 ? 1 : last.fragments_passed);
  state.counters["constant"] = double(last.statistics.fragments_constant) / written;
  state.counters["one_texel"] = double(last.statistics.fragments_one_texel) / written;
  if (variant != Variant::budget) return;
  // The budget's promise, measured on the last frame.
  Framebuffer exact(kBudgetWidth, kBudgetHeight);
  exact.clear(kClearColour, 1.0f);
  draw(exact, mesh, options_of(*s, isa, Variant::exact, threads));
  const std::vector<std::uint8_t> a = image_of(target), b = image_of(exact);
  int largest = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    largest = std::max(largest, std::abs(int{a[i]} - int{b[i]}));
  state.counters["largest_codes"] = largest;
  if (largest > 1) state.SkipWithError("the budgeted image leaves the budget");
}

}  // namespace

void register_budget_draw_benchmarks() {
  for (Isa isa : supported_isas()) {
    if (isa == Isa::reference) continue;  // seconds per frame
    for (const BudgetScene& s : budget_scenes()) {
      for (Variant variant : {Variant::exact, Variant::budget, Variant::floor}) {
        const char* name = variant == Variant::exact    ? "exact"
                           : variant == Variant::budget ? "budget:1/255"
                                                        : "floor";
        const std::string base =
            "BudgetDraw/" + std::string(name_of(isa)) + "/" + s.name + "/" + name;
        benchmark::RegisterBenchmark(base.c_str(), budget_draw, isa, &s, variant, std::size_t{1})
            ->Unit(benchmark::kMillisecond);
        if (isa == compiled_isas().back()) {
          benchmark::RegisterBenchmark((base + "/threads:all").c_str(), budget_draw, isa, &s,
                                       variant, std::size_t{0})
              ->Unit(benchmark::kMillisecond)
              ->UseRealTime();
        }
      }
    }
  }
}

}  // namespace edgewise::bench
