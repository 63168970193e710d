// skyport/get_position's request and answer (position_request.h, 3.7.1): the base time's fraction
// carried into the offsets, the 2 s window before the newest UTC push, event-index matching,
// solution 0 as no fix.
#include <gtest/gtest.h>

#include "k40t_driver/skyport/position_request.h"

namespace k40t::driver::skyport {
namespace {

using namespace psdk;

constexpr int64_t kS = 1'000'000'000;
constexpr int64_t kJuly1 = 1719792000;  // 2024-07-01 00:00:00 UTC

TEST(PositionRequest, TheBaseTimesFractionMovesIntoTheOffsets) {
  // Base 00:00:10.250, newest sync 00:00:11.000; points at +0 and +500 ms.
  const Result<GetPosition> r =
      plan_position_request((kJuly1 + 10) * kS + 250'000'000, {0, 500000}, (kJuly1 + 11) * kS, 7);
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->base_time.year, 2024);
  EXPECT_EQ(r->base_time.month, 7);
  EXPECT_EQ(r->base_time.day, 1);
  EXPECT_EQ(r->base_time.second, 10);  // whole seconds only on the wire
  EXPECT_EQ(r->count, 2);
  EXPECT_EQ(r->points[0].time_offset_us, 250000u);
  EXPECT_EQ(r->points[1].time_offset_us, 750000u);
  EXPECT_EQ(r->points[0].event.event_index, 7);
  EXPECT_EQ(r->points[1].event.event_index, 8);
  // Stamped back at the instants asked for, not at the whole second.
  EXPECT_EQ(position_time_ns(r.value(), r->points[1].time_offset_us),
            (kJuly1 + 10) * kS + 750'000'000);
}

TEST(PositionRequest, InstantsOutsideTheTwoSecondWindowAreRefused) {
  const int64_t newest = (kJuly1 + 20) * kS;
  EXPECT_FALSE(plan_position_request((kJuly1 + 17) * kS, {0}, newest, 0));          // 3 s before
  EXPECT_FALSE(plan_position_request((kJuly1 + 20) * kS, {1}, newest, 0));          // after it
  EXPECT_TRUE(plan_position_request((kJuly1 + 18) * kS, {0, 2000000}, newest, 0));  // both ends
  EXPECT_FALSE(plan_position_request((kJuly1 + 19) * kS, {0}, std::nullopt, 0));    // no sync yet
}

TEST(PositionRequest, AnOffsetPushedBeyondTwoSecondsByTheFractionIsRefused) {
  const Result<GetPosition> r =
      plan_position_request((kJuly1 + 18) * kS + 1'000, {2000000}, (kJuly1 + 21) * kS, 0);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("2000000"), std::string::npos) << r.error();
}

TEST(PositionRequest, PointCountIsChecked) {
  EXPECT_FALSE(plan_position_request(kJuly1 * kS, {}, kJuly1 * kS, 0));
  EXPECT_FALSE(plan_position_request(kJuly1 * kS, {0, 0, 0, 0, 0}, kJuly1 * kS, 0));
}

TEST(PositionRequest, EventIndicesWrapAtThirteenBits) {
  const Result<GetPosition> r = plan_position_request(kJuly1 * kS, {0, 0}, kJuly1 * kS, 8191);
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->points[0].event.event_index, 8191);
  EXPECT_EQ(r->points[1].event.event_index, 0);
}

TEST(PositionRequest, AnswersAreMatchedByEventIndexNotOrder) {
  const Result<GetPosition> r =
      plan_position_request(kJuly1 * kS, {0, 100000, 200000}, kJuly1 * kS + 500'000'000, 40);
  ASSERT_TRUE(r) << r.error();
  GetPositionAck ack;
  ack.count = 2;  // the adapter answered 42 then 40, and left 41 out
  ack.points[0].event.event_index = 42;
  ack.points[0].latitude_deg = 42.0;
  ack.points[0].solution = PositionSolution::kFixed;
  ack.points[1].event.event_index = 40;
  ack.points[1].latitude_deg = 40.0;
  ack.points[1].solution = PositionSolution::kNotAvailable;
  const auto m = match_positions(r.value(), ack);
  ASSERT_EQ(m.size(), 3u);
  ASSERT_TRUE(m[0]);
  EXPECT_EQ(m[0]->latitude_deg, 40.0);
  EXPECT_FALSE(m[1]);
  ASSERT_TRUE(m[2]);
  EXPECT_EQ(m[2]->latitude_deg, 42.0);
  EXPECT_FALSE(is_fix(m[0]->solution));  // solution 0: not available, no fix
  EXPECT_TRUE(is_fix(m[2]->solution));
}

}  // namespace
}  // namespace k40t::driver::skyport
