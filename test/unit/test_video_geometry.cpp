// The simulated cameras' pinhole model and the floating-point clipping the scene is drawn with
// (sim/video/pinhole_view.h, sim/video/clip.h).
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/sim/video/clip.h"
#include "k40t_driver/sim/video/pinhole_view.h"

namespace k40t::sim::video {
namespace {

TEST(PinholeView, TheCentreRayIsTheBoresight) {
  const PinholeView view(30, -10, 1000, {640, 512});
  const Vec3 centre = view.ray(319.5, 255.5);
  const Vec3 boresight = direction(30, -10);
  EXPECT_NEAR(centre.x, boresight.x, 1e-12);
  EXPECT_NEAR(centre.y, boresight.y, 1e-12);
  EXPECT_NEAR(centre.z, boresight.z, 1e-12);
}

TEST(PinholeView, YawIsPositiveToTheRightAndPitchPositiveUp) {
  const PinholeView view(0, 0, 1000, {640, 512});
  const auto right = view.project(direction(5, 0));
  const auto up = view.project(direction(0, 5));
  ASSERT_TRUE(right && up);
  EXPECT_NEAR(right->x, 319.5 + 1000 * std::tan(5 * M_PI / 180), 1e-6);
  EXPECT_NEAR(right->y, 255.5, 1e-6);
  EXPECT_NEAR(up->y, 255.5 - 1000 * std::tan(5 * M_PI / 180), 1e-6);
}

TEST(PinholeView, ProjectUndoesRay) {
  const PinholeView view(-140, 25, 2345, {1920, 1080});
  for (double u : {0.0, 100.5, 959.5, 1919.0}) {
    for (double v : {0.0, 540.0, 1079.0}) {
      const auto p = view.project(view.ray(u, v));
      ASSERT_TRUE(p);
      EXPECT_NEAR(p->x, u, 1e-6);
      EXPECT_NEAR(p->y, v, 1e-6);
    }
  }
}

TEST(PinholeView, NothingBehindTheCamera) {
  const PinholeView view(0, 0, 1000, {640, 512});
  EXPECT_FALSE(view.project(direction(180, 0)));
  EXPECT_FALSE(view.project(direction(95, 0)));
}

TEST(PinholeView, TheHorizonRowFollowsPitch) {
  const PinholeView level(0, 0, 1000, {640, 512});
  EXPECT_NEAR(level.horizon_row(), 255.5, 1e-9);
  const PinholeView down(0, -10, 1000, {640, 512});
  EXPECT_NEAR(down.horizon_row(), 255.5 - 1000 * std::tan(10 * M_PI / 180), 1e-9);
}

TEST(FocalPx, FollowsZoomWithinTheLensRange) {
  // sim/lens.h: telephoto 4.7 mm on 5.6 mm, 160x hybrid; thermal 13 mm on 640 x 12 um.
  const double one = focal_px(Lens::kTele, 1, 1920);
  EXPECT_NEAR(one, 1920 * 4.7 / 5.6, 1e-9);
  EXPECT_NEAR(focal_px(Lens::kTele, 10, 1920), 10 * one, 1e-9);
  EXPECT_NEAR(focal_px(Lens::kTele, 1000, 1920), 160 * one, 1e-9);
  EXPECT_NEAR(focal_px(Lens::kTele, 0.1, 1920), one, 1e-9);
  EXPECT_NEAR(focal_px(Lens::kThermal, 1, 640), 640 * 13 / 7.68, 1e-9);
  EXPECT_NEAR(focal_px(Lens::kThermal, 8, 640), 8 * 640 * 13 / 7.68, 1e-9);
}

TEST(Clip, SegmentsAreCutToTheBox) {
  const cv::Rect2d box(0, 0, 100, 50);
  const auto inside = clip_segment({10, 10}, {20, 20}, box);
  ASSERT_TRUE(inside);
  EXPECT_EQ(inside->first, cv::Point2d(10, 10));
  EXPECT_EQ(inside->second, cv::Point2d(20, 20));
  const auto across = clip_segment({-1e6, 25}, {1e6, 25}, box);
  ASSERT_TRUE(across);
  EXPECT_NEAR(across->first.x, 0, 1e-6);
  EXPECT_NEAR(across->second.x, 100, 1e-6);
  EXPECT_FALSE(clip_segment({-10, -10}, {-1, 60}, box));
  EXPECT_FALSE(clip_segment({0, 60}, {100, 60}, box));
}

TEST(Clip, PolygonsAreCutToTheBox) {
  const cv::Rect2d box(0, 0, 100, 100);
  const std::vector<cv::Point2d> huge{{-1e5, -1e5}, {1e5, -1e5}, {1e5, 1e5}, {-1e5, 1e5}};
  const auto clipped = clip_polygon(huge, box);
  ASSERT_EQ(clipped.size(), 4u);
  for (const auto& p : clipped) {
    EXPECT_TRUE(p.x == 0 || p.x == 100);
    EXPECT_TRUE(p.y == 0 || p.y == 100);
  }
  EXPECT_TRUE(clip_polygon({{200, 200}, {300, 200}, {250, 300}}, box).empty());
}

}  // namespace
}  // namespace k40t::sim::video
