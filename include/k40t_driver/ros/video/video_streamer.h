// The pod's RTSP stream as ROS images. With the tuned GStreamer configuration (the default) an
// AccessUnitSource keeps the stream encoded: every access unit is published at once on
// image_raw/k40t_video (k40t_driver/CompressedVideo, the passthrough: no decoding, no
// re-encoding) while someone subscribes there, and decoded only while image_raw has subscribers.
// Otherwise (FFmpeg, OpenCV defaults) a FrameGrabber decodes every frame. Either keeps the newest
// decoded frame; a publisher thread takes each new one (never a backlog), converts it once into the
// message's own buffer, stamps it (stamp_estimator.h), picks its frame id and camera_info from the
// image mode and zoom the driver reports, and publishes image_raw + camera_info through
// image_transport as shared pointers (zero copies to subscribers in the same nodelet manager). A
// frame's access unit and its image carry the same stamp and frame id. In split screen it also
// publishes split/visible/camera_info and split/thermal/camera_info (lens_models.h: each panel
// in the frame's pixel coordinates, roi = the panel), with the image's stamp, for locate_pixel.
//
// Subscribed (relative to the node's namespace, where the driver publishes): camera/status (image
// mode, stream resolution), visible/status (tele focal length and zoom), and the driver's
// dynamic_reconfigure updates (~settings_topic) for the thermal digital zoom.
#pragma once

#include <array>
#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <dynamic_reconfigure/Config.h>
#include <image_transport/image_transport.h>
#include <ros/node_handle.h>

#include "k40t_driver/CameraStatus.h"
#include "k40t_driver/VisibleStatus.h"
#include "k40t_driver/protocol/result.h"
#include "k40t_driver/ros/video/bgr_message.h"
#include "k40t_driver/ros/video/lens_models.h"
#include "k40t_driver/ros/video/video_config.h"
#include "k40t_driver/ros/video/video_diagnostics.h"
#include "k40t_driver/video/access_unit_source.h"
#include "k40t_driver/video/frame_grabber.h"
#include "k40t_driver/video/stamp_estimator.h"

namespace k40t::driver {

class VideoStreamer {
 public:
  // Reads ~parameters; an error names the parameter. The stream is opened in the background
  // (a pod that is not there yet is retried, and shows in diagnostics).
  static Result<std::unique_ptr<VideoStreamer>> create(const ros::NodeHandle& nh,
                                                       const ros::NodeHandle& private_nh);
  ~VideoStreamer();

 private:
  VideoStreamer(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh,
                const VideoConfig& config);
  void publish_loop();
  void publish(const video::GrabbedFrame& frame);
  // On GStreamer's streaming thread: one access unit to image_raw/k40t_video.
  void publish_unit(const video::AccessUnit& unit);
  // The frame's stamp (the same for its access unit and its image) and frame id.
  std_msgs::Header header_for(uint64_t sequence, int64_t received_us, std::optional<double> pts_ms,
                              cv::Size size, video::StreamView* view = nullptr);
  void publish_split_panels(const ros::Time& stamp, cv::Size frame, const ZoomState& zoom);

  void on_camera_status(const k40t_driver::CameraStatus::ConstPtr& status);
  void on_visible_status(const k40t_driver::VisibleStatus::ConstPtr& status);
  void on_settings(const dynamic_reconfigure::Config::ConstPtr& config);

  ros::NodeHandle nh_;
  const VideoConfig config_;
  LensModels lenses_;
  std::mutex stamp_mutex_;        // the publisher and streaming threads stamp
  video::StampEstimator stamps_;  // guarded by stamp_mutex_
  std::deque<std::pair<uint64_t, int64_t>> recent_stamps_;  // sequence -> stamp (us)
  image_transport::ImageTransport transport_;
  image_transport::CameraPublisher publisher_;
  BgrMessageMaker bgr_messages_;  // the publisher thread's
  ros::Publisher passthrough_;
  std::unique_ptr<video::FrameSource> grabber_;
  video::AccessUnitSource* units_ = nullptr;        // grabber_, when it is the access-unit source
  std::array<ros::Publisher, 2> panel_publishers_;  // split screen: visible, thermal
  ros::Subscriber camera_status_sub_;
  ros::Subscriber visible_status_sub_;
  ros::Subscriber settings_sub_;

  mutable std::mutex mutex_;  // guards what the callbacks write and the diagnostics read
  std::optional<int> image_mode_;
  std::optional<int> stream_resolution_;
  ZoomState zoom_;
  PublishedState published_;

  std::atomic<bool> running_{true};
  std::unique_ptr<VideoDiagnostics> diagnostics_;
  std::thread publisher_thread_;
};

}  // namespace k40t::driver
