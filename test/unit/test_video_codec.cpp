// The H.264 encoder and decoder (video_codec.h) on their own, no network: a synthetic picture
// survives encode + decode (PSNR >= 35 dB at 4 Mbit/s), key frames come at the set interval with
// their SPS/PPS in front, a decoder joining mid-stream starts at the next key frame, and bad input
// is refused with a message.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "k40t_driver/video/video_codec.h"
#include "video_codec_support.h"

namespace k40t::video {
namespace {

using std::chrono::milliseconds;
using testing::contains;
using testing::h264_nal_types;
using testing::psnr;

// A picture with gradients, a disc and text that moves by `shift` pixels per frame.
cv::Mat test_picture(int width, int height, int shift) {
  cv::Mat bgr(height, width, CV_8UC3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      bgr.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<uint8_t>((x + shift) * 255 / (width + 60)),
                                          static_cast<uint8_t>(y * 255 / height), 128);
  cv::circle(bgr, {width / 2 + shift, height / 2}, height / 4, {20, 200, 240}, -1);
  cv::putText(bgr, "K40T " + std::to_string(shift), {20, 60}, cv::FONT_HERSHEY_SIMPLEX, 1.5,
              {255, 255, 255}, 3);
  return bgr;
}

std::vector<EncodedUnit> encode_frames(int count, int key_interval,
                                       std::vector<cv::Mat>* pictures) {
  EncoderOptions options;
  options.key_frame_interval = key_interval;
  auto encoder = VideoEncoder::create("bgr8", 640, 480, options);
  EXPECT_TRUE(encoder) << encoder.error();
  std::vector<EncodedUnit> units;
  if (!encoder) return units;
  for (int i = 0; i < count; ++i) {
    cv::Mat picture = test_picture(640, 480, i * 3);
    auto unit = encoder.value()->encode(picture.data, picture.step);
    EXPECT_TRUE(unit) << unit.error();
    if (!unit) break;
    units.push_back(unit.value());
    if (pictures) pictures->push_back(picture);
  }
  return units;
}

TEST(VideoCodec, KeyFramesComeAtTheIntervalWithTheirParameterSets) {
  const std::vector<EncodedUnit> units = encode_frames(12, 5, nullptr);
  ASSERT_EQ(units.size(), 12u);
  for (size_t i = 0; i < units.size(); ++i) {
    const std::vector<int> types = h264_nal_types(units[i].bytes);
    const bool key = i % 5 == 0;
    EXPECT_EQ(units[i].key_frame, key) << "frame " << i;
    EXPECT_EQ(contains(types, 5), key) << "IDR slice in frame " << i;
    EXPECT_EQ(contains(types, 7), key) << "SPS in frame " << i;
    EXPECT_EQ(contains(types, 8), key) << "PPS in frame " << i;
    if (!key) {
      EXPECT_TRUE(contains(types, 1)) << "non-IDR slice in frame " << i;
    }
  }
}

TEST(VideoCodec, EncodeThenDecodeKeepsThePicture) {
  std::vector<cv::Mat> pictures;
  const std::vector<EncodedUnit> units = encode_frames(10, 5, &pictures);
  auto decoder = VideoDecoder::create(Codec::kH264);
  ASSERT_TRUE(decoder) << decoder.error();
  for (size_t i = 0; i < units.size(); ++i) {
    auto pushed =
        decoder.value()->push(units[i].bytes.data(), units[i].bytes.size(), units[i].key_frame, i);
    ASSERT_TRUE(pushed) << pushed.error();
    EXPECT_TRUE(pushed.value());
    auto frame = decoder.value()->pull(milliseconds(2000));
    ASSERT_TRUE(frame) << "frame " << i << ": " << decoder.value()->error();
    EXPECT_EQ(frame->tag, i);
    EXPECT_EQ(frame->size, cv::Size(640, 480));
    EXPECT_GE(psnr(i420_to_bgr(*frame), pictures[i]), 35.0) << "frame " << i;
  }
}

// The decoder's pictures are its own buffers, not copies of them (a 1080p frame copied twice cost
// ~2 % of a core at 30 fps), and they stay valid after the decoder is gone.
TEST(VideoCodec, DecodedPicturesAreTheDecodersBuffersAndOutliveIt) {
  std::vector<cv::Mat> pictures;
  const std::vector<EncodedUnit> units = encode_frames(4, 5, &pictures);
  auto decoder = VideoDecoder::create(Codec::kH264);
  ASSERT_TRUE(decoder) << decoder.error();
  std::vector<DecodedFrame> frames;
  for (size_t i = 0; i < units.size(); ++i) {
    ASSERT_TRUE(
        decoder.value()->push(units[i].bytes.data(), units[i].bytes.size(), units[i].key_frame, i));
    auto frame = decoder.value()->pull(milliseconds(2000));
    ASSERT_TRUE(frame) << "frame " << i << ": " << decoder.value()->error();
    EXPECT_EQ(frame->i420.u, nullptr) << "an OpenCV allocation: the picture was copied";
    EXPECT_EQ(frame->i420.data, frame->memory.get());
    frames.push_back(std::move(*frame));
  }
  decoder.value().reset();  // the pipeline torn down; the frames still hold their buffers
  for (size_t i = 0; i < frames.size(); ++i)
    EXPECT_GE(psnr(i420_to_bgr(frames[i]), pictures[i]), 35.0) << "frame " << i;
}

TEST(VideoCodec, DecoderJoiningMidStreamStartsAtTheNextKeyFrame) {
  const std::vector<EncodedUnit> units = encode_frames(8, 5, nullptr);
  auto decoder = VideoDecoder::create(Codec::kH264);
  ASSERT_TRUE(decoder) << decoder.error();
  for (size_t i = 2; i < units.size(); ++i) {
    auto pushed =
        decoder.value()->push(units[i].bytes.data(), units[i].bytes.size(), units[i].key_frame, i);
    ASSERT_TRUE(pushed) << pushed.error();
    EXPECT_EQ(pushed.value(), i >= 5) << "frame " << i;
  }
  auto first = decoder.value()->pull(milliseconds(2000));
  ASSERT_TRUE(first) << decoder.value()->error();
  EXPECT_EQ(first->tag, 5u);
}

TEST(VideoCodec, BadInputIsRefusedWithAMessage) {
  auto odd = VideoEncoder::create("bgr8", 641, 480, {});
  ASSERT_FALSE(odd);
  EXPECT_NE(odd.error().find("641x480"), std::string::npos) << odd.error();
  auto float_image = VideoEncoder::create("32FC1", 640, 480, {});
  ASSERT_FALSE(float_image);
  EXPECT_NE(float_image.error().find("32FC1"), std::string::npos) << float_image.error();
  EncoderOptions options;
  options.key_frame_interval = 0;
  auto no_keys = VideoEncoder::create("bgr8", 640, 480, options);
  ASSERT_FALSE(no_keys);
  EXPECT_NE(no_keys.error().find("key frame interval"), std::string::npos) << no_keys.error();
  EXPECT_FALSE(parse_codec("vp8"));
  EXPECT_EQ(parse_codec("h265").value(), Codec::kH265);
}

TEST(VideoCodec, GarbageAccessUnitsGiveNoPictureAndNoCrash) {
  auto decoder = VideoDecoder::create(Codec::kH264);
  ASSERT_TRUE(decoder) << decoder.error();
  std::vector<uint8_t> garbage(5000);
  for (size_t i = 0; i < garbage.size(); ++i) garbage[i] = static_cast<uint8_t>(i * 7919 % 251);
  for (int i = 0; i < 3; ++i) {
    (void)decoder.value()->push(garbage.data(), garbage.size(), true, i);
  }
  EXPECT_FALSE(decoder.value()->pull(milliseconds(300)));
}

}  // namespace
}  // namespace k40t::video
