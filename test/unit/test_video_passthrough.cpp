// The access-unit source (access_unit_source.h) against the simulated pod's RTSP server: the
// stream's own H.264 comes out one access unit per frame, key frames with SPS/PPS, without any
// decoding while nobody wants pixels; decoding switched on starts at the next key frame and the
// decoded frame is the access unit's (same sequence, same reception time, its frame stamp).
#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>
#include <vector>

#include "k40t_driver/sim/video/frame_stamp.h"
#include "k40t_driver/video/access_unit_source.h"
#include "video_codec_support.h"
#include "video_stream_fixture.h"
#include "video_test_support.h"

namespace k40t::video {
namespace {

using sim::video::ImageMode;
using std::chrono::seconds;
using testing::contains;
using testing::h264_nal_types;
using testing::h265_nal_types;
using testing::Stream;
using testing::wait_until;

constexpr int kKeyInterval = 10;

struct Received {
  std::mutex mutex;
  std::vector<AccessUnit> units;
  size_t size() {
    std::lock_guard<std::mutex> lock(mutex);
    return units.size();
  }
  std::vector<AccessUnit> copy() {
    std::lock_guard<std::mutex> lock(mutex);
    return units;
  }
};

// The sink that keeps every access unit in `received`.
AccessUnitSource::UnitSink keep_in(Received& received) {
  return [&received](const AccessUnit& unit) {
    std::lock_guard<std::mutex> lock(received.mutex);
    received.units.push_back(unit);
  };
}

CaptureOptions options_for(const std::string& url) {
  CaptureOptions o;
  o.url = url;
  o.read_timeout_s = 1.0;
  o.open_timeout_s = 4.0;
  return o;
}

TEST(VideoPassthrough, AccessUnitsArriveEncodedAndNothingIsDecoded) {
  Stream stream(ImageMode::kThermal, 0, kKeyInterval);
  Received received;
  AccessUnitSource source(options_for(stream.url()), keep_in(received));
  source.start();
  ASSERT_TRUE(wait_until([&] { return received.size() >= 3 * kKeyInterval + 1; }, seconds(15)))
      << source.stats().last_error;
  source.stop();
  const std::vector<AccessUnit> units = received.copy();
  std::vector<size_t> keys;
  for (size_t i = 0; i < units.size(); ++i) {
    const AccessUnit& unit = units[i];
    EXPECT_EQ(unit.codec, Codec::kH264);
    EXPECT_EQ(unit.width, 640);
    EXPECT_EQ(unit.height, 512);
    EXPECT_EQ(unit.sequence, i + 1);
    const std::vector<int> types = h264_nal_types(unit.bytes);
    EXPECT_EQ(contains(types, 5), unit.key_frame) << "unit " << i;
    if (unit.key_frame) {
      keys.push_back(i);
      EXPECT_TRUE(contains(types, 7) && contains(types, 8)) << "SPS/PPS before key unit " << i;
    } else {
      EXPECT_TRUE(contains(types, 1)) << "unit " << i;
    }
  }
  ASSERT_GE(keys.size(), 3u);
  for (size_t k = 1; k < keys.size(); ++k) EXPECT_EQ(keys[k] - keys[k - 1], size_t(kKeyInterval));
  EXPECT_EQ(source.decoded_frames(), 0u);
  EXPECT_FALSE(source.wait_newer(0, std::chrono::milliseconds(0)));
}

TEST(VideoPassthrough, DecodingStartsAtTheNextKeyFrameWithTheUnitsTimes) {
  Stream stream(ImageMode::kThermal, 0, kKeyInterval);
  Received received;
  AccessUnitSource source(options_for(stream.url()), keep_in(received));
  source.start();
  // Joins mid-stream: after a few units, wherever the key frames are.
  ASSERT_TRUE(wait_until([&] { return received.size() >= 5; }, seconds(15)));
  source.set_decoding(true);
  const size_t joined_after = received.size();
  auto frame = source.wait_newer(0, seconds(5));
  ASSERT_TRUE(frame) << source.stats().last_error;
  const std::vector<AccessUnit> units = received.copy();
  ASSERT_GE(units.size(), frame->sequence);
  const AccessUnit& unit = units[frame->sequence - 1];
  EXPECT_EQ(unit.sequence, frame->sequence);
  // The first picture is the first key frame after decoding was asked for: at most one interval.
  EXPECT_TRUE(unit.key_frame);
  EXPECT_LE(frame->sequence, joined_after + kKeyInterval + 1);
  EXPECT_EQ(frame->received_us, unit.received_us);
  EXPECT_EQ(frame->size, cv::Size(640, 512));
  ASSERT_TRUE(frame->i420);
  EXPECT_TRUE(sim::video::read_frame_stamp(to_bgr(*frame)));
  // Every unit after that is decoded.
  auto later = source.wait_newer(frame->sequence + kKeyInterval, seconds(5));
  ASSERT_TRUE(later);
  EXPECT_TRUE(sim::video::read_frame_stamp(to_bgr(*later)));
  source.stop();
}

TEST(VideoPassthrough, AStoppedServerIsNoticedAndTheUnitsComeBack) {
  auto stream = std::make_unique<Stream>(ImageMode::kThermal, 0, kKeyInterval);
  const std::string url = stream->url();
  const int port = std::stoi(url.substr(url.rfind(':') + 1));
  Received received;
  AccessUnitSource source(options_for(url), keep_in(received));
  source.start();
  ASSERT_TRUE(wait_until([&] { return received.size() >= 5; }, seconds(15)));
  stream.reset();
  ASSERT_TRUE(wait_until([&] { return !source.stats().streaming; }, seconds(3)));
  const size_t before = received.size();
  stream = std::make_unique<Stream>(ImageMode::kThermal, port, kKeyInterval);
  ASSERT_TRUE(wait_until([&] { return received.size() >= before + 5; }, seconds(15)))
      << source.stats().last_error;
  EXPECT_GE(source.stats().reconnects, 1u);
}

// What the k40t_video subscriber plugin relies on: from the first key frame on, each access unit
// of the stream gives one picture, at once.
TEST(VideoPassthrough, EachAccessUnitDecodesToOnePictureAtOnce) {
  Stream stream(ImageMode::kThermal, 0, kKeyInterval);
  Received received;
  AccessUnitSource source(options_for(stream.url()), keep_in(received));
  source.start();
  ASSERT_TRUE(wait_until([&] { return received.size() >= 3 * kKeyInterval; }, seconds(15)));
  source.stop();
  auto decoder = VideoDecoder::create(Codec::kH264);
  ASSERT_TRUE(decoder) << decoder.error();
  int pictures = 0;
  for (const AccessUnit& unit : received.copy()) {
    Result<bool> pushed =
        decoder.value()->push(unit.bytes.data(), unit.bytes.size(), unit.key_frame, unit.sequence);
    ASSERT_TRUE(pushed) << pushed.error();
    if (!pushed.value()) continue;
    auto picture = decoder.value()->pull(std::chrono::milliseconds(1000));
    ASSERT_TRUE(picture) << "unit " << unit.sequence << " (" << unit.bytes.size() << " bytes, key "
                         << unit.key_frame << ") after " << pictures
                         << " pictures: " << decoder.value()->error();
    EXPECT_EQ(picture->tag, unit.sequence);
    ++pictures;
  }
  EXPECT_GE(pictures, 2 * kKeyInterval);
}

// The pod may send H.265 (0x00030B): the simulator's x265 stream passes through the same way
// (VPS/SPS/PPS before every key frame, which is an IRAP picture) and decodes from a key frame.
TEST(VideoPassthrough, H265AccessUnitsPassThroughAndDecode) {
  Stream stream(ImageMode::kThermal, 0, kKeyInterval, Codec::kH265);
  Received received;
  AccessUnitSource source(options_for(stream.url()), keep_in(received));
  source.start();
  ASSERT_TRUE(wait_until([&] { return received.size() >= 2 * kKeyInterval + 1; }, seconds(15)))
      << source.stats().last_error;
  source.set_decoding(true);
  auto frame = source.wait_newer(0, seconds(5));
  ASSERT_TRUE(frame) << source.stats().last_error;
  EXPECT_TRUE(sim::video::read_frame_stamp(to_bgr(*frame)));
  EXPECT_EQ(frame->size, cv::Size(640, 512));
  source.stop();
  const std::vector<AccessUnit> units = received.copy();
  std::vector<size_t> keys;
  for (size_t i = 0; i < units.size(); ++i) {
    const AccessUnit& unit = units[i];
    EXPECT_EQ(unit.codec, Codec::kH265);
    EXPECT_EQ(unit.width, 640);
    const std::vector<int> types = h265_nal_types(unit.bytes);
    const bool irap =
        std::any_of(types.begin(), types.end(), [](int t) { return t >= 16 && t <= 23; });
    EXPECT_EQ(irap, unit.key_frame) << "unit " << i;
    if (!unit.key_frame) continue;
    keys.push_back(i);
    EXPECT_TRUE(contains(types, 32) && contains(types, 33) && contains(types, 34))
        << "VPS/SPS/PPS before key unit " << i;
  }
  ASSERT_GE(keys.size(), 2u);
  for (size_t k = 1; k < keys.size(); ++k) EXPECT_EQ(keys[k] - keys[k - 1], size_t(kKeyInterval));
}

TEST(VideoPassthrough, TheFrameSizeFollowsTheImageMode) {
  Stream stream(ImageMode::kThermal, 0, kKeyInterval);
  std::mutex mutex;
  cv::Size unit_size;
  AccessUnitSource source(options_for(stream.url()), [&](const AccessUnit& unit) {
    std::lock_guard<std::mutex> lock(mutex);
    unit_size = cv::Size(unit.width, unit.height);
  });
  source.set_decoding(true);
  source.start();
  auto thermal = source.wait_newer(0, seconds(10));
  ASSERT_TRUE(thermal) << source.stats().last_error;
  EXPECT_EQ(thermal->size, cv::Size(640, 512));
  stream.set_mode(ImageMode::kVisible);
  std::optional<GrabbedFrame> visible;
  ASSERT_TRUE(wait_until(
      [&] {
        visible = source.wait_newer(0, std::chrono::milliseconds(50));
        return visible && visible->size == cv::Size(1920, 1080);
      },
      seconds(10)));
  EXPECT_TRUE(sim::video::read_frame_stamp(to_bgr(*visible)));
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_EQ(unit_size, cv::Size(1920, 1080));
}

TEST(VideoPassthrough, AFrozenServerIsNoticedWithinTheReadTimeout) {
  testing::SimStreamProcess sim({"--mode", "0", "--key-interval", "10"});
  ASSERT_FALSE(sim.url().empty());
  Received received;
  AccessUnitSource source(options_for(sim.url()), keep_in(received));
  source.start();
  ASSERT_TRUE(wait_until([&] { return received.size() >= 5; }, seconds(10)))
      << source.stats().last_error;
  sim.freeze();
  const auto noticed = wait_until([&] { return !source.stats().streaming; }, seconds(4));
  ASSERT_TRUE(noticed) << "the stall was never noticed";
  EXPECT_LT(noticed->count(), 1.0 + 0.8);  // read_timeout plus scheduling slack
  EXPECT_GE(source.stats().read_errors, 1u);
}

}  // namespace
}  // namespace k40t::video
