// CommandedValue (commanded_value.h): a getter right after an accepted set reads the set value, not
// the pod's last (1 Hz) report from before it.
#include <gtest/gtest.h>

#include "k40t_driver/skyport/commanded_value.h"

namespace k40t::driver::skyport {
namespace {

using Clock = CommandedValue<bool>::Clock;
using std::chrono::milliseconds;

TEST(CommandedValue, AnsweredUntilTheReportAgrees) {
  CommandedValue<bool> video(milliseconds(3000));
  const Clock::time_point t0 = Clock::now();
  EXPECT_FALSE(video.answer(false, t0));  // nothing set: the report
  video.accepted(true, t0);
  EXPECT_TRUE(video.answer(false, t0 + milliseconds(10)));  // the stale report is not answered
  video.reported(false, t0 + milliseconds(400));            // a report from before the switch
  EXPECT_TRUE(video.answer(false, t0 + milliseconds(500)));
  video.reported(true, t0 + milliseconds(1400));  // the pod confirms: the reports rule again
  EXPECT_FALSE(video.answer(false, t0 + milliseconds(1500)));
}

TEST(CommandedValue, AReportThatKeepsDisagreeingWinsAfterTheHold) {
  CommandedValue<bool> video(milliseconds(3000));
  const Clock::time_point t0 = Clock::now();
  video.accepted(true, t0);
  EXPECT_TRUE(video.answer(false, t0 + milliseconds(2900)));
  EXPECT_FALSE(video.answer(false, t0 + milliseconds(3100)));  // even before the next report
  video.reported(false, t0 + milliseconds(3200));
  EXPECT_FALSE(video.answer(false, t0 + milliseconds(3300)));
}

}  // namespace
}  // namespace k40t::driver::skyport
