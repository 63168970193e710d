// locate_pixel's rule without ROS (driver/pixel_locator.h), on a fixed mounting worked out by
// hand: a camera and a laser both looking straight down from a level vehicle heading north, on
// the equator, 100 m above its take-off point. Camera 1280x1024, fx = fy = 1000 px, centre
// (640, 512), no distortion; image right = east, image down = south.
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/driver/pixel_locator.h"

namespace k40t::driver {
namespace {

// WGS 84 at the equator: a * pi / 180 metres per degree of longitude.
constexpr double kMetresPerDegreeAtEquator = 6378137.0 * M_PI / 180.0;

VehicleState hovering_vehicle() {
  VehicleState v;
  v.has_fix = true;
  v.latitude_deg = 0.0;
  v.longitude_deg = 10.0;
  v.altitude_m = 300.0;           // ellipsoid
  v.relative_altitude_m = 100.0;  // the take-off point is at 200 m
  v.has_attitude = true;
  v.heading_deg = 0.0;
  return v;
}

CameraView down_camera() {
  CameraView view;
  view.lens.K = {1000, 0, 640, 0, 1000, 512, 0, 0, 1};
  view.width = 1280;
  view.height = 1024;
  view.frame = "camera_optical";
  return view;
}

// The mounting: the optical frame's z (forward) is the body's -z (down), its x (right) the
// body's -y (the right wing), its y (image down) the body's -x (backwards). The laser frame's x
// is the body's -z as well. Both at the body's origin. The map swaps and negates axes, so it is its
// own inverse: one function turns optical into body directions and back.
geo::Vector3 swap_optical_body(const geo::Vector3& d) {
  return {-d[1], -d[0], -d[2]};
}

FrameRay fixed_mounting() {
  return [](const std::string& target, const std::string& source,
            const geo::Vector3& d) -> Result<geo::BodyRay> {
    if (target == "base_link" && source == "camera_optical")
      return geo::BodyRay{{0, 0, 0}, swap_optical_body(d)};
    if (target == "camera_optical" && source == "laser")  // laser x = body -z
      return geo::BodyRay{{0, 0, 0}, swap_optical_body({0, 0, -d[0]})};
    return Result<geo::BodyRay>::fail("no transform from " + source + " to " + target);
  };
}

PixelLocatorSetup setup() {
  PixelLocatorSetup s;
  s.vehicle_frame = "base_link";
  s.laser_frame = "laser";
  return s;
}

PixelQuery pixel(double u, double v) {
  PixelQuery q;
  q.u = u;
  q.v = v;
  return q;  // plane 0 m above the take-off point, laser allowed
}

TEST(PixelLocator, TheImageCentreIsStraightBelowOnTheTakeOffPlane) {
  const Result<PixelLocation> at = locate_pixel(pixel(640, 512), down_camera(), hovering_vehicle(),
                                                std::nullopt, fixed_mounting(), setup());
  ASSERT_TRUE(at) << at.error();
  EXPECT_FALSE(at->on_laser_axis);  // no range yet
  EXPECT_NEAR(at->located.position.latitude_deg, 0.0, 1e-8);
  EXPECT_NEAR(at->located.position.longitude_deg, 10.0, 1e-8);
  EXPECT_NEAR(at->located.position.height_ellipsoid_m, 200.0, 0.01);
  EXPECT_NEAR(at->located.slant_range_m, 100.0, 0.01);
  ASSERT_TRUE(at->altitude_msl);  // the EGM96 grid covers the equator
}

TEST(PixelLocator, APixelRightOfCentreIsEastByDepthTimesItsNormalisedOffset) {
  // (740, 512): x = 100 / 1000 = 0.1, so 100 m down is 10 m east; slant sqrt(100^2 + 10^2).
  const Result<PixelLocation> at = locate_pixel(pixel(740, 512), down_camera(), hovering_vehicle(),
                                                std::nullopt, fixed_mounting(), setup());
  ASSERT_TRUE(at) << at.error();
  EXPECT_NEAR(at->located.position.latitude_deg, 0.0, 1e-8);
  EXPECT_NEAR((at->located.position.longitude_deg - 10.0) * kMetresPerDegreeAtEquator, 10.0, 0.01);
  EXPECT_NEAR(at->located.slant_range_m, std::hypot(100.0, 10.0), 0.01);
  EXPECT_NEAR(at->optical[0], 0.1, 1e-9);
  EXPECT_NEAR(at->optical[1], 0.0, 1e-9);
}

TEST(PixelLocator, APixelOnTheLaserAxisEndsAtTheRange) {
  // The laser looks straight down too: its axis appears at the centre; 5 px off is within the
  // 8 px tolerance, so the 80 m range ends the ray (not the plane 100 m down).
  const Result<PixelLocation> at = locate_pixel(pixel(645, 512), down_camera(), hovering_vehicle(),
                                                80.0, fixed_mounting(), setup());
  ASSERT_TRUE(at) << at.error();
  EXPECT_TRUE(at->on_laser_axis);
  EXPECT_NEAR(at->located.slant_range_m, 80.0, 1e-6);
  EXPECT_NEAR(at->located.position.height_ellipsoid_m, 300.0 - 80.0, 0.01);

  // 60 px off the axis: the plane.
  const Result<PixelLocation> off = locate_pixel(pixel(700, 512), down_camera(), hovering_vehicle(),
                                                 80.0, fixed_mounting(), setup());
  ASSERT_TRUE(off) << off.error();
  EXPECT_FALSE(off->on_laser_axis);
  EXPECT_NEAR(off->located.position.height_ellipsoid_m, 200.0, 0.01);

  // use_laser false: the plane even on the axis.
  PixelQuery no_laser = pixel(640, 512);
  no_laser.use_laser = false;
  const Result<PixelLocation> plane =
      locate_pixel(no_laser, down_camera(), hovering_vehicle(), 80.0, fixed_mounting(), setup());
  ASSERT_TRUE(plane) << plane.error();
  EXPECT_FALSE(plane->on_laser_axis);
  EXPECT_NEAR(plane->located.slant_range_m, 100.0, 0.01);
}

TEST(PixelLocator, APlaneGivenAboveTheTakeOffPointIsThatMuchHigher) {
  PixelQuery q = pixel(640, 512);
  q.plane_height = 30.0;  // 230 m ellipsoid: 70 m below the vehicle
  const Result<PixelLocation> at =
      locate_pixel(q, down_camera(), hovering_vehicle(), std::nullopt, fixed_mounting(), setup());
  ASSERT_TRUE(at) << at.error();
  EXPECT_NEAR(at->located.slant_range_m, 70.0, 0.01);
}

TEST(PixelLocator, BadInputAndMissingInputsAreClearErrors) {
  const auto error_of = [](const PixelQuery& q, const VehicleState& v, const FrameRay& rays) {
    const Result<PixelLocation> at = locate_pixel(q, down_camera(), v, std::nullopt, rays, setup());
    return at ? std::string("located") : at.error();
  };
  const VehicleState v = hovering_vehicle();
  EXPECT_EQ(error_of(pixel(std::nan(""), 3), v, fixed_mounting()), "u, v must be finite");
  EXPECT_EQ(error_of(pixel(1300, 3), v, fixed_mounting()),
            "u, v must be inside the 1280x1024 image");
  EXPECT_EQ(error_of(pixel(-1, 3), v, fixed_mounting()), "u, v must be inside the 1280x1024 image");
  PixelQuery bad_reference = pixel(640, 512);
  bad_reference.plane_reference = 2;
  EXPECT_EQ(error_of(bad_reference, v, fixed_mounting()),
            "plane_reference must be 0 (ABOVE_TAKEOFF) or 1 (MSL)");
  PixelQuery bad_height = pixel(640, 512);
  bad_height.plane_height = INFINITY;
  EXPECT_EQ(error_of(bad_height, v, fixed_mounting()), "plane_height must be finite");
  EXPECT_EQ(error_of(pixel(640, 512), VehicleState{}, fixed_mounting()),
            "no vehicle fix (topic fix)");
  const FrameRay no_tf = [](const std::string&, const std::string& source, const geo::Vector3&) {
    return Result<geo::BodyRay>::fail("no transform from " + source);
  };
  EXPECT_EQ(error_of(pixel(640, 512), v, no_tf), "no transform from camera_optical");
  PixelQuery above = pixel(640, 512);
  above.plane_height = 150.0;  // 350 m ellipsoid: above the vehicle, which looks down
  EXPECT_EQ(error_of(above, v, fixed_mounting()),
            "the pixel's ray misses the ground plane (above the horizon or beyond 10 km)");
}

}  // namespace
}  // namespace k40t::driver
