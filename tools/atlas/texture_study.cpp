#include "atlas/texture_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "edgewise/edgewise.hpp"
#include "texture_quality/filter_methods.hpp"
#include "texture_quality/ground_truth_store.hpp"
#include "texture_quality/oiio_peer.hpp"
#include "texture_quality/scenes.hpp"
#include "texture_scene/ground_truth.hpp"
#include "texture_scene/image_metrics.hpp"
#include "texture_scene/linear_image.hpp"
#include "texture_scene/texture_view.hpp"

namespace edgewise::atlas {
namespace {

using namespace texture_quality;
namespace ts = texture_scene;

constexpr std::int32_t kTextureSize = 1024;
constexpr const char* kTexturePareto = "texture-pareto";
constexpr const char* kAnisotropy = "texture-anisotropy";
constexpr const char* kSummedArea = "texture-summed-area";

double rmse_of(std::span<const Vec4> colours, const ts::LinearImage& truth) {
  return ts::compare_images(ts::image_from_samples(truth.width, truth.height, colours), truth).rmse;
}

// The checkerboard ground plane (the view of edgewise-texture-quality, at a quarter of full HD;
// its ground truth is cached as that tool caches it). A quick run takes the magnification view,
// whose ground truth takes a moment where the ground plane's takes a minute.
void texture_pareto(const StudySettings& settings, StudyOutput& out) {
  const std::int32_t width = settings.quick ? 96 : 960, height = settings.quick ? 54 : 540;
  const SceneView scene = settings.quick ? SceneView::magnification : SceneView::ground_plane;
  const std::string scene_name(scene_view_name(scene));
  std::string title = "Error against time per sample, checkerboard " + scene_name;
  std::replace(title.begin(), title.end(), '_', ' ');
  out.add_chart({kTexturePareto, title, "ns per sample", "RMSE against ground truth", true, true,
                 ChartKind::scatter, ""});
  const ts::LinearImage image = scene_texture_image(SceneTexture::checkerboard, kTextureSize);
  const Texture texture = scene_texture(image, PyramidFilter::box);
  const ts::TextureView view = scene_view(scene, width, height, kTextureSize);
  const StoredGroundTruth truth = load_or_compute_ground_truth(
      settings.cache, "checkerboard1024_" + scene_name, image, view, std::cerr);
  const std::vector<TextureQuery> queries = view.queries();
  std::vector<Vec4> colours(queries.size());
  const double per_sample = 1.0 / static_cast<double>(queries.size());
  double trilinear = 0.0, peer_trilinear = 0.0, trilinear_fixed = 0.0;
  double fastest_trilinear = INFINITY, fastest_trilinear_fixed = INFINITY;
  for (const FilterMethod& method : filter_methods({})) {
    for (Isa isa : supported_isas()) {
      if (isa == Isa::reference) continue;  // seconds per run; its error is the ISAs'
      const double ns = per_sample * median_nanoseconds(
                                         "texture/" + method.name + "/" + std::string(name_of(isa)),
                                         [&] {
                                           sample(texture, {method.options, isa}, queries, colours);
                                         },
                                         settings.timer);
      const double rmse = rmse_of(colours, truth.truth.image);
      out.add(kTexturePareto, method.name, ns, rmse, std::string(name_of(isa)));
      if (method.name == "trilinear") {
        trilinear = rmse;
        fastest_trilinear = std::min(fastest_trilinear, ns);
      }
      if (method.name == "trilinear_fixed16") {
        trilinear_fixed = rmse;
        fastest_trilinear_fixed = std::min(fastest_trilinear_fixed, ns);
      }
    }
  }
  OiioPeer peer(image, "atlas_checkerboard");
  for (std::size_t mode = 0; mode < std::size(kPeerModeNames); ++mode) {
    const std::string name = "OpenImageIO " + std::string(kPeerModeNames[mode]);
    const double ns =
        per_sample *
        median_nanoseconds(
            "texture/" + name, [&] { peer.sample(mode, queries, colours); }, settings.timer);
    const double rmse = rmse_of(colours, truth.truth.image);
    out.add(kTexturePareto, name, ns, rmse);
    if (kPeerModeNames[mode] == "trilinear") peer_trilinear = rmse;
  }
  char reading[500];
  std::snprintf(reading, sizeof reading,
                "Lower left is better; each filter is a point per ISA. Trilinear's RMSE is %.4f "
                "against OpenImageIO's trilinear %.4f on the same queries. Its fixed-point taps "
                "(trilinear_fixed16) give RMSE %.4f at %.2fx float32's time (fastest ISA each).",
                trilinear, peer_trilinear, trilinear_fixed,
                fastest_trilinear_fixed / fastest_trilinear);
  out.set_reading(kTexturePareto, reading);
}

// An affine view of the band-limited texture whose every footprint has the same axes: `minor`
// texels across and `ratio` times that along, turned by 30 degrees.
ts::TextureView anisotropic_view(std::int32_t size, double ratio, double minor) {
  const double angle = std::numbers::pi / 6.0, c = std::cos(angle), s = std::sin(angle);
  const double major = minor * ratio, texel = 1.0 / kTextureSize;
  // Columns of the Jacobian: screen x goes `major` texels along the turned axis, y `minor`
  // across it.
  ts::ProjectiveMap map;
  map.s_row = {c * major * texel, -s * minor * texel, 0.25};
  map.t_row = {s * major * texel, c * minor * texel, 0.25};
  map.w_row = {0.0, 0.0, 1.0};
  return ts::TextureView(size, size, map);
}

void anisotropy(const StudySettings& settings, StudyOutput& out) {
  out.add_chart({kAnisotropy,
                 "Error as the footprint's anisotropy grows (sinusoids, 2 texels across)",
                 "anisotropy (footprint's long axis / short axis)", "RMSE against ground truth",
                 true, true, ChartKind::line, ""});
  const ts::LinearImage image = scene_texture_image(SceneTexture::sinusoids, kTextureSize);
  const Texture texture = scene_texture(image, PyramidFilter::box);
  const std::int32_t size = settings.quick ? 8 : 48;
  const TextureFilter filters[] = {TextureFilter::trilinear,   TextureFilter::ripmap,
                                   TextureFilter::summed_area, TextureFilter::anisotropic,
                                   TextureFilter::ewa,         TextureFilter::supersample};
  double trilinear_last = 0.0, anisotropic_last = 0.0, last_ratio = 1.0;
  for (double ratio : {1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0}) {
    if (settings.quick && ratio > 4.0) break;
    last_ratio = ratio;
    const ts::TextureView view = anisotropic_view(size, ratio, 2.0);
    ts::GroundTruthOptions options;
    const ts::GroundTruth truth =
        ts::ground_truth(image, WrapMode::repeat, WrapMode::repeat, view, view.screen(), options);
    const std::vector<TextureQuery> queries = view.queries();
    std::vector<Vec4> colours(queries.size());
    for (TextureFilter filter : filters) {
      SamplerOptions sampler;
      sampler.filter = filter;
      sample(texture, {sampler, active_isa()}, queries, colours);
      const double rmse = rmse_of(colours, truth.image);
      out.add(kAnisotropy, std::string(name_of(filter)), ratio, rmse);
      if (filter == TextureFilter::trilinear) trilinear_last = rmse;
      if (filter == TextureFilter::anisotropic) anisotropic_last = rmse;
    }
  }
  char reading[300];
  std::snprintf(reading, sizeof reading,
                "Isotropic filters blur along the short axis as the footprint stretches "
                "(trilinear RMSE %.4f at %g:1); anisotropic probes (16 at most) keep the error "
                "lower (%.4f at %g:1) up to their limit.",
                trilinear_last, last_ratio, anisotropic_last, last_ratio);
  out.set_reading(kAnisotropy, reading);
}

// Sums of 8-bit texels over boxes, from a float32 summed-area table against exact integer
// sums: the largest error of a box average, in 8-bit codes, as the table grows.
void summed_area(const StudySettings& settings, StudyOutput& out) {
  out.add_chart({kSummedArea, "Float32 summed-area sums against exact ones (random 8-bit texels)",
                 "texture side (texels)", "largest error of a box average (8-bit codes)", true,
                 true, ChartKind::line, ""});
  std::mt19937_64 rng(0x5a7);
  std::uniform_int_distribution<int> texel(0, 255);
  int exact_from = 0;
  for (std::int32_t n = 64; n <= (settings.quick ? 256 : 4096); n *= 2) {
    std::vector<std::uint8_t> texels(std::size_t(n) * n);
    for (std::uint8_t& t : texels)
      t = static_cast<std::uint8_t>(texel(rng));
    // Inclusive prefix sums, (n + 1)^2 with a zero border, in both arithmetics.
    const std::size_t stride = std::size_t(n) + 1;
    std::vector<std::int64_t> exact(stride * stride, 0);
    std::vector<float> single(stride * stride, 0.0f);
    for (std::int32_t y = 1; y <= n; ++y) {
      for (std::int32_t x = 1; x <= n; ++x) {
        const std::size_t i = y * stride + x;
        const std::uint8_t t = texels[std::size_t(y - 1) * n + (x - 1)];
        exact[i] = t + exact[i - 1] + exact[i - stride] - exact[i - stride - 1];
        single[i] =
            static_cast<float>(t) + single[i - 1] + single[i - stride] - single[i - stride - 1];
      }
    }
    std::uniform_int_distribution<std::int32_t> corner(0, n);
    double worst = 0.0;
    for (int box = 0; box < 20000; ++box) {
      std::int32_t x0 = corner(rng), x1 = corner(rng), y0 = corner(rng), y1 = corner(rng);
      if (x0 > x1) std::swap(x0, x1);
      if (y0 > y1) std::swap(y0, y1);
      if (x0 == x1 || y0 == y1) continue;
      const auto at = [&](auto& table, std::int32_t x, std::int32_t y) {
        return table[y * stride + x];
      };
      const double area = double(x1 - x0) * (y1 - y0);
      const double exact_sum =
          double(at(exact, x1, y1) - at(exact, x0, y1) - at(exact, x1, y0) + at(exact, x0, y0));
      const double float_sum =
          double(at(single, x1, y1)) - at(single, x0, y1) - at(single, x1, y0) + at(single, x0, y0);
      worst = std::max(worst, std::abs(float_sum - exact_sum) / area);
    }
    out.add(kSummedArea, "float32 table", n, worst);
    out.add(kSummedArea, "exact table (the library's)", n, 0.0);
    if (worst > 0.5 && exact_from == 0) exact_from = n;
  }
  char reading[300];
  if (exact_from == 0) {
    std::snprintf(reading, sizeof reading,
                  "A float32 table of 8-bit texels stays within half a code up to the sizes "
                  "measured; the library sums in double over 16-bit fixed-point values, exact "
                  "for any texture that fits in memory.");
  } else {
    std::snprintf(reading, sizeof reading,
                  "A float32 table of 8-bit texels errs by more than half a code from %d texels "
                  "a side on; the library sums in double over 16-bit fixed-point values, exact "
                  "for any texture that fits in memory.",
                  exact_from);
  }
  out.set_reading(kSummedArea, reading);
}

}  // namespace

StudyOutput texture_study(const StudySettings& settings, const std::string& cpu) {
  StudyOutput out("texture", "Texture filtering: every filter against ground truth", cpu);
  texture_pareto(settings, out);
  anisotropy(settings, out);
  summed_area(settings, out);
  return out;
}

}  // namespace edgewise::atlas
