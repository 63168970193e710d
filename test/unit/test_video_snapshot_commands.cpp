// The control lines of k40t_video_sim (sim/video/snapshot_commands.h).
#include <gtest/gtest.h>

#include "k40t_driver/sim/video/snapshot_commands.h"

namespace k40t::sim::video {
namespace {

TEST(SnapshotCommands, EachCommandSetsItsField) {
  VideoSnapshot s;
  ASSERT_TRUE(apply_command("mode 0", s));
  EXPECT_EQ(s.image_mode, ImageMode::kThermal);
  ASSERT_TRUE(apply_command("palette 12", s));
  EXPECT_EQ(s.palette, 12);
  ASSERT_TRUE(apply_command("zoom 12.5", s));
  EXPECT_DOUBLE_EQ(s.hybrid_zoom, 12.5);
  ASSERT_TRUE(apply_command("thermal_zoom 4", s));
  EXPECT_EQ(s.thermal_zoom, 4);
  ASSERT_TRUE(apply_command("  gimbal -30.5 -12 ", s));
  EXPECT_DOUBLE_EQ(s.yaw_deg, -30.5);
  EXPECT_DOUBLE_EQ(s.pitch_deg, -12);
  ASSERT_TRUE(apply_command("resolution 720", s));
  EXPECT_EQ(s.resolution, StreamResolution::k720p);
  EXPECT_TRUE(apply_command("", s));
  EXPECT_TRUE(apply_command("# a comment", s));
}

TEST(SnapshotCommands, BadLinesChangeNothingAndSayWhatIsExpected) {
  const struct {
    const char* line;
    const char* expected;
  } cases[] = {{"mode 3", "image mode"},
               {"mode", "image mode"},
               {"palette 21", "1..20"},
               {"palette 2.5", "1..20"},
               {"zoom 0.5", "1..160"},
               {"zoom ten", "1..160"},
               {"thermal_zoom 9", "1..8"},
               {"gimbal 10", "yaw and a pitch"},
               {"gimbal 0 91", "-90..90"},
               {"resolution 480", "1080 or 720"},
               {"fly away", "unknown command 'fly'"}};
  for (const auto& c : cases) {
    VideoSnapshot s;
    const VideoSnapshot before = s;
    const Status status = apply_command(c.line, s);
    ASSERT_FALSE(status) << c.line;
    EXPECT_NE(status.message().find(c.expected), std::string::npos)
        << c.line << " -> " << status.message();
    EXPECT_EQ(s.image_mode, before.image_mode);
    EXPECT_EQ(s.palette, before.palette);
    EXPECT_EQ(s.hybrid_zoom, before.hybrid_zoom);
  }
}

}  // namespace
}  // namespace k40t::sim::video
