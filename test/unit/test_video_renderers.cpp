// What the simulated stream shows (sim/video/*_renderer.h): palettes, zoom and gimbal show in the
// picture, frame sizes follow the image mode, every frame is stamped.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include <opencv2/imgproc.hpp>

#include "k40t_driver/sim/video/frame_renderer.h"
#include "k40t_driver/sim/video/pinhole_view.h"

namespace k40t::sim::video {
namespace {

// A scene with one hot spot at heading 10, elevation -5 (a 1 deg cone at 80 degC, 20 elsewhere).
double hot_spot(const Vec3& d) {
  return dot(d, direction(10, -5)) > std::cos(1.0 * M_PI / 180) ? 80 : 20;
}

// The spot on a smooth left-to-right ramp (10..30 degC), so every palette entry is in use.
double spot_on_a_ramp(const Vec3& d) {
  return std::max(hot_spot(d), 20 + 10 * d.y / std::hypot(d.x, d.y));
}

VideoSnapshot looking_at_the_spot() {
  VideoSnapshot s;
  s.image_mode = ImageMode::kThermal;
  s.yaw_deg = 10;
  s.pitch_deg = -5;
  s.temperature = hot_spot;
  return s;
}

// How much larger `measure` (a size in pixels) is at `zoom` than at 1x; fails the test if the 1x
// size is below `minimum` (too small to compare).
double magnification(const std::function<int(double)>& measure, double zoom, int minimum) {
  const int one = measure(1);
  EXPECT_GE(one, minimum);
  return measure(zoom) / static_cast<double>(std::max(one, 1));
}

double difference(const cv::Mat& a, const cv::Mat& b) {
  return cv::norm(a, b, cv::NORM_L1) / static_cast<double>(a.total() * a.channels());
}

TEST(ThermalRenderer, TheHotSpotIsBrightInWhiteHotAndDarkInBlackHot) {
  ThermalRenderer renderer;
  VideoSnapshot s = looking_at_the_spot();
  s.palette = 1;
  const cv::Mat white = renderer.render(s).clone();
  s.palette = 2;
  const cv::Mat black = renderer.render(s).clone();
  ASSERT_EQ(white.size(), cv::Size(640, 512));
  const cv::Vec3b centre_white = white.at<cv::Vec3b>(256, 320);
  const cv::Vec3b corner_white = white.at<cv::Vec3b>(10, 10);
  EXPECT_GT(centre_white[0], 200);
  EXPECT_LT(corner_white[0], 50);
  EXPECT_LT(black.at<cv::Vec3b>(256, 320)[0], 50);
  EXPECT_GT(black.at<cv::Vec3b>(10, 10)[0], 200);
}

TEST(ThermalRenderer, EveryPaletteChangesThePicture) {
  ThermalRenderer renderer;
  VideoSnapshot s = looking_at_the_spot();
  s.temperature = spot_on_a_ramp;
  cv::Mat previous;
  for (int p = 1; p <= 20; ++p) {
    s.palette = p;
    const cv::Mat image = renderer.render(s).clone();
    if (!previous.empty()) {
      EXPECT_GT(difference(image, previous), 1.0) << "palette " << p;
    }
    previous = image;
  }
}

TEST(ThermalRenderer, DigitalZoomMagnifiesTheSpot) {
  ThermalRenderer renderer;
  VideoSnapshot s = looking_at_the_spot();
  auto hot_pixels = [&](double zoom) {
    s.thermal_zoom = static_cast<int>(zoom);
    renderer.render(s);
    return cv::countNonZero(renderer.temperatures() > 50);
  };
  EXPECT_NEAR(magnification(hot_pixels, 4, 50), 16, 2.5);  // an area: the square of the zoom
}

TEST(ThermalRenderer, TurningTheGimbalMovesTheSpot) {
  ThermalRenderer renderer;
  VideoSnapshot s = looking_at_the_spot();
  s.yaw_deg = 5;  // the spot is now 5 deg right of the centre
  renderer.render(s);
  cv::Point hottest;
  cv::minMaxLoc(renderer.temperatures(), nullptr, nullptr, nullptr, &hottest);
  const double expected_x = 319.5 + focal_px(Lens::kThermal, 1, 640) * std::tan(5 * M_PI / 180);
  EXPECT_NEAR(hottest.x, expected_x, 8);
}

TEST(ThermalRenderer, AUniformSceneIsOneColour) {
  ThermalRenderer renderer;
  VideoSnapshot s;
  s.image_mode = ImageMode::kThermal;
  const cv::Mat image = renderer.render(s);
  cv::Scalar mean, stddev;
  cv::meanStdDev(image, mean, stddev);
  EXPECT_LT(stddev[0], 1e-9);
}

TEST(VisibleRenderer, TurningTheGimbalShiftsThePicture) {
  VisibleRenderer renderer;
  VideoSnapshot s;
  s.pitch_deg = -3;
  const cv::Mat before = renderer.render(s, {1280, 720}).clone();
  s.yaw_deg = 2;
  const cv::Mat after = renderer.render(s, {1280, 720}).clone();
  // The scene moves left by focal * tan(2 deg) pixels. Compared on horizontal gradients of the
  // picture's middle, so that neither the row-wise sky/ground shading nor the fixed OSD text
  // (both the same in the two images) pulls the estimate to zero.
  const double shift = focal_px(Lens::kTele, 1, 1280) * std::tan(2 * M_PI / 180);
  auto edges = [](const cv::Mat& bgr) {
    cv::Mat grey, dx;
    cv::cvtColor(bgr(cv::Rect(0, 100, 1280, 512)), grey, cv::COLOR_BGR2GRAY);
    cv::Sobel(grey, dx, CV_32F, 1, 0);
    return cv::Mat(cv::abs(dx));
  };
  const cv::Point2d moved = cv::phaseCorrelate(edges(before), edges(after));
  EXPECT_NEAR(moved.x, -shift, 3);
  EXPECT_NEAR(moved.y, 0, 3);
}

TEST(VisibleRenderer, ZoomMagnifiesTheTarget) {
  VisibleRenderer renderer;
  VideoSnapshot s;
  s.pitch_deg = -4;  // the ring target at heading 0 in the centre
  auto centre_disc_width = [&](double zoom) {
    s.hybrid_zoom = zoom;
    const cv::Mat image = renderer.render(s, {1280, 720});
    // Width of the run of white pixels through the centre row: the 1.6 deg outer ring at 1x.
    const int row = 360;
    int width = 0;
    for (int x = 0; x < image.cols; ++x) {
      const cv::Vec3b p = image.at<cv::Vec3b>(row, x);
      if (p[0] > 240 && p[1] > 240 && p[2] > 240) ++width;
    }
    return width;
  };
  EXPECT_NEAR(magnification(centre_disc_width, 2, 20), 2, 0.2);
}

TEST(VisibleRenderer, DrawsAtTheLongestZoomWithoutOverflow) {
  VisibleRenderer renderer;
  VideoSnapshot s;
  s.pitch_deg = -4;
  s.hybrid_zoom = 160;
  const cv::Mat image = renderer.render(s, {1920, 1080});
  cv::Scalar mean, stddev;
  cv::meanStdDev(image, mean, stddev);
  EXPECT_GT(stddev[0], 10);  // the smallest rings, not a flat colour
}

TEST(FrameRenderer, SizeFollowsTheImageModeAndEveryFrameIsStamped) {
  FrameRenderer renderer;
  VideoSnapshot s;
  const struct {
    ImageMode mode;
    StreamResolution resolution;
    cv::Size size;
  } cases[] = {{ImageMode::kThermal, StreamResolution::k1080p, {640, 512}},
               {ImageMode::kVisible, StreamResolution::k1080p, {1920, 1080}},
               {ImageMode::kVisibleAlt, StreamResolution::k720p, {1280, 720}},
               {ImageMode::kSplit, StreamResolution::k1080p, {1920, 1080}}};
  uint32_t counter = 100;
  for (const auto& c : cases) {
    s.image_mode = c.mode;
    s.resolution = c.resolution;
    const cv::Mat frame = renderer.render(s, {counter, 555});
    EXPECT_EQ(frame.size(), c.size);
    EXPECT_EQ(frame_size(s), c.size);
    const auto stamp = read_frame_stamp(frame);
    ASSERT_TRUE(stamp);
    EXPECT_EQ(stamp->counter, counter++);
  }
}

TEST(FrameRenderer, SplitScreenShowsBothCameras) {
  FrameRenderer renderer;
  VideoSnapshot s = looking_at_the_spot();
  s.image_mode = ImageMode::kSplit;
  s.palette = 1;
  const cv::Mat frame = renderer.render(s, {1, 1});
  const auto layout = k40t::video::split_layout(frame.size());
  EXPECT_EQ(layout.visible, cv::Rect(0, 270, 960, 540));
  EXPECT_EQ(layout.thermal, cv::Rect(960, 156, 960, 768));
  // The thermal panel's centre is the hot spot (white hot), the visible panel is not black.
  const cv::Vec3b spot = frame.at<cv::Vec3b>(156 + 384, 960 + 480);
  EXPECT_GT(spot[0], 200);
  EXPECT_GT(cv::mean(frame(layout.visible))[0], 30);
  EXPECT_EQ(cv::countNonZero(frame(cv::Rect(0, 1000, 960, 80)).reshape(1)), 0);
}

}  // namespace
}  // namespace k40t::sim::video
