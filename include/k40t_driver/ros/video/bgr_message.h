// Decoded frames into bgr8 sensor_msgs/Images, converted (I420) or copied (BGR) once, straight
// into the message's own buffer. The video node and the k40t_video subscriber plugin publish
// their pictures with it.
#pragma once

#include <sensor_msgs/Image.h>
#include <sensor_msgs/image_encodings.h>
#include <boost/make_shared.hpp>
#include <opencv2/core.hpp>

#include <memory>
#include <mutex>
#include <vector>

#include "k40t_driver/video/video_codec.h"

namespace k40t::driver {

// Makes each picture's message. The pixel buffer of a message that is gone (roscpp has sent it,
// every subscriber in this process has let go: its last reference dropped) is kept and given to
// the next message: a 1080p frame then costs no new 6 MB buffer and no zero-filling of it. Only a
// destroyed message's buffer is reused, so nothing anyone can still reach (not even through a
// weak pointer) is ever written to.
class BgrMessageMaker {
 public:
  // `pixels`: I420 (CV_8UC1, size.height * 3 / 2 rows) if `i420`, else BGR (CV_8UC3) of `size`.
  sensor_msgs::ImagePtr make(const cv::Mat& pixels, bool i420, cv::Size size) {
    auto* message = new sensor_msgs::Image;
    message->data = spare_->take();
    // Hands the buffer back when the message dies, on whichever thread drops it last.
    sensor_msgs::ImagePtr image(message, [spare = spare_](sensor_msgs::Image* dead) {
      spare->give(std::move(dead->data));
      delete dead;
    });
    image->width = static_cast<uint32_t>(size.width);
    image->height = static_cast<uint32_t>(size.height);
    image->encoding = sensor_msgs::image_encodings::BGR8;
    image->step = image->width * 3;
    image->data.resize(static_cast<size_t>(image->step) * image->height);
    cv::Mat target(size, CV_8UC3, image->data.data(), image->step);
    if (i420) {
      video::i420_to_bgr(pixels, target);
    } else {
      pixels.copyTo(target);
    }
    return image;
  }

 private:
  // The buffer of the last message that died; shared with the messages' deleters, which may
  // outlive the maker.
  struct Spare {
    std::mutex mutex;
    std::vector<uint8_t> buffer;
    std::vector<uint8_t> take() {
      std::lock_guard<std::mutex> lock(mutex);
      return std::move(buffer);
    }
    void give(std::vector<uint8_t>&& data) {
      std::lock_guard<std::mutex> lock(mutex);
      buffer = std::move(data);
    }
  };
  std::shared_ptr<Spare> spare_ = std::make_shared<Spare>();
};

}  // namespace k40t::driver
