// Helpers of the simulator conformance tests (test_sim_conformance*.cpp): a pod with short
// calibrations and reboots, gimbal angle requests, and aiming the gimbal before a measurement.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "k40t_driver/protocol/messages/gimbal.h"
#include "request_with.h"
#include "sim_link_harness.h"

namespace k40t::sim::testing {

using k40t::testing::request_with;

using protocol::ResponseCode;

inline bool near(double a, double b, double tolerance) {
  return std::abs(a - b) <= tolerance;
}

// Short calibrations and reboots keep the tests quick; the behaviour is the same.
inline SimOptions quick_pod() {
  SimOptions options;
  options.pod.gimbal.drift_calibration_s = 1;
  options.pod.gimbal.linear_calibration_s = 1;
  options.pod.gimbal.accelerometer_calibration_s = 1;
  options.pod.gimbal.restart_s = 1.2;  // two 2 Hz gimbal status reports see it
  options.pod.camera_boot_s = 1;
  return options;
}

inline protocol::GimbalAngleRequest angles(double pitch_deg, double yaw_deg) {
  protocol::GimbalAngleRequest request;
  request.pitch_deg = pitch_deg;
  request.yaw_deg = yaw_deg;
  return request;
}

inline protocol::GimbalDialSpeedRequest dial_speed(double pitch_deg_s, double yaw_deg_s) {
  protocol::GimbalDialSpeedRequest request;
  request.pitch_speed_deg_s = pitch_deg_s;
  request.yaw_speed_deg_s = yaw_deg_s;
  return request;
}

// The suite of most conformance tests: a quick pod behind a link.
class SimConformance : public ::testing::Test {
 protected:
  SimLink link{quick_pod()};
};

// Turns the gimbal at full speed and waits until the attitude report shows it there.
inline void aim(SimLink& link, double pitch_deg, double yaw_deg) {
  ASSERT_EQ(link.send(dial_speed(30, 30)), ResponseCode::kOk);
  ASSERT_EQ(link.send(angles(pitch_deg, yaw_deg)), ResponseCode::kOk);
  ASSERT_TRUE(link.wait_report<protocol::GimbalAttitude>(
      [&](const protocol::GimbalAttitude& a) {
        return near(a.joint_pitch_deg, pitch_deg, 0.011) && near(a.joint_yaw_deg, yaw_deg, 0.011);
      },
      std::chrono::seconds(15)));
}

}  // namespace k40t::sim::testing
