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

}  // namespace
}  // namespace k40t::driver
