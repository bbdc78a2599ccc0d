// The progress of a run on stderr (drivers/progress.cpp): with stderr sent to a log, whole lines with the
// fraction done and the time left, one per interval; nothing when off.
#include <chrono>
#include <string>

#include <gtest/gtest.h>

#include "drivers/progress.hpp"

using granmc::ProgressLine;

TEST(ProgressLine, WritesWholeLinesToALog) {
  testing::internal::CaptureStderr();
  {
    ProgressLine progress(4, ProgressLine::Mode::log, std::chrono::milliseconds(0));
    for (int k = 0; k < 4; ++k) progress.tick();
  }
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(err.find('\r'), std::string::npos);
  EXPECT_NE(err.find("granmc:  25.0%"), std::string::npos) << err;
  EXPECT_NE(err.find("granmc: 100.0%"), std::string::npos) << err;
  EXPECT_NE(err.find("s left\n"), std::string::npos) << err;
}

TEST(ProgressLine, WritesALineOncePerInterval) {
  testing::internal::CaptureStderr();
  {
    ProgressLine progress(100, ProgressLine::Mode::log);  // one line a minute: none in this test
    for (int k = 0; k < 100; ++k) progress.tick();
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(ProgressLine, WritesNothingWhenOff) {
  testing::internal::CaptureStderr();
  {
    ProgressLine progress(4, ProgressLine::Mode::off, std::chrono::milliseconds(0));
    for (int k = 0; k < 4; ++k) progress.tick();
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}
