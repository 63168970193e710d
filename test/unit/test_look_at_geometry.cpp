// geo/look_at_geometry.h: target -> gimbal angles, reach, the yaw's way, pointing error and the
// footprint zoom. Figures worked by hand (docs/geo.md "Looking at a place").
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/geo/look_at_geometry.h"

namespace k40t::geo {
namespace {

VehiclePose pose_at(double heading, double pitch = 0, double roll = 0) {
  VehiclePose pose;
  pose.position = {47.0, 8.0, 600.0};
  pose.heading_deg = heading;
  pose.pitch_deg = pitch;
  pose.roll_deg = roll;
  return pose;
}

TEST(LookAtGeometry, AimOfForwardLeftUpAndDown) {
  // x forward: yaw 0, pitch 0. y left (0, 1, 0): 90 deg left = yaw -90 (right positive).
  EXPECT_NEAR(aim_along({1, 0, 0})->yaw_deg, 0, 1e-12);
  EXPECT_NEAR(aim_along({0, 1, 0})->yaw_deg, -90, 1e-12);
  EXPECT_NEAR(aim_along({0, -1, 0})->yaw_deg, 90, 1e-12);
  // 100 m ahead, 100 m down: 45 deg down.
  const Result<GimbalAim> down = aim_along({100, 0, -100});
  EXPECT_NEAR(down->pitch_deg, -45, 1e-12);
  // Behind: yaw 180 (the wrap's one place), not -180.
  EXPECT_NEAR(aim_along({-1, 0, 0})->yaw_deg, 180, 1e-12);
  // 3-4-5: 40 m ahead, 30 m right, 0 down: yaw atan(30/40) = 36.87 deg right.
  EXPECT_NEAR(aim_along({40, -30, 0})->yaw_deg, 36.8698976, 1e-6);
  // Straight down: yaw 0 by convention, pitch -90.
  EXPECT_NEAR(aim_along({0, 0, -5})->yaw_deg, 0, 1e-12);
  EXPECT_NEAR(aim_along({0, 0, -5})->pitch_deg, -90, 1e-12);
  EXPECT_FALSE(aim_along({0, 0, 0}));
  EXPECT_FALSE(aim_along({NAN, 0, 0}));
}

TEST(LookAtGeometry, BoresightIsTheInverseOfAim) {
  const Vector3 b = boresight({30, -20});
  // cos 20 cos 30 = 0.813798, -cos 20 sin 30 = -0.469846, sin -20 = -0.342020
  EXPECT_NEAR(b[0], 0.8137977, 1e-6);
  EXPECT_NEAR(b[1], -0.4698463, 1e-6);
  EXPECT_NEAR(b[2], -0.3420201, 1e-6);
  EXPECT_NEAR(aim_along(b)->yaw_deg, 30, 1e-9);
  EXPECT_NEAR(aim_along(b)->pitch_deg, -20, 1e-9);
}

TEST(LookAtGeometry, OpticalFrameOfTheBoresight) {
  // Looking ahead: a point 100 m ahead, 10 m left and 5 m up is x -10 (left), y -5 (up), z 100.
  Vector3 o = in_optical_frame({0, 0}, {100, 10, 5});
  EXPECT_NEAR(o[0], -10, 1e-9);
  EXPECT_NEAR(o[1], -5, 1e-9);
  EXPECT_NEAR(o[2], 100, 1e-9);
  // Looking 90 deg right (base -y) and 45 deg down: the point (0, -10, -10) is 14.14 m ahead;
  // the base's forward (1, 0, 0) is on the camera's left (x -1).
  o = in_optical_frame({90, -45}, {0, -10, -10});
  EXPECT_NEAR(o[2], std::sqrt(200.0), 1e-9);
  EXPECT_NEAR(o[0], 0, 1e-9);
  EXPECT_NEAR(o[1], 0, 1e-9);
  o = in_optical_frame({90, -45}, {1, 0, 0});
  EXPECT_NEAR(o[0], -1, 1e-9);
}

TEST(LookAtGeometry, EnuToBodyUndoesTheAttitude) {
  // Heading east: ENU east (1, 0, 0) is body forward; north is body left.
  Vector3 v = enu_to_body(pose_at(90), {1, 0, 0});
  EXPECT_NEAR(v[0], 1, 1e-12);
  EXPECT_NEAR(v[1], 0, 1e-12);
  v = enu_to_body(pose_at(90), {0, 1, 0});
  EXPECT_NEAR(v[1], 1, 1e-12);
  // Nose up 30 deg, heading north: a point level ahead (0, 1, 0) is 30 deg below the nose:
  // body (cos 30, 0, -sin 30).
  v = enu_to_body(pose_at(0, 30), {0, 1, 0});
  EXPECT_NEAR(v[0], 0.8660254, 1e-6);
  EXPECT_NEAR(v[2], -0.5, 1e-12);
  // Right wing down 90 deg: the body's left (y) points up, so ENU up is body +y.
  v = enu_to_body(pose_at(0, 0, 90), {0, 0, 1});
  EXPECT_NEAR(v[1], 1, 1e-12);
  // The inverse of ray_direction_enu at an arbitrary attitude.
  const VehiclePose pose = pose_at(37, -8, 12);
  const Vector3 there = ray_direction_enu(pose, BodyRay{{0, 0, 0}, {0.6, -0.64, -0.48}});
  v = enu_to_body(pose, there);
  EXPECT_NEAR(v[0], 0.6, 1e-9);
  EXPECT_NEAR(v[1], -0.64, 1e-9);
  EXPECT_NEAR(v[2], -0.48, 1e-9);
}

TEST(LookAtGeometry, TargetInBodyFromWgs84) {
  // A point 100 m north and 30 m below a vehicle heading north: 100 m ahead, 30 m down, within
  // the Earth's curvature over 100 m (100^2 / 2R = 0.8 mm).
  const VehiclePose pose = pose_at(0);
  const Result<LocalFrame> frame = LocalFrame::at(pose.position);
  const Geodetic target = frame->to_geodetic({0, 100, -30});
  const Result<Vector3> body = target_in_body(pose, target);
  ASSERT_TRUE(body) << body.error();
  EXPECT_NEAR((*body)[0], 100, 1e-6);
  EXPECT_NEAR((*body)[1], 0, 1e-6);
  EXPECT_NEAR((*body)[2], -30, 1e-6);
  EXPECT_FALSE(target_in_body(pose, {91, 0, 0}));
}

TEST(LookAtGeometry, ReachNamesTheLimit) {
  const GimbalLimits limits;
  EXPECT_TRUE(check_reach({0, 30}, limits));
  EXPECT_TRUE(check_reach({180, -90}, limits));
  const Status above = check_reach({10, 45}, limits);
  ASSERT_FALSE(above);
  EXPECT_EQ(above.message(),
            "the target is 45.0 deg up, above the gimbal's upper limit (30.0 deg up)");
  GimbalLimits narrow;
  narrow.yaw_min_deg = -90;
  narrow.yaw_max_deg = 90;
  EXPECT_FALSE(check_reach({120, 0}, narrow));
  narrow.yaw_continuous = true;  // a continuous yaw has no end stops
  EXPECT_TRUE(check_reach({120, 0}, narrow));
}

TEST(LookAtGeometry, YawTakesTheShortWayOnlyWhenContinuous) {
  GimbalLimits limits;
  // From 170 right to 170 left (-170): 20 deg through the back, or 340 deg through 0.
  EXPECT_NEAR(yaw_turn_deg(170, -170, limits), -340, 1e-12);
  limits.yaw_continuous = true;
  EXPECT_NEAR(yaw_turn_deg(170, -170, limits), 20, 1e-12);
  EXPECT_NEAR(yaw_turn_deg(-170, 170, limits), -20, 1e-12);
  EXPECT_NEAR(yaw_turn_deg(10, 30, limits), 20, 1e-12);
  EXPECT_NEAR(wrap_deg(540), 180, 1e-12);
  EXPECT_NEAR(wrap_deg(-180), 180, 1e-12);
  EXPECT_NEAR(wrap_deg(-190), 170, 1e-12);
}

TEST(LookAtGeometry, PointingErrorIsTheAngleBetween) {
  EXPECT_NEAR(pointing_error_deg({0, 0}, {1, 0, 0}), 0, 1e-12);
  // 1 m sideways at 100 m: atan(0.01) = 0.572939 deg.
  EXPECT_NEAR(pointing_error_deg({0, 0}, {100, 1, 0}), 0.5729387, 1e-6);
  EXPECT_NEAR(pointing_error_deg({90, 0}, {1, 0, 0}), 90, 1e-9);
  // Small angles stay exact: 1 mm at 1 km is 5.73e-5 deg.
  EXPECT_NEAR(pointing_error_deg({0, 0}, {1000, 0, 0.001}), 5.729578e-5, 1e-10);
}

TEST(LookAtGeometry, FootprintZoom) {
  // The tele's 1x: 5.6 mm wide behind 4.7 mm, tan(h/2) = 2.8 / 4.7 = 0.595745.
  const double tan_half = 2.8 / 4.7;
  // At 153 m (150 m horizontal, 30 m down: sqrt(150^2 + 30^2) = 152.97 m) 1x covers
  // 2 x 152.97 x 0.595745 = 182.26 m; 30 m needs 6.075x.
  const double slant = std::hypot(150.0, 30.0);
  EXPECT_NEAR(footprint_width_m(slant, 1.0, tan_half), 182.263, 1e-3);
  EXPECT_NEAR(footprint_zoom(slant, 30, tan_half, 1, 160), 6.0754, 1e-4);
  EXPECT_NEAR(footprint_width_m(slant, 6.0754, tan_half), 30, 1e-3);
  // Beyond the range: clamped.
  EXPECT_NEAR(footprint_zoom(5, 30, tan_half, 1, 160), 1, 1e-12);
  EXPECT_NEAR(footprint_zoom(20000, 1, tan_half, 1, 160), 160, 1e-12);
}

}  // namespace
}  // namespace k40t::geo
