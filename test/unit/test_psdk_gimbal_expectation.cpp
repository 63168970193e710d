// What `check gimbal` expects the gimbal state to read (gimbal_expectation.h): joint angles stay
// as set; NED angles turn with the simulated aircraft's heading, with a tolerance for the heading
// the payload knows being up to the lag old. The flight (flight_model.h): nose north while it
// climbs for 10 s, then a clockwise circle of 50 m at 5 m/s, 0.1 rad/s = 5.73 deg/s, heading
// 0 at 10 s (north first), so 5.73 * (t - 10) degrees.
#include <gtest/gtest.h>

#include "k40t_driver/psdk/sim/gimbal_expectation.h"

namespace k40t::psdk::sim {
namespace {

constexpr double kTurnDegPerS = 0.1 * 180.0 / M_PI;  // 5.7296

TEST(GimbalExpectation, JointAnglesIgnoreTheHeading) {
  const FlightModel flight;
  const GimbalExpectation joints(flight, false, 2.0);
  const ExpectedYaw e = joints.after_angle(20.0, 15.0, 25.0);
  EXPECT_DOUBLE_EQ(e.yaw_deg, 20.0);
  EXPECT_DOUBLE_EQ(e.tolerance_deg, 2.0);
  EXPECT_TRUE(e.holds(21.9));
  EXPECT_FALSE(e.holds(22.1));
  EXPECT_DOUBLE_EQ(joints.centred(25.0).yaw_deg, 0.0);
}

TEST(GimbalExpectation, NedWhileTheHeadingHoldsIsTheCommandedAngle) {
  // During the climb (t < 10 s, lag 2 s before it too) the nose stays north.
  const FlightModel flight;
  const GimbalExpectation ned(flight, true, 2.0);
  const ExpectedYaw e = ned.after_angle(20.0, 3.0, 7.0);
  EXPECT_NEAR(e.yaw_deg, 20.0, 1e-9);
  EXPECT_NEAR(e.tolerance_deg, 2.0, 1e-9);
  EXPECT_NEAR(ned.centred(7.0).yaw_deg, 0.0, 1e-9);
}

TEST(GimbalExpectation, NedWhileTurningAddsTheTurnSinceTheCommand) {
  const FlightModel flight;
  const GimbalExpectation ned(flight, true, 2.0, 2.0);
  // Commanded at 20 s, read at 23 s: the heading turned 3 s * 5.73 = 17.19 deg; the known
  // heading may be 0..2 s old at either end: +-5.73 deg each.
  const ExpectedYaw e = ned.after_angle(20.0, 20.0, 23.0);
  EXPECT_NEAR(e.yaw_deg, 20.0 + 3 * kTurnDegPerS, 1e-6);
  EXPECT_NEAR(e.tolerance_deg, 2.0 + 2 * kTurnDegPerS, 1e-6);
  EXPECT_FALSE(e.holds(20.0));  // a payload that does not turn with the aircraft fails
  // Centred at 23 s: the heading known is that of 21..23 s, 11..13 s of turn: 12 +- 1 s.
  const ExpectedYaw c = ned.centred(23.0);
  EXPECT_NEAR(c.yaw_deg, 12 * kTurnDegPerS, 1e-6);
  EXPECT_NEAR(c.tolerance_deg, 2.0 + kTurnDegPerS, 1e-6);
  EXPECT_FALSE(c.holds(0.0));
}

TEST(GimbalExpectation, TheYawWrapsAcrossTheBack) {
  const ExpectedYaw e{179.0, 2.0};
  EXPECT_TRUE(e.holds(-179.5));
  EXPECT_FALSE(e.holds(-176.0));
}

}  // namespace
}  // namespace k40t::psdk::sim
