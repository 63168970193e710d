// skyport/get_position's ROS-free logic (position_query.h) against the simulated adapter, which
// answers from its flight: nothing asked before a UTC push, the points' instants and event indices,
// the rate limit, and the event indices rolling on from one request to the next.
#include "k40t_driver/skyport/position_query.h"

#include "skyport_bridge_rig.h"

namespace k40t::driver::skyport {
namespace {

using namespace bridge_testing;
using namespace std::chrono_literals;

// The simulated flight starts 2024-07-01 00:00:00 UTC (flight_model.h): 1719792000 s.
constexpr int64_t kFlightStartNs = 1'719'792'000'000'000'000;
constexpr int64_t kS = 1'000'000'000;

TEST(PositionQuery, NothingIsAskedBeforeTheFirstUtcPush) {
  Rig rig;
  PositionQuery query(*rig.payload, 0.2);
  const PositionAnswer answer =
      query.ask(kFlightStartNs + 9 * kS, {0}, PositionQuery::Clock::now());
  EXPECT_FALSE(answer.success);
  EXPECT_NE(answer.message.find("no UTC time push"), std::string::npos) << answer.message;
  EXPECT_TRUE(answer.points.empty());
  EXPECT_EQ(rig.adapter->stats().positions_answered, 0u);
}

TEST(PositionQuery, PointsAtTheirInstantsMatchedByEventIndexThenRateLimited) {
  Rig rig;
  PositionQuery query(*rig.payload, 0.2);
  query.synchronised(kFlightStartNs + 10 * kS);
  // 8.25 s and 8.75 s into the flight: within the 2 s before the newest UTC push.
  const int64_t base_ns = kFlightStartNs + 8 * kS + 250'000'000;
  const auto t0 = PositionQuery::Clock::now();
  const PositionAnswer first = query.ask(base_ns, {0, 500'000}, t0);
  ASSERT_TRUE(first.success) << first.message;
  EXPECT_EQ(first.message, "ok");
  ASSERT_EQ(first.points.size(), 2u);
  EXPECT_EQ(first.times_ns,
            (std::vector<int64_t>{kFlightStartNs + 8'250'000'000, kFlightStartNs + 8'750'000'000}));
  for (size_t i = 0; i < 2; ++i) {
    ASSERT_TRUE(first.points[i]) << i;
    EXPECT_EQ(first.points[i]->event.event_index, i);  // the first request's indices: 0, 1
    EXPECT_EQ(first.points[i]->solution, psdk::PositionSolution::kFixed);
  }

  // 0.1 s later: refused by the 0.2 s rate limit, nothing sent.
  const PositionAnswer too_soon = query.ask(base_ns, {0}, t0 + 100ms);
  EXPECT_FALSE(too_soon.success);
  EXPECT_EQ(too_soon.message.rfind("rate limit", 0), 0u) << too_soon.message;
  EXPECT_EQ(rig.adapter->stats().positions_answered, 1u);

  // 0.25 s later: asked again, the event indices go on from 2.
  const PositionAnswer next = query.ask(base_ns, {100'000}, t0 + 250ms);
  ASSERT_TRUE(next.success) << next.message;
  ASSERT_EQ(next.points.size(), 1u);
  ASSERT_TRUE(next.points[0]);
  EXPECT_EQ(next.points[0]->event.event_index, 2);
  EXPECT_EQ(next.times_ns[0], kFlightStartNs + 8'350'000'000);
  EXPECT_EQ(rig.adapter->stats().positions_answered, 2u);
}

TEST(PositionQuery, BadRequestIsRefusedWithoutSending) {
  Rig rig;
  PositionQuery query(*rig.payload, 0.2);
  query.synchronised(kFlightStartNs + 10 * kS);
  const PositionAnswer none = query.ask(kFlightStartNs + 9 * kS, {}, PositionQuery::Clock::now());
  EXPECT_FALSE(none.success);
  EXPECT_EQ(none.message, "time_offsets_us: 1..4 points, got 0");
  EXPECT_EQ(rig.adapter->stats().positions_answered, 0u);
}

}  // namespace
}  // namespace k40t::driver::skyport
