// The simulated laser rangefinder (section 3.2.5) and the target geolocation of 0x000320.
#include <gtest/gtest.h>

#include <cmath>

#include "geo_test_support.h"
#include "k40t_driver/sim/laser_model.h"

namespace k40t::sim {
namespace {

TEST(SimLaser, RangeOverFlatGroundIsHeightOverSineOfDepression) {
  WorldConfig config;
  config.ground_height_m = 50;
  config.hot.north_m = -500;  // out of the way, behind the pod
  config.cold.north_m = -500;
  const World world(config);
  const LaserModel laser;
  for (double depression : {5.0, 10.0, 30.0, 60.0, 90.0}) {
    const auto range = laser.range(world, 0, -depression);
    ASSERT_TRUE(range) << depression;
    EXPECT_NEAR(*range, 50 / std::sin(deg_to_rad(depression)), 1e-6) << depression;
  }
}

TEST(SimLaser, NoReturnAboveTheHorizonOrBeyondMaximumRange) {
  WorldConfig config;
  config.ground_height_m = 30;
  const World world(config);
  const LaserModel laser(LaserConfig{3000});
  EXPECT_FALSE(laser.range(world, 0, 0));
  EXPECT_FALSE(laser.range(world, 0, 10));
  // 30 / sin(0.5 deg) = 3438 m: past 3000 m.
  EXPECT_FALSE(laser.range(world, 180, -0.5));
  EXPECT_TRUE(laser.range(world, 180, -0.6));
}

TEST(SimLaser, AimedAtTheHotObjectItRangesTheObject) {
  const World world;
  const LaserModel laser;
  const Vec3 centre = world.hot_object_centre();
  const auto range = laser.range(world, yaw_of(centre), pitch_of(centre));
  ASSERT_TRUE(range);
  EXPECT_NEAR(*range, norm(centre) - world.config().hot.radius_m, 1e-6);
  const double ground = world.config().ground_height_m / std::sin(deg_to_rad(-pitch_of(centre)));
  EXPECT_LT(*range, ground);
}

TEST(SimLaser, TargetIsWhereTheBeamHits) {
  WorldConfig config;
  config.ground_height_m = 100;
  config.hot.north_m = -500;
  const World world(config);
  const LaserModel laser;
  GeoPoint pod{47.0, 8.0, 100, 600};
  // 45 degrees down, heading east: the spot is 100 m east and 100 m below.
  const auto target = laser.locate_target(world, pod, 90, -45);
  ASSERT_TRUE(target);
  // Due east along the tangent plane ends a little south of the parallel (0.8 mm at 100 m).
  EXPECT_NEAR(test::metres_north(47.0, target->latitude_deg, 600), 0, 2e-3);
  EXPECT_NEAR(test::metres_east(47.0, 8.0, target->longitude_deg, 600), 100, 1e-3);
  // 100 m along the tangent plane the ellipsoid has dropped by d^2 / 2R = 0.8 mm (and the
  // geoid moved by less than that): the spot is that much higher above the ground.
  EXPECT_NEAR(target->relative_height_m, 0, 2e-3);
  EXPECT_GT(target->relative_height_m, 0);
  EXPECT_NEAR(target->altitude_m, 500, 2e-3);
  EXPECT_FALSE(laser.locate_target(world, pod, 90, 10));
}

}  // namespace
}  // namespace k40t::sim
