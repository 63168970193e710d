#include <ros/console.h>
#include <pluginlib/class_list_macros.hpp>

#include "k40t_driver/ros/video/bgr_message.h"
#include "k40t_driver/ros/video/video_transport_name.h"
#include "k40t_driver/ros/video/video_transport_plugins.h"

namespace k40t::driver {

namespace {

// Far above a frame's decoding time; a picture the decoder drops (damaged) costs this once.
constexpr std::chrono::milliseconds kDecodeTimeout{500};

}  // namespace

std::string VideoTransportSubscriber::getTransportName() const {
  return kVideoTransportName;
}

void VideoTransportSubscriber::internalCallback(
    const k40t_driver::CompressedVideo::ConstPtr& message, const Callback& user_cb) {
  auto report = [this](const std::string& error) {
    if (error != last_error_) ROS_ERROR("k40t_video transport: %s", error.c_str());
    last_error_ = error;
  };
  Result<video::Codec> codec = video::parse_codec(message->format);
  if (!codec) return report(codec.error() + ": message dropped");
  if (!decoder_ || decoder_->codec() != codec.value()) {
    auto created = video::VideoDecoder::create(codec.value());
    if (!created) return report(created.error());
    decoder_ = std::move(created.value());
  }
  // A message lost on the way (a slow subscriber's queue dropped it) breaks the pictures that
  // refer to it: start again at the next key frame.
  if (have_seq_ && message->header.seq != last_seq_ + 1 && message->header.seq != 0)
    decoder_->resync();
  have_seq_ = true;
  last_seq_ = message->header.seq;
  Result<bool> pushed = decoder_->push(message->data.data(), message->data.size(),
                                       message->key_frame, message->header.seq);
  if (!pushed) {
    decoder_.reset();  // a fresh decoder from the next key frame
    return report(pushed.error());
  }
  if (!pushed.value()) return;  // waiting for a key frame
  std::optional<video::DecodedFrame> frame = decoder_->pull(kDecodeTimeout);
  if (!frame) {
    decoder_.reset();
    return report("no picture decoded from a " + message->format + " access unit");
  }
  last_error_.clear();
  sensor_msgs::ImagePtr image = bgr_messages_.make(frame->i420, true, frame->size);
  image->header = message->header;
  user_cb(image);
}

}  // namespace k40t::driver

PLUGINLIB_EXPORT_CLASS(k40t::driver::VideoTransportPublisher, image_transport::PublisherPlugin)
PLUGINLIB_EXPORT_CLASS(k40t::driver::VideoTransportSubscriber, image_transport::SubscriberPlugin)
