// geo/ray_locator.h: rays from the vehicle to the Earth, and their first-order covariance.
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/geo/ray_locator.h"

namespace k40t::geo {
namespace {

VehiclePose pose_at(double heading, double pitch = 0, double roll = 0) {
  VehiclePose pose;
  pose.position = {47.0, 8.0, 600.0};
  pose.position_covariance = {};
  pose.heading_deg = heading;
  pose.pitch_deg = pitch;
  pose.roll_deg = roll;
  return pose;
}

constexpr RayUncertainty kExact{0, 0, 0};

TEST(RayLocator, HeadingTurnsTheBodyFrame) {
  const Result<Located> east = locate_at_range(pose_at(90), BodyRay{}, 100, kExact);
  ASSERT_TRUE(east) << east.error();
  EXPECT_NEAR(east->offset.east, 100, 1e-9);
  EXPECT_NEAR(east->offset.north, 0, 1e-9);
  EXPECT_NEAR(east->slant_range_m, 100, 1e-9);
  // Body y is left: heading north, left is west.
  const Result<Located> left =
      locate_at_range(pose_at(0), BodyRay{{0, 0, 0}, {0, 1, 0}}, 10, kExact);
  EXPECT_NEAR(left->offset.east, -10, 1e-9);
  // Nose up 30 deg lifts the forward ray; right wing down 90 deg turns body y (left) up.
  const Result<Located> up = locate_at_range(pose_at(0, 30), BodyRay{}, 10, kExact);
  EXPECT_NEAR(up->offset.up, 5, 1e-9);
  const Result<Located> rolled =
      locate_at_range(pose_at(0, 0, 90), BodyRay{{0, 0, 0}, {0, 1, 0}}, 10, kExact);
  EXPECT_NEAR(rolled->offset.up, 10, 1e-9);
}

TEST(RayLocator, TheOriginIsTheSensorsPlaceOnTheVehicle) {
  const Result<Located> p =
      locate_at_range(pose_at(0), BodyRay{{1, 0, -0.5}, {0, 0, -1}}, 20, kExact);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->offset.north, 1, 1e-9);
  EXPECT_NEAR(p->offset.up, -20.5, 1e-9);
  // Its geodetic position: 20.5 m below the vehicle (plus the tangent plane's drop, 0.08 mm).
  EXPECT_NEAR(p->position.height_ellipsoid_m, 579.5, 1e-3);
}

TEST(RayLocator, APlaneBelowEndsTheRayOrItMisses) {
  const BodyRay down45{{0, 0, 0}, {1, 0, -1}};
  const Result<Located> hit = locate_on_plane(pose_at(0), down45, -30, kExact);
  ASSERT_TRUE(hit) << hit.error();
  EXPECT_NEAR(hit->offset.north, 30, 1e-9);
  EXPECT_NEAR(hit->offset.up, -30, 1e-9);
  EXPECT_NEAR(hit->slant_range_m, 30 * std::sqrt(2.0), 1e-9);
  EXPECT_FALSE(locate_on_plane(pose_at(0), BodyRay{{0, 0, 0}, {1, 0, 0.2}}, -30, kExact));
  EXPECT_FALSE(locate_on_plane(pose_at(0), down45, -30, kExact, 40.0));  // beyond the range
  EXPECT_FALSE(locate_at_range(pose_at(0), down45, -1, kExact));
}

TEST(RayLocator, RangeAndPointingErrorsLieAlongAndAcrossTheRay) {
  // Heading east, level: the ray is the east axis.
  RayUncertainty range_only{0, 0, 2.0};
  const Result<Located> a = locate_at_range(pose_at(90), BodyRay{}, 500, range_only);
  ASSERT_TRUE(a);
  EXPECT_NEAR(a->covariance[0], 4.0, 1e-6);  // east-east: sigma_r^2
  EXPECT_NEAR(a->covariance[4], 0.0, 1e-6);
  EXPECT_NEAR(a->covariance[8], 0.0, 1e-6);
  RayUncertainty pointing_only{0, 0.1, 0};
  const Result<Located> b = locate_at_range(pose_at(90), BodyRay{}, 500, pointing_only);
  const double across = 500 * 0.1 * M_PI / 180;  // 0.87 m at 500 m
  EXPECT_NEAR(b->covariance[0], 0.0, 1e-6);
  EXPECT_NEAR(b->covariance[4], across * across, 1e-4);
  EXPECT_NEAR(b->covariance[8], across * across, 1e-4);
  // The fix's covariance passes through unchanged.
  VehiclePose fixed = pose_at(90);
  fixed.position_covariance = {1, 0.5, 0, 0.5, 2, 0, 0, 0, 3};
  const Result<Located> c = locate_at_range(fixed, BodyRay{}, 500, kExact);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(c->covariance[i], fixed.position_covariance[i], 1e-6);
}

TEST(RayLocator, OnAPlaneAHeadingErrorMovesThePointSideways) {
  // 45 deg down to a plane 100 m below, heading north; 1 deg on each attitude angle.
  RayUncertainty heading{1.0, 0, 0};
  const Result<Located> p =
      locate_on_plane(pose_at(0), BodyRay{{0, 0, 0}, {1, 0, -1}}, -100, heading);
  ASSERT_TRUE(p);
  // Sideways (east): a heading error swings the point at 100 m horizontal distance, a roll error
  // tilts the ray's 100 m of drop sideways: (100 m x 1 deg)^2 twice.
  const double sideways = 100 * M_PI / 180;
  EXPECT_NEAR(p->covariance[0], 2 * sideways * sideways, 1e-3);
  // Pitch error along the ray's ground track: d(100 / tan(e))/de = 100 / sin^2(e) = 200 m/rad.
  EXPECT_NEAR(p->covariance[4], std::pow(200 * M_PI / 180, 2), 1e-2);
  EXPECT_NEAR(p->covariance[8], 0, 1e-9);  // on the plane
}

}  // namespace
}  // namespace k40t::geo
