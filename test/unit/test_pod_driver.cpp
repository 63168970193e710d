// PodDriver end to end over a real pty, against a scripted pod (no ROS, no simulator): stamps,
// GPS answers, the cmd_rate dead-man on the wire, time sync, pod-online events, replay.
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>

#include "fake_pod.h"
#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/protocol/messages/camera_system.h"
#include "k40t_driver/protocol/messages/flight_controller.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "pod_driver_test_support.h"

namespace k40t::driver {
namespace {

using std::chrono::milliseconds;
using namespace testing;  // k40t::driver::testing: FakePod and the helpers

TEST(PodDriver, StampIsReceptionMinusWireTime) {
  const std::string pty = unique_pty("stamp");
  FakePod pod(pty);
  std::unique_ptr<PodDriver> driver = make_driver(options_for(pty));
  std::atomic<StampNs> stamp{0};
  driver->on<protocol::GimbalAttitude>(
      [&](const protocol::GimbalAttitude&, StampNs s) { stamp = s; });
  ASSERT_TRUE(driver->start().is_ok());
  protocol::GimbalAttitude attitude;
  attitude.joint_pitch_deg = -12.5;
  for (int i = 0; i < 100 && stamp == 0; ++i) {
    pod.send(attitude);
    std::this_thread::sleep_for(milliseconds(20));
  }
  // 20 payload bytes + 12 of frame, 10 bits each at 115200 baud (docs/protocol/decisions.md#a10).
  const StampNs wire_ns = std::llround(32 * 10.0 / 115200.0 * 1e9);
  EXPECT_EQ(stamp.load(), kFixedNow - wire_ns);
}

TEST(PodDriver, GpsRequestIsAnsweredFromTheVehicleState) {
  const std::string pty = unique_pty("gps");
  FakePod pod(pty);
  std::unique_ptr<PodDriver> driver = started_driver(pod, options_for(pty));
  protocol::CameraGpsRequest request;
  request.hour = 13;
  request.minute = 14;
  request.second = 15;
  request.millisecond = 160;

  // No fix yet: answered, with a failure code.
  pod.send(request);
  std::vector<SentFrame> frames =
      pod.wait_for(FakePod::count_of(protocol::CameraGpsAck::kId, 1), milliseconds(3000));
  std::vector<SentFrame> acks = pod.frames_with_id(protocol::CameraGpsAck::kId);
  ASSERT_EQ(acks.size(), 1u);
  Result<protocol::CameraGpsAck> refusal = protocol::decode_payload<protocol::CameraGpsAck>(
      acks[0].payload.data(), acks[0].payload.size());
  ASSERT_TRUE(refusal.is_ok()) << refusal.error();
  EXPECT_EQ(refusal->code, protocol::ResponseCode::kFailure);

  VehicleState vehicle;
  vehicle.has_fix = true;
  vehicle.latitude_deg = 47.1234567;
  vehicle.longitude_deg = 8.7654321;
  vehicle.altitude_m = 560.0;      // above the ellipsoid
  vehicle.altitude_msl_m = 512.3;  // above sea level: what the pod gets
  vehicle.relative_altitude_m = 40.5;
  vehicle.has_attitude = true;
  vehicle.heading_deg = 270.0;  // west: -90 on the wire's -180..180
  vehicle.pitch_deg = 2.5;
  driver->set_vehicle_state(vehicle);
  pod.send(request);
  pod.wait_for(FakePod::count_of(protocol::CameraGpsAck::kId, 2), milliseconds(3000));
  acks = pod.frames_with_id(protocol::CameraGpsAck::kId);
  ASSERT_EQ(acks.size(), 2u);
  Result<protocol::CameraGpsAck> ack = protocol::decode_payload<protocol::CameraGpsAck>(
      acks[1].payload.data(), acks[1].payload.size());
  ASSERT_TRUE(ack.is_ok()) << ack.error();
  EXPECT_EQ(ack->code, protocol::ResponseCode::kOk);
  EXPECT_EQ(ack->hour, 13);
  EXPECT_EQ(ack->minute, 14);
  EXPECT_EQ(ack->second, 15);
  EXPECT_EQ(ack->millisecond, 160);
  EXPECT_NEAR(ack->latitude_deg, 47.1234567, 1e-7);
  EXPECT_NEAR(ack->longitude_deg, 8.7654321, 1e-7);
  EXPECT_NEAR(ack->altitude_m, 512.3, 0.05);
  EXPECT_NEAR(ack->relative_height_m, 40.5, 0.05);
  EXPECT_NEAR(ack->yaw_deg, -90.0, 0.01);
  EXPECT_NEAR(ack->pitch_deg, 2.5, 0.01);
  EXPECT_EQ(driver->stats().gps_requests_answered, 1u);
  EXPECT_EQ(driver->stats().gps_requests_unanswerable, 1u);
}

TEST(PodDriver, RateCommandsStopHalfASecondAfterTheLast) {
  const std::string pty = unique_pty("deadman");
  FakePod pod(pty);
  std::unique_ptr<PodDriver> driver = started_driver(pod, options_for(pty));

  const auto commanded = std::chrono::steady_clock::now();
  driver->command_rate(10.0, 0.0);
  pod.wait_for(FakePod::count_of(protocol::GimbalControlRequest::kId, 2), milliseconds(2000));
  const std::vector<SentFrame> controls = pod.frames_with_id(protocol::GimbalControlRequest::kId);
  ASSERT_EQ(controls.size(), 2u);
  // 0x000010: byte 1 mode, byte 2 yaw (2 stop), byte 3 pitch (0 up, 2 stop).
  EXPECT_EQ(controls[0].payload[2], 0) << "first command: pitch up";
  EXPECT_EQ(controls[1].payload[1], 2);
  EXPECT_EQ(controls[1].payload[2], 2) << "dead-man: pitch stop";
  const double after_s = std::chrono::duration<double>(controls[1].at - commanded).count();
  EXPECT_GE(after_s, 0.5);
  EXPECT_LT(after_s, 0.8);
  EXPECT_EQ(pod.frames_with_id(protocol::GimbalDialSpeedRequest::kId).size(), 1u);
  EXPECT_EQ(driver->stats().deadman_stops, 1u);
}

// The 0x000017 frames the pod got, as deg/s (pitch, yaw).
std::vector<std::pair<double, double>> dial_speeds(FakePod& pod) {
  std::vector<std::pair<double, double>> out;
  for (const SentFrame& f : pod.frames_with_id(protocol::GimbalDialSpeedRequest::kId)) {
    Result<protocol::GimbalDialSpeedRequest> speed =
        protocol::decode_payload<protocol::GimbalDialSpeedRequest>(f.payload.data(),
                                                                   f.payload.size());
    EXPECT_TRUE(speed) << speed.error();
    if (speed) out.emplace_back(speed->pitch_speed_deg_s, speed->yaw_speed_deg_s);
  }
  return out;
}

// cmd_rate sends 0x000017 only when its speed changes; "changes" is against what the pod was last
// told by anyone: the reconfigure dial speed, a gimbal restart and a refused 0x000017 all make the
// next rate command send its speed again (it used to turn at 30 deg/s when 10 were commanded).
TEST(PodDriver, RateCommandsResendTheirSpeedWhenAnotherChangedIt) {
  const std::string pty = unique_pty("dialspeed");
  FakePod pod(pty);
  std::unique_ptr<PodDriver> driver = started_driver(pod, options_for(pty));
  const auto speeds_after = [&](size_t n) {
    pod.wait_for(FakePod::count_of(protocol::GimbalDialSpeedRequest::kId, n), milliseconds(2000));
    return dial_speeds(pod);
  };
  driver->command_rate(10.0, 0.0);
  ASSERT_EQ(speeds_after(1).size(), 1u);
  driver->command_rate(10.0, 0.0);  // the same speed: nothing new
  protocol::GimbalDialSpeedRequest reconfigure;
  reconfigure.pitch_speed_deg_s = 30;
  reconfigure.yaw_speed_deg_s = 30;
  ASSERT_TRUE(driver->request(reconfigure).ok());
  ASSERT_EQ(speeds_after(2).size(), 2u);
  driver->command_rate(10.0, 0.0);
  std::vector<std::pair<double, double>> sent = speeds_after(3);
  ASSERT_EQ(sent.size(), 3u) << "the pod would turn at the reconfigure's 30 deg/s";
  EXPECT_EQ(sent[2], std::make_pair(10.0, 10.0));

  ASSERT_TRUE(driver->request(protocol::GimbalRestartRequest{}).ok());
  driver->command_rate(10.0, 0.0);
  ASSERT_EQ(speeds_after(4).size(), 4u) << "a restarted gimbal's speed is unknown";

  pod.set_auto_ack(false);  // the pod refuses (here: never answers) the next speed
  driver->command_rate(20.0, 0.0);
  pod.wait_for(FakePod::count_of(protocol::GimbalDialSpeedRequest::kId, 7), milliseconds(2000));
  // The request's last timeout (3 sends, 100 ms each) and its failure handled: generous, as a
  // busy machine delays the session's timer; a driver that never forgets fails at any wait.
  std::this_thread::sleep_for(milliseconds(600));
  pod.set_auto_ack(true);
  const size_t before = dial_speeds(pod).size();
  driver->command_rate(20.0, 0.0);
  sent = speeds_after(before + 1);
  ASSERT_EQ(sent.size(), before + 1) << "a speed that did not take is sent again";
  EXPECT_EQ(sent.back(), std::make_pair(20.0, 20.0));
}

// The ids of the frames the pod got, in order, from the `from`th on.
std::vector<protocol::MessageId> ids_from(FakePod& pod, size_t from) {
  std::vector<protocol::MessageId> ids;
  const std::vector<SentFrame> frames =
      pod.wait_for([](const auto&) { return true; }, milliseconds(0));
  for (size_t i = from; i < frames.size(); ++i) ids.push_back(frames[i].id);
  return ids;
}

// Section 3.2.4.25's note: box tracking goes off before the gimbal is driven, or the request is
// refused with the reason (it used to be sent with the tracker still steering).
TEST(PodDriver, BoxTrackingIsSwitchedOffBeforeTheGimbalIsDriven) {
  const std::string pty = unique_pty("tracking");
  FakePod pod(pty);
  std::unique_ptr<PodDriver> driver = started_driver(pod, options_for(pty));
  constexpr protocol::MessageId kTracking = protocol::BoxTrackingRequest::kId;
  constexpr protocol::MessageId kAngle = protocol::GimbalAngleRequest::kId;
  protocol::BoxTrackingRequest on;
  on.width_px = 100;
  on.height_px = 80;
  ASSERT_TRUE(driver->request(on).ok());
  protocol::GimbalAngleRequest angle;
  angle.yaw_deg = 10;
  size_t from = pod.wait_for([](const auto&) { return true; }, milliseconds(0)).size();
  ASSERT_TRUE(driver->request(angle).ok());
  EXPECT_EQ(ids_from(pod, from), (std::vector<protocol::MessageId>{kTracking, kAngle}));
  const std::vector<SentFrame> off = pod.frames_with_id(kTracking);
  ASSERT_EQ(off.size(), 2u);
  EXPECT_EQ(off[1].payload[0], 2) << "byte 1: 2 = off";
  from += 2;
  ASSERT_TRUE(driver->request(angle).ok());
  EXPECT_EQ(ids_from(pod, from), (std::vector<protocol::MessageId>{kAngle})) << "already off";

  // cmd_rate (asynchronous) too; its dead-man stop is only a stop and goes at once.
  ASSERT_TRUE(driver->request(on).ok());
  driver->command_rate(0.0, 10.0);
  pod.wait_for(FakePod::count_of(protocol::GimbalControlRequest::kId, 2), milliseconds(2000));
  const std::vector<protocol::MessageId> ids = ids_from(pod, from + 2);  // after angle and "on"
  const auto at = [&ids](protocol::MessageId id) { return std::find(ids.begin(), ids.end(), id); };
  ASSERT_NE(at(kTracking), ids.end());
  EXPECT_LT(at(kTracking), at(protocol::GimbalControlRequest::kId)) << "off before turning";

  ASSERT_TRUE(driver->request(on).ok());
  pod.set_auto_ack(false);  // the pod does not switch it off
  const size_t angles = pod.frames_with_id(kAngle).size();
  const session::AckResult refused = driver->request(angle);
  EXPECT_FALSE(refused.ok());
  EXPECT_FALSE(refused.sent);
  EXPECT_NE(refused.message.find("box tracking is on"), std::string::npos) << refused.message;
  EXPECT_EQ(pod.frames_with_id(kAngle).size(), angles) << "the angle was not sent";
}

// The first `count` time syncs of a driver that syncs every 0.25 s, its clock `offset_ms` off the
// system clock (set_clock_offset_ms, as the SKYPORT's UTC does).
std::vector<SentFrame> quarter_second_time_syncs(const char* name, size_t count,
                                                 int64_t offset_ms) {
  const std::string pty = unique_pty(name);
  FakePod pod(pty);
  DriverOptions o = options_for(pty);
  o.time_sync_period_s = 0.25;
  std::unique_ptr<PodDriver> driver = make_driver(o);
  if (offset_ms != 0) driver->set_clock_offset_ms(offset_ms);
  EXPECT_TRUE(driver->start().is_ok());
  wait_until_linked(pod, *driver);
  return wait_for_time_syncs(pod, count);
}

TEST(PodDriver, TimeSyncEveryPeriodWithTheWallClock) {
  const std::vector<SentFrame> syncs = quarter_second_time_syncs("timesync", 4, 0);
  ASSERT_GE(syncs.size(), 4u);
  const std::optional<int64_t> sent_ms = time_sync_ms(syncs.back());
  ASSERT_TRUE(sent_ms);
  EXPECT_NEAR(static_cast<double>(*sent_ms), static_cast<double>(system_now_ms()), 1000.0);
  const double gap_s = std::chrono::duration<double>(syncs[3].at - syncs[2].at).count();
  EXPECT_NEAR(gap_s, 0.25, 0.1);
}

TEST(PodDriver, TimeSyncFollowsABetterClock) {
  // The SKYPORT's UTC says the system clock is an hour ahead: the pod is set an hour back.
  const std::vector<SentFrame> syncs = quarter_second_time_syncs("timeref", 2, -3'600'000);
  ASSERT_GE(syncs.size(), 2u);
  const std::optional<int64_t> sent_ms = time_sync_ms(syncs.back());
  ASSERT_TRUE(sent_ms);
  EXPECT_NEAR(static_cast<double>(*sent_ms), static_cast<double>(system_now_ms() - 3'600'000),
              1000.0);
}

TEST(PodDriver, PodOnlineOnFirstFrameAndAfterSilence) {
  const std::string pty = unique_pty("online");
  FakePod pod(pty);
  DriverOptions o = options_for(pty);
  o.silence_timeout_s = 0.3;
  std::unique_ptr<PodDriver> driver = make_driver(o);
  std::atomic<int> online{0};
  driver->on_pod_online([&] { ++online; });
  ASSERT_TRUE(driver->start().is_ok());
  wait_until_linked(pod, *driver);
  for (int i = 0; i < 10; ++i) {  // 10 more frames 50 ms apart: still one event
    pod.send(protocol::GimbalAttitude{});
    std::this_thread::sleep_for(milliseconds(50));
  }
  EXPECT_EQ(online.load(), 1);
  std::this_thread::sleep_for(milliseconds(500));  // silent for longer than the timeout
  pod.send(protocol::GimbalAttitude{});
  std::this_thread::sleep_for(milliseconds(200));
  EXPECT_EQ(online.load(), 2);
}

TEST(PodDriver, ReplayUsesTheRecordedStampAndSendsNothing) {
  DriverOptions o;
  o.replay = true;
  std::unique_ptr<PodDriver> driver = make_driver(o, [] { return StampNs{42}; });
  StampNs stamp = 0;
  double pitch = 0;
  driver->on<protocol::GimbalAttitude>([&](const protocol::GimbalAttitude& a, StampNs s) {
    stamp = s;
    pitch = a.joint_pitch_deg;
  });
  ASSERT_TRUE(driver->start().is_ok());
  protocol::GimbalAttitude attitude;
  attitude.joint_pitch_deg = 12.34;
  Result<protocol::Payload> payload = protocol::encode_payload(attitude);
  protocol::FrameHeader header;
  header.message_id = protocol::GimbalAttitude::kId;
  Result<protocol::EncodedFrame> frame = protocol::encode_frame(
      header, payload->data(), payload->size, protocol::CrcCoverage::kHeaderExcluded);
  driver->replay_frame(frame->data(), frame->size(), 987654321);
  EXPECT_EQ(stamp, 987654321);
  EXPECT_NEAR(pitch, 12.34, 1e-9);
  const session::AckResult sent = driver->request(protocol::GimbalRestartRequest{});
  EXPECT_FALSE(sent.sent);
  EXPECT_NE(sent.message.find("replay"), std::string::npos) << sent.message;
}

TEST(PodDriver, BadDeviceUrlIsAReadableError) {
  DriverOptions o;
  o.device = "serail:///dev/ttyUSB0";
  Result<std::unique_ptr<PodDriver>> driver = PodDriver::create(o, [] { return StampNs{0}; });
  ASSERT_FALSE(driver.is_ok());
  EXPECT_NE(driver.error().find("serail"), std::string::npos) << driver.error();
}

}  // namespace
}  // namespace k40t::driver
