// The simulated thermal camera (sections 3.2.1.2 and 3.2.2): a scene fixed in the world, seen
// through the gimbal's attitude and the thermal zoom.
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/sim/lens.h"
#include "k40t_driver/sim/thermal_model.h"

namespace k40t::sim {
namespace {

struct Aim {
  double yaw_deg;
  double pitch_deg;
};
Aim aim_at(const Vec3& point) {
  return {yaw_of(point), pitch_of(point)};
}

constexpr int kCentreX = 800;  // middle of x 320..1279
constexpr int kCentreY = 528;  // middle of y 32..1023

// The scene's statistics with the thermal camera aimed straight at `point`.
ThermalStats measured_at(const World& world, const ThermalModel& thermal, const Vec3& point) {
  const Aim aim = aim_at(point);
  return thermal.measure(world, aim.yaw_deg, aim.pitch_deg);
}

void expect_at_the_centre(const PixelPoint& at) {
  EXPECT_NEAR(at.x, kCentreX, 3);
  EXPECT_NEAR(at.y, kCentreY, 3);
}

// The default scene and a thermal camera with its default settings.
class SimThermal : public ::testing::Test {
 protected:
  const World world;
  ThermalModel thermal;
};

TEST_F(SimThermal, MaximumSitsOnTheHotObjectWhenAimedAtIt) {
  const ThermalStats stats = measured_at(world, thermal, world.hot_object_centre());
  EXPECT_NEAR(stats.max_degC, world.config().hot.temperature_degC, 0.5);
  expect_at_the_centre(stats.max_at);
  EXPECT_NEAR(stats.centre_degC, stats.max_degC, 0.5);
  EXPECT_GT(stats.max_degC, stats.average_degC);
  EXPECT_GE(stats.average_degC, stats.min_degC);
}

TEST_F(SimThermal, MaximumMovesAcrossTheImageAsYawChanges) {
  const Aim aim = aim_at(world.hot_object_centre());
  const double tan_half = std::tan(deg_to_rad(field_of_view(Lens::kThermal, 1).horizontal_deg / 2));
  int previous_x = 100000;
  for (double turn : {-6.0, -3.0, 0.0, 3.0, 6.0}) {
    const ThermalStats stats = thermal.measure(world, aim.yaw_deg + turn, aim.pitch_deg);
    // Turning right moves the object left in the image, by the projection of the turn.
    EXPECT_LT(stats.max_at.x, previous_x) << "turn " << turn;
    previous_x = stats.max_at.x;
    // Where the object's centre projects (pinhole through the turned, pitched camera).
    const CameraBasis basis = camera_basis(aim.yaw_deg + turn, aim.pitch_deg);
    const Vec3 hot = world.hot_object_centre();
    const double expected_x =
        kCentreX + dot(hot, basis.right) / dot(hot, basis.forward) / tan_half * 480;
    EXPECT_NEAR(stats.max_at.x, expected_x, 3) << "turn " << turn;
    EXPECT_LT(std::abs(stats.max_at.x - kCentreX), std::abs(turn) * 30 + 3) << "turn " << turn;
    EXPECT_NEAR(stats.max_degC, world.config().hot.temperature_degC, 1.0) << "turn " << turn;
  }
  // Turned away, the hot object is out of view and the maximum is the ground's.
  const ThermalStats away = thermal.measure(world, aim.yaw_deg + 40, aim.pitch_deg);
  EXPECT_LT(away.max_degC,
            world.config().ground_temperature_degC + world.config().ground_texture_degC + 0.1);
}

TEST_F(SimThermal, DigitalZoomMagnifiesTheOffsetFromCentre) {
  const Aim aim = aim_at(world.hot_object_centre());
  const ThermalStats wide = thermal.measure(world, aim.yaw_deg - 2, aim.pitch_deg);
  ASSERT_EQ(thermal.set_digital_zoom(2), Outcome::kOk);
  const ThermalStats zoomed = thermal.measure(world, aim.yaw_deg - 2, aim.pitch_deg);
  EXPECT_NEAR(zoomed.max_at.x - kCentreX, 2 * (wide.max_at.x - kCentreX), 4);
  EXPECT_EQ(thermal.set_digital_zoom(9), Outcome::kFailure);
}

TEST_F(SimThermal, MinimumSitsOnTheColdObject) {
  const ThermalStats stats = measured_at(world, thermal, world.cold_object_centre());
  EXPECT_NEAR(stats.min_degC, world.config().cold.temperature_degC, 0.5);
  expect_at_the_centre(stats.min_at);
}

TEST_F(SimThermal, SkyIsColdestAboveTheHorizon) {
  const ThermalStats stats = thermal.measure(world, 0, 30);
  EXPECT_LT(stats.max_degC, world.config().sky_horizon_degC + 0.1);
  EXPECT_EQ(stats.min_at.y, ThermalFrame::kTop);  // highest elevation: top row
}

TEST_F(SimThermal, SpotReadsThePixelItIsSetOn) {
  const Aim aim = aim_at(world.hot_object_centre());
  const ThermalStats overview = thermal.measure(world, aim.yaw_deg + 5, aim.pitch_deg);
  ASSERT_EQ(thermal.set_spot(overview.max_at.x, overview.max_at.y), Outcome::kOk);
  const ThermalStats spot = thermal.measure(world, aim.yaw_deg + 5, aim.pitch_deg);
  EXPECT_NEAR(spot.spot_degC, overview.max_degC, 1.0);
  EXPECT_EQ(spot.spot_at.x, overview.max_at.x);
  EXPECT_EQ(thermal.settings().reported.measurement_type, MeasurementType::kPoint);
  EXPECT_EQ(thermal.set_spot(100, 500), Outcome::kFailure);  // on the black border
}

TEST_F(SimThermal, AreaMeasurementLooksOnlyInsideTheRectangle) {
  const Aim aim = aim_at(world.hot_object_centre());
  // A rectangle in the left half of the image: the hot object at the centre is outside it.
  ASSERT_EQ(thermal.set_area(300, 400, 500, 528), Outcome::kOk);
  const ThermalStats stats = thermal.measure(world, aim.yaw_deg, aim.pitch_deg);
  EXPECT_LT(stats.max_degC, 30);
  EXPECT_GE(stats.max_at.x, 350);
  EXPECT_LE(stats.max_at.x, 650);
  EXPECT_EQ(stats.centre_at.x / 10, 50);
  EXPECT_EQ(thermal.set_area(400, 100, 400, 528), Outcome::kFailure);  // sticks out on the left
}

TEST_F(SimThermal, AlarmsTripAtTheirThresholds) {
  const Aim aim = aim_at(world.hot_object_centre());
  const ThermalStats plain = thermal.measure(world, aim.yaw_deg, aim.pitch_deg);
  EXPECT_FALSE(plain.high_alarm || plain.low_alarm || plain.difference_alarm ||
               plain.threshold_alarm);

  ASSERT_EQ(thermal.set_alarms(plain.max_degC - 1, plain.min_degC + 1,
                               plain.max_degC - plain.min_degC - 1),
            Outcome::kOk);
  ThermalStats s = thermal.measure(world, aim.yaw_deg, aim.pitch_deg);
  EXPECT_TRUE(s.high_alarm);
  EXPECT_TRUE(s.low_alarm);
  EXPECT_TRUE(s.difference_alarm);

  ASSERT_EQ(thermal.set_alarms(plain.max_degC + 1, plain.min_degC - 1,
                               plain.max_degC - plain.min_degC + 1),
            Outcome::kOk);
  s = thermal.measure(world, aim.yaw_deg, aim.pitch_deg);
  EXPECT_FALSE(s.high_alarm);
  EXPECT_FALSE(s.low_alarm);
  EXPECT_FALSE(s.difference_alarm);

  // Threshold alarm: the region leaves reference +- float (85 degC is far above 20 + 10).
  ASSERT_EQ(thermal.set_threshold_alarm(true, 20, 10), Outcome::kOk);
  EXPECT_TRUE(thermal.measure(world, aim.yaw_deg, aim.pitch_deg).threshold_alarm);
  ASSERT_EQ(thermal.set_threshold_alarm(true, 50, 80), Outcome::kOk);
  EXPECT_FALSE(thermal.measure(world, aim.yaw_deg, aim.pitch_deg).threshold_alarm);
  EXPECT_EQ(thermal.set_threshold_alarm(true, 51, 10), Outcome::kFailure);
  EXPECT_EQ(thermal.set_alarms(501, std::nullopt, std::nullopt), Outcome::kFailure);
}

TEST(SimThermalGain, HighGainSaturatesWhereLowGainMeasures) {
  WorldConfig config;
  config.hot.temperature_degC = 300;
  const World world(config);
  ThermalModel thermal;
  const Aim aim = aim_at(world.hot_object_centre());
  EXPECT_DOUBLE_EQ(thermal.measure(world, aim.yaw_deg, aim.pitch_deg).max_degC,
                   gain_range(GainMode::kHigh).max_degC);
  thermal.settings().reported.gain_mode = GainMode::kLow;
  EXPECT_NEAR(thermal.measure(world, aim.yaw_deg, aim.pitch_deg).max_degC, 300, 1);
  thermal.settings().reported.gain_mode = GainMode::kAuto;
  EXPECT_NEAR(thermal.measure(world, aim.yaw_deg, aim.pitch_deg).max_degC, 300, 1);
}

TEST(SimThermalFrame, FrameCoordinatesMapTheSensorOntoTheDocumentsActiveArea) {
  EXPECT_EQ(ThermalFrame::from_sensor(0, 0).x, ThermalFrame::kLeft);
  EXPECT_EQ(ThermalFrame::from_sensor(0, 0).y, ThermalFrame::kTop);
  EXPECT_EQ(ThermalFrame::from_sensor(639, 511).x, ThermalFrame::kRight);
  EXPECT_EQ(ThermalFrame::from_sensor(639, 511).y, ThermalFrame::kBottom);
  EXPECT_NEAR(ThermalFrame::sensor_u(ThermalFrame::from_sensor(200, 100).x), 200.5, 1.0);
}

}  // namespace
}  // namespace k40t::sim
