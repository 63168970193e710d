// The frame stamp drawn into simulated frames (sim/video/frame_stamp.h).
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "k40t_driver/sim/video/frame_stamp.h"

namespace k40t::sim::video {
namespace {

cv::Mat grey_frame() {
  return cv::Mat(512, 640, CV_8UC3, cv::Scalar(90, 120, 150));
}

TEST(FrameStamp, ReadsBackWhatWasDrawn) {
  cv::Mat frame = grey_frame();
  const FrameStamp stamp{0xDEADBEEF, 1700000000123456};
  ASSERT_TRUE(draw_frame_stamp(frame, stamp));
  const auto read = read_frame_stamp(frame);
  ASSERT_TRUE(read);
  EXPECT_EQ(read->counter, stamp.counter);
  EXPECT_EQ(read->render_time_us, stamp.render_time_us);
}

TEST(FrameStamp, SurvivesBlurAndAGreyConversion) {
  cv::Mat frame = grey_frame();
  ASSERT_TRUE(draw_frame_stamp(frame, {42, -5}));
  cv::GaussianBlur(frame, frame, cv::Size(3, 3), 0);
  cv::Mat grey;
  cv::cvtColor(frame, grey, cv::COLOR_BGR2GRAY);
  const auto read = read_frame_stamp(grey);
  ASSERT_TRUE(read);
  EXPECT_EQ(read->counter, 42u);
  EXPECT_EQ(read->render_time_us, -5);
}

TEST(FrameStamp, AFlippedBlockIsRejectedByTheCrc) {
  cv::Mat frame = grey_frame();
  ASSERT_TRUE(draw_frame_stamp(frame, {7, 123456789}));
  // Block 40 lies in the counter/time bytes; invert it.
  cv::Mat block = frame(cv::Rect(8 * 8, 8, 8, 8));
  cv::bitwise_not(block, block);
  EXPECT_FALSE(read_frame_stamp(frame));
}

TEST(FrameStamp, FramesWithoutAStampReadNothing) {
  EXPECT_FALSE(read_frame_stamp(grey_frame()));
  EXPECT_FALSE(read_frame_stamp(cv::Mat(512, 640, CV_8UC3, cv::Scalar::all(0))));
  EXPECT_FALSE(read_frame_stamp(cv::Mat(512, 640, CV_8UC3, cv::Scalar::all(255))));
}

TEST(FrameStamp, RefusesImagesItCannotHold) {
  cv::Mat small(16, 640, CV_8UC3);
  EXPECT_FALSE(draw_frame_stamp(small, {1, 1}));
  cv::Mat grey(512, 640, CV_8UC1);
  EXPECT_FALSE(draw_frame_stamp(grey, {1, 1}));
  EXPECT_FALSE(read_frame_stamp(small));
  EXPECT_FALSE(read_frame_stamp(cv::Mat()));
}

}  // namespace
}  // namespace k40t::sim::video
