#include "k40t_driver/video/capture_open.h"

#include <cstdlib>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/video/opencv_log_scope.h"
#include "k40t_driver/video/rtsp_probe.h"
#include "k40t_driver/video/stall_guard.h"

namespace k40t::video {

namespace {

constexpr const char* kFfmpegOptionsVariable = "OPENCV_FFMPEG_CAPTURE_OPTIONS";

// Sets (or, with nothing, removes) an environment variable until destroyed.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (const char* old = std::getenv(name)) previous_ = old;
    if (value) {
      setenv(name, value->c_str(), 1);
    } else {
      unsetenv(name);
    }
  }
  ~ScopedEnvironment() {
    if (previous_) {
      setenv(name_, previous_->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> previous_;
};

std::mutex& ffmpeg_open_mutex() {
  static std::mutex mutex;
  return mutex;
}

bool open_ffmpeg(cv::VideoCapture& capture, const CaptureOptions& options) {
  std::lock_guard<std::mutex> lock(ffmpeg_open_mutex());
  if (!options.low_latency) {
    ScopedEnvironment defaults(kFfmpegOptionsVariable, std::nullopt);
    return capture.open(options.url, cv::CAP_FFMPEG);
  }
  ScopedEnvironment tuned(kFfmpegOptionsVariable, ffmpeg_capture_options(options));
  const std::vector<int> parameters{
      cv::CAP_PROP_OPEN_TIMEOUT_MSEC, static_cast<int>(options.open_timeout_s * 1000),
      cv::CAP_PROP_READ_TIMEOUT_MSEC, static_cast<int>(options.read_timeout_s * 1000)};
  return capture.open(options.url, cv::CAP_FFMPEG, parameters);
}

}  // namespace

bool delivers_i420(const CaptureOptions& options) {
  return options.backend == Backend::kGStreamer && options.low_latency;
}

Result<std::shared_ptr<cv::VideoCapture>> open_capture(const CaptureOptions& options) {
  if (Status s = validate(options); !s) return s;
  if (options.low_latency) {
    if (Status s = probe_rtsp(options.url, options.open_timeout_s); !s) return s;
  }
  auto capture = std::make_shared<cv::VideoCapture>();
  bool opened = false;
  try {
    if (options.backend == Backend::kFFmpeg) {
      opened = open_ffmpeg(*capture, options);
    } else if (options.low_latency) {
      if (Status s = register_stall_guard(); !s) return s;
      OpenCvLogScope live_stream;  // no duration, no position: not a warning (opencv_log_scope.h)
      opened = capture->open(gstreamer_pipeline(options), cv::CAP_GSTREAMER);
    } else {
      OpenCvLogScope live_stream;
      opened = capture->open(options.url, cv::CAP_GSTREAMER);
    }
  } catch (const cv::Exception& e) {
    return Status::fail("cannot open " + options.url + " with " + to_string(options.backend) +
                        ": " + e.what());
  }
  if (!opened || !capture->isOpened()) {
    return Status::fail("cannot open " + options.url + " with " + to_string(options.backend));
  }
  return capture;
}

}  // namespace k40t::video
