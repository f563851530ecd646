#include "common/median.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace edgewise::tools {
namespace {

double median_of(std::vector<double> values) {
  return median(values);
}

TEST(Median, OddEvenAndSingle) {
  EXPECT_EQ(median_of({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(median_of({4.0, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_EQ(median_of({7.0}), 7.0);
  // An outlier (a run slowed by another job) does not move it.
  EXPECT_EQ(median_of({1.0, 1.0, 1000.0}), 1.0);
}

TEST(Median, NoValuesThrows) {
  EXPECT_THROW(median_of({}), std::invalid_argument);
}

TEST(MedianSeconds, RunsTheWorkOncePerRepetitionAndAtLeastOnce) {
  int runs = 0;
  const double seconds = median_seconds(5, [&runs] { ++runs; });
  EXPECT_EQ(runs, 5);
  EXPECT_GE(seconds, 0.0);
  runs = 0;
  median_seconds(0, [&runs] { ++runs; });
  EXPECT_EQ(runs, 1);
}

}  // namespace
}  // namespace edgewise::tools
