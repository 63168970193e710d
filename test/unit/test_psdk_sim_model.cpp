// The simulated adapter's building blocks: the flight (consistent position, velocity, attitude,
// battery, time), the pushes built from it, and the byte-level faults.
#include <gtest/gtest.h>

#include <cmath>

#include "geo_test_support.h"
#include "k40t_driver/psdk/parser.h"
#include "k40t_driver/psdk/sim/faulty_transport.h"
#include "k40t_driver/psdk/sim/flight_model.h"
#include "k40t_driver/psdk/sim/pushes.h"
#include "psdk_fake_transport.h"
#include "psdk_test_support.h"

namespace k40t::psdk::sim {
namespace {

// Expected dates from Python: datetime.datetime.utcfromtimestamp(t).
TEST(PsdkSimTime, UtcFromUnixMicroseconds) {
  struct Case {
    int64_t unix_s;
    DateTime expected;
  };
  const Case cases[] = {{0, {1970, 1, 1, 0, 0, 0}},
                        {951782400, {2000, 2, 29, 0, 0, 0}},
                        {1709251199, {2024, 2, 29, 23, 59, 59}},
                        {1719792000, {2024, 7, 1, 0, 0, 0}},
                        {4102444800, {2100, 1, 1, 0, 0, 0}}};
  for (const Case& c : cases) {
    const UtcTime t = utc_from_unix_us(c.unix_s * 1000000 + 123456);
    EXPECT_EQ(t.date_time.year, c.expected.year) << c.unix_s;
    EXPECT_EQ(t.date_time.month, c.expected.month) << c.unix_s;
    EXPECT_EQ(t.date_time.day, c.expected.day) << c.unix_s;
    EXPECT_EQ(t.date_time.hour, c.expected.hour) << c.unix_s;
    EXPECT_EQ(t.date_time.minute, c.expected.minute) << c.unix_s;
    EXPECT_EQ(t.date_time.second, c.expected.second) << c.unix_s;
    EXPECT_EQ(t.microsecond, 123456u);
  }
}

TEST(PsdkSimFlight, StartsAtHomeClimbsThenCircles) {
  FlightModel model;
  const FlightModelOptions& o = model.options();
  const AirframeState start = model.state_at(0);
  EXPECT_DOUBLE_EQ(start.latitude_deg, o.home_latitude_deg);
  EXPECT_DOUBLE_EQ(start.longitude_deg, o.home_longitude_deg);
  EXPECT_EQ(start.landing, LandingState::kLanded);
  const AirframeState climbing = model.state_at(o.climb_s / 2);
  EXPECT_NEAR(climbing.relative_height_m, o.altitude_m / 2, 1e-9);
  EXPECT_LT(climbing.velocity_down_m_s, 0);  // up is negative down
  EXPECT_EQ(climbing.landing, LandingState::kInTheSky);
  // Half a circle later the airframe is one diameter east of home.
  const double half_circle_s = M_PI * o.circle_radius_m / o.speed_m_s;
  const AirframeState opposite = model.state_at(o.climb_s + half_circle_s);
  const double east_m =
      test::metres_east(o.home_latitude_deg, o.home_longitude_deg, opposite.longitude_deg,
                        o.home_altitude_msl_m + o.altitude_m);
  EXPECT_NEAR(east_m, 2 * o.circle_radius_m, 1e-3);
  EXPECT_NEAR(opposite.relative_height_m, o.altitude_m, 1e-9);
}

TEST(PsdkSimFlight, VelocityIsTheDerivativeOfPositionAndYawFollowsTheTrack) {
  FlightModel model;
  for (double t : {12.0, 20.0, 33.3, 61.0}) {
    const double dt = 1e-3;
    const AirframeState a = model.state_at(t);
    const AirframeState b = model.state_at(t + dt);
    const double north_rate =
        test::metres_north(a.latitude_deg, b.latitude_deg, a.altitude_msl_m) / dt;
    EXPECT_NEAR(north_rate, a.velocity_north_m_s, 0.01) << t;
    EXPECT_NEAR(std::atan2(a.velocity_east_m_s, a.velocity_north_m_s), a.yaw_rad, 1e-9) << t;
    EXPECT_NEAR(std::hypot(a.velocity_north_m_s, a.velocity_east_m_s), model.options().speed_m_s,
                1e-9);
  }
}

TEST(PsdkSimFlight, BatteryDrainsAndAnnouncesPowerOff) {
  FlightModelOptions o;
  o.battery_start_percent = 50;
  o.battery_drain_percent_per_min = 6;
  o.power_off_after_s = 100;
  FlightModel model(o);
  EXPECT_DOUBLE_EQ(model.state_at(60).battery_percent, 44);
  EXPECT_FALSE(model.state_at(99.9).power_off_soon);
  EXPECT_TRUE(model.state_at(100).power_off_soon);
  EXPECT_DOUBLE_EQ(model.state_at(1e6).battery_percent, 0);
}

TEST(PsdkSimPushes, AgreeWithTheState) {
  FlightModel model;
  const AirframeState s = model.state_at(25.0);
  const AttitudePush att = attitude_push(s);
  EXPECT_NEAR(att.q0 * att.q0 + att.q1 * att.q1 + att.q2 * att.q2 + att.q3 * att.q3, 1.0, 1e-6);
  // Yaw back out of the quaternion (ZYX).
  const double yaw = std::atan2(2.0 * (att.q0 * att.q3 + att.q1 * att.q2),
                                1.0 - 2.0 * (att.q2 * att.q2 + att.q3 * att.q3));
  EXPECT_NEAR(yaw, s.yaw_rad, 1e-5);

  const GpsPush gps = gps_push(s, 14);
  EXPECT_NEAR(gps.latitude_rad, s.latitude_deg * M_PI / 180.0, 1e-12);
  EXPECT_NEAR(gps.relative_height_m, s.relative_height_m, 0.05);
  EXPECT_EQ(gps.signal, GpsSignal::kVeryStrong);
  EXPECT_TRUE(encode_data(gps));

  const RawGpsPush raw = raw_gps_push(s, 7);
  EXPECT_EQ(raw.date_yyyymmdd, 20240701u);
  EXPECT_EQ(raw.time_hhmmss, 25u);  // 00:00:25
  EXPECT_NEAR(raw.velocity_north_cm_s, s.velocity_north_m_s * 100, 1e-3);
  EXPECT_TRUE(encode_data(raw));

  const UtcTimePush utc = utc_time_push(model.state_at(25.75));
  EXPECT_EQ(utc.time.second, 25);
  EXPECT_EQ(utc.microsecond, 0u);  // the PPS edge is on the whole second

  EXPECT_TRUE(encode_data(raw_rtk_push(s)));
  EXPECT_TRUE(encode_data(battery_push(s)));
  EXPECT_TRUE(encode_data(uav_state_push(s, DroneType::kM210RtkV2)));
  EXPECT_TRUE(encode_data(link_bandwidth_push(s)));
  EXPECT_TRUE(encode_data(app_date_time_push(s)));
  EXPECT_TRUE(encode_data(barometric_altitude_push(s)));
}

std::unique_ptr<FaultyTransport> faulty_over(testing::FakeLink*& raw, ByteFaults faults) {
  auto link = std::make_unique<testing::FakeLink>();
  raw = link.get();
  return std::make_unique<FaultyTransport>(std::move(link), faults);
}

// `count` GetVersion frames sent through a FaultyTransport with `faults`, and what a parser makes
// of the bytes that reached the link.
struct FaultyRun {
  FaultyRun(ByteFaults faults, int count) : faulty(faulty_over(link, faults)) {
    EXPECT_TRUE(faulty->open());
    for (int i = 0; i < count; ++i)
      EXPECT_TRUE(faulty->send(testing::kGetVersion.data(), testing::kGetVersion.size()));
    for (const auto& write : link->sent())
      parser.feed(write.data(), write.size(), [&](const FrameView&) { ++good; });
    faulty->close();
  }
  testing::FakeLink* link = nullptr;
  std::unique_ptr<FaultyTransport> faulty;
  FrameParser parser;
  size_t good = 0;
};

TEST(PsdkSimFaults, CorruptionShowsUpAsCrcErrors) {
  ByteFaults faults;
  faults.corrupt_rate = 0.05;
  const FaultyRun run(faults, 200);
  const ParserStats& p = run.parser.stats();
  EXPECT_GT(run.faulty->fault_stats().bytes_corrupted, 0u);
  EXPECT_LT(run.good, 200u);
  EXPECT_GT(p.header_crc_errors + p.frame_crc_errors + p.length_errors + p.version_errors, 0u);
}

TEST(PsdkSimFaults, GarbageBetweenFramesLosesNoFrame) {
  ByteFaults faults;
  faults.garbage_rate = 1.0;
  const FaultyRun run(faults, 100);
  EXPECT_EQ(run.good, 100u);
  EXPECT_EQ(run.faulty->fault_stats().garbage_bursts, 100u);
  EXPECT_EQ(run.parser.stats().bytes_discarded, run.faulty->fault_stats().garbage_bytes);
}

TEST(PsdkSimFaults, SilenceWritesNothing) {
  testing::FakeLink* link = nullptr;
  auto faulty = faulty_over(link, {});
  ASSERT_TRUE(faulty->open());
  faulty->silence_for(std::chrono::hours(1));
  EXPECT_TRUE(faulty->send(testing::kGetVersion.data(), testing::kGetVersion.size()));
  EXPECT_TRUE(link->sent().empty());
  EXPECT_EQ(faulty->fault_stats().writes_silenced, 1u);
  faulty->silence_for(std::chrono::milliseconds(0));
  EXPECT_TRUE(faulty->send(testing::kGetVersion.data(), testing::kGetVersion.size()));
  EXPECT_EQ(link->sent().size(), 1u);
  faulty->close();
}

}  // namespace
}  // namespace k40t::psdk::sim
