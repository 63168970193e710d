// The pod's RTSP stream as ROS images: a FrameGrabber keeps the newest decoded frame; a publisher
// thread takes each new one (never a backlog), converts it once into the message's own buffer,
// stamps it (stamp_estimator.h), picks its frame id and camera_info from the image mode and zoom
// the driver reports, and publishes image_raw + camera_info through image_transport as shared
// pointers (zero copies to subscribers in the same nodelet manager). In split screen it also
// publishes split/visible/camera_info and split/thermal/camera_info (lens_models.h: each panel
// in the frame's pixel coordinates, roi = the panel), with the image's stamp, for locate_pixel.
//
// Subscribed (relative to the node's namespace, where the driver publishes): camera/status (image
// mode, stream resolution), visible/status (tele focal length and zoom), and the driver's
// dynamic_reconfigure updates (~settings_topic) for the thermal digital zoom.
#pragma once

#include <array>
#include <atomic>
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
#include "k40t_driver/ros/video/lens_models.h"
#include "k40t_driver/ros/video/video_config.h"
#include "k40t_driver/ros/video/video_diagnostics.h"
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
  void publish_split_panels(const ros::Time& stamp, cv::Size frame, const ZoomState& zoom);

  void on_camera_status(const k40t_driver::CameraStatus::ConstPtr& status);
  void on_visible_status(const k40t_driver::VisibleStatus::ConstPtr& status);
  void on_settings(const dynamic_reconfigure::Config::ConstPtr& config);

  ros::NodeHandle nh_;
  const VideoConfig config_;
  LensModels lenses_;
  video::FrameGrabber grabber_;
  video::StampEstimator stamps_;  // publisher thread only
  image_transport::ImageTransport transport_;
  image_transport::CameraPublisher publisher_;
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
