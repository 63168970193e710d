// The simulated telephoto zoom and focus (sections 3.2.4.5, 3.2.4.6, 3.2.4.18) and the lenses.
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/sim/lens.h"
#include "k40t_driver/sim/zoom_model.h"
#include "sim_test_util.h"

namespace k40t::sim {
namespace {

using testing::advance;
using testing::events_of;

TEST(SimZoom, StatusSequenceIsZoomingWhileMovingThenDone) {
  ZoomModel zoom;  // a doubling every 0.5 s, "zooming" every 0.2 s
  EventQueue events;
  ASSERT_EQ(zoom.set_zoom(8.0), Outcome::kOk);
  advance(zoom, 0.01, events);
  ASSERT_EQ(events_of<ZoomStatusEvent>(events).size(), 1u);
  EXPECT_TRUE(events_of<ZoomStatusEvent>(events)[0].zooming);
  EXPECT_TRUE(zoom.zooming());

  advance(zoom, 1.6, events);  // three doublings: 1.5 s
  const auto status = events_of<ZoomStatusEvent>(events);
  ASSERT_GE(status.size(), 3u);
  for (size_t i = 0; i + 1 < status.size(); ++i) EXPECT_TRUE(status[i].zooming) << i;
  EXPECT_FALSE(status.back().zooming);
  // Opening frame plus one every 0.2 s during 1.5 s, then done.
  EXPECT_EQ(status.size(), 1u + 7u + 1u);
  EXPECT_FALSE(zoom.zooming());
  EXPECT_DOUBLE_EQ(zoom.zoom(), 8.0);
}

TEST(SimZoom, TakesTheTimeOfItsDoublings) {
  ZoomModel zoom;
  EventQueue events;
  ASSERT_EQ(zoom.set_zoom(4.0), Outcome::kOk);
  advance(zoom, 0.5, events);
  EXPECT_NEAR(zoom.zoom(), 2.0, 0.01);
  advance(zoom, 0.5, events);
  EXPECT_NEAR(zoom.zoom(), 4.0, 1e-9);
}

TEST(SimZoom, FocalLengthFollowsTheOpticalPartOnly) {
  ZoomModel zoom;
  EventQueue events;
  const double base = lens_spec(Lens::kTele).focal_length_mm;
  EXPECT_DOUBLE_EQ(zoom.focal_length_mm(), base);
  ASSERT_EQ(zoom.set_zoom(5.0), Outcome::kOk);
  advance(zoom, 3.0, events);
  EXPECT_NEAR(zoom.focal_length_mm(), base * 5, 1e-9);
  ASSERT_EQ(zoom.set_zoom(40.0), Outcome::kOk);
  advance(zoom, 3.0, events);
  EXPECT_NEAR(zoom.zoom(), 40.0, 1e-9);
  EXPECT_NEAR(zoom.focal_length_mm(), base * 11, 1e-9);  // optical stops at 11x
  EXPECT_NEAR(digital_zoom(Lens::kTele, 40.0), 40.0 / 11.0, 1e-12);
}

TEST(SimZoom, OutOfRangeZoomIsRefused) {
  ZoomModel zoom;
  EXPECT_EQ(zoom.set_zoom(0.9), Outcome::kFailure);
  EXPECT_EQ(zoom.set_zoom(160.1), Outcome::kFailure);
  EXPECT_EQ(zoom.set_zoom(160.0), Outcome::kOk);
}

TEST(SimZoom, ContinuousZoomMovesUntilStopped) {
  ZoomModel zoom;
  EventQueue events;
  ASSERT_EQ(zoom.zoom_control(ContinuousZoom::kIn), Outcome::kOk);
  advance(zoom, 1.0, events);
  EXPECT_NEAR(zoom.zoom(), 4.0, 0.05);
  ASSERT_EQ(zoom.zoom_control(ContinuousZoom::kStop), Outcome::kOk);
  advance(zoom, 0.02, events);
  EXPECT_FALSE(zoom.zooming());
  const double stopped_at = zoom.zoom();
  advance(zoom, 1.0, events);
  EXPECT_DOUBLE_EQ(zoom.zoom(), stopped_at);
  EXPECT_FALSE(events_of<ZoomStatusEvent>(events).back().zooming);
}

TEST(SimZoom, StepsAreHalfADoubling) {
  ZoomModel zoom;
  EventQueue events;
  ASSERT_EQ(zoom.set_zoom(4.0), Outcome::kOk);
  advance(zoom, 2.0, events);
  ASSERT_EQ(zoom.zoom_control(ContinuousZoom::kStepIn), Outcome::kOk);
  advance(zoom, 1.0, events);
  EXPECT_NEAR(zoom.zoom(), 4.0 * std::sqrt(2.0), 1e-9);
  ASSERT_EQ(zoom.zoom_control(ContinuousZoom::kStepOut), Outcome::kOk);
  ASSERT_EQ(zoom.zoom_control(ContinuousZoom::kStepOut), Outcome::kOk);
  advance(zoom, 1.0, events);
  EXPECT_NEAR(zoom.zoom(), 2.0 * std::sqrt(2.0), 1e-9);
}

TEST(SimZoom, FocusIsBusyAfterAZoomAndForFocusCommands) {
  ZoomConfig config;
  config.focus_time_s = 0.6;
  ZoomModel zoom(config);
  EventQueue events;
  ASSERT_EQ(zoom.set_zoom(2.0), Outcome::kOk);
  advance(zoom, 0.6, events);  // zoom done at 0.5 s
  EXPECT_FALSE(zoom.zooming());
  EXPECT_TRUE(zoom.focusing());
  advance(zoom, 0.6, events);
  EXPECT_FALSE(zoom.focusing());

  ASSERT_EQ(zoom.focus(FocusCommand::kAutoAfterZoomOff), Outcome::kOk);
  ASSERT_EQ(zoom.set_zoom(1.0), Outcome::kOk);
  advance(zoom, 0.6, events);
  EXPECT_FALSE(zoom.focusing());

  ASSERT_EQ(zoom.focus(FocusCommand::kOneTouch), Outcome::kOk);
  EXPECT_TRUE(zoom.focusing());
  advance(zoom, 0.7, events);
  EXPECT_FALSE(zoom.focusing());

  ASSERT_EQ(zoom.focus(FocusCommand::kManualNear), Outcome::kOk);
  advance(zoom, 5.0, events);
  EXPECT_TRUE(zoom.focusing());  // manual fine-tuning runs until stopped
  ASSERT_EQ(zoom.focus(FocusCommand::kStopManual), Outcome::kOk);
  EXPECT_FALSE(zoom.focusing());
}

TEST(SimLens, FieldOfViewNarrowsWithZoom) {
  const FieldOfView one = field_of_view(Lens::kTele, 1);
  const FieldOfView twenty = field_of_view(Lens::kTele, 20);
  EXPECT_NEAR(
      std::tan(one.horizontal_deg * M_PI / 360) / std::tan(twenty.horizontal_deg * M_PI / 360), 20,
      1e-9);
  const FieldOfView thermal = field_of_view(Lens::kThermal, 1);
  EXPECT_NEAR(thermal.horizontal_deg, 32.9, 0.1);  // 7.68 mm behind 13 mm
  EXPECT_NEAR(thermal.vertical_deg, 26.6, 0.1);
  EXPECT_DOUBLE_EQ(optical_zoom(Lens::kWide, 4), 1.0);
}

}  // namespace
}  // namespace k40t::sim
