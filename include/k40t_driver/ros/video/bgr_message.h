// A decoded frame into a new bgr8 sensor_msgs/Image, converted (I420) or copied (BGR) once,
// straight into the message's own buffer. The video node and the k40t_video subscriber plugin
// publish their pictures with it.
#pragma once

#include <sensor_msgs/Image.h>
#include <sensor_msgs/image_encodings.h>
#include <boost/make_shared.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace k40t::driver {

// `pixels`: I420 (CV_8UC1, size.height * 3 / 2 rows) if `i420`, else BGR (CV_8UC3) of `size`.
inline sensor_msgs::ImagePtr bgr_message(const cv::Mat& pixels, bool i420, cv::Size size) {
  auto image = boost::make_shared<sensor_msgs::Image>();
  image->width = static_cast<uint32_t>(size.width);
  image->height = static_cast<uint32_t>(size.height);
  image->encoding = sensor_msgs::image_encodings::BGR8;
  image->step = image->width * 3;
  image->data.resize(static_cast<size_t>(image->step) * image->height);
  cv::Mat target(size, CV_8UC3, image->data.data(), image->step);
  if (i420) {
    cv::cvtColor(pixels, target, cv::COLOR_YUV2BGR_I420);
  } else {
    pixels.copyTo(target);
  }
  return image;
}

}  // namespace k40t::driver
