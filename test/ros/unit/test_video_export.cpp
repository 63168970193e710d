// `k40t bag --video / --video-frames` (video_export.h) on a bag of k40t_driver/CompressedVideo
// written here from the H.264 encoder (10 s at 30 fps, the first messages before a key frame):
// the MP4 plays in GStreamer (gst-discoverer-1.0 reports the recording's duration within 1 s),
// the MKV too, the PNG frames are the pictures (PSNR >= 35 dB) with their stamps in frames.csv,
// and bad requests get a message.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <rosbag/bag.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "k40t_driver/CompressedVideo.h"
#include "k40t_driver/Frame.h"
#include "k40t_driver/ros/bag/video_export.h"
#include "k40t_driver/video/video_codec.h"

namespace k40t::driver {
namespace {

constexpr int kFrames = 300;  // 10 s at 30 fps
constexpr int kSkipped = 4;   // recorded from mid-stream: the bag starts 4 frames before a key
const std::string kTopic = "/k40t/image_raw/k40t_video";

std::string temp_path(const std::string& name) {
  return "/tmp/k40t_video_export_" + std::to_string(::getpid()) + "_" + name;
}

cv::Mat picture(int i) {
  cv::Mat bgr(240, 320, CV_8UC3, cv::Scalar(40, 90, 160));
  cv::circle(bgr, {60 + i % 200, 120}, 40, {250, 250, 250}, -1);
  cv::putText(bgr, std::to_string(i), {10, 40}, cv::FONT_HERSHEY_SIMPLEX, 1.2, {0, 0, 0}, 2);
  return bgr;
}

int64_t stamp_ns(int i) {
  return 1'700'000'000'000'000'000LL + static_cast<int64_t>(i) * 33'333'333LL;
}

// The bag, and the pictures from the first key frame on (the ones an export can give back).
std::vector<cv::Mat> write_bag(const std::string& path) {
  video::EncoderOptions options;
  options.key_frame_interval = 30;
  auto encoder = video::VideoEncoder::create("bgr8", 320, 240, options);
  EXPECT_TRUE(encoder) << encoder.error();
  std::vector<cv::Mat> kept;
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  k40t_driver::Frame other;  // another topic in the same bag
  bag.write("/k40t/raw/rx", ros::Time(1'700'000'000), other);
  for (int i = 0; i < kFrames + 30 - kSkipped; ++i) {
    cv::Mat bgr = picture(i);
    auto unit = encoder.value()->encode(bgr.data, bgr.step);
    EXPECT_TRUE(unit) << unit.error();
    if (i < 30 - kSkipped) continue;  // the recording starts here, mid-way through a key interval
    const int frame = i - (30 - kSkipped);
    k40t_driver::CompressedVideo m;
    m.header.stamp.fromNSec(stamp_ns(frame));
    m.header.frame_id = "k40t_tele_optical_frame";
    m.format = "h264";
    m.data = unit->bytes;
    m.key_frame = unit->key_frame;
    bag.write(kTopic, m.header.stamp, m);
    if (frame >= kSkipped) kept.push_back(bgr);
  }
  bag.close();
  return kept;
}

std::string run(const std::string& command) {
  std::string out;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return out;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
  ::pclose(pipe);
  return out;
}

// gst-discoverer-1.0's "Duration: H:MM:SS.nnnnnnnnn", in seconds; negative if none.
double discovered_duration(const std::string& file) {
  const std::string out = run("gst-discoverer-1.0 " + file + " 2>&1");
  std::smatch m;
  if (!std::regex_search(out, m, std::regex(R"(Duration: (\d+):(\d+):(\d+\.\d+))"))) {
    ADD_FAILURE() << out;
    return -1;
  }
  return std::stod(m[1]) * 3600 + std::stod(m[2]) * 60 + std::stod(m[3]);
}

double psnr(const cv::Mat& a, const cv::Mat& b) {
  const double mse = cv::norm(a, b, cv::NORM_L2SQR) / static_cast<double>(a.total() * 3);
  return mse == 0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

class VideoExport : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    bag_ = temp_path("in.bag");
    pictures_ = write_bag(bag_);
  }
  static void TearDownTestSuite() { std::remove(bag_.c_str()); }
  static std::string bag_;
  static std::vector<cv::Mat> pictures_;
};
std::string VideoExport::bag_;
std::vector<cv::Mat> VideoExport::pictures_;

TEST_F(VideoExport, Mp4AndMkvPlayWithTheRecordingsDuration) {
  // From the first key frame to the last message.
  const double recorded_s = (stamp_ns(kFrames - 1) - stamp_ns(kSkipped)) / 1e9;
  for (const std::string name : {"out.mp4", "out.mkv"}) {
    VideoExportOptions options;
    options.video_file = temp_path(name);
    Result<VideoExportSummary> summary = export_video(bag_, options);
    ASSERT_TRUE(summary) << summary.error();
    EXPECT_EQ(summary->topic, kTopic);
    EXPECT_EQ(summary->format, "h264");
    EXPECT_EQ(summary->messages, static_cast<uint64_t>(kFrames));
    EXPECT_EQ(summary->written, static_cast<uint64_t>(kFrames - kSkipped));
    EXPECT_NEAR(summary->duration_s, recorded_s, 1e-6);
    EXPECT_NEAR(discovered_duration(options.video_file), recorded_s, 1.0) << name;
    std::remove(options.video_file.c_str());
  }
}

TEST_F(VideoExport, PngFramesAreThePicturesWithTheirStamps) {
  VideoExportOptions options;
  options.frames_dir = temp_path("frames");
  Result<VideoExportSummary> summary = export_video(bag_, options);
  ASSERT_TRUE(summary) << summary.error();
  ASSERT_EQ(summary->frames, pictures_.size());
  std::ifstream csv(options.frames_dir + "/frames.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "frame,stamp_ns,key_frame,file");
  for (size_t i = 0; i < pictures_.size(); ++i) {
    ASSERT_TRUE(std::getline(csv, line)) << "row " << i;
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06zu.png", i);
    const bool key = (i % 30) == 0;  // the first kept frame is a key frame, then every 30
    EXPECT_EQ(line, std::to_string(i) + "," + std::to_string(stamp_ns(i + kSkipped)) + "," +
                        (key ? "1" : "0") + "," + name);
    if (i % 50 == 0) {
      const cv::Mat png = cv::imread(options.frames_dir + "/" + name);
      ASSERT_FALSE(png.empty()) << name;
      EXPECT_GE(psnr(png, pictures_[i]), 35.0) << name;
    }
    std::remove((options.frames_dir + "/" + name).c_str());
  }
  EXPECT_FALSE(std::getline(csv, line));
  std::remove((options.frames_dir + "/frames.csv").c_str());
  ::rmdir(options.frames_dir.c_str());
}

TEST_F(VideoExport, BadRequestsAreRefusedWithAMessage) {
  VideoExportOptions options;
  options.video_file = temp_path("out.avi");
  auto wrong_extension = export_video(bag_, options);
  ASSERT_FALSE(wrong_extension);
  EXPECT_NE(wrong_extension.error().find(".mp4"), std::string::npos) << wrong_extension.error();

  options.video_file = temp_path("out.mp4");
  options.topic = "/k40t/raw/rx";
  auto wrong_type = export_video(bag_, options);
  ASSERT_FALSE(wrong_type);
  EXPECT_NE(wrong_type.error().find("is not k40t_driver/CompressedVideo"), std::string::npos)
      << wrong_type.error();
  EXPECT_NE(::access(options.video_file.c_str(), F_OK), 0) << "no file left behind";

  options.topic = "/nowhere";
  auto missing = export_video("/nonexistent.bag", options);
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("/nonexistent.bag"), std::string::npos);
}

}  // namespace
}  // namespace k40t::driver
