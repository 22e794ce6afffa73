// calibration/sample_mean.hpp against values worked by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "calibration/sample_mean.hpp"

namespace rbcal::calibration {
namespace {

TEST(SampleMean, MeanSdAndStandardErrorOfFourValues) {
  // 2, 4, 4, 6: mean 4, squares 4 + 0 + 0 + 4 = 8, sd sqrt(8 / 3), se sd / 2.
  const SampleMean s = sample_mean({2.0, 4.0, 4.0, 6.0});
  EXPECT_EQ(s.count, 4);
  EXPECT_DOUBLE_EQ(s.mean, 4.0);
  EXPECT_DOUBLE_EQ(s.sd, std::sqrt(8.0 / 3.0));
  EXPECT_DOUBLE_EQ(s.standard_error, std::sqrt(8.0 / 3.0) / 2.0);
}

TEST(SampleMean, OneValueHasNoSpreadAndNoneHasNoMean) {
  const SampleMean one = sample_mean({3.5});
  EXPECT_EQ(one.count, 1);
  EXPECT_DOUBLE_EQ(one.mean, 3.5);
  EXPECT_EQ(one.sd, 0.0);
  EXPECT_EQ(one.standard_error, 0.0);
  const SampleMean none = sample_mean({});
  EXPECT_EQ(none.count, 0);
  EXPECT_EQ(none.mean, 0.0);
}

}  // namespace
}  // namespace rbcal::calibration
