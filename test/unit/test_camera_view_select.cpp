// camera/view_select.h: which camera_info describes a pixel of the split screen.
#include <gtest/gtest.h>

#include "k40t_driver/camera/view_select.h"

namespace k40t::camera {
namespace {

constexpr int64_t kSecond = 1000000000;
constexpr int64_t kSkew = kSecond / 2;

// The 1080p split screen (docs/video.md): visible x 0..959 y 270..809, thermal x 960..1919
// y 156..923.
std::vector<ViewCandidate> split_at(int64_t stamp) {
  return {{stamp, {0, 270, 960, 540}, "visible panel"},
          {stamp, {960, 156, 960, 768}, "thermal panel"}};
}

TEST(ViewSelect, WithoutPanelsTheImagesOwnCameraInfo) {
  const auto chosen = select_view(5 * kSecond, {}, 1500, 500, kSkew);
  ASSERT_TRUE(chosen);
  EXPECT_FALSE(chosen.value());
}

TEST(ViewSelect, APixelOfEachPanelPicksThatPanel) {
  const auto panels = split_at(5 * kSecond);
  const auto thermal = select_view(5 * kSecond, panels, 1439.5, 539.5, kSkew);
  ASSERT_TRUE(thermal) << thermal.error();
  EXPECT_EQ(thermal.value(), std::optional<size_t>(1));
  const auto visible = select_view(5 * kSecond, panels, 479.5, 539.5, kSkew);
  ASSERT_TRUE(visible) << visible.error();
  EXPECT_EQ(visible.value(), std::optional<size_t>(0));
  // Thermal panel's top rows are above the visible panel's: the right half there is thermal.
  EXPECT_EQ(select_view(5 * kSecond, panels, 1000, 160, kSkew).value(), std::optional<size_t>(1));
}

TEST(ViewSelect, PanelEdgesFollowPixelCentres) {
  const auto panels = split_at(0);
  // Pixel 959 is the visible panel's last column, 960 the thermal's first; the border between
  // them is at 959.5.
  EXPECT_EQ(select_view(0, panels, 959.4, 500, kSkew).value(), std::optional<size_t>(0));
  EXPECT_EQ(select_view(0, panels, 959.5, 500, kSkew).value(), std::optional<size_t>(1));
  EXPECT_EQ(select_view(0, panels, 1919.4, 923.4, kSkew).value(), std::optional<size_t>(1));
  EXPECT_FALSE(select_view(0, panels, 1919.5, 500, kSkew));
}

TEST(ViewSelect, APixelInTheBlackBarsIsInNeitherPanel) {
  const auto chosen = select_view(0, split_at(0), 400, 100, kSkew);
  ASSERT_FALSE(chosen);
  EXPECT_NE(chosen.error().find("neither panel"), std::string::npos) << chosen.error();
  EXPECT_NE(chosen.error().find("thermal panel x 960..1919 y 156..923"), std::string::npos)
      << chosen.error();
}

TEST(ViewSelect, PanelsOfAnEndedSplitScreenAreIgnored) {
  // Panels last published 2 s before the current image: the split screen has ended.
  const auto chosen = select_view(7 * kSecond, split_at(5 * kSecond), 1439.5, 539.5, kSkew);
  ASSERT_TRUE(chosen);
  EXPECT_FALSE(chosen.value());
  // A panel one frame older than the image still counts (separate topics arrive in any order).
  EXPECT_EQ(
      select_view(5 * kSecond + kSecond / 30, split_at(5 * kSecond), 1439.5, 539.5, kSkew).value(),
      std::optional<size_t>(1));
}

}  // namespace
}  // namespace k40t::camera
