// The Pareto front: a method is on it unless another is at least as fast and as accurate, and
// strictly better in one of the two.
#include "texture_quality/pareto_front.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace edgewise::texture_quality {
namespace {

std::vector<bool> front_of(std::vector<CostAndError> points) {
  return pareto_front(points);
}

TEST(ParetoFront, EmptyAndSingle) {
  EXPECT_TRUE(front_of({}).empty());
  EXPECT_EQ(front_of({{5.0, 0.1}}), std::vector<bool>{true});
}

TEST(ParetoFront, Staircase) {
  // Faster and worse, slower and better: all on the front, except the points each beaten by
  // one of them on both axes.
  const std::vector<CostAndError> points = {
      {1.0, 0.5},   // fastest
      {2.0, 0.3},   // on the front
      {3.0, 0.4},   // beaten by (2, 0.3)
      {10.0, 0.1},  // most accurate
      {12.0, 0.1},  // as accurate as (10, 0.1) but slower
      {2.0, 0.6},   // beaten by (1, 0.5)
  };
  EXPECT_EQ(pareto_front(points), (std::vector<bool>{true, true, false, true, false, false}));
}

TEST(ParetoFront, TiesOnOneAxisAreBrokenByTheOther) {
  EXPECT_EQ(front_of({{1.0, 0.2}, {1.0, 0.1}}), (std::vector<bool>{false, true}));
  EXPECT_EQ(front_of({{2.0, 0.1}, {1.0, 0.1}}), (std::vector<bool>{false, true}));
}

TEST(ParetoFront, EqualPointsAreAllOnTheFront) {
  EXPECT_EQ(front_of({{1.0, 0.1}, {1.0, 0.1}, {3.0, 0.3}}), (std::vector<bool>{true, true, false}));
}

TEST(ParetoFront, ErrorsWithinTheAllowanceAreEqual) {
  // The same filter on a fast ISA and on the slow reference: rounding puts the reference's
  // error a little lower, which does not earn it a place on the front.
  const double error = 0.0149;
  const double rounding = error * kEqualErrorFraction * 0.5;
  EXPECT_EQ(front_of({{240.0, error}, {1950.0, error - rounding}}),
            (std::vector<bool>{true, false}));
  // A slower method clearly more accurate stays on it.
  const double better = error * (1.0 - 2.0 * kEqualErrorFraction);
  EXPECT_EQ(front_of({{240.0, error}, {1950.0, better}}), (std::vector<bool>{true, true}));
  // At the same cost, errors within the allowance are a tie: both stay.
  EXPECT_EQ(front_of({{240.0, error}, {240.0, error - rounding}}), (std::vector<bool>{true, true}));
}

TEST(ParetoFront, NanIsNeverOnTheFrontAndBeatsNothing) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(front_of({{nan, 0.0}, {1.0, nan}, {5.0, 0.5}}),
            (std::vector<bool>{false, false, true}));
}

TEST(ParetoFront, InfiniteErrorLosesToAnyFiniteOneAtTheSameCost) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(front_of({{1.0, inf}, {1.0, 0.9}}), (std::vector<bool>{false, true}));
  // Alone at its cost, it is the fastest: on the front.
  EXPECT_EQ(front_of({{0.5, inf}, {1.0, 0.9}}), (std::vector<bool>{true, true}));
}

}  // namespace
}  // namespace edgewise::texture_quality
