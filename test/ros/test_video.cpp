// rostest of the video through the whole chain: k40t_sim (pod model + --rtsp-port stream, spawned
// here so the test can kill and restart it), PodNodelet and VideoNodelet in one manager
// (test/ros/video.test). Changes go through the driver, as a user makes them: set_palette,
// set_zoom, dynamic_reconfigure image_mode / thermal_zoom; the stream and the reports follow.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <dynamic_reconfigure/Reconfigure.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <opencv2/core.hpp>

#include "k40t_driver/SetPalette.h"
#include "k40t_driver/SetZoom.h"
#include "k40t_driver/VisibleStatus.h"

namespace {

using Clock = std::chrono::steady_clock;
using diagnostic_msgs::DiagnosticStatus;

bool wait_until(const std::function<bool()>& condition, double timeout_s) {
  const auto deadline = Clock::now() + std::chrono::duration<double>(timeout_s);
  while (Clock::now() < deadline && ros::ok()) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return condition();
}

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// k40t_sim from this package's build, serving the pod on a pty and the video on a port.
class SimProcess {
 public:
  void start(const std::string& link, int rtsp_port) {
    char self[4096] = {};
    const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    const std::string dir =
        std::string(self, n > 0 ? n : 0).substr(0, std::string(self).rfind('/'));
    const std::string program = dir + "/k40t_sim";
    std::vector<std::string> args{program, "--link", "pty:" + link, "--rtsp-port",
                                  std::to_string(rtsp_port)};
    pid_ = fork();
    if (pid_ == 0) {
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(program.c_str(), argv.data());
      _exit(127);
    }
  }
  void kill_now() {
    if (pid_ <= 0) return;
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
  ~SimProcess() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }

 private:
  pid_t pid_ = -1;
};

// The newest message of a topic, a count, and each arrival.
template <class Msg>
class Watch {
 public:
  Watch(ros::NodeHandle& nh, const std::string& topic) {
    sub_ = nh.subscribe<Msg>(topic, 2, &Watch::on_msg, this, ros::TransportHints().tcpNoDelay());
  }
  typename Msg::ConstPtr latest() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return latest_;
  }
  size_t count() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return count_;
  }
  // The first message arriving from now on that satisfies `match`, waiting up to `timeout_s`.
  typename Msg::ConstPtr next(const std::function<bool(const Msg&)>& match, double timeout_s) {
    const size_t after = count();
    typename Msg::ConstPtr found;
    wait_until(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          if (count_ > after && latest_ && match(*latest_)) found = latest_;
          return found != nullptr;
        },
        timeout_s);
    return found;
  }

 private:
  void on_msg(const typename Msg::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_ = msg;
    ++count_;
  }
  mutable std::mutex mutex_;
  typename Msg::ConstPtr latest_;
  size_t count_ = 0;
  ros::Subscriber sub_;
};

// Levels of the "video stream" diagnostic status with their arrival times.
class VideoDiagnosticsWatch {
 public:
  explicit VideoDiagnosticsWatch(ros::NodeHandle& nh) {
    sub_ = nh.subscribe("/diagnostics", 50, &VideoDiagnosticsWatch::on_msg, this);
  }
  // Seconds from `since` to the first status at `level` after it, if one came within timeout.
  std::optional<double> first_level_after(Clock::time_point since, uint8_t level,
                                          double timeout_s) {
    std::optional<double> found;
    wait_until(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          for (const auto& [t, l] : history_) {
            if (t >= since && l == level) {
              found = std::chrono::duration<double>(t - since).count();
              return true;
            }
          }
          return false;
        },
        timeout_s);
    return found;
  }

 private:
  void on_msg(const diagnostic_msgs::DiagnosticArray::ConstPtr& array) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& status : array->status) {
      const std::string suffix = "video stream";
      if (status.name.size() >= suffix.size() &&
          status.name.compare(status.name.size() - suffix.size(), suffix.size(), suffix) == 0) {
        history_.emplace_back(Clock::now(), status.level);
      }
    }
  }
  std::mutex mutex_;
  std::deque<std::pair<Clock::time_point, uint8_t>> history_;
  ros::Subscriber sub_;
};

cv::Scalar channel_means(const sensor_msgs::Image& image) {
  const cv::Mat pixels(image.height, image.width, CV_8UC3, const_cast<uint8_t*>(image.data.data()),
                       image.step);
  return cv::mean(pixels);
}

class Video : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    nh_ = new ros::NodeHandle();  // the test runs in the driver's namespace (video.test)
    ros::NodeHandle private_nh("~");
    link_ = private_nh.param<std::string>("sim_link", "/tmp/k40t_video_test_pod");
    rtsp_port_ = private_nh.param("rtsp_port", 18654);
    images_ = new Watch<sensor_msgs::Image>(*nh_, "image_raw");
    infos_ = new Watch<sensor_msgs::CameraInfo>(*nh_, "camera_info");
    visible_ = new Watch<k40t_driver::VisibleStatus>(*nh_, "visible/status");
    diagnostics_ = new VideoDiagnosticsWatch(*nh_);
    sim_ = new SimProcess();
    sim_->start(link_, rtsp_port_);
  }
  static void TearDownTestSuite() {
    delete sim_;
    delete images_;
    delete infos_;
    delete visible_;
    delete diagnostics_;
    delete nh_;
  }

  void SetUp() override {
    ASSERT_TRUE(wait_until([] { return images_->count() > 0; }, 30))
        << "no image_raw from the simulated pod's stream";
  }

  template <class Srv>
  static void call(const std::string& name, Srv& srv) {
    ASSERT_TRUE(ros::service::waitForService(nh_->resolveName(name), ros::Duration(15))) << name;
    ASSERT_TRUE(ros::service::call(nh_->resolveName(name), srv)) << name;
  }
  static void reconfigure(const std::string& name, int value) {
    dynamic_reconfigure::Reconfigure srv;
    dynamic_reconfigure::IntParameter parameter;
    parameter.name = name;
    parameter.value = value;
    srv.request.config.ints.push_back(parameter);
    call("driver/set_parameters", srv);
  }
  static void set_palette(int palette) {
    k40t_driver::SetPalette srv;
    srv.request.palette = static_cast<uint8_t>(palette);
    call("set_palette", srv);
    ASSERT_TRUE(srv.response.success) << srv.response.message;
  }
  // Sets the zoom and waits until the pod reports it reached it.
  static void set_zoom(double ratio) {
    k40t_driver::SetZoom srv;
    srv.request.ratio = static_cast<float>(ratio);
    call("set_zoom", srv);
    ASSERT_TRUE(srv.response.success) << srv.response.message;
    ASSERT_TRUE(visible_->next(
        [ratio](const auto& s) { return !s.zooming && std::abs(s.zoom_ratio - ratio) < 0.05; },
        10));
  }
  // The image mode through dynamic_reconfigure, then the first frame showing `frame_id`.
  static sensor_msgs::ImageConstPtr show(int image_mode, const std::string& frame_id) {
    reconfigure("image_mode", image_mode);
    return images_->next([&](const auto& image) { return image.header.frame_id == frame_id; }, 5);
  }
  // camera_info of a frame that came after the pod reported what we just set.
  static sensor_msgs::CameraInfoConstPtr info_for(const std::string& frame_id) {
    ros::Duration(0.3).sleep();  // the driver's report (5 Hz) reaches the video node
    return infos_->next([&](const auto& info) { return info.header.frame_id == frame_id; }, 5);
  }

  static ros::NodeHandle* nh_;
  static std::string link_;
  static int rtsp_port_;
  static Watch<sensor_msgs::Image>* images_;
  static Watch<sensor_msgs::CameraInfo>* infos_;
  static Watch<k40t_driver::VisibleStatus>* visible_;
  static VideoDiagnosticsWatch* diagnostics_;
  static SimProcess* sim_;
};

ros::NodeHandle* Video::nh_ = nullptr;
std::string Video::link_;
int Video::rtsp_port_ = 0;
Watch<sensor_msgs::Image>* Video::images_ = nullptr;
Watch<sensor_msgs::CameraInfo>* Video::infos_ = nullptr;
Watch<k40t_driver::VisibleStatus>* Video::visible_ = nullptr;
VideoDiagnosticsWatch* Video::diagnostics_ = nullptr;
SimProcess* Video::sim_ = nullptr;

const std::string kThermal = "k40t_thermal_optical_frame";
const std::string kTele = "k40t_tele_optical_frame";

TEST_F(Video, ImagesAndCameraInfoArriveAtTheStreamRate) {
  const size_t images_before = images_->count();
  const size_t infos_before = infos_->count();
  const auto start = Clock::now();
  std::this_thread::sleep_for(std::chrono::seconds(3));
  const double elapsed = seconds_since(start);
  const double image_rate = (images_->count() - images_before) / elapsed;
  const double info_rate = (infos_->count() - infos_before) / elapsed;
  EXPECT_NEAR(image_rate, 30, 6) << "the simulated stream runs at 30 fps";
  EXPECT_NEAR(info_rate, image_rate, 2);
  // Each camera_info goes with its image: same stamp and frame id; stamps are not in the future.
  const auto image = images_->latest();
  const auto info =
      infos_->next([&](const auto& i) { return i.header.stamp >= image->header.stamp; }, 2);
  ASSERT_TRUE(info);
  EXPECT_EQ(info->width, images_->latest()->width);
  EXPECT_LE(image->header.stamp, ros::Time::now());
}

TEST_F(Video, APaletteChangeGivesMeasurablyDifferentThermalFrames) {
  ASSERT_TRUE(show(0, kThermal));
  set_palette(1);  // white hot: grey
  const auto white_hot = images_->next(
      [](const auto& image) {
        const cv::Scalar m = channel_means(image);
        return std::abs(m[0] - m[2]) < 2;  // B == R: grey
      },
      5);
  ASSERT_TRUE(white_hot) << "no grey thermal frame after palette 1";
  set_palette(5);  // iron red
  const auto iron_red = images_->next(
      [](const auto& image) {
        const cv::Scalar m = channel_means(image);
        return m[2] - m[0] > 20;  // clearly redder than blue
      },
      5);
  ASSERT_TRUE(iron_red) << "no reddish thermal frame after palette 5";
  const cv::Scalar a = channel_means(*white_hot);
  const cv::Scalar b = channel_means(*iron_red);
  EXPECT_GT(std::abs(a[2] - b[2]) + std::abs(a[0] - b[0]), 20) << a << " vs " << b;
}

TEST_F(Video, AZoomChangeMovesFxByTheZoomRatio) {
  ASSERT_TRUE(show(5, kTele));
  set_zoom(2);
  const auto at_2 = info_for(kTele);
  ASSERT_TRUE(at_2);
  set_zoom(8);  // optical
  const auto at_8 = info_for(kTele);
  ASSERT_TRUE(at_8);
  EXPECT_NEAR(at_8->K[0] / at_2->K[0], 4, 0.04);
  EXPECT_NEAR(at_8->K[4] / at_2->K[4], 4, 0.04);
  set_zoom(22);  // 11x optical, then 2x digital
  const auto at_22 = info_for(kTele);
  ASSERT_TRUE(at_22);
  EXPECT_NEAR(at_22->K[0] / at_2->K[0], 11, 0.11);
  set_zoom(1);

  // The thermal digital zoom, read back through the driver's settings.
  ASSERT_TRUE(show(0, kThermal));
  reconfigure("thermal_zoom", 1);
  const auto thermal_1 = info_for(kThermal);
  reconfigure("thermal_zoom", 4);
  const auto thermal_4 =
      infos_->next([&](const auto& i) { return i.K[0] > thermal_1->K[0] * 1.5; }, 5);
  ASSERT_TRUE(thermal_1 && thermal_4);
  EXPECT_NEAR(thermal_4->K[0] / thermal_1->K[0], 4, 1e-6);
  reconfigure("thermal_zoom", 1);
}

TEST_F(Video, AnImageModeChangeSwitchesFrameIdAndSize) {
  const auto thermal = show(0, kThermal);
  ASSERT_TRUE(thermal);
  EXPECT_EQ(thermal->width, 640u);
  EXPECT_EQ(thermal->height, 512u);
  const auto visible = show(5, kTele);
  ASSERT_TRUE(visible);
  EXPECT_EQ(visible->width, 1920u);
  EXPECT_EQ(visible->height, 1080u);
  const auto visible_info = info_for(kTele);
  ASSERT_TRUE(visible_info);

  // Split screen: still the tele's frame (its panel is the left half at half scale).
  reconfigure("image_mode", 7);
  const auto split_info =
      infos_->next([&](const auto& i) { return std::abs(i.K[0] - visible_info->K[0] / 2) < 1; }, 5);
  ASSERT_TRUE(split_info) << "camera_info did not switch to the split-screen panel";
  EXPECT_EQ(split_info->header.frame_id, kTele);
  EXPECT_EQ(split_info->width, 1920u);

  const auto back = show(0, kThermal);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->width, 640u);
}

TEST_F(Video, AKilledStreamIsAnErrorWithinTwoSecondsAndFramesComeBack) {
  ASSERT_TRUE(diagnostics_->first_level_after(Clock::now() - std::chrono::seconds(1),
                                              DiagnosticStatus::OK, 5))
      << "the stream is not OK to begin with";
  const auto killed = Clock::now();
  sim_->kill_now();
  const auto error = diagnostics_->first_level_after(killed, DiagnosticStatus::ERROR, 5);
  ASSERT_TRUE(error) << "no ERROR after the stream died";
  EXPECT_LE(*error, 2.0);
  const size_t before = images_->count();
  sim_->start(link_, rtsp_port_);
  const auto restarted = Clock::now();
  ASSERT_TRUE(wait_until([&] { return images_->count() > before + 10; }, 20))
      << "frames did not come back";
  RecordProperty("seconds_until_frames_back", std::to_string(seconds_since(restarted)));
  EXPECT_TRUE(diagnostics_->first_level_after(restarted, DiagnosticStatus::OK, 5));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_video");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
