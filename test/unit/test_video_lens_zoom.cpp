// The tele's zoom split into optical and digital parts (video/lens_zoom.h), ROS-free. A 5 mm 1x
// focal length and a 30x optical maximum; factors relative to the 5 mm nominal optics.
#include <gtest/gtest.h>

#include "k40t_driver/video/lens_zoom.h"

namespace k40t::video {
namespace {

constexpr double kOneX = 5.0;
constexpr double kMaxOptical = 30.0;

TeleZoom at(double ratio, double focal_mm, double reference_mm = kOneX) {
  ZoomState zoom;
  zoom.zoom_ratio = ratio;
  zoom.focal_length_mm = focal_mm;
  return tele_zoom(kOneX, kMaxOptical, zoom, reference_mm);
}

TEST(TeleZoom, WithoutAReportedFocalLengthTheRatioIsOpticalUpToTheMaximum) {
  EXPECT_DOUBLE_EQ(at(10.0, 0).optical, 10.0);  // 50 mm / 5 mm
  EXPECT_DOUBLE_EQ(at(10.0, 0).digital, 1.0);
  EXPECT_DOUBLE_EQ(at(60.0, 0).optical, 30.0);  // 150 mm: the optical maximum
  EXPECT_DOUBLE_EQ(at(60.0, 0).digital, 2.0);   // 60 * 5 / 150
}

TEST(TeleZoom, AReportedFocalLengthIsTheOpticalPart) {
  EXPECT_DOUBLE_EQ(at(8.0, 20.0).optical, 4.0);  // 20 mm / 5 mm
  EXPECT_DOUBLE_EQ(at(8.0, 20.0).digital, 2.0);  // 8 * 5 / 20
  // Relative to a calibration taken at 6 mm instead of the nominal 5 mm.
  EXPECT_DOUBLE_EQ(at(8.0, 20.0, 6.0).optical, 20.0 / 6.0);
}

TEST(TeleZoom, RatiosBelowOneCountAsOne) {
  EXPECT_DOUBLE_EQ(at(0.5, 0).optical, 1.0);
  EXPECT_DOUBLE_EQ(at(0.5, 0).digital, 1.0);
}

}  // namespace
}  // namespace k40t::video
