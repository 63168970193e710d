// LensModels (ros/video/lens_models.h) and the calibration camera_info_manager saves: with no URL
// set, a calibration saved in ROS_HOME/camera_info/<prefix><lens>.yaml is used (its distortion
// reaches camera_info) and one saved while the node runs is picked up; without one, the nominal
// pinhole (zero distortion), and the manager is not asked (it would warn "calibration file not
// found" on every start, which check_field.py's quiet start forbids).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <ros/ros.h>

#include "k40t_driver/ros/video/lens_models.h"

namespace k40t::driver {
namespace {

class LensModelsCalibration : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!ros::isInitialized()) {
      int argc = 0;
      ros::init(argc, nullptr, "lens_models_test", ros::init_options::AnonymousName);
    }
  }
  void SetUp() override {
    home_ = std::filesystem::temp_directory_path() /
            ("k40t_lens_models_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(home_ / "camera_info");
    const char* old = std::getenv("ROS_HOME");
    if (old) saved_ros_home_ = old;
    setenv("ROS_HOME", home_.c_str(), 1);
    config_.frame_prefix = "lens_test_";
  }
  void TearDown() override {
    if (saved_ros_home_.empty()) {
      unsetenv("ROS_HOME");
    } else {
      setenv("ROS_HOME", saved_ros_home_.c_str(), 1);
    }
    std::filesystem::remove_all(home_);
  }
  // A calibration as camera_calibration saves it (camera_calibration_parsers' YAML), k1 = 0.1.
  void save_tele_calibration() const {
    std::ofstream f(home_ / "camera_info" / "lens_test_tele.yaml");
    f << "image_width: 1920\nimage_height: 1080\ncamera_name: lens_test_tele\n"
         "camera_matrix: {rows: 3, cols: 3, data: [1500, 0, 960, 0, 1500, 540, 0, 0, 1]}\n"
         "distortion_model: plumb_bob\n"
         "distortion_coefficients: {rows: 1, cols: 5, data: [0.1, 0, 0, 0, 0]}\n"
         "rectification_matrix: {rows: 3, cols: 3, data: [1, 0, 0, 0, 1, 0, 0, 0, 1]}\n"
         "projection_matrix: {rows: 3, cols: 4, data: [1500, 0, 960, 0, 0, 1500, 540, 0, 0, 0, 1, "
         "0]}\n";
  }
  double tele_k1(const LensModels& models) const {
    const sensor_msgs::CameraInfo info =
        models.camera_info(video::StreamView{}, cv::Size(1920, 1080), ZoomState{});
    return info.D.empty() ? -1.0 : info.D[0];
  }

  std::filesystem::path home_;
  std::string saved_ros_home_;
  VideoConfig config_;
  ros::NodeHandle nh_{"~"};
};

TEST_F(LensModelsCalibration, NoCalibrationSavedGivesTheNominalPinhole) {
  LensModels models(nh_, config_);
  EXPECT_EQ(tele_k1(models), 0.0);
}

TEST_F(LensModelsCalibration, ASavedCalibrationIsUsed) {
  save_tele_calibration();
  LensModels models(nh_, config_);
  EXPECT_DOUBLE_EQ(tele_k1(models), 0.1);
}

TEST_F(LensModelsCalibration, ACalibrationSavedWhileRunningIsPickedUp) {
  LensModels models(nh_, config_);
  EXPECT_EQ(tele_k1(models), 0.0);
  save_tele_calibration();
  EXPECT_DOUBLE_EQ(tele_k1(models), 0.1);
}

}  // namespace
}  // namespace k40t::driver
