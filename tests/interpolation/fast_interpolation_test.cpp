// The float32 interpolators of every ISA against the double references, pixel by pixel, within
// the bounds derived in error_bounds.cpp. Rows are evaluated from a tile corner (as the shading
// kernels do) and from the bounding box's first tile to a tile far across it (the largest
// offsets the plane equations meet).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "error_bounds.hpp"
#include "fast_interpolation.hpp"
#include "interpolation_triangles.hpp"
#include "isa_params.hpp"
#include "interpolation/interpolation_reference.hpp"

namespace edgewise::test {
namespace {

constexpr int kFastTrianglesPerSource = 150;
constexpr int kTile = 8;

class FastInterpolationTest : public IsaTest {
 protected:
  void SetUp() override {
    IsaTest::SetUp();
    if (IsSkipped()) return;
    fast_ = fast_interpolation(isa());
    ASSERT_NE(fast_, nullptr);
    ASSERT_EQ(fast_->isa, isa());
  }
  const FastInterpolation* fast_ = nullptr;
};

struct Checked {
  long pixels = 0;
  double worst_inside[6] = {};          // screen-space error at pixels inside the triangle
  std::vector<double> relative_bounds;  // barycentric methods: bound / (|b| + 1)
};

std::string where(const ScreenTriangle& t, InterpolationMethod method, double px, double py,
                  int vertex) {
  char text[400];
  std::snprintf(text, sizeof text,
                "%s b%d at (%.17g, %.17g), triangle (%.17g, %.17g) (%.17g, %.17g) "
                "(%.17g, %.17g) w %.17g %.17g %.17g",
                std::string(name_of(method)).c_str(), vertex, px, py, t.x[0], t.y[0], t.x[1],
                t.y[1], t.x[2], t.y[2], t.w[0], t.w[1], t.w[2]);
  return text;
}

bool one_hot(const float* weights, std::size_t lanes, std::size_t lane, int vertex) {
  for (int i = 0; i < 3; ++i) {
    if (weights[i * lanes + lane] != (i == vertex ? 1.0f : 0.0f)) return false;
  }
  return true;
}

// Checks one row of `lanes` pixels of every method, screen space and perspective-correct.
void check_row(const FastInterpolation& fast, const ScreenTriangle& t, double origin_x,
               double origin_y, std::int32_t column, std::int32_t row, Checked& checked) {
  const std::size_t lanes = fast.lanes;
  std::vector<float> screen(3 * lanes), correct(3 * lanes);
  std::vector<ExactWeights> exact(lanes);
  for (std::size_t lane = 0; lane < lanes; ++lane) {
    exact[lane] = exact_weights_with_error(t, origin_x + column + static_cast<double>(lane) + 0.5,
                                           origin_y + row + 0.5);
  }
  for (InterpolationMethod method : kInterpolationMethods) {
    fast.screen_row(method, t, origin_x, origin_y, column, row, screen.data());
    fast.perspective_row(method, t, origin_x, origin_y, column, row, correct.data());
    for (std::size_t lane = 0; lane < lanes; ++lane) {
      const double px = origin_x + column + static_cast<double>(lane) + 0.5;
      const double py = origin_y + row + 0.5;
      ++checked.pixels;
      if (method == InterpolationMethod::nearest_vertex) {
        // One-hot on the reference's vertex, or on one whose squared distance is tied with it
        // within the rounding bounds.
        const reference::Weights ref = reference::screen_weights(method, t, px, py);
        const int chosen = static_cast<int>(std::max_element(ref.b, ref.b + 3) - ref.b);
        Bounded squared[3];
        squared_distance_bounds(Evaluator::float32, t, origin_x, origin_y, px, py, squared);
        bool matched = false;
        for (int i = 0; i < 3 && !matched; ++i) {
          const bool tied = std::abs(squared[i].value - squared[chosen].value) <=
                            squared[i].error + squared[chosen].error;
          matched = (i == chosen || tied) && one_hot(screen.data(), lanes, lane, i);
        }
        ASSERT_TRUE(matched) << where(t, method, px, py, chosen);
        continue;
      }
      BoundedWeights bound =
          screen_weight_bounds(method, Evaluator::float32, t, origin_x, origin_y, px, py);
      const ExactWeights& e = exact[lane];
      const bool by_distance = method == InterpolationMethod::inverse_distance;
      const reference::Weights truth =
          by_distance ? reference::screen_weights(method, t, px, py) : e.screen;
      const bool inside = std::min({e.screen.b[0], e.screen.b[1], e.screen.b[2]}) >= 0.0;
      for (int i = 0; i < 3; ++i) {
        const double truth_error =
            by_distance ? reference_inverse_distance_error(truth.b[i]) : e.screen_error[i];
        const double error = std::abs(screen[i * lanes + lane] - truth.b[i]);
        ASSERT_LE(error, bound.b[i].error + truth_error) << where(t, method, px, py, i);
        if (inside) {
          auto& worst = checked.worst_inside[static_cast<int>(method)];
          worst = std::max(worst, error);
        }
        if (method != InterpolationMethod::inverse_distance) {
          checked.relative_bounds.push_back(bound.b[i].error / (std::abs(truth.b[i]) + 1.0));
        }
      }
      // Perspective: the exact perspective-correct weights (inverse distance: the reference's
      // perspective step on its own weights, with that step's bound).
      const BoundedWeights perspective_bound = perspective_bounds(Evaluator::float32, bound, t);
      reference::Weights perspective_truth;
      double perspective_truth_error[3];
      if (by_distance) {
        double w[3];
        reference::usable_clip_w(t, w);
        perspective_truth = reference::perspective_correct(truth, w);
        BoundedWeights truth_bound;
        for (int i = 0; i < 3; ++i)
          truth_bound.b[i] = {truth.b[i], reference_inverse_distance_error(truth.b[i])};
        const BoundedWeights step = perspective_bounds(Evaluator::reference, truth_bound, t);
        for (int i = 0; i < 3; ++i)
          perspective_truth_error[i] = step.b[i].error;
      } else {
        perspective_truth = e.correct;
        for (int i = 0; i < 3; ++i)
          perspective_truth_error[i] = e.correct_error[i];
      }
      for (int i = 0; i < 3; ++i) {
        ASSERT_LE(std::abs(correct[i * lanes + lane] - perspective_truth.b[i]),
                  perspective_bound.b[i].error + perspective_truth_error[i])
            << "perspective " << where(t, method, px, py, i);
      }
    }
  }
}

TEST_P(FastInterpolationTest, WithinDerivedBoundOfReference) {
  Random random(0xfa57 + static_cast<int>(isa()));
  std::vector<double> relative_bounds;
  for (const InterpolationTriangleSource& source : interpolation_triangle_sources()) {
    Checked checked;
    for (int n = 0; n < kFastTrianglesPerSource; ++n) {
      ScreenTriangle t = source.make(random);
      assign_depths(random, random.log_uniform(1.0, 1000.0), t);
      double px, py;
      random_pixel_center(random, t, px, py);
      // The tile holding the sample, evaluated from its own corner.
      const double tile_x = std::floor(px / kTile) * kTile, tile_y = std::floor(py / kTile) * kTile;
      for (std::int32_t row = 0; row < kTile; ++row) {
        for (std::int32_t column = 0; column < kTile;
             column += static_cast<std::int32_t>(fast_->lanes))
          check_row(*fast_, t, tile_x, tile_y, column, row, checked);
      }
      // The same sample's row evaluated from the bounding box's first tile.
      const double box_x = std::floor(std::min({t.x[0], t.x[1], t.x[2]}) / kTile) * kTile;
      const double box_y = std::floor(std::min({t.y[0], t.y[1], t.y[2]}) / kTile) * kTile;
      check_row(*fast_, t, box_x, box_y, static_cast<std::int32_t>(tile_x - box_x),
                static_cast<std::int32_t>(py - 0.5 - box_y), checked);
      if (HasFatalFailure()) return;
    }
    std::printf("%-6s %-11s %ld pixels; worst screen-space error inside:",
                std::string(name_of(isa())).c_str(), std::string(source.name).c_str(),
                checked.pixels);
    for (InterpolationMethod method : kInterpolationMethods) {
      if (method == InterpolationMethod::nearest_vertex) continue;
      std::printf(" %s %.2g", std::string(name_of(method)).c_str(),
                  checked.worst_inside[static_cast<int>(method)]);
    }
    std::printf("\n");
    relative_bounds.insert(relative_bounds.end(), checked.relative_bounds.begin(),
                           checked.relative_bounds.end());
  }
  // The bounds are informative: for nine pixels in ten, below 2^-16 (2^8 ulps of 1 in float32).
  std::sort(relative_bounds.begin(), relative_bounds.end());
  const double p90 = relative_bounds[relative_bounds.size() * 9 / 10];
  std::printf("90th percentile of bound / (|b| + 1): %.3g\n", p90);
  EXPECT_LT(p90, 0x1.0p-16);
}

EDGEWISE_INSTANTIATE_PER_ISA(FastInterpolationTest, fast_isas());

}  // namespace
}  // namespace edgewise::test
