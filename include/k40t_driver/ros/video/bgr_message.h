// Decoded frames into bgr8 sensor_msgs/Images, converted (I420) or copied (BGR) once, straight
// into the message's own buffer. The video node and the k40t_video subscriber plugin publish
// their pictures with it.
#pragma once

#include <sensor_msgs/Image.h>
#include <sensor_msgs/image_encodings.h>
#include <boost/make_shared.hpp>
#include <opencv2/core.hpp>

#include "k40t_driver/video/video_codec.h"

namespace k40t::driver {

// Makes each picture's message. The previous message is reused when nobody else holds it any
// more (roscpp has sent it, the subscribers in this process have let go): a 1080p frame then
// costs no new 6 MB buffer and no zero-filling of it. A message still held by anyone is never
// written to; a new one is made instead.
class BgrMessageMaker {
 public:
  // `pixels`: I420 (CV_8UC1, size.height * 3 / 2 rows) if `i420`, else BGR (CV_8UC3) of `size`.
  sensor_msgs::ImagePtr make(const cv::Mat& pixels, bool i420, cv::Size size) {
    sensor_msgs::ImagePtr image = reusable() ? previous_ : boost::make_shared<sensor_msgs::Image>();
    image->header = std_msgs::Header();
    image->width = static_cast<uint32_t>(size.width);
    image->height = static_cast<uint32_t>(size.height);
    image->encoding = sensor_msgs::image_encodings::BGR8;
    image->is_bigendian = 0;
    image->step = image->width * 3;
    image->data.resize(static_cast<size_t>(image->step) * image->height);
    cv::Mat target(size, CV_8UC3, image->data.data(), image->step);
    if (i420) {
      video::i420_to_bgr(pixels, target);
    } else {
      pixels.copyTo(target);
    }
    previous_ = image;
    return image;
  }

 private:
  bool reusable() const { return previous_ && previous_.use_count() == 1; }
  sensor_msgs::ImagePtr previous_;
};

}  // namespace k40t::driver
