// geo/state_history.h: time-matched vehicle state for the pod's geotags (0x000310).
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "k40t_driver/geo/geodesy.h"
#include "k40t_driver/geo/state_history.h"

namespace k40t::geo {
namespace {

constexpr int64_t kSecond = 1000000000;

TEST(StateHistory, InterpolatesBetweenSamplesAndFlagsTimesOutside) {
  StateHistory history;
  EXPECT_FALSE(history.position_at(0));
  history.add_position(10 * kSecond, {47.0, 8.0, 500});
  history.add_position(11 * kSecond, {47.001, 8.002, 510});
  const auto mid = history.position_at(10 * kSecond + kSecond / 4);
  ASSERT_TRUE(mid);
  EXPECT_TRUE(mid->in_history);
  EXPECT_NEAR(mid->value.latitude_deg, 47.00025, 1e-12);
  EXPECT_NEAR(mid->value.longitude_deg, 8.0005, 1e-12);
  EXPECT_NEAR(mid->value.height_ellipsoid_m, 502.5, 1e-9);
  EXPECT_NEAR(mid->gap_s, 0.25, 1e-9);
  const auto late = history.position_at(12 * kSecond);
  ASSERT_TRUE(late);
  EXPECT_FALSE(late->in_history);  // the nearest (last) sample, flagged
  EXPECT_DOUBLE_EQ(late->value.latitude_deg, 47.001);
  EXPECT_NEAR(late->gap_s, 1.0, 1e-9);
  const auto early = history.position_at(9 * kSecond);
  ASSERT_TRUE(early);
  EXPECT_FALSE(early->in_history);
  EXPECT_DOUBLE_EQ(early->value.latitude_deg, 47.0);
  EXPECT_TRUE(history.position_at(11 * kSecond)->in_history);  // exactly on the last sample
}

TEST(StateHistory, HeadingTakesTheShortWayRound) {
  StateHistory history;
  history.add_attitude(0, {350, 10, -20});
  history.add_attitude(kSecond, {10, -10, 20});
  const auto a = history.attitude_at(kSecond / 4);
  ASSERT_TRUE(a);
  EXPECT_NEAR(a->value.heading_deg, 355, 1e-9);
  EXPECT_NEAR(history.attitude_at(kSecond * 3 / 4)->value.heading_deg, 5, 1e-9);
  EXPECT_NEAR(a->value.pitch_deg, 5, 1e-9);
  EXPECT_NEAR(a->value.roll_deg, -10, 1e-9);
}

TEST(StateHistory, DropsWhatIsOlderThanTheSpanAndKeepsOrder) {
  StateHistory history(HistoryLimits{2.0, 1000});
  for (int i = 0; i <= 50; ++i) history.add_position(i * kSecond / 10, {0, i * 1e-5, 0});
  // Only the last 2 s remain: 3.0 .. 5.0 s.
  EXPECT_FALSE(history.position_at(2 * kSecond)->in_history);
  EXPECT_NEAR(history.position_at(2 * kSecond)->value.longitude_deg, 30e-5, 1e-12);
  history.add_position(4 * kSecond + kSecond / 20, {0, 99, 0});  // late, inserted in place
  EXPECT_NEAR(history.position_at(4 * kSecond + kSecond / 20)->value.longitude_deg, 99, 1e-12);
  history.add_position(kSecond, {0, -1, 0});  // older than the span: ignored
  EXPECT_NEAR(history.position_at(kSecond)->value.longitude_deg, 30e-5, 1e-12);
  StateHistory small(HistoryLimits{100.0, 5});
  for (int i = 0; i < 10; ++i) small.add_position(i * kSecond, {0, static_cast<double>(i), 0});
  EXPECT_FALSE(small.position_at(4 * kSecond)->in_history);  // 5 samples: 5 .. 9 s
  EXPECT_TRUE(small.position_at(5 * kSecond)->in_history);
}

TEST(StateHistory, VelocityFromTheInputOrFromThePositions) {
  const LocalFrame frame = LocalFrame::at({47.0, 8.0, 500}).value();
  StateHistory history;
  EXPECT_FALSE(history.velocity_at(0));
  for (int i = 0; i < 5; ++i) {
    const Geodetic p = frame.to_geodetic({3.0 * i, 4.0 * i, -1.0 * i});  // (3, 4, -1) m/s
    history.add_position(i * kSecond, {p.latitude_deg, p.longitude_deg, p.height_ellipsoid_m});
  }
  const auto derived = history.velocity_at(kSecond * 5 / 2);
  ASSERT_TRUE(derived);
  EXPECT_FALSE(history.has_velocity_input());
  // In the ENU frame of the sample before (10 m from the origin: axes turned by ~1e-6 rad).
  EXPECT_NEAR(derived->value.east, 3, 1e-4);
  EXPECT_NEAR(derived->value.north, 4, 1e-4);
  EXPECT_NEAR(derived->value.up, -1, 1e-4);
  history.add_velocity(0, {1, 2, 3});
  history.add_velocity(kSecond, {3, 2, 1});
  const auto given = history.velocity_at(kSecond / 2);
  ASSERT_TRUE(given);
  EXPECT_NEAR(given->value.east, 2, 1e-12);
  EXPECT_NEAR(given->value.up, 2, 1e-12);
}

TEST(StateHistory, TimeOfDayBelongsToTheNearestDay) {
  const int64_t day = 86400000;
  const int64_t now = 20000 * day + 12 * 3600000;  // noon
  EXPECT_EQ(unix_ms_of_time_of_day(12 * 3600000 - 200, now), now - 200);
  // Just after midnight, asked about a photo just before it: yesterday.
  const int64_t after_midnight = 20001 * day + 100;
  EXPECT_EQ(unix_ms_of_time_of_day(day - 300, after_midnight), 20001 * day - 300);
  // Just before midnight, a time of day just after it (a pod clock slightly ahead): tomorrow.
  EXPECT_EQ(unix_ms_of_time_of_day(50, 20001 * day - 100), 20001 * day + 50);
}

// The geotag the pod gets for a photo taken at T, answered 200 ms later, on a vehicle flying a
// 50 m circle at 15 m/s with 10 Hz fixes: today's answer (the latest fix) against the fix
// history interpolated at T. Errors are horizontal+vertical distances to the truth at T.
TEST(StateHistory, GeotagErrorAt15MetresPerSecond) {
  const LocalFrame frame = LocalFrame::at({47.0, 8.0, 500}).value();
  const double speed = 15, radius = 50, lag_s = 0.2;
  auto truth = [&](double t) {
    const double a = speed / radius * t;
    return frame.to_geodetic({radius * std::sin(a), radius * (1 - std::cos(a)), 30});
  };
  auto error_m = [&](const PositionSample& p, double t) {
    const Enu d = LocalFrame::at(truth(t)).value().to_enu(
        {p.latitude_deg, p.longitude_deg, p.height_ellipsoid_m});
    return std::sqrt(d.east * d.east + d.north * d.north + d.up * d.up);
  };
  StateHistory history;
  double worst_before = 0, worst_after = 0;
  int fixes = 0;
  for (double photo = 1.013; photo < 20; photo += 0.731) {
    const double answer = photo + lag_s;
    // The fixes received by the time of the answer (10 Hz, stamped at their own time).
    PositionSample latest;
    for (; fixes * 0.1 <= answer; ++fixes) {
      const Geodetic g = truth(fixes * 0.1);
      latest = {g.latitude_deg, g.longitude_deg, g.height_ellipsoid_m};
      history.add_position(static_cast<int64_t>(std::llround(fixes * 0.1 * kSecond)), latest);
    }
    const auto matched = history.position_at(static_cast<int64_t>(std::llround(photo * kSecond)));
    ASSERT_TRUE(matched);
    EXPECT_TRUE(matched->in_history);
    worst_before = std::max(worst_before, error_m(latest, photo));
    worst_after = std::max(worst_after, error_m(matched->value, photo));
  }
  std::printf(
      "geotag error at 15 m/s, 200 ms lag, 10 Hz fixes: latest fix %.3f m, "
      "time-matched %.3f m\n",
      worst_before, worst_after);
  EXPECT_GT(worst_before, 2.9);  // 15 m/s x (200 ms .. 300 ms) of staleness minus one fix period
  EXPECT_LE(worst_after, 0.5);
}

}  // namespace
}  // namespace k40t::geo
