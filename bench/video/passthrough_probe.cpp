// k40t_passthrough_probe: one subscriber of the video node in its own process, as a ground
// station would be (bench/video/run_passthrough_bench.sh). ~kind:
//   raw          image_raw, plain sensor_msgs/Image;
//   passthrough  image_raw/k40t_video, the encoded access units, not decoded;
//   k40t_video   image_raw through the k40t_video image_transport plugin (decoded here).
// After ~seconds it prints one line: messages/s, payload bytes/s and, for pictures, render ->
// arrival latency p50/p90 from the simulator's frame stamp in the pixels.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <vector>

#include <image_transport/image_transport.h>
#include <ros/ros.h>

#include "k40t_driver/CompressedVideo.h"
#include "k40t_driver/sim/video/frame_stamp.h"

namespace {

std::mutex mutex;
uint64_t messages = 0;
uint64_t bytes = 0;
std::vector<double> latency_ms;

int64_t now_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

void on_image(const sensor_msgs::ImageConstPtr& image) {
  const int64_t arrival = now_us();
  std::optional<k40t::sim::video::FrameStamp> stamp;
  if (image->encoding == "bgr8") {
    cv::Mat bgr(static_cast<int>(image->height), static_cast<int>(image->width), CV_8UC3,
                const_cast<uint8_t*>(image->data.data()), image->step);
    stamp = k40t::sim::video::read_frame_stamp(bgr);
  }
  std::lock_guard<std::mutex> lock(mutex);
  ++messages;
  bytes += image->data.size();
  if (stamp) latency_ms.push_back((arrival - stamp->render_time_us) / 1000.0);
}

void on_unit(const k40t_driver::CompressedVideo::ConstPtr& unit) {
  std::lock_guard<std::mutex> lock(mutex);
  ++messages;
  bytes += unit->data.size();
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return -1;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(p * v.size()))];
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "passthrough_probe");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  const std::string kind = pnh.param<std::string>("kind", "raw");
  const double seconds = pnh.param("seconds", 20.0);
  const std::string label = pnh.param<std::string>("label", kind);
  image_transport::ImageTransport it(nh);
  image_transport::Subscriber images;
  ros::Subscriber units;
  if (kind == "passthrough") {
    units = nh.subscribe("image_raw/k40t_video", 30, &on_unit, ros::TransportHints().tcpNoDelay());
  } else {
    images =
        it.subscribe("image_raw", 2, &on_image, ros::VoidPtr(),
                     image_transport::TransportHints(kind, ros::TransportHints().tcpNoDelay()));
  }
  ros::AsyncSpinner spinner(1);
  spinner.start();
  ros::WallDuration(2.0).sleep();  // warm-up: connection, first key frame
  {
    std::lock_guard<std::mutex> lock(mutex);
    messages = bytes = 0;
    latency_ms.clear();
  }
  ros::WallDuration(seconds).sleep();
  std::lock_guard<std::mutex> lock(mutex);
  std::printf(
      "%s: %.1f msg/s, %.0f bytes/s (%.3f MB/s), latency render->here p50 %.1f ms p90 %.1f ms\n",
      label.c_str(), messages / seconds, bytes / seconds, bytes / seconds / 1e6,
      percentile(latency_ms, 0.5), percentile(latency_ms, 0.9));
  std::fflush(stdout);
  return 0;
}
