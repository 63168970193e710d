// Issue 10 fixes in PodDriver, on the wire against a scripted pod: every GPS request (0x000310)
// gets an ACK and is counted only once its answer is written, including a height beyond what
// section 3.2.4.15's int16 x0.1 m carries; the time-zone parameter reaches 0x00030E.
#include <gtest/gtest.h>

#include "k40t_driver/protocol/messages/flight_controller.h"
#include "pod_driver_test_support.h"

namespace k40t::driver {
namespace {

using namespace testing;  // k40t::driver::testing

VehicleState high_vehicle() {
  VehicleState vehicle;
  vehicle.has_fix = true;
  vehicle.latitude_deg = 27.9881;
  vehicle.longitude_deg = 86.9250;
  vehicle.altitude_m = 5335.0;
  vehicle.altitude_msl_m = 5364.0;  // Everest base camp: beyond int16 x0.1 m (3276.7 m)
  vehicle.relative_altitude_m = 120.0;
  return vehicle;
}

protocol::CameraGpsAck gps_answer(FakePod& pod, size_t nth) {
  protocol::CameraGpsRequest request;
  request.hour = 9;
  pod.send(request);
  pod.wait_for(FakePod::count_of(protocol::CameraGpsAck::kId, nth), milliseconds(3000));
  const std::vector<SentFrame> acks = pod.frames_with_id(protocol::CameraGpsAck::kId);
  EXPECT_EQ(acks.size(), nth) << "a GPS request went unanswered";
  if (acks.size() < nth) return {};
  Result<protocol::CameraGpsAck> ack = protocol::decode_payload<protocol::CameraGpsAck>(
      acks[nth - 1].payload.data(), acks[nth - 1].payload.size());
  EXPECT_TRUE(ack.is_ok()) << ack.error();
  return ack ? ack.value() : protocol::CameraGpsAck{};
}

// The answer to one GPS request from a driver with `clamp` whose vehicle is high_vehicle().
protocol::CameraGpsAck answer_for_high_vehicle(bool clamp, DriverStats* stats) {
  const std::string pty = unique_pty(clamp ? "gps_clamp" : "gps_refuse");
  FakePod pod(pty);
  DriverOptions o = options_for(pty);
  o.gps_clamp_height = clamp;
  std::unique_ptr<PodDriver> driver = started_driver(pod, o);
  driver->set_vehicle_state(high_vehicle());
  const protocol::CameraGpsAck ack = gps_answer(pod, 1);
  *stats = driver->stats();
  return ack;
}

TEST(GpsAnswer, AHeightBeyondTheWireIsClampedByDefault) {
  EXPECT_TRUE(DriverOptions{}.gps_clamp_height);
  DriverStats stats;
  const protocol::CameraGpsAck ack = answer_for_high_vehicle(true, &stats);
  EXPECT_EQ(ack.code, protocol::ResponseCode::kOk);
  EXPECT_NEAR(ack.altitude_m, 3276.7, 0.05);  // int16 32767 x0.1
  EXPECT_NEAR(ack.latitude_deg, 27.9881, 1e-7);
  EXPECT_EQ(stats.gps_requests_answered, 1u);
  EXPECT_EQ(stats.gps_requests_unanswerable, 0u);
}

TEST(GpsAnswer, WithoutClampingTheRequestIsRefusedButStillAnswered) {
  DriverStats stats;
  const protocol::CameraGpsAck ack = answer_for_high_vehicle(false, &stats);
  EXPECT_EQ(ack.code, protocol::ResponseCode::kFailure);
  EXPECT_EQ(ack.hour, 9);  // the request's time of day echoed
  EXPECT_EQ(ack.latitude_deg, 0.0);
  EXPECT_EQ(stats.gps_requests_answered, 0u);
  EXPECT_EQ(stats.gps_requests_unanswerable, 1u);
}

TEST(TimeSync, CarriesTheTimeZoneParameter) {
  const std::string pty = unique_pty("tz");
  FakePod pod(pty);
  DriverOptions o = options_for(pty);
  o.time_sync_period_s = 0.25;
  o.time_zone_minutes_west = -480;  // UTC+8
  std::unique_ptr<PodDriver> driver = started_driver(pod, o);
  const std::vector<SentFrame> syncs = wait_for_time_syncs(pod, 1);
  ASSERT_GE(syncs.size(), 1u);
  // Section 3.2.4.13: int64 ms, then int32 tz_minuteswest low byte first: -480 = 20 FE FF FF.
  ASSERT_EQ(syncs[0].payload.size(), 16u);
  EXPECT_EQ(std::vector<uint8_t>(syncs[0].payload.begin() + 8, syncs[0].payload.begin() + 12),
            (std::vector<uint8_t>{0x20, 0xFE, 0xFF, 0xFF}));
}

}  // namespace
}  // namespace k40t::driver
