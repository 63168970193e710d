// The vehicle state in the geo layer's terms (driver/vehicle_geo.h), ROS-free: the pose needs a
// fix and an attitude; the laser target's covariance grows with the slant range.
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/driver/vehicle_geo.h"

namespace k40t::driver {
namespace {

VehicleState vehicle_at(double latitude_deg, double longitude_deg, double height_m) {
  VehicleState v;
  v.has_fix = true;
  v.latitude_deg = latitude_deg;
  v.longitude_deg = longitude_deg;
  v.altitude_m = height_m;
  return v;
}

TEST(VehicleGeo, PoseNeedsAFixAndAnAttitude) {
  VehicleState v;
  EXPECT_EQ(vehicle_pose(v).error(), "no vehicle fix (topic fix)");
  v = vehicle_at(47.1, 8.5, 500.0);
  EXPECT_EQ(vehicle_pose(v).error(), "no vehicle attitude (topic attitude)");
  v.has_attitude = true;
  v.heading_deg = 30.0;
  v.pitch_deg = -5.0;
  v.roll_deg = 2.0;
  v.position_covariance[0] = 9.0;
  const Result<geo::VehiclePose> pose = vehicle_pose(v);
  ASSERT_TRUE(pose) << pose.error();
  EXPECT_EQ(pose->position.latitude_deg, 47.1);
  EXPECT_EQ(pose->position.longitude_deg, 8.5);
  EXPECT_EQ(pose->position.height_ellipsoid_m, 500.0);  // ellipsoid heights on both sides
  EXPECT_EQ(pose->heading_deg, 30.0);
  EXPECT_EQ(pose->pitch_deg, -5.0);
  EXPECT_EQ(pose->roll_deg, 2.0);
  EXPECT_EQ(pose->position_covariance[0], 9.0);
}

TEST(VehicleGeo, LaserTargetCovarianceAddsTheAttitudeErrorOverTheSlantRange) {
  const VehicleState v = vehicle_at(22.5, 113.9, 400.0);
  // The target 390 m straight below: the attitude error (0.5 deg) spans 390 * 0.5 * pi / 180 =
  // 3.4034 m, squared 11.583 m^2, plus the range error's 1 m^2: 12.583 on each diagonal entry.
  const std::optional<geo::Covariance3> c = laser_target_covariance({22.5, 113.9, 10.0}, v);
  ASSERT_TRUE(c);
  EXPECT_NEAR((*c)[0], 4.0 + 12.583, 0.01);
  EXPECT_NEAR((*c)[4], 4.0 + 12.583, 0.01);
  EXPECT_NEAR((*c)[8], 16.0 + 12.583, 0.01);
  EXPECT_EQ((*c)[1], 0.0);
  geo::RayUncertainty exact;
  exact.attitude_sigma_deg = 0.0;
  exact.range_sigma_m = 0.0;
  EXPECT_EQ(laser_target_covariance({22.5, 113.9, 10.0}, v, exact), v.position_covariance);
  EXPECT_FALSE(laser_target_covariance({22.5, 113.9, 10.0}, VehicleState()));  // no fix
}

TEST(VehicleGeo, PlaneHeightsAreGivenAboveTheTakeoffPointOrSeaLevel) {
  VehicleState v = vehicle_at(47.1, 8.5, 530.0);
  v.relative_altitude_m = 30.0;  // took off at 500 m above the ellipsoid
  const Result<double> takeoff = plane_height_ellipsoid(v, PlaneReference::kAboveTakeoff, 10.0);
  ASSERT_TRUE(takeoff) << takeoff.error();
  EXPECT_DOUBLE_EQ(takeoff.value(), 510.0);
  // The EGM96 geoid is 47.9 m above the ellipsoid at 47.1N 8.5E.
  const Result<double> msl = plane_height_ellipsoid(v, PlaneReference::kMeanSeaLevel, 100.0);
  ASSERT_TRUE(msl) << msl.error();
  EXPECT_NEAR(msl.value(), 147.9, 0.2);
}

}  // namespace
}  // namespace k40t::driver
