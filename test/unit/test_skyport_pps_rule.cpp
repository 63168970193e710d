// The UTC push's 500 ms rule (pps_rule.h, 3.3.10).
#include <gtest/gtest.h>

#include "k40t_driver/skyport/pps_rule.h"

namespace k40t::driver::skyport {
namespace {

TEST(PpsRule, APushWithin500MsOfItsEdgeIsUsed) {
  EXPECT_EQ(judge_utc_push(100.0, 100.02), UtcPushVerdict::kUse);
  EXPECT_EQ(judge_utc_push(100.0, 100.5), UtcPushVerdict::kUse);
  EXPECT_EQ(judge_utc_push(100.0, 99.999), UtcPushVerdict::kUse);  // jitter: before the edge
}

TEST(PpsRule, ALatePushOrNoEdgeIsNot) {
  EXPECT_EQ(judge_utc_push(100.0, 100.501), UtcPushVerdict::kLate);
  EXPECT_EQ(judge_utc_push(100.0, 101.2), UtcPushVerdict::kLate);  // the edge before: stale
  EXPECT_EQ(judge_utc_push(std::nullopt, 100.0), UtcPushVerdict::kNoEdge);
}

}  // namespace
}  // namespace k40t::driver::skyport

namespace k40t::driver::skyport {
namespace {

// Without PPS: pushes once a second, 120 ms after their edge on a local clock 1000 s ahead of UTC.
TEST(UtcPushLateness, APushOver500MsLaterThanThePunctualOnesIsDropped) {
  UtcPushLateness rule;
  const double offset = 1000.0;
  for (int s = 0; s < 5; ++s) {
    EXPECT_EQ(rule.judge(s, s + offset + 0.12).verdict, UtcPushVerdict::kUse) << s;
  }
  // Second 5 arrives 700 ms after its edge: 580 ms later than the others.
  const UtcPushLateness::Judgement late = rule.judge(5, 5 + offset + 0.7);
  EXPECT_EQ(late.verdict, UtcPushVerdict::kLate);
  EXPECT_NEAR(late.excess_delay_s, 0.58, 1e-9);
  // 400 ms after its edge: 280 ms later than the others, used, its stamp 280 ms before receipt.
  const UtcPushLateness::Judgement slow = rule.judge(6, 6 + offset + 0.4);
  EXPECT_EQ(slow.verdict, UtcPushVerdict::kUse);
  EXPECT_NEAR(slow.excess_delay_s, 0.28, 1e-9);
  // The microseconds count: a push of 7.25 s received 120 ms after it is punctual.
  EXPECT_NEAR(rule.judge(7.25, 7.25 + offset + 0.12).excess_delay_s, 0.0, 1e-9);
}

TEST(UtcPushLateness, TheFirstPushIsItsOwnReferenceAndTheWindowForgets) {
  UtcPushLateness rule(10.0);
  EXPECT_EQ(rule.judge(0, 0.9).verdict, UtcPushVerdict::kUse);  // nothing to compare with
  EXPECT_EQ(rule.judge(1, 1.1).verdict, UtcPushVerdict::kUse);  // more punctual: the reference
  EXPECT_EQ(rule.judge(2, 2.7).verdict, UtcPushVerdict::kLate);
  // 11 s later the punctual push of second 1 has left the window: 2.7 - 2 = 0.7 is the least.
  EXPECT_EQ(rule.judge(12, 12.7).verdict, UtcPushVerdict::kUse);
}

TEST(UtcPushLateness, AClockStepStartsAgainAfterThreeLatePushes) {
  UtcPushLateness rule;
  for (int s = 0; s < 3; ++s) rule.judge(s, s + 0.1);
  // UTC corrected one second backwards: every push now looks 1 s late.
  for (int s = 3; s < 6; ++s) {
    EXPECT_EQ(rule.judge(s - 1, s + 0.1).verdict, UtcPushVerdict::kLate) << s;
  }
  EXPECT_EQ(rule.judge(5, 6 + 0.1).verdict, UtcPushVerdict::kUse);
}

}  // namespace
}  // namespace k40t::driver::skyport
