// The image_transport plugin pair of the k40t_video transport (k40t_video_plugins.xml):
//   publisher   encodes a plain sensor_msgs/Image stream (bgr8, rgb8, bgra8, rgba8, mono8) to
//               H.264 with x264 through GStreamer, one k40t_driver/CompressedVideo per image on
//               <base>/k40t_video, so the transport serves any camera. Parameters (in
//               <base>/k40t_video/): bitrate (kbit/s, 4000), key_frame_interval (frames, 30),
//               fps (rate control, 30).
//   subscriber  decodes <base>/k40t_video (H.264 or H.265, avdec through GStreamer) into bgr8
//               images with the message's header. It starts at the first key frame it sees (a
//               late subscriber waits at most one key-frame interval) and starts again at the
//               next one after a gap in the stream or a decoder error.
// The video node publishes the pod's own bitstream on image_raw/k40t_video itself (no encoding);
// this publisher is for other cameras.
#pragma once

#include <image_transport/simple_publisher_plugin.h>
#include <image_transport/simple_subscriber_plugin.h>

#include <memory>
#include <mutex>
#include <string>

#include "k40t_driver/CompressedVideo.h"
#include "k40t_driver/ros/video/bgr_message.h"
#include "k40t_driver/video/video_codec.h"

namespace k40t::driver {

class VideoTransportPublisher
    : public image_transport::SimplePublisherPlugin<k40t_driver::CompressedVideo> {
 public:
  std::string getTransportName() const override;

 protected:
  void publish(const sensor_msgs::Image& image, const PublishFn& publish_fn) const override;

 private:
  video::EncoderOptions options() const;
  mutable std::mutex mutex_;
  mutable std::unique_ptr<video::VideoEncoder> encoder_;
  mutable std::string last_error_;  // logged once per new error, not per frame
  mutable uint32_t seq_ = 0;
};

class VideoTransportSubscriber
    : public image_transport::SimpleSubscriberPlugin<k40t_driver::CompressedVideo> {
 public:
  std::string getTransportName() const override;

 protected:
  void internalCallback(const k40t_driver::CompressedVideo::ConstPtr& message,
                        const Callback& user_cb) override;

 private:
  std::unique_ptr<video::VideoDecoder> decoder_;
  BgrMessageMaker bgr_messages_;
  uint32_t last_seq_ = 0;
  bool have_seq_ = false;
  std::string last_error_;
};

}  // namespace k40t::driver
