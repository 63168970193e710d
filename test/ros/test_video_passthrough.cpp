// rostest of the passthrough video and the k40t_video image_transport (video_passthrough.test).
// This test spawns the simulated stream (k40t_video_sim on a free port, 640x512 thermal, a key
// frame every 15 frames, panning so every frame differs) and the video node (its own process);
// its own subscribers are the remote side:
//   - image_raw (raw) and image_raw through the k40t_video plugin (decoding in this process):
//     for every stamp both have, the plugin's picture matches image_raw's (PSNR >= 35 dB) and has
//     its frame id; the plugin's extra latency (arrival after image_raw's, p50) and both latencies
//     from the simulator's render time (the frame stamp in the pixels) are recorded as test
//     properties for docs/video.md, not asserted;
//   - a late subscriber through the plugin gets its first picture within one key-frame interval
//     of access units;
//   - with only encoded subscribers, the node publishes no image (diagnostics' counters);
//   - the plugin's publisher side: an image stream of this node encoded to H.264 and decoded back;
//   - `rosrun image_transport list_transports` lists the transport.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <image_transport/image_transport.h>
#include <ros/ros.h>
#include <opencv2/imgproc.hpp>

#include "../unit/video_test_support.h"
#include "k40t_driver/CompressedVideo.h"
#include "k40t_driver/sim/video/frame_stamp.h"

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kKeyInterval = 15;

bool wait_until(const std::function<bool()>& condition, double timeout_s) {
  const auto deadline = Clock::now() + std::chrono::duration<double>(timeout_s);
  while (Clock::now() < deadline && ros::ok()) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return condition();
}

std::string program_dir() {
  char self[4096] = {};
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  const std::string path(self, n > 0 ? n : 0);
  return path.substr(0, path.rfind('/'));
}

// A child program, ended with SIGTERM.
class Child {
 public:
  explicit Child(std::vector<std::string> args) {
    pid_ = fork();
    if (pid_ == 0) {
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(argv[0], argv.data());
      _exit(127);
    }
  }
  ~Child() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }

 private:
  pid_t pid_ = -1;
};

struct Arrival {
  cv::Mat bgr;
  std::string frame_id;
  double arrival_s = 0;  // wall clock
};

double now_s() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// Images by stamp, as they arrive.
class ImageLog {
 public:
  void add(const sensor_msgs::ImageConstPtr& image) {
    Arrival a;
    a.arrival_s = now_s();
    if (image->encoding != "bgr8") return;  // both sides publish bgr8
    a.bgr = cv::Mat(static_cast<int>(image->height), static_cast<int>(image->width), CV_8UC3,
                    const_cast<uint8_t*>(image->data.data()), image->step)
                .clone();
    a.frame_id = image->header.frame_id;
    std::lock_guard<std::mutex> lock(mutex_);
    by_stamp_[image->header.stamp.toNSec()] = std::move(a);
  }
  std::map<uint64_t, Arrival> copy() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return by_stamp_;
  }
  size_t size() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return by_stamp_.size();
  }

 private:
  mutable std::mutex mutex_;
  std::map<uint64_t, Arrival> by_stamp_;
};

double psnr(const cv::Mat& a, const cv::Mat& b) {
  const double mse = cv::norm(a, b, cv::NORM_L2SQR) / static_cast<double>(a.total() * 3);
  return mse == 0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

double median(std::vector<double> v) {
  if (v.empty()) return -1;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Render -> arrival, from the simulator's frame stamp in the pixels.
std::optional<double> render_latency_ms(const Arrival& a) {
  auto stamp = k40t::sim::video::read_frame_stamp(a.bgr);
  if (!stamp) return std::nullopt;
  return (a.arrival_s * 1e6 - stamp->render_time_us) / 1000.0;
}

class VideoPassthrough : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string dir = program_dir();
    sim_ = std::make_unique<k40t::video::testing::SimStreamProcess>(
        dir + "/k40t_video_sim",
        std::vector<std::string>{"--mode", "0", "--key-interval", std::to_string(kKeyInterval),
                                 "--sweep", "20"});
    ASSERT_FALSE(sim_->url().empty()) << "k40t_video_sim did not start";
    video_ = std::make_unique<Child>(std::vector<std::string>{
        dir + "/k40t_video_node", "__name:=video", "__ns:=" + ros::this_node::getNamespace(),
        "_url:=" + sim_->url(), "_latency:=0.01"});
  }
  std::unique_ptr<k40t::video::testing::SimStreamProcess> sim_;
  std::unique_ptr<Child> video_;
};

TEST_F(VideoPassthrough, PluginPicturesMatchImageRawAndALateSubscriberStartsAtAKeyFrame) {
  ros::NodeHandle nh;
  image_transport::ImageTransport it(nh);
  ImageLog raw;
  ImageLog decoded;
  auto raw_sub = it.subscribe(
      "image_raw", 10, [&](const sensor_msgs::ImageConstPtr& m) { raw.add(m); }, ros::VoidPtr(),
      image_transport::TransportHints("raw"));
  auto video_sub = it.subscribe(
      "image_raw", 10, [&](const sensor_msgs::ImageConstPtr& m) { decoded.add(m); }, ros::VoidPtr(),
      image_transport::TransportHints("k40t_video"));
  ASSERT_EQ(video_sub.getTransport(), "k40t_video");
  ASSERT_TRUE(wait_until([&] { return raw.size() > 0 && decoded.size() > 0; }, 15))
      << "raw " << raw.size() << ", through the plugin " << decoded.size();
  ASSERT_TRUE(wait_until([&] { return decoded.size() >= 120; }, 10)) << decoded.size();
  video_sub.shutdown();
  const auto raw_frames = raw.copy();
  const auto decoded_frames = decoded.copy();
  std::vector<double> extra_ms, raw_ms, plugin_ms;
  size_t matched = 0;
  for (const auto& [stamp, d] : decoded_frames) {
    auto r = raw_frames.find(stamp);
    if (r == raw_frames.end()) continue;
    ++matched;
    EXPECT_EQ(d.frame_id, r->second.frame_id);
    ASSERT_EQ(d.bgr.size(), r->second.bgr.size());
    EXPECT_GE(psnr(d.bgr, r->second.bgr), 35.0) << "stamp " << stamp;
    extra_ms.push_back((d.arrival_s - r->second.arrival_s) * 1000);
    if (auto l = render_latency_ms(d)) plugin_ms.push_back(*l);
    if (auto l = render_latency_ms(r->second)) raw_ms.push_back(*l);
  }
  // image_raw drops frames when its subscriber is slow; most stamps are in both.
  EXPECT_GE(matched, decoded_frames.size() / 2) << matched << " of " << decoded_frames.size();
  std::printf(
      "[ MEASURED ] plugin after image_raw p50 %.1f ms; render->image_raw p50 %.1f ms; "
      "render->plugin p50 %.1f ms (%zu frames)\n",
      median(extra_ms), median(raw_ms), median(plugin_ms), matched);
  RecordProperty("plugin_after_raw_p50_ms", std::to_string(median(extra_ms)));
  RecordProperty("render_to_raw_p50_ms", std::to_string(median(raw_ms)));
  RecordProperty("render_to_plugin_p50_ms", std::to_string(median(plugin_ms)));

  // The late subscriber: access units seen on the topic until its first picture.
  std::mutex mutex;
  int units_seen = 0;
  std::optional<int> units_before_picture;
  ros::Subscriber counter = nh.subscribe<k40t_driver::CompressedVideo>(
      "image_raw/k40t_video", 100, [&](const k40t_driver::CompressedVideo::ConstPtr&) {
        std::lock_guard<std::mutex> lock(mutex);
        ++units_seen;
      });
  ASSERT_TRUE(wait_until(
      [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return units_seen > 0;
      },
      5));
  {
    std::lock_guard<std::mutex> lock(mutex);
    units_seen = 0;
  }
  const auto joined = Clock::now();
  auto late = it.subscribe(
      "image_raw", 10,
      [&](const sensor_msgs::ImageConstPtr&) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!units_before_picture) units_before_picture = units_seen;
      },
      ros::VoidPtr(), image_transport::TransportHints("k40t_video"));
  ASSERT_TRUE(wait_until(
      [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return units_before_picture.has_value();
      },
      10))
      << "no picture for the late subscriber";
  const double waited_ms = std::chrono::duration<double, std::milli>(Clock::now() - joined).count();
  std::printf("[ MEASURED ] late subscriber: first picture after %d access units, %.0f ms\n",
              *units_before_picture, waited_ms);
  RecordProperty("late_subscriber_ms", std::to_string(waited_ms));
  // Its connection comes up a few frames after the counter's was already there: allow 3 more.
  EXPECT_LE(*units_before_picture, kKeyInterval + 3);

  // Only encoded subscribers left: the node publishes access units and no image (it decodes
  // only for image_raw's subscribers), as its diagnostics count them.
  raw_sub.shutdown();
  std::mutex diag_mutex;
  std::vector<std::pair<long, long>> counts;  // (frames published, access units published)
  ros::Subscriber diagnostics = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 20, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& array) {
        for (const auto& status : array->status) {
          long frames = -1, units = -1;
          for (const auto& kv : status.values) {
            if (kv.key == "frames published") frames = std::stol(kv.value);
            if (kv.key == "access units published (passthrough)") units = std::stol(kv.value);
          }
          std::lock_guard<std::mutex> lock(diag_mutex);
          if (frames >= 0 && units >= 0) counts.emplace_back(frames, units);
        }
      });
  std::this_thread::sleep_for(std::chrono::milliseconds(700));  // image_raw's last frames go out
  {
    std::lock_guard<std::mutex> lock(diag_mutex);
    counts.clear();
  }
  ASSERT_TRUE(wait_until(
      [&] {
        std::lock_guard<std::mutex> lock(diag_mutex);
        return counts.size() >= 2 && counts.back().second - counts.front().second >= 30;
      },
      5))
      << "no diagnostics, or no access units";
  std::lock_guard<std::mutex> lock(diag_mutex);
  EXPECT_EQ(counts.back().first, counts.front().first) << "images published without subscribers";
}

TEST(VideoTransport, ThePublisherSideEncodesAnyImageStream) {
  ros::NodeHandle nh;
  image_transport::ImageTransport it(nh);
  image_transport::Publisher pub = it.advertise("other_camera/image", 5);
  ImageLog decoded;
  auto sub = it.subscribe(
      "other_camera/image", 50, [&](const sensor_msgs::ImageConstPtr& m) { decoded.add(m); },
      ros::VoidPtr(), image_transport::TransportHints("k40t_video"));
  ASSERT_TRUE(wait_until([&] { return pub.getNumSubscribers() > 0; }, 5));
  std::map<uint64_t, cv::Mat> sent;
  for (int i = 0; i < 40 && ros::ok(); ++i) {
    cv::Mat bgr(240, 320, CV_8UC3, cv::Scalar(30, 60 + i, 90));
    cv::circle(bgr, {40 + 5 * i, 120}, 30, {255, 255, 255}, -1);
    std_msgs::Header header;
    header.stamp.fromNSec(1'000'000'000ULL + i * 33'000'000ULL);
    header.frame_id = "other_camera";
    sensor_msgs::Image image;
    image.header = header;
    image.width = 320;
    image.height = 240;
    image.encoding = "bgr8";
    image.step = 320 * 3;
    image.data.assign(bgr.data, bgr.data + bgr.total() * 3);
    pub.publish(image);
    sent[header.stamp.toNSec()] = bgr;
    std::this_thread::sleep_for(std::chrono::milliseconds(33));
  }
  ASSERT_TRUE(wait_until([&] { return decoded.size() >= 35; }, 5)) << decoded.size();
  for (const auto& [stamp, d] : decoded.copy()) {
    EXPECT_EQ(d.frame_id, "other_camera");
    EXPECT_GE(psnr(d.bgr, sent.at(stamp)), 35.0) << "stamp " << stamp;
  }
}

TEST(VideoTransportListing, ListTransportsNamesIt) {
  std::string out;
  FILE* pipe = popen("rosrun image_transport list_transports 2>&1", "r");
  ASSERT_NE(pipe, nullptr);
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe)) out += buffer;
  pclose(pipe);
  EXPECT_NE(out.find("image_transport/k40t_video"), std::string::npos) << out;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_video_passthrough");
  ros::AsyncSpinner spinner(3);
  spinner.start();
  const int result = RUN_ALL_TESTS();
  ros::shutdown();
  return result;
}
