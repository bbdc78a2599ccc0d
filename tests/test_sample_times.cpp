#include <gtest/gtest.h>

#include "kernel/schemes/sample_times.hpp"

using namespace granmc;

TEST(SampleTimes, LinearAndLogEndAtTEnd) {
  RunConfig run;
  run.t_end = 10.0;
  run.dt = 0.01;
  run.samples = 4;
  EXPECT_EQ(sample_times(run), (std::vector<double>{0.0, 2.5, 5.0, 7.5, 10.0}));
  run.sample_spacing = SampleSpacing::log;
  const auto t = sample_times(run);
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t[0], 0.0);
  EXPECT_DOUBLE_EQ(t[1], 0.01);
  EXPECT_DOUBLE_EQ(t[2], 0.1);
  EXPECT_DOUBLE_EQ(t[3], 1.0);
  EXPECT_EQ(t[4], 10.0);
}
