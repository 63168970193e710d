// Three readings the simulator plays with state of its own
// (docs/protocol/decisions.md#conventions): attitude_order (the gimbal holds a roll, so the
// attitude's Euler order shows), focus_plus (a focus distance that manual focus moves) and
// photo_mode_2 (a self-timer or a time-lapse). The driver core loaded with the pod's reading gives
// the truth; loaded with the other it does not.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <thread>

#include "conventions_rig.h"
#include "k40t_driver/driver/pod_frames.h"
#include "k40t_driver/operations/capture_mode_guard.h"
#include "k40t_driver/protocol/convention_readings.h"
#include "k40t_driver/protocol/messages/camera_capture.h"
#include "k40t_driver/protocol/messages/camera_imaging.h"
#include "k40t_driver/protocol/messages/gimbal.h"

namespace k40t::driver::testing {
namespace {

namespace p = protocol;
using test::eventually;

// The angle (degrees) of the rotation between two unit quaternions.
double degrees_between(const Quaternion& a, const Quaternion& b) {
  const double d = std::abs(a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w);
  return 2 * std::acos(std::min(1.0, d)) * 180 / M_PI;
}

// gimbal/attitude's rotation as the ROS glue builds it (ros/conversions.cpp, to_attitude).
Quaternion published(const p::GimbalAttitude& a, p::AttitudeOrder order) {
  return attitude_rotation(rep103_from_pod(a.yaw_deg, a.roll_deg, a.pitch_deg), order);
}

// Right 30, down 45, with the roll joint at 10 deg: 7.6 deg between the two readings.
struct AttitudeCase {
  double driver_error_deg = 0;  // the driver's attitude against the truth
  double order_spread_deg = 0;  // the truth's angles composed in the other order
};

AttitudeCase attitude_against_truth(const std::string& pod, const std::string& driver) {
  ConventionsRig rig({"attitude_order=" + pod}, {"attitude_order=" + driver},
                     [](sim::SimOptions& o) { o.pod.gimbal.roll_deg = 10; });
  p::GimbalAngleRequest move;
  move.yaw_deg = 30;
  move.pitch_deg = -45;
  EXPECT_TRUE(rig.driver().request(move).ok());
  EXPECT_TRUE(eventually([&] {
    const auto a = rig.attitude();
    return a && std::abs(a->joint_yaw_deg - 30) < 0.02 && std::abs(a->joint_pitch_deg + 45) < 0.02;
  })) << "the gimbal never reached right 30, down 45";
  // The true camera rotation: the joint chain (yaw, roll, pitch) turned by the vehicle heading.
  sim::YawPitchRoll chain;
  rig.pod().with_model([&](sim::PodModel& m) {
    chain = m.gimbal().pose().joint_deg;
    chain.yaw = m.attitude_yaw_deg();
  });
  EXPECT_DOUBLE_EQ(chain.roll, 10);
  const Quaternion truth = attitude_rotation(rep103_from_pod(chain.yaw, chain.roll, chain.pitch),
                                             p::AttitudeOrder::kZxy);
  const p::GimbalAttitude a = *rig.attitude();
  AttitudeCase out;
  out.driver_error_deg =
      degrees_between(published(a, rig.driver().codec().conventions.attitude_order), truth);
  out.order_spread_deg =
      degrees_between(attitude_rotation(rep103_from_pod(chain.yaw, chain.roll, chain.pitch),
                                        p::AttitudeOrder::kZyx),
                      truth);
  return out;
}

TEST(ConventionsAttitudeOrder, TheRightReadingGivesTheTrueRotation) {
  for (const char* order : {"zyx", "zxy"}) {
    const AttitudeCase c = attitude_against_truth(order, order);
    EXPECT_LT(c.driver_error_deg, 0.1) << order;
    EXPECT_GT(c.order_spread_deg, 5.0) << "the case cannot tell the readings apart";
  }
}

TEST(ConventionsAttitudeOrder, TheOtherReadingIsDegreesOff) {
  EXPECT_GT(attitude_against_truth("zxy", "zyx").driver_error_deg, 5.0);
  EXPECT_GT(attitude_against_truth("zyx", "zxy").driver_error_deg, 5.0);
}

// The driver's `focus` service sends MANUAL_NEAR as manual_focus_command(true, reading)
// (ros/pod_services.cpp); the simulator's focus distance is the truth of which way it went.
double focus_distance_after_near(const std::string& pod, const std::string& driver) {
  ConventionsRig rig({"focus_plus=" + pod}, {"focus_plus=" + driver});
  double before = 0;
  rig.pod().with_model([&](sim::PodModel& m) { before = m.zoom().focus_distance_m(); });
  p::FocusRequest near;
  near.command = p::manual_focus_command(true, rig.driver().codec().conventions.focus_plus);
  EXPECT_TRUE(rig.driver().request(near).ok());
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  p::FocusRequest stop;
  stop.command = p::FocusCommand::kFineStop;
  EXPECT_TRUE(rig.driver().request(stop).ok());
  double after = 0;
  rig.pod().with_model([&](sim::PodModel& m) { after = m.zoom().focus_distance_m(); });
  return after / before;
}

TEST(ConventionsFocusPlus, NearGoesNearerUnderTheRightReading) {
  EXPECT_LT(focus_distance_after_near("near", "near"), 0.9);
  EXPECT_LT(focus_distance_after_near("far", "far"), 0.9);
}

TEST(ConventionsFocusPlus, TheOtherReadingGoesFarther) {
  EXPECT_GT(focus_distance_after_near("far", "near"), 1.1);
  EXPECT_GT(focus_distance_after_near("near", "far"), 1.1);
}

// A photo started in photo mode 2, then "stop" as the driver's take_photo service does it: the
// guard (fed the driver's frames, as ros/pod_services.cpp feeds it) decides under the driver's
// reading. Returns the guard's verdict and, sent anyway, the pod's answer.
struct StopOutcome {
  Status guard = Status::ok();
  bool pod_stopped = false;  // the pod accepted the stop and its photo job ended
};

StopOutcome stop_in_photo_mode_2(const std::string& pod, const std::string& driver) {
  auto guard = std::make_shared<operations::CaptureModeGuard>();
  ConventionsRig rig(
      {"photo_mode_2=" + pod}, {"photo_mode_2=" + driver}, {}, [guard](PodDriver& d) {
        d.on_rx_frame(
            [guard, &d](const p::FrameView& f, StampNs) { guard->frame_received(f, d.codec()); });
      });
  p::PhotoSettingsRequest mode2;
  mode2.photo_mode = p::PhotoMode::kTimeLapse;
  mode2.time_lapse_interval_s = 5;
  EXPECT_TRUE(rig.driver().request(mode2).ok());
  EXPECT_TRUE(eventually([&] {
    const auto c = rig.camera();
    return c && c->photo_mode == p::PhotoMode::kTimeLapse;
  }));
  EXPECT_TRUE(rig.driver().request(p::TakePhotoRequest{}).ok());
  StopOutcome out;
  out.guard = guard->allows_stop(rig.driver().codec().conventions.photo_mode_2);
  p::TakePhotoRequest stop;
  stop.action = p::PhotoAction::kStop;
  const bool accepted = rig.driver().request(stop).ok();
  out.pod_stopped =
      accepted && eventually([&] {
        bool shooting = true;
        rig.pod().with_model([&](sim::PodModel& m) { shooting = m.camera().shooting(); });
        return !shooting;
      });
  return out;
}

TEST(ConventionsPhotoMode2, ATimeLapseIsStopped) {
  const StopOutcome lapse = stop_in_photo_mode_2("time_lapse", "time_lapse");
  EXPECT_TRUE(lapse.guard) << lapse.guard.message();
  EXPECT_TRUE(lapse.pod_stopped);
}

TEST(ConventionsPhotoMode2, ASelfTimersStopIsRefusedWithTheReason) {
  const StopOutcome timer = stop_in_photo_mode_2("self_timer", "self_timer");
  ASSERT_FALSE(timer.guard);
  EXPECT_NE(timer.guard.message().find("self-timer"), std::string::npos) << timer.guard.message();
  EXPECT_FALSE(timer.pod_stopped) << "the pod refuses it too (3.2.4.3)";
  // The wrong reading lets the stop go out, and the pod refuses it.
  const StopOutcome wrong = stop_in_photo_mode_2("self_timer", "time_lapse");
  EXPECT_TRUE(wrong.guard);
  EXPECT_FALSE(wrong.pod_stopped);
}

}  // namespace
}  // namespace k40t::driver::testing
