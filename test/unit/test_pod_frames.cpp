// The pod's angles in REP 103 signs and units (driver/pod_frames.h), ROS-free.
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/driver/pod_frames.h"

namespace k40t::driver {
namespace {

constexpr double kEps = 1e-9;

TEST(Rep103, PodUpAndRightBecomeNegativePitchAndYaw) {
  const Rep103Angles a = rep103_from_pod(90.0, 10.0, 30.0);  // right 90, roll 10, up 30
  EXPECT_NEAR(a.yaw, -M_PI / 2, kEps);                       // REP 103: left positive
  EXPECT_NEAR(a.roll, 10.0 * M_PI / 180, kEps);
  EXPECT_NEAR(a.pitch, -M_PI / 6, kEps);  // REP 103: down positive
}

TEST(Rep103, CommandsGoBackToThePodsSigns) {
  const PodAngles pod = pod_from_rep103({-M_PI / 2, 0.0, M_PI / 6});  // right, 30 deg down
  EXPECT_NEAR(pod.yaw_deg, 90.0, kEps);                               // the pod: right positive
  EXPECT_NEAR(pod.pitch_deg, -30.0, kEps);                            // the pod: up positive
  const PodAngles back = pod_from_rep103(rep103_from_pod(12.0, -3.0, 45.0));
  EXPECT_NEAR(back.yaw_deg, 12.0, kEps);
  EXPECT_NEAR(back.roll_deg, -3.0, kEps);
  EXPECT_NEAR(back.pitch_deg, 45.0, kEps);
}

}  // namespace
}  // namespace k40t::driver
