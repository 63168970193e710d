// The vehicle topics' rules (driver/vehicle_inputs.h), ROS-free: ENU orientation -> aviation
// angles, a zero quaternion ignored, the first fix as the take-off reference, sea-level heights.
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/driver/vehicle_inputs.h"

namespace k40t::driver {
namespace {

// The quaternion of R = Rz(yaw) Ry(pitch) Rx(roll), as tf2's setRPY() gives it.
geo::Orientation from_rpy(double roll, double pitch, double yaw) {
  const double cr = std::cos(roll / 2), sr = std::sin(roll / 2);
  const double cp = std::cos(pitch / 2), sp = std::sin(pitch / 2);
  const double cy = std::cos(yaw / 2), sy = std::sin(yaw / 2);
  return {sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy,
          cr * cp * cy + sr * sp * sy};
}

TEST(VehicleState, ImuEnuBecomesAviationAngles) {
  VehicleState s;
  apply_enu_orientation(s, from_rpy(0.0, 0.1, M_PI / 2));  // facing north, nose down 0.1 rad
  EXPECT_TRUE(s.has_attitude);
  EXPECT_NEAR(s.heading_deg, 0.0, 1e-6);
  EXPECT_NEAR(s.pitch_deg, -0.1 * 180 / M_PI, 1e-6);  // nose down is negative in aviation
  apply_enu_orientation(s, from_rpy(0.2, 0.0, 0.0));  // facing east, right side down
  EXPECT_NEAR(s.heading_deg, 90.0, 1e-6);
  EXPECT_NEAR(s.roll_deg, 0.2 * 180 / M_PI, 1e-6);
}

TEST(VehicleState, ImuWithoutOrientationIsIgnored) {
  VehicleState s;
  apply_enu_orientation(s, {0.0, 0.0, 0.0, 0.0});  // all zeros: "no orientation"
  EXPECT_FALSE(s.has_attitude);
}

TEST(VehicleState, FirstFixIsTheRelativeAltitudeReference) {
  VehicleState s;
  double reference = std::nan("");
  GnssFix fix;
  fix.quality = GnssFix::Quality::kFix;
  fix.latitude_deg = 47.1;
  fix.longitude_deg = 8.5;
  fix.altitude_m = 500.0;
  fix.stamp_ns = 1700000000250000000;
  apply_fix(s, fix, &reference);
  EXPECT_TRUE(s.has_fix);
  EXPECT_EQ(s.gps_status, 3);
  EXPECT_EQ(s.utc_ms, 1700000000250);
  EXPECT_DOUBLE_EQ(s.relative_altitude_m, 0.0);
  fix.altitude_m = 530.0;
  apply_fix(s, fix, &reference);
  EXPECT_DOUBLE_EQ(s.relative_altitude_m, 30.0);
  EXPECT_DOUBLE_EQ(s.altitude_m, 530.0);
  // Sea level for the pod: the EGM96 geoid is 47.9 m above the ellipsoid at 47.1N 8.5E.
  EXPECT_NEAR(s.altitude_msl_m, 530.0 - 47.9, 0.2);
  fix.quality = GnssFix::Quality::kNone;
  apply_fix(s, fix, &reference);
  EXPECT_FALSE(s.has_fix);
}

// 0x000320 byte 2 (section 3.2.4.24): 2 = 2D, 3 = 3D, 4 = 3D with DGPS/SBAS, 6 = fixed RTK. A
// GBAS fix (DGPS, float or fixed RTK alike) used to go out as fixed RTK, a fix without a height
// as 3D.
TEST(VehicleState, TheGpsStatusClaimsNoMoreThanTheFixHas) {
  VehicleState s;
  double reference = std::nan("");
  GnssFix fix;
  fix.latitude_deg = 47.1;
  fix.longitude_deg = 8.5;
  fix.altitude_m = 500.0;
  const std::pair<GnssFix::Quality, int> with_height[] = {{GnssFix::Quality::kNone, 1},
                                                          {GnssFix::Quality::kFix, 3},
                                                          {GnssFix::Quality::kSbas, 4},
                                                          {GnssFix::Quality::kGbas, 4}};
  for (const auto& [quality, status] : with_height) {
    fix.quality = quality;
    apply_fix(s, fix, &reference);
    EXPECT_EQ(s.gps_status, status) << static_cast<int>(quality);
  }
  fix.altitude_m = std::nan("");
  fix.quality = GnssFix::Quality::kFix;
  apply_fix(s, fix, &reference);
  EXPECT_EQ(s.gps_status, 2) << "no height: 2D";
  fix.quality = GnssFix::Quality::kGbas;
  apply_fix(s, fix, &reference);
  EXPECT_EQ(s.gps_status, 2);
}

}  // namespace
}  // namespace k40t::driver
