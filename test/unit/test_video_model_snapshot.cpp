// The live model behind k40t_sim --rtsp-port (sim/video/model_snapshot.h, --rtsp-port).
#include <gtest/gtest.h>

#include "k40t_driver/sim/sim_options.h"
#include "k40t_driver/sim/video/model_snapshot.h"

namespace k40t::sim::video {
namespace {

TEST(ModelSnapshot, FollowsTheModelsSettings) {
  PodModel model;
  model.camera().settings().image_mode = 0;
  model.camera().settings().stream_resolution = 1;
  model.thermal().settings().reported.palette = protocol::Palette::kSky;  // 7
  ASSERT_EQ(model.thermal().set_digital_zoom(3), Outcome::kOk);
  ASSERT_EQ(model.zoom().set_zoom(4), Outcome::kOk);
  ASSERT_EQ(model.gimbal().command_angles(-20, 35), Outcome::kOk);
  for (int i = 0; i < 1000; ++i) model.step(0.01);  // zoom and gimbal get there

  const VideoSnapshot s = snapshot_of(model);
  EXPECT_EQ(s.image_mode, ImageMode::kThermal);
  EXPECT_EQ(s.resolution, StreamResolution::k720p);
  EXPECT_EQ(s.palette, 7);
  EXPECT_EQ(s.thermal_zoom, 3);
  EXPECT_NEAR(s.hybrid_zoom, 4, 1e-6);
  EXPECT_NEAR(s.yaw_deg, model.boresight_yaw_deg(), 1e-9);
  EXPECT_NEAR(s.pitch_deg, -20, 0.5);
  ASSERT_TRUE(s.temperature);
  // The sampler is the model's world: straight up is sky, straight down is ground.
  EXPECT_LT(s.temperature(Vec3{0, 0, 1}), 0);
  EXPECT_NEAR(s.temperature(Vec3{0, 0, -1}), model.world().config().ground_temperature_degC, 3);
}

TEST(ModelSnapshot, TheSceneVersionChangesWithTheWorld) {
  PodModel model;
  const uint64_t before = snapshot_of(model).scene_version;
  EXPECT_EQ(snapshot_of(model).scene_version, before);
  model.world().set_ground_height(55);
  EXPECT_NE(snapshot_of(model).scene_version, before);
}

TEST(ModelSnapshot, UndefinedImageModesShowTheVisibleImage) {
  PodModel model;
  model.camera().settings().image_mode = 3;
  EXPECT_EQ(snapshot_of(model).image_mode, ImageMode::kVisible);
  model.camera().settings().image_mode = 7;
  EXPECT_EQ(snapshot_of(model).image_mode, ImageMode::kSplit);
}

TEST(SimOptionsRtsp, PortIsOptionalAndChecked) {
  EXPECT_FALSE(parse_sim_options({}).value().rtsp_port);
  EXPECT_EQ(parse_sim_options({"--rtsp-port", "8554"}).value().rtsp_port, 8554);
  EXPECT_EQ(parse_sim_options({"--rtsp-port=0"}).value().rtsp_port, 0);
  for (const char* bad : {"70000", "-1", "85.5", "x"}) {
    const auto options = parse_sim_options({"--rtsp-port", bad});
    ASSERT_FALSE(options) << bad;
    EXPECT_NE(options.error().find("--rtsp-port"), std::string::npos) << options.error();
  }
}

}  // namespace
}  // namespace k40t::sim::video
