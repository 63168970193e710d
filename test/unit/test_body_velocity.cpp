// geo/body_velocity.h: nav_msgs/Odometry's body-frame twist turned into east-north-up by its
// orientation. Expected values worked out by hand from the rotations named in each test.
#include <cmath>

#include <gtest/gtest.h>

#include "k40t_driver/geo/body_velocity.h"

namespace k40t::geo {
namespace {

constexpr double kEps = 1e-9;

TEST(BodyVelocity, IdentityOrientationKeepsForwardAsEast) {
  // REP 103: with no rotation the body's x (forward) is ENU's x (east).
  const Result<VelocitySample> v = enu_velocity_from_body({0, 0, 0, 1}, 10, 2, -1);
  ASSERT_TRUE(v) << v.error();
  EXPECT_NEAR(v->east, 10, kEps);
  EXPECT_NEAR(v->north, 2, kEps);
  EXPECT_NEAR(v->up, -1, kEps);
}

TEST(BodyVelocity, YawNinetyDegreesFliesNorth) {
  // +90 deg about z (x = y = 0, z = w = sin 45 = cos 45): forward is north, left is west.
  const double h = std::sqrt(0.5);
  const Result<VelocitySample> v = enu_velocity_from_body({0, 0, h, h}, 15, 2, 0);
  ASSERT_TRUE(v) << v.error();
  EXPECT_NEAR(v->east, -2, kEps);
  EXPECT_NEAR(v->north, 15, kEps);
  EXPECT_NEAR(v->up, 0, kEps);
  // The same rotation, not normalised (twice as long): the same velocity.
  const Result<VelocitySample> scaled = enu_velocity_from_body({0, 0, 2 * h, 2 * h}, 15, 2, 0);
  ASSERT_TRUE(scaled);
  EXPECT_NEAR(scaled->east, -2, kEps);
  EXPECT_NEAR(scaled->north, 15, kEps);
}

TEST(BodyVelocity, NoseUpThirtyDegreesClimbs) {
  // Nose up is -30 deg about y (REP 103: pitch positive nose down): y = sin(-15 deg),
  // w = cos 15 deg. Forward 10 m/s -> 10 cos 30 = 8.660254 east, 10 sin 30 = 5 up.
  const double half = -15.0 * M_PI / 180.0;
  const Result<VelocitySample> v =
      enu_velocity_from_body({0, std::sin(half), 0, std::cos(half)}, 10, 0, 0);
  ASSERT_TRUE(v) << v.error();
  EXPECT_NEAR(v->east, 8.660254037844386, 1e-9);
  EXPECT_NEAR(v->north, 0, kEps);
  EXPECT_NEAR(v->up, 5, 1e-9);
}

TEST(BodyVelocity, UnknownOrientationOrNotFiniteIsRefused) {
  const Result<VelocitySample> zero = enu_velocity_from_body({0, 0, 0, 0}, 10, 0, 0);
  ASSERT_FALSE(zero);
  EXPECT_NE(zero.error().find("zero quaternion"), std::string::npos) << zero.error();
  EXPECT_FALSE(enu_velocity_from_body({0, 0, 0, 1}, std::nan(""), 0, 0));
  EXPECT_FALSE(enu_velocity_from_body({0, 0, std::nan(""), 1}, 1, 0, 0));
}

}  // namespace
}  // namespace k40t::geo
