// camera/pixel_ray.h: pixels to rays through K and OpenCV's lens distortion, checked against the
// distortion models as ROS's camera_info documents them (plumb_bob: Brown-Conrady k1 k2 p1 p2 k3;
// equidistant: Kannala-Brandt theta_d = theta (1 + k1 theta^2 + k2 theta^4 + k3 theta^6 +
// k4 theta^8)) written out below, so a wrong undistortion fails.
#include <cmath>

#include <gtest/gtest.h>

#include "k40t_driver/camera/pixel_ray.h"

namespace k40t::camera {
namespace {

constexpr double kFx = 1000, kFy = 1010, kCx = 640.5, kCy = 359.5;

CameraModel model(const std::string& name, std::vector<double> d) {
  CameraModel m;
  m.K = {kFx, 0, kCx, 0, kFy, kCy, 0, 0, 1};
  m.distortion_model = name;
  m.D = std::move(d);
  return m;
}

// Where the normalised point (x, y) lands in the image under plumb_bob.
std::array<double, 2> plumb_bob_pixel(const std::vector<double>& d, double x, double y) {
  const double k1 = d[0], k2 = d[1], p1 = d[2], p2 = d[3], k3 = d[4];
  const double r2 = x * x + y * y;
  const double radial = 1 + k1 * r2 + k2 * r2 * r2 + k3 * r2 * r2 * r2;
  const double xd = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x);
  const double yd = y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y;
  return {kFx * xd + kCx, kFy * yd + kCy};
}

std::array<double, 2> equidistant_pixel(const std::vector<double>& d, double x, double y) {
  const double r = std::hypot(x, y);
  const double t = std::atan(r);
  const double t2 = t * t;
  const double td =
      t * (1 + d[0] * t2 + d[1] * t2 * t2 + d[2] * t2 * t2 * t2 + d[3] * t2 * t2 * t2 * t2);
  const double s = r > 0 ? td / r : 1;
  return {kFx * x * s + kCx, kFy * y * s + kCy};
}

TEST(PixelRay, WithoutDistortionItIsThePinhole) {
  const CameraModel m = model("plumb_bob", {0, 0, 0, 0, 0});
  EXPECT_FALSE(has_distortion(m));
  const auto n = pixel_to_normalised(m, 1640.5, 359.5 - 505);
  ASSERT_TRUE(n) << n.error();
  EXPECT_NEAR((*n)[0], 1.0, 1e-12);
  EXPECT_NEAR((*n)[1], -0.5, 1e-12);
  // An unknown model with an all-zero D is a pinhole too (nothing to undistort).
  EXPECT_TRUE(pixel_to_normalised(model("", {}), 10, 10));
}

TEST(PixelRay, AHandComputedBarrelDistortionIsUndone) {
  // k1 = -0.2 alone: (0.3, 0.2) has r^2 = 0.13, so it is drawn at 0.974 x (0.3, 0.2):
  // u = 640.5 + 1000 x 0.2922 = 932.7, v = 359.5 + 1010 x 0.1948 = 556.248.
  const CameraModel m = model("plumb_bob", {-0.2, 0, 0, 0, 0});
  const auto n = pixel_to_normalised(m, 932.7, 556.248);
  ASSERT_TRUE(n) << n.error();
  EXPECT_NEAR((*n)[0], 0.3, 1e-9);
  EXPECT_NEAR((*n)[1], 0.2, 1e-9);
  // The pinhole alone would be 2.7 % off: the distortion is not ignored.
  EXPECT_GT(
      std::abs(pixel_to_normalised(model("plumb_bob", {0, 0, 0, 0, 0}), 932.7, 556.248).value()[0] -
               0.3),
      0.007);
  const auto p = project_ray(m, {0.6, 0.4, 2.0});  // the same ray, not unit length
  ASSERT_TRUE(p) << p.error();
  EXPECT_NEAR((*p)[0], 932.7, 1e-9);
  EXPECT_NEAR((*p)[1], 556.248, 1e-9);
}

TEST(PixelRay, PlumbBobWithTangentialTermsOverTheImage) {
  const std::vector<double> d{-0.28, 0.09, 0.0012, -0.0008, -0.015};
  const CameraModel m = model("plumb_bob", d);
  for (double x = -0.6; x <= 0.61; x += 0.2) {
    for (double y = -0.35; y <= 0.36; y += 0.1) {
      const auto pixel = plumb_bob_pixel(d, x, y);
      const auto n = pixel_to_normalised(m, pixel[0], pixel[1]);
      ASSERT_TRUE(n) << n.error();
      EXPECT_NEAR((*n)[0], x, 1e-7) << x << " " << y;
      EXPECT_NEAR((*n)[1], y, 1e-7) << x << " " << y;
      const auto back = project_ray(m, {x, y, 1});
      ASSERT_TRUE(back) << back.error();
      EXPECT_NEAR((*back)[0], pixel[0], 1e-6);
      EXPECT_NEAR((*back)[1], pixel[1], 1e-6);
    }
  }
}

TEST(PixelRay, RationalPolynomialTakesEightCoefficients) {
  // k4..k6 = 0: the same as plumb_bob with those k1 k2 p1 p2 k3.
  const std::vector<double> d{-0.28, 0.09, 0.0012, -0.0008, -0.015, 0, 0, 0};
  const auto pixel = plumb_bob_pixel(d, 0.4, -0.25);
  const auto n = pixel_to_normalised(model("rational_polynomial", d), pixel[0], pixel[1]);
  ASSERT_TRUE(n) << n.error();
  EXPECT_NEAR((*n)[0], 0.4, 1e-7);
  EXPECT_NEAR((*n)[1], -0.25, 1e-7);
}

TEST(PixelRay, EquidistantIsOpenCVsFisheye) {
  const std::vector<double> d{0.05, -0.01, 0.002, -0.0005};
  const CameraModel m = model("equidistant", d);
  for (const auto& [x, y] :
       std::vector<std::pair<double, double>>{{0.0, 0.0}, {0.5, -0.3}, {-0.8, 0.6}}) {
    const auto pixel = equidistant_pixel(d, x, y);
    const auto n = pixel_to_normalised(m, pixel[0], pixel[1]);
    ASSERT_TRUE(n) << n.error();
    EXPECT_NEAR((*n)[0], x, 1e-6);
    EXPECT_NEAR((*n)[1], y, 1e-6);
  }
}

TEST(PixelRay, RefusesWhatItCannotModel) {
  const auto unknown = pixel_to_normalised(model("fov", {0.9}), 10, 10);
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().find("'fov'"), std::string::npos) << unknown.error();
  EXPECT_FALSE(pixel_to_normalised(model("plumb_bob", {0.1, 0, 0}), 10, 10));  // 3 coefficients
  CameraModel no_k = model("plumb_bob", {0, 0, 0, 0, 0});
  no_k.K[0] = 0;
  EXPECT_FALSE(pixel_to_normalised(no_k, 10, 10));
  EXPECT_FALSE(project_ray(model("plumb_bob", {0, 0, 0, 0, 0}), {0, 0, -1}));
}

}  // namespace
}  // namespace k40t::camera
