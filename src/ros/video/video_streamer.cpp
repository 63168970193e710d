#include "k40t_driver/ros/video/video_streamer.h"

#include <algorithm>

#include "k40t_driver/CompressedVideo.h"
#include "k40t_driver/ros/video/bgr_message.h"
#include "k40t_driver/ros/video/video_transport_name.h"
#include "k40t_driver/video/capture_open.h"

#include "k40t_driver/transport/thread_name.h"

namespace k40t::driver {

namespace {

// Thermal frames and the others differ in size: the FFmpeg back-end must reopen to follow.
bool changes_frame_size(std::optional<int> before, int after) {
  return before && ((*before == 0) != (after == 0));
}

// image_raw without our own transport's publisher: the passthrough publishes there itself, and
// the plugin would re-encode the decoded frames into the same topic.
image_transport::CameraPublisher advertise_raw(ros::NodeHandle& nh,
                                               image_transport::ImageTransport& transport) {
  nh.setParam("image_raw/disable_pub_plugins", std::vector<std::string>{kVideoTransportLookupName});
  return transport.advertiseCamera("image_raw", 1);
}

constexpr size_t kRememberedStamps = 128;  // access units between reception and decoding

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
      stamps_(config_.stamps),
      transport_(nh_),
      publisher_(advertise_raw(nh_, transport_)) {
  panel_publishers_ = {nh_.advertise<sensor_msgs::CameraInfo>("split/visible/camera_info", 1),
                       nh_.advertise<sensor_msgs::CameraInfo>("split/thermal/camera_info", 1)};
  camera_status_sub_ = nh_.subscribe("camera/status", 5, &VideoStreamer::on_camera_status, this);
  visible_status_sub_ = nh_.subscribe("visible/status", 5, &VideoStreamer::on_visible_status, this);
  settings_sub_ = nh_.subscribe(config_.settings_topic, 5, &VideoStreamer::on_settings, this);
  if (video::delivers_i420(config_.capture)) {
    passthrough_ = nh_.advertise<k40t_driver::CompressedVideo>(
        std::string("image_raw/") + kVideoTransportName, 30);
    auto units = std::make_unique<video::AccessUnitSource>(
        config_.capture, [this](const video::AccessUnit& unit) { publish_unit(unit); });
    units_ = units.get();
    grabber_ = std::move(units);
  } else {
    grabber_ = std::make_unique<video::FrameGrabber>(config_.capture);
  }
  diagnostics_ = std::make_unique<VideoDiagnostics>(
      nh_, private_nh, config_, [this] { return grabber_->stats(); },
      [this] {
        std::lock_guard<std::mutex> lock(mutex_);
        return published_;
      });
  grabber_->start();
  publisher_thread_ = std::thread([this] { publish_loop(); });
}

VideoStreamer::~VideoStreamer() {
  running_ = false;
  if (publisher_thread_.joinable()) publisher_thread_.join();
  grabber_->stop();
}

void VideoStreamer::publish_loop() {
  transport::name_this_thread("k40t_vpub");
  uint64_t last = 0;
  while (running_ && ros::ok()) {
    // Decode only for someone who wants pixels (checked at least every 100 ms).
    if (units_) units_->set_decoding(publisher_.getNumSubscribers() > 0);
    std::optional<video::GrabbedFrame> frame =
        grabber_->wait_newer(last, std::chrono::milliseconds(100));
    if (!frame) continue;
    last = frame->sequence;
    publish(*frame);
  }
}

std_msgs::Header VideoStreamer::header_for(uint64_t sequence, int64_t received_us,
                                           std::optional<double> pts_ms, cv::Size size,
                                           video::StreamView* view_out) {
  int64_t stamp_us = 0;
  {
    std::lock_guard<std::mutex> lock(stamp_mutex_);
    auto known = std::find_if(recent_stamps_.begin(), recent_stamps_.end(),
                              [&](const auto& entry) { return entry.first == sequence; });
    if (known != recent_stamps_.end()) {
      stamp_us = known->second;
    } else {
      stamp_us = stamps_.stamp(received_us, pts_ms);
      recent_stamps_.emplace_back(sequence, stamp_us);
      if (recent_stamps_.size() > kRememberedStamps) recent_stamps_.pop_front();
    }
  }
  std::optional<int> mode;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    mode = image_mode_;
  }
  const video::StreamView view = video::stream_view(mode, size, config_.mode6_lens);
  if (view_out) *view_out = view;
  std_msgs::Header header;
  header.stamp.fromNSec(static_cast<uint64_t>(stamp_us) * 1000);
  header.frame_id = optical_frame(config_, view.lens);
  return header;
}

void VideoStreamer::publish_unit(const video::AccessUnit& unit) {
  if (passthrough_.getNumSubscribers() == 0) return;  // not even the stamp
  auto message = boost::make_shared<k40t_driver::CompressedVideo>();
  message->header =
      header_for(unit.sequence, unit.received_us, unit.pts_ms, cv::Size(unit.width, unit.height));
  // Consecutive while the stream runs: a subscriber sees a lost message as a gap and waits for
  // the next key frame instead of decoding pictures whose references are missing.
  message->header.seq = static_cast<uint32_t>(unit.sequence);
  message->format = video::to_string(unit.codec);
  message->data = unit.bytes;
  message->key_frame = unit.key_frame;
  passthrough_.publish(message);
  std::lock_guard<std::mutex> lock(mutex_);
  ++published_.units_published;
}

void VideoStreamer::publish(const video::GrabbedFrame& frame) {
  video::StreamView view;
  std_msgs::Header header =
      header_for(frame.sequence, frame.received_us, frame.pts_ms, frame.size, &view);
  ZoomState zoom;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    zoom = zoom_;
    published_.frame_id = header.frame_id;
    published_.width = frame.size.width;
    published_.height = frame.size.height;
  }
  if (view.split) publish_split_panels(header.stamp, frame.size, zoom);
  if (publisher_.getNumSubscribers() == 0) return;  // no conversion for nobody

  sensor_msgs::ImagePtr image = bgr_messages_.make(frame.pixels, frame.i420, frame.size);
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
  if (restart && config_.capture.backend == video::Backend::kFFmpeg) grabber_->restart();
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
