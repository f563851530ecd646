// What the theory predicts about the filters' errors, checked on the fixtures' scores: orderings
// between filters (never absolute thresholds, which would only hold for one size and texture),
// OpenImageIO's bilinear filter agreeing with edgewise's, and the reference agreeing with the
// fast path within the sampler's bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "edgewise/sample.hpp"
#include "texture_quality/filter_methods.hpp"
#include "tool_runs.hpp"

namespace edgewise::texture_quality::test {
namespace {

double rmse(const std::vector<ScoreRow>& rows, const char* texture, const char* view,
            const char* method) {
  return find_row(rows, texture, view, method, first_run_isa(rows)).rmse;
}

// On the ground plane the checkerboard is minified up to hundreds of times along the far
// footprints' major axes, so the scores order as the filters' footprints cover the pixel's:
TEST(Quality, GroundPlaneCheckerboardOrdersAsTheTheoryPredicts) {
  const std::vector<ScoreRow> rows = first_scores();
  const auto error = [&rows](const char* method) {
    return rmse(rows, "checkerboard", "ground_plane", method);
  };
  // Level 0 alone aliases wherever a pixel spans many texels; a mip level matched to the
  // footprint averages them.
  EXPECT_LT(error("trilinear"), error("bilinear"));
  EXPECT_LT(error("trilinear"), error("nearest"));
  // Trilinear's level follows the footprint's major axis and blurs along the minor one;
  // anisotropic probes and EWA follow both axes.
  EXPECT_LT(error("anisotropic_16x"), error("trilinear"));
  EXPECT_LT(error("ewa_16x"), error("trilinear"));
  // More taps over the same footprint: a finer estimate of the same box average.
  EXPECT_LT(error("supersample_8x8"), error("supersample_4x4"));
}

// In the magnification view a pixel covers a small part of a texel: the continuous bilinear
// reconstruction, which the ground truth integrates, is far closer than nearest's steps.
TEST(Quality, MagnificationBilinearBeatsNearest) {
  const std::vector<ScoreRow> rows = first_scores();
  for (const char* texture : {"checkerboard", "sinusoids"}) {
    EXPECT_LT(rmse(rows, texture, "magnification", "bilinear"),
              rmse(rows, texture, "magnification", "nearest"))
        << texture;
  }
}

// FilterPrecision::automatic takes fixed16 for a filter only where its PSNR stays within
// 0.05 dB of float32's in every scene (sample.hpp, default_precision()): checked both ways on the
// fixture's scores, for the filters made of bilinear taps at their default settings. Fixed
// point's weights are off by up to 2^-16, which the magnification views, within 1e-4 of ground
// truth, show; the minified ground planes do not.
TEST(Quality, DefaultPrecisionAsTheScoresDecide) {
  const std::vector<ScoreRow> rows = first_scores();
  const std::string isa = first_run_isa(rows);
  int filters = 0;
  for (const FilterMethod& method : filter_methods(MethodSettings{})) {
    const TextureFilter filter = method.options.filter;
    if (!reads_bilinear_taps(filter) || method.options.precision != FilterPrecision::float32 ||
        method.options.supersample_taps != SamplerOptions{}.supersample_taps) {
      continue;
    }
    double largest_loss = -INFINITY;
    for (const char* texture : {"checkerboard", "sinusoids"}) {
      for (const char* view : {"ground_plane", "magnification"}) {
        const double float32 = find_row(rows, texture, view, method.name, isa).psnr;
        const double fixed16 = find_row(rows, texture, view, method.name + "_fixed16", isa).psnr;
        largest_loss = std::max(largest_loss, float32 - fixed16);
      }
    }
    if (default_precision(filter) == FilterPrecision::fixed16) {
      EXPECT_LE(largest_loss, 0.05) << method.name;
    } else {
      EXPECT_GT(largest_loss, 0.05) << method.name;
    }
    ++filters;
  }
  EXPECT_EQ(filters, 6);  // bilinear, mip_nearest, trilinear, supersample, ripmap, anisotropic
}

// OpenImageIO's bilinear lookup in level 0 evaluates the same function of the same texels (same
// texel centres, wrap and 8-bit decoding), so the two errors may differ only by rounding.
// Bound: each side rounds the texel coordinate u = s W - 0.5 in float a few times; in the
// magnification view u stays within a few texels of W / 2 (W = 128), below 128, so each
// rounding is below 2^-17 texel and four of them below 3.1e-5 texel. A bilinear checkerboard
// changes by at most 1 per texel and the sinusoids by less, so one value differs by at most
// 3.1e-5 plus the weights' rounding (a few float ulps of 1, about 1e-6). |rmse_a - rmse_b| is
// at most the RMS of the differences (the triangle inequality), so at most 3.2e-5 < 4e-5.
TEST(Quality, OpenImageIOBilinearAgreesWithEdgewise) {
  const std::vector<ScoreRow> rows = first_scores();
  for (const char* texture : {"checkerboard", "sinusoids"}) {
    const ScoreRow peer = find_row(rows, texture, "magnification", "oiio_bilinear", "oiio");
    EXPECT_NEAR(peer.rmse, rmse(rows, texture, "magnification", "bilinear"), 4e-5) << texture;
  }
}

// The second run scores the scalar reference on the same scenes. Every fast filter is within
// 1/255 of its reference in each channel on 8-bit textures (sample.hpp's contract, checked by
// the sampler's tests); RMSE and the worst error against the same ground truth can then differ
// by at most 1/255 (the triangle inequality, for the RMS and for the maximum).
TEST(Quality, ReferenceScoresWithinTheSamplerBoundOfTheFastPath) {
  const std::vector<ScoreRow> fast = first_scores();
  const std::vector<ScoreRow> reference = second_scores();
  const std::string isa = first_run_isa(fast);
  int compared = 0;
  for (const ScoreRow& row : reference) {
    ASSERT_EQ(row.isa, "reference");
    if (row.method.starts_with("draw_")) continue;  // below
    const ScoreRow other = find_row(fast, row.texture, row.view, row.method, isa);
    EXPECT_NEAR(row.rmse, other.rmse, 1.0 / 255.0)
        << row.texture << "/" << row.view << "/" << row.method;
    EXPECT_NEAR(row.worst, other.worst, 1.0 / 255.0)
        << row.texture << "/" << row.view << "/" << row.method;
    ++compared;
  }
  EXPECT_EQ(compared, kSceneCount * static_cast<int>(filter_methods(MethodSettings{}).size()));
}

// The second run also draws each view (--draw). With analytic derivatives the drawn queries are
// the view's up to float rounding (texture_scene/view_mesh.hpp's test: under 1e-5 of a texture
// period, 1e-3 texel at 128 texels), which moves a filter with linear weights by at most that
// times the texel range (1); the framebuffer then rounds to 8 bits (at most 0.5 / 255). So the
// drawn RMSE lies within 0.5 / 255 + 1e-3 of the sampled one (the triangle inequality), for the
// filters that are continuous in their query and stay within [0, 1] (the framebuffer clamps the
// cubics' overshoot, and nearest's texel choice may flip on a rounding).
TEST(Quality, DrawnViewScoresLikeTheSampledView) {
  const std::vector<ScoreRow> reference = second_scores();
  int compared = 0, continuous_methods = 0;
  for (const FilterMethod& method : filter_methods(MethodSettings{})) {
    const TextureFilter f = method.options.filter;
    const bool continuous = f != TextureFilter::nearest && f != TextureFilter::mip_nearest &&
                            f != TextureFilter::bicubic_catmull_rom;
    continuous_methods += continuous ? 1 : 0;
    for (const char* derivatives : {"quad", "analytic"}) {
      for (const char* texture : {"checkerboard", "sinusoids"}) {
        for (const char* view : {"ground_plane", "magnification"}) {
          const std::string name = "draw_" + std::string(derivatives) + "_" + method.name;
          const ScoreRow drawn = find_row(reference, texture, view, name, "reference");
          const ScoreRow sampled = find_row(reference, texture, view, method.name, "reference");
          if (std::string(derivatives) != "analytic" || !continuous) continue;
          EXPECT_NEAR(drawn.rmse, sampled.rmse, 0.5 / 255.0 + 1e-3)
              << texture << "/" << view << "/" << name;
          ++compared;
        }
      }
    }
  }
  EXPECT_EQ(compared, 4 * continuous_methods);
  EXPECT_GT(continuous_methods, 0);
}

}  // namespace
}  // namespace edgewise::texture_quality::test
