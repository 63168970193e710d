#include <ros/console.h>
#include <sensor_msgs/image_encodings.h>

#include "k40t_driver/ros/video/video_transport_name.h"
#include "k40t_driver/ros/video/video_transport_plugins.h"

namespace k40t::driver {

std::string VideoTransportPublisher::getTransportName() const {
  return kVideoTransportName;
}

video::EncoderOptions VideoTransportPublisher::options() const {
  video::EncoderOptions o;
  nh().param("bitrate", o.bitrate_kbps, o.bitrate_kbps);
  nh().param("key_frame_interval", o.key_frame_interval, o.key_frame_interval);
  nh().param("fps", o.fps, o.fps);
  return o;
}

void VideoTransportPublisher::publish(const sensor_msgs::Image& image,
                                      const PublishFn& publish_fn) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const int width = static_cast<int>(image.width);
  const int height = static_cast<int>(image.height);
  auto report = [this](const std::string& error) {
    if (error != last_error_) ROS_ERROR("k40t_video transport: %s", error.c_str());
    last_error_ = error;
  };
  if (image.data.size() < static_cast<size_t>(image.step) * image.height)
    return report("image data is shorter than step x height: not published");
  if (!encoder_ || !encoder_->accepts(image.encoding, width, height)) {
    // A new size or encoding: a new stream, starting with a key frame.
    encoder_.reset();
    auto created = video::VideoEncoder::create(image.encoding, width, height, options());
    if (!created) return report(created.error() + ": not published");
    encoder_ = std::move(created.value());
  }
  auto unit = encoder_->encode(image.data.data(), image.step);
  if (!unit) {
    encoder_.reset();
    return report(unit.error());
  }
  last_error_.clear();
  k40t_driver::CompressedVideo message;
  message.header = image.header;
  message.header.seq = ++seq_;  // consecutive: the subscriber notices a lost message
  message.format = video::to_string(video::Codec::kH264);
  message.data = std::move(unit->bytes);
  message.key_frame = unit->key_frame;
  publish_fn(message);
}

}  // namespace k40t::driver
