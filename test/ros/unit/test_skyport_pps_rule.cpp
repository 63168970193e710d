// The UTC push's 500 ms rule (pps_rule.h, 3.3.10).
#include <gtest/gtest.h>

#include "k40t_driver/ros/skyport/pps_rule.h"

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
