#include "k40t_driver/ros/video/video_streamer.h"

#include <sensor_msgs/image_encodings.h>
#include <opencv2/imgproc.hpp>

#include "k40t_driver/transport/thread_name.h"

namespace k40t::driver {

namespace {

// The frame converted (or copied) once, straight into the message's buffer.
sensor_msgs::ImagePtr to_message(const video::GrabbedFrame& frame) {
  auto image = boost::make_shared<sensor_msgs::Image>();
  image->width = static_cast<uint32_t>(frame.size.width);
  image->height = static_cast<uint32_t>(frame.size.height);
  image->encoding = sensor_msgs::image_encodings::BGR8;
  image->step = image->width * 3;
  image->data.resize(static_cast<size_t>(image->step) * image->height);
  cv::Mat target(frame.size, CV_8UC3, image->data.data(), image->step);
  if (frame.i420) {
    cv::cvtColor(frame.pixels, target, cv::COLOR_YUV2BGR_I420);
  } else {
    frame.pixels.copyTo(target);
  }
  return image;
}

// Thermal frames and the others differ in size: the FFmpeg back-end must reopen to follow.
bool changes_frame_size(std::optional<int> before, int after) {
  return before && ((*before == 0) != (after == 0));
}

}  // namespace

Result<std::unique_ptr<VideoStreamer>> VideoStreamer::create(const ros::NodeHandle& nh,
                                                             const ros::NodeHandle& private_nh) {
  Result<VideoConfig> config = read_video_config(private_nh);
  if (!config) return config.status();
  return std::unique_ptr<VideoStreamer>(new VideoStreamer(nh, private_nh, config.value()));
}

VideoStreamer::VideoStreamer(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh,
                             const VideoConfig& config)
    : nh_(nh),
      config_(config),
      lenses_(private_nh, config_),
      grabber_(config_.capture),
      stamps_(config_.stamps),
      transport_(nh_),
      publisher_(transport_.advertiseCamera("image_raw", 1)) {
  panel_publishers_ = {nh_.advertise<sensor_msgs::CameraInfo>("split/visible/camera_info", 1),
                       nh_.advertise<sensor_msgs::CameraInfo>("split/thermal/camera_info", 1)};
  camera_status_sub_ = nh_.subscribe("camera/status", 5, &VideoStreamer::on_camera_status, this);
  visible_status_sub_ = nh_.subscribe("visible/status", 5, &VideoStreamer::on_visible_status, this);
  settings_sub_ = nh_.subscribe(config_.settings_topic, 5, &VideoStreamer::on_settings, this);
  diagnostics_ = std::make_unique<VideoDiagnostics>(
      nh_, private_nh, config_, [this] { return grabber_.stats(); },
      [this] {
        std::lock_guard<std::mutex> lock(mutex_);
        return published_;
      });
  grabber_.start();
  publisher_thread_ = std::thread([this] { publish_loop(); });
}

VideoStreamer::~VideoStreamer() {
  running_ = false;
  if (publisher_thread_.joinable()) publisher_thread_.join();
  grabber_.stop();
}

void VideoStreamer::publish_loop() {
  transport::name_this_thread("k40t_vpub");
  uint64_t last = 0;
  while (running_ && ros::ok()) {
    std::optional<video::GrabbedFrame> frame =
        grabber_.wait_newer(last, std::chrono::milliseconds(100));
    if (!frame) continue;
    last = frame->sequence;
    publish(*frame);
  }
}

void VideoStreamer::publish(const video::GrabbedFrame& frame) {
  const int64_t stamp_us = stamps_.stamp(frame.received_us, frame.pts_ms);
  std::optional<int> mode;
  ZoomState zoom;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    mode = image_mode_;
    zoom = zoom_;
  }
  const video::StreamView view = video::stream_view(mode, frame.size, config_.mode6_lens);
  const std::string frame_id = optical_frame(config_, view.lens);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    published_.frame_id = frame_id;
    published_.width = frame.size.width;
    published_.height = frame.size.height;
  }
  std_msgs::Header header;
  header.stamp.fromNSec(static_cast<uint64_t>(stamp_us) * 1000);
  header.frame_id = frame_id;
  if (view.split) publish_split_panels(header.stamp, frame.size, zoom);
  if (publisher_.getNumSubscribers() == 0) return;  // no conversion for nobody

  sensor_msgs::ImagePtr image = to_message(frame);
  auto info =
      boost::make_shared<sensor_msgs::CameraInfo>(lenses_.camera_info(view, frame.size, zoom));
  image->header = header;
  info->header = image->header;
  publisher_.publish(image, info);
  std::lock_guard<std::mutex> lock(mutex_);
  ++published_.published;
}

void VideoStreamer::publish_split_panels(const ros::Time& stamp, cv::Size frame,
                                         const ZoomState& zoom) {
  if (panel_publishers_[0].getNumSubscribers() == 0 &&
      panel_publishers_[1].getNumSubscribers() == 0)
    return;
  std::array<sensor_msgs::CameraInfo, 2> panels = lenses_.split_panels(frame, zoom);
  const std::array<video::Lens, 2> lenses{video::Lens::kTele, video::Lens::kThermal};
  for (size_t i = 0; i < panels.size(); ++i) {
    panels[i].header.stamp = stamp;
    panels[i].header.frame_id = optical_frame(config_, lenses[i]);
    panel_publishers_[i].publish(panels[i]);
  }
}

void VideoStreamer::on_camera_status(const k40t_driver::CameraStatus::ConstPtr& status) {
  bool restart = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    restart = changes_frame_size(image_mode_, status->image_mode) ||
              (stream_resolution_ && *stream_resolution_ != status->stream_resolution);
    image_mode_ = status->image_mode;
    stream_resolution_ = status->stream_resolution;
  }
  if (restart && config_.capture.backend == video::Backend::kFFmpeg) grabber_.restart();
}

void VideoStreamer::on_visible_status(const k40t_driver::VisibleStatus::ConstPtr& status) {
  std::lock_guard<std::mutex> lock(mutex_);
  zoom_.focal_length_mm = status->focal_length_mm;
  zoom_.zoom_ratio = status->zoom_ratio;
}

void VideoStreamer::on_settings(const dynamic_reconfigure::Config::ConstPtr& config) {
  for (const auto& parameter : config->ints) {
    if (parameter.name == "thermal_zoom") {
      std::lock_guard<std::mutex> lock(mutex_);
      zoom_.thermal_zoom = parameter.value;
    }
  }
}

}  // namespace k40t::driver
