// Issue 12 in PodDriver, on the wire against a scripted pod: the GPS request (0x000310) is
// answered with the vehicle state at the requested time of day, interpolated in the input
// history through the pod-clock offset, with sea-level heights; a time outside the history gets
// the nearest state and is counted.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "k40t_driver/geo/geodesy.h"
#include "k40t_driver/protocol/convention_readings.h"
#include "k40t_driver/protocol/messages/flight_controller.h"
#include "pod_driver_test_support.h"

namespace k40t::driver {
namespace {

using namespace testing;  // k40t::driver::testing

constexpr double kSpeed = 15.0;  // m/s due east
constexpr int64_t kMs = 1000000;

StampNs system_now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// A driver whose clock is the system clock (ROS time without sim time), fed with 10 Hz fixes of
// a vehicle flying east at 15 m/s for the last 3 s, heading turning 1 deg per fix.
struct Flight {
  geo::LocalFrame frame = geo::LocalFrame::at({47.0, 8.0, 500.0}).value();
  StampNs start = system_now_ns() - 3000 * kMs;

  geo::Geodetic truth(StampNs t) const {
    return frame.to_geodetic({kSpeed * (t - start) * 1e-9, 0, 0});
  }

  void feed(PodDriver& driver) const {
    VehicleState latest;
    latest.has_fix = true;
    latest.has_attitude = true;
    latest.altitude_m = 500.0;  // the take-off reference: relative height 0 at 500 m
    for (int i = 0; i <= 30; ++i) {
      const StampNs t = start + i * 100 * kMs;
      const geo::Geodetic g = truth(t);
      driver.record_position(t, {g.latitude_deg, g.longitude_deg, g.height_ellipsoid_m});
      driver.record_attitude(t, {90.0 + i, 1.0, 0.0});
    }
    driver.set_vehicle_state(latest);
  }
};

protocol::CameraGpsRequest request_at(int64_t unix_ms) {
  const int64_t of_day = ((unix_ms % 86400000) + 86400000) % 86400000;
  protocol::CameraGpsRequest r;
  r.hour = static_cast<uint8_t>(of_day / 3600000);
  r.minute = static_cast<uint8_t>(of_day / 60000 % 60);
  r.second = static_cast<uint8_t>(of_day / 1000 % 60);
  r.millisecond = static_cast<uint16_t>(of_day % 1000);
  return r;
}

protocol::CameraGpsAck ask(FakePod& pod, const protocol::CameraGpsRequest& r, size_t nth) {
  pod.send(r);
  pod.wait_for(FakePod::count_of(protocol::CameraGpsAck::kId, nth), milliseconds(3000));
  const std::vector<SentFrame> acks = pod.frames_with_id(protocol::CameraGpsAck::kId);
  EXPECT_EQ(acks.size(), nth);
  if (acks.size() < nth) return {};
  return protocol::decode_payload<protocol::CameraGpsAck>(acks[nth - 1].payload.data(),
                                                          acks[nth - 1].payload.size())
      .value();
}

double distance_m(const protocol::CameraGpsAck& ack, const geo::Geodetic& truth) {
  const double msl =
      geo::Geoid::egm96().msl_from_ellipsoid(truth.latitude_deg, truth.longitude_deg, 0).value();
  const geo::Enu d = geo::LocalFrame::at(truth).value().to_enu(
      {ack.latitude_deg, ack.longitude_deg, ack.altitude_m - msl});  // msl < 0 here: -N
  return std::sqrt(d.east * d.east + d.north * d.north + d.up * d.up);
}

// A driver linked to `pod` that has been fed the whole flight.
std::unique_ptr<PodDriver> flown_driver(FakePod& pod, const std::string& pty, bool match,
                                        const Flight& flight,
                                        const std::function<void(DriverOptions&)>& tweak = {}) {
  DriverOptions o = options_for(pty);
  o.geotag_time_match = match;
  if (tweak) tweak(o);
  std::unique_ptr<PodDriver> driver = started_driver(pod, o, system_now_ns);
  flight.feed(*driver);
  return driver;
}

TEST(GeotagTimeMatch, TheAnswerIsTheStateAtTheRequestedTime) {
  const std::string pty = unique_pty("geotag");
  FakePod pod(pty);
  const Flight flight;
  std::unique_ptr<PodDriver> driver = flown_driver(pod, pty, true, flight);
  // A photo 1.55 s after the start (between two fixes), the pod's clock on the system's.
  const StampNs photo = flight.start + 1550 * kMs;
  const protocol::CameraGpsAck ack = ask(pod, request_at(photo / kMs), 1);
  ASSERT_EQ(ack.code, protocol::ResponseCode::kOk);
  const geo::Geodetic truth = flight.truth(photo);
  const double error = distance_m(ack, truth);
  std::printf("time-matched geotag error at 15 m/s: %.3f m\n", error);
  EXPECT_LT(error, 0.1);  // 0.1 m heights and 1 ms of time of day on the wire
  // Sea level: the ellipsoid height minus the EGM96 undulation at 47N 8E (about 48.4 m).
  EXPECT_NEAR(ack.altitude_m, 500.0 - 48.39, 0.1);
  EXPECT_NEAR(ack.relative_height_m, 0.0, 0.1);
  EXPECT_NEAR(ack.yaw_deg, 90.0 + 15.5, 0.05);  // heading interpolated between fixes 15 and 16
  DriverStats stats = driver->stats();
  EXPECT_EQ(stats.gps_requests_time_matched, 1u);
  EXPECT_EQ(stats.gps_requests_out_of_history, 0u);
  EXPECT_NEAR(stats.last_geotag_gap_s, 0.05, 0.002);

  // The pod's clock 5 s ahead of the system's (a time_reference offset): the same photo.
  driver->set_clock_offset_ms(5000);
  const protocol::CameraGpsAck shifted = ask(pod, request_at(photo / kMs + 5000), 2);
  EXPECT_LT(distance_m(shifted, truth), 0.1);

  // 20 s ago: before the history; the first fix answers, counted.
  const protocol::CameraGpsAck old = ask(pod, request_at(photo / kMs + 5000 - 20000), 3);
  EXPECT_EQ(old.code, protocol::ResponseCode::kOk);
  EXPECT_LT(distance_m(old, flight.truth(flight.start)), 0.1);
  stats = driver->stats();
  EXPECT_EQ(stats.gps_requests_out_of_history, 1u);
  EXPECT_NEAR(stats.last_geotag_gap_s, 20 - 1.55, 0.01);
}

TEST(GeotagTimeMatch, WithoutMatchingTheLatestStateAnswers) {
  const std::string pty = unique_pty("geotag_latest");
  FakePod pod(pty);
  const Flight flight;
  std::unique_ptr<PodDriver> driver = flown_driver(pod, pty, false, flight);
  VehicleState latest = driver->vehicle_state();
  const geo::Geodetic last = flight.truth(flight.start + 3000 * kMs);
  latest.latitude_deg = last.latitude_deg;
  latest.longitude_deg = last.longitude_deg;
  latest.altitude_msl_m = 451.6;
  driver->set_vehicle_state(latest);
  const StampNs photo = flight.start + 2800 * kMs;  // answered 200 ms after the photo
  const protocol::CameraGpsAck ack = ask(pod, request_at(photo / kMs), 1);
  const double error = distance_m(ack, flight.truth(photo));
  std::printf("latest-state geotag error at 15 m/s, 200 ms late: %.3f m\n", error);
  EXPECT_NEAR(error, kSpeed * 0.2, 0.1);
  EXPECT_EQ(driver->stats().gps_requests_time_matched, 0u);
}

// gps_request_time and gps_answer_byte_order (docs/protocol/decisions.md#conventions): a pod in
// UTC+2 (tz_minuteswest -120, which the driver's time syncs give it) asking in its local time,
// and reading the answer's data low byte first.
TEST(GeotagTimeMatch, APodAskingInLocalTimeGetsThePhotosState) {
  const std::string pty = unique_pty("geotag_local");
  FakePod pod(pty);
  const Flight flight;
  std::unique_ptr<PodDriver> driver = flown_driver(pod, pty, true, flight, [](DriverOptions& o) {
    o.time_zone_minutes_west = -120;
    o.session.codec.conventions.gps_request_time = protocol::GpsRequestTime::kLocal;
    o.session.codec.conventions.gps_answer_byte_order = protocol::GpsAnswerByteOrder::kLittle;
  });
  const StampNs photo = flight.start + 1550 * kMs;
  const int64_t local_ms = photo / kMs + 2 * 3600 * 1000;
  pod.send(request_at(local_ms));
  pod.wait_for(FakePod::count_of(protocol::CameraGpsAck::kId, 1), milliseconds(3000));
  const std::vector<SentFrame> acks = pod.frames_with_id(protocol::CameraGpsAck::kId);
  ASSERT_EQ(acks.size(), 1u);
  Result<protocol::CameraGpsAck> ack =
      protocol::decode_gps_answer(acks[0].payload.data(), acks[0].payload.size(), driver->codec());
  ASSERT_TRUE(ack) << ack.error();
  EXPECT_EQ(ack->code, protocol::ResponseCode::kOk);
  EXPECT_EQ(ack->millisecond, request_at(local_ms).millisecond);  // echoed, low byte first
  EXPECT_LT(distance_m(*ack, flight.truth(photo)), 0.1);
  EXPECT_EQ(driver->stats().gps_requests_out_of_history, 0u);
}

TEST(GeotagTimeMatch, ALocalTimeReadAsUtcMissesTheHistory) {
  const std::string pty = unique_pty("geotag_local_as_utc");
  FakePod pod(pty);
  const Flight flight;
  std::unique_ptr<PodDriver> driver = flown_driver(
      pod, pty, true, flight, [](DriverOptions& o) { o.time_zone_minutes_west = -120; });
  const StampNs photo = flight.start + 1550 * kMs;
  ask(pod, request_at(photo / kMs + 2 * 3600 * 1000), 1);
  EXPECT_EQ(driver->stats().gps_requests_out_of_history, 1u);
}

}  // namespace
}  // namespace k40t::driver
