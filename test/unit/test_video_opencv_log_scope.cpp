// OpenCvLogScope (video/opencv_log_scope.h): quiet while any scope lives, the process's own level
// back after the last one, whatever order overlapping scopes end in.
#include <gtest/gtest.h>

#include <memory>

#include "k40t_driver/video/opencv_log_scope.h"

namespace k40t::video {
namespace {

using cv::utils::logging::getLogLevel;
using cv::utils::logging::LOG_LEVEL_ERROR;
using cv::utils::logging::LOG_LEVEL_INFO;
using cv::utils::logging::setLogLevel;

TEST(OpenCvLogScope, QuietInsideTheLevelBackAfter) {
  const auto before = setLogLevel(LOG_LEVEL_INFO);
  {
    OpenCvLogScope scope;
    EXPECT_EQ(getLogLevel(), LOG_LEVEL_ERROR);
  }
  EXPECT_EQ(getLogLevel(), LOG_LEVEL_INFO);
  setLogLevel(before);
}

TEST(OpenCvLogScope, OverlappingScopesEndingOutOfOrderRestoreTheProcessLevel) {
  const auto before = setLogLevel(LOG_LEVEL_INFO);
  auto first = std::make_unique<OpenCvLogScope>();
  auto second = std::make_unique<OpenCvLogScope>();
  first.reset();  // the first grabber's call ends while the second's still runs
  EXPECT_EQ(getLogLevel(), LOG_LEVEL_ERROR);
  second.reset();
  EXPECT_EQ(getLogLevel(), LOG_LEVEL_INFO);
  setLogLevel(before);
}

}  // namespace
}  // namespace k40t::video
