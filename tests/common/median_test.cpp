// The median of every timing table (common/median): the middle value, the mean of the two
// middle ones, 0 for nothing, whatever the order and however extreme the outliers.
#include <gtest/gtest.h>
#include <median/median.h>

#include <limits>
#include <vector>

namespace {

TEST(Median, OddCountIsTheMiddleValueInAnyOrder) {
  EXPECT_EQ(median::of({3.0}), 3.0);
  EXPECT_EQ(median::of({9.0, 1.0, 5.0}), 5.0);
  EXPECT_EQ(median::of({1.0, 5.0, 9.0}), 5.0);
  EXPECT_EQ(median::of({5.0, 5.0, 1.0, 100.0, 5.0}), 5.0);
}

TEST(Median, EvenCountIsTheMeanOfTheTwoMiddleValues) {
  EXPECT_EQ(median::of({2.0, 4.0}), 3.0);
  EXPECT_EQ(median::of({10.0, 1.0, 4.0, 2.0}), 3.0);
  EXPECT_EQ(median::of({7.0, 7.0, 7.0, 7.0}), 7.0);
}

TEST(Median, AnOutlierDoesNotMoveIt) {
  const double huge = std::numeric_limits<double>::max();
  EXPECT_EQ(median::of({1.0, 2.0, huge}), 2.0);
  EXPECT_EQ(median::of({-huge, 2.0, 3.0}), 2.0);
}

TEST(Median, NoValuesGiveZero) { EXPECT_EQ(median::of({}), 0.0); }

}  // namespace
