// BgrMessageMaker (bgr_message.h): the picture lands in the message as bgr8, exactly what
// OpenCV's conversion gives; a dead message's buffer is reused by the next one, and a message
// someone still holds is never written to.
#include <gtest/gtest.h>

#include <boost/weak_ptr.hpp>
#include <opencv2/imgproc.hpp>

#include "k40t_driver/ros/video/bgr_message.h"

namespace k40t::driver {
namespace {

// A BGR picture with structure in every channel, and its I420.
cv::Mat test_bgr(cv::Size size, int shift) {
  cv::Mat bgr(size, CV_8UC3);
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x)
      bgr.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<uint8_t>(x * 3 + shift),
                                          static_cast<uint8_t>(y * 5), static_cast<uint8_t>(x ^ y));
  return bgr;
}

cv::Mat to_i420(const cv::Mat& bgr) {
  cv::Mat i420;
  cv::cvtColor(bgr, i420, cv::COLOR_BGR2YUV_I420);
  return i420;
}

cv::Mat expected_bgr(const cv::Mat& i420) {
  cv::Mat bgr;
  cv::cvtColor(i420, bgr, cv::COLOR_YUV2BGR_I420);
  return bgr;
}

cv::Mat pixels_of(const sensor_msgs::Image& image) {
  return cv::Mat(static_cast<int>(image.height), static_cast<int>(image.width), CV_8UC3,
                 const_cast<uint8_t*>(image.data.data()), image.step);
}

bool same(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && cv::norm(a, b, cv::NORM_INF) == 0;
}

TEST(BgrMessage, I420AndBgrPicturesBecomeBgr8Messages) {
  BgrMessageMaker maker;
  const cv::Size size(64, 48);
  const cv::Mat i420 = to_i420(test_bgr(size, 0));
  sensor_msgs::ImagePtr image = maker.make(i420, true, size);
  EXPECT_EQ(image->encoding, "bgr8");
  EXPECT_EQ(image->width, 64u);
  EXPECT_EQ(image->height, 48u);
  EXPECT_EQ(image->step, 64u * 3);
  EXPECT_EQ(image->data.size(), 64u * 48 * 3);
  EXPECT_TRUE(same(pixels_of(*image), expected_bgr(i420)));
  const cv::Mat bgr = test_bgr(size, 7);
  EXPECT_TRUE(same(pixels_of(*maker.make(bgr, false, size)), bgr));
}

TEST(BgrMessage, ADeadMessagesBufferIsReusedALiveOnesIsNot) {
  BgrMessageMaker maker;
  const cv::Size size(64, 48);
  sensor_msgs::ImagePtr first = maker.make(to_i420(test_bgr(size, 0)), true, size);
  const uint8_t* first_pixels = first->data.data();
  boost::weak_ptr<sensor_msgs::Image> watcher = first;
  first.reset();  // published and let go by everyone
  EXPECT_TRUE(watcher.expired());

  const cv::Mat second_i420 = to_i420(test_bgr(size, 40));
  sensor_msgs::ImagePtr second = maker.make(second_i420, true, size);
  EXPECT_EQ(second->data.data(), first_pixels);
  EXPECT_EQ(second->header.frame_id, "");  // a message of its own, nothing of the previous one
  EXPECT_TRUE(same(pixels_of(*second), expected_bgr(second_i420)));

  // `second` is still held (a subscriber's queue): the next picture goes elsewhere.
  const cv::Mat kept = pixels_of(*second).clone();
  sensor_msgs::ImagePtr third = maker.make(to_i420(test_bgr(size, 90)), true, size);
  EXPECT_NE(third->data.data(), second->data.data());
  EXPECT_TRUE(same(pixels_of(*second), kept));

  // A reused buffer of another size is resized; a message may outlive its maker.
  second.reset();
  const cv::Size larger(96, 64);
  const cv::Mat larger_i420 = to_i420(test_bgr(larger, 3));
  sensor_msgs::ImagePtr fourth = maker.make(larger_i420, true, larger);
  EXPECT_EQ(fourth->width, 96u);
  EXPECT_EQ(fourth->data.size(), 96u * 64 * 3);
  EXPECT_TRUE(same(pixels_of(*fourth), expected_bgr(larger_i420)));
  {
    BgrMessageMaker short_lived;
    third = short_lived.make(to_i420(test_bgr(size, 5)), true, size);
  }
  third.reset();  // its deleter still finds the (shared) spare buffer
}

}  // namespace
}  // namespace k40t::driver
