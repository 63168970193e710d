// k40t_driver/VideoLatencyProbe (benchmark only): a nodelet in the video nodelet's manager that
// reads the frame stamp (sim/video/frame_stamp.h) out of every image_raw it gets by pointer and
// measures, over ~duration seconds after ~warmup:
//   latency      render (in the simulator) -> this callback, ms: p50, p90, p99, max
//   stamp error  header.stamp - render time, ms, p10/p50/p90 (how far the stamps are from the
//                truth). With the video nodelet's latency 0 and no presentation times the stamp
//                is the moment OpenCV's read() returned, so this is render -> decoded frame (the
//                encoder, network and decoder's own latency) and
//   after read   this callback - header.stamp: what the nodelet adds (conversion, publishing)
//   backlog      latency p50 over the first and the last 10 s (growth = a queue filling up)
//   frames       received, missing (counter gaps: dropped as too old, never queued), repeated
//   CPU          of the whole manager process (decode, conversion, publishing), % of one core
// and appends one line to ~output.
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <unistd.h>
#include <pluginlib/class_list_macros.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "k40t_driver/sim/video/frame_stamp.h"

namespace k40t::bench {

namespace {

struct Sample {
  double arrival_s;  // since the measurement started
  double latency_ms;
  double stamp_error_ms;
  double after_read_ms;
  uint32_t counter;
};

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const size_t i = std::min(values.size() - 1, static_cast<size_t>(p * (values.size() - 1) + 0.5));
  return values[i];
}

// User + system CPU seconds of this process (/proc/self/stat fields 14 and 15).
double process_cpu_s() {
  std::ifstream in("/proc/self/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::istringstream fields(text.substr(text.rfind(')') + 2));
  std::string field;
  unsigned long long utime = 0, stime = 0;
  for (int i = 3; i <= 15 && fields >> field; ++i) {
    if (i == 14) utime = std::stoull(field);
    if (i == 15) stime = std::stoull(field);
  }
  return static_cast<double>(utime + stime) / sysconf(_SC_CLK_TCK);
}

}  // namespace

class VideoLatencyProbe : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    label_ = pnh.param<std::string>("label", getName());
    output_ = pnh.param<std::string>("output", "");
    duration_s_ = pnh.param("duration", 60.0);
    warmup_s_ = pnh.param("warmup", 5.0);
    sub_ = getNodeHandle().subscribe("image_raw", 1, &VideoLatencyProbe::on_image, this);
  }

  void on_image(const sensor_msgs::ImageConstPtr& image) {
    const int64_t now_us = sim::video::system_time_us();
    const cv::Mat pixels(image->height, image->width, CV_8UC3,
                         const_cast<uint8_t*>(image->data.data()), image->step);
    const auto stamp = sim::video::read_frame_stamp(pixels);
    std::lock_guard<std::mutex> lock(mutex_);
    if (done_) return;
    if (!first_us_) first_us_ = now_us;
    const double since_first_s = (now_us - *first_us_) / 1e6;
    if (since_first_s < warmup_s_) return;
    if (!start_us_) {
      start_us_ = now_us;
      start_cpu_s_ = process_cpu_s();
    }
    if (!stamp) {
      ++unreadable_;
    } else {
      const double stamp_us = image->header.stamp.toNSec() / 1000.0;
      samples_.push_back({(now_us - *start_us_) / 1e6, (now_us - stamp->render_time_us) / 1e3,
                          (stamp_us - stamp->render_time_us) / 1e3, (now_us - stamp_us) / 1e3,
                          stamp->counter});
    }
    if ((now_us - *start_us_) / 1e6 >= duration_s_) finish((now_us - *start_us_) / 1e6);
  }

  void finish(double elapsed_s) {
    done_ = true;
    const double cpu_percent = 100 * (process_cpu_s() - start_cpu_s_) / elapsed_s;
    std::vector<double> latency, stamp_error, after_read, first10, last10;
    uint64_t missing = 0, repeated = 0;
    for (size_t i = 0; i < samples_.size(); ++i) {
      const Sample& s = samples_[i];
      latency.push_back(s.latency_ms);
      stamp_error.push_back(s.stamp_error_ms);
      after_read.push_back(s.after_read_ms);
      if (s.arrival_s < 10) first10.push_back(s.latency_ms);
      if (s.arrival_s > elapsed_s - 10) last10.push_back(s.latency_ms);
      if (i > 0) {
        const int64_t step = static_cast<int64_t>(s.counter) - samples_[i - 1].counter;
        if (step > 1) missing += step - 1;
        if (step == 0) ++repeated;
      }
    }
    char line[512];
    std::snprintf(
        line, sizeof line,
        "%-26s %5zu fr %4.1f fps | latency p50 %5.1f p90 %5.1f p99 %5.1f max %5.1f ms | "
        "stamp-render p10/50/90 %+5.1f/%+5.1f/%+5.1f ms | after read p50 %4.1f p99 %4.1f "
        "ms | p50 first/last 10 s %5.1f/%5.1f ms | missing %3llu repeated %2llu "
        "unreadable %2llu | cpu %5.1f%%",
        label_.c_str(), samples_.size(), samples_.size() / elapsed_s, percentile(latency, 0.5),
        percentile(latency, 0.9), percentile(latency, 0.99), percentile(latency, 1.0),
        percentile(stamp_error, 0.1), percentile(stamp_error, 0.5), percentile(stamp_error, 0.9),
        percentile(after_read, 0.5), percentile(after_read, 0.99), percentile(first10, 0.5),
        percentile(last10, 0.5), static_cast<unsigned long long>(missing),
        static_cast<unsigned long long>(repeated), static_cast<unsigned long long>(unreadable_),
        cpu_percent);
    NODELET_INFO("%s", line);
    if (!output_.empty()) std::ofstream(output_, std::ios::app) << line << "\n";
  }

  std::mutex mutex_;
  ros::Subscriber sub_;
  std::string label_;
  std::string output_;
  double duration_s_ = 60;
  double warmup_s_ = 5;
  std::optional<int64_t> first_us_;
  std::optional<int64_t> start_us_;
  double start_cpu_s_ = 0;
  std::vector<Sample> samples_;
  uint64_t unreadable_ = 0;
  bool done_ = false;
};

}  // namespace k40t::bench

PLUGINLIB_EXPORT_CLASS(k40t::bench::VideoLatencyProbe, nodelet::Nodelet)
