// H.264/H.265 in and out of the driver without OpenCV's videoio: the decoder (avdec through
// GStreamer) turns access units — the pod's own, passed through (access_unit_source.h), or those
// of a recorded or remote topic — into I420 frames; the encoder (x264 through GStreamer) turns a
// camera's raw frames into access units, for the image_transport plugin's publisher side.
//
// An access unit is one coded picture in Annex B form (start codes); a key frame (IDR) carries
// its parameter sets (SPS/PPS, and VPS for H.265) in front, so a decoder can start on any key
// frame.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "k40t_driver/protocol/result.h"
#include "k40t_driver/video/app_pipeline.h"

namespace k40t::video {

enum class Codec { kH264, kH265 };

Result<Codec> parse_codec(const std::string& format);  // "h264" | "h265"
const char* to_string(Codec codec);                    // the message's `format`
// GStreamer caps of one access unit per buffer in Annex B form.
std::string access_unit_caps(Codec codec);

struct AccessUnit {
  Codec codec = Codec::kH264;
  std::vector<uint8_t> bytes;
  bool key_frame = false;
  int width = 0;  // from the parameter sets (0 if unknown)
  int height = 0;
  int64_t received_us = 0;       // system clock when it came off the stream
  std::optional<double> pts_ms;  // the stream's presentation time
  uint64_t sequence = 0;         // 1, 2, 3... over the source's life
};

struct DecodedFrame {
  // CV_8UC1, height * 3 / 2 rows: Y, then U, then V. Usually the decoder's own buffer, not a
  // copy: `memory` keeps it alive; keep the frame (not only the Mat) while using the pixels.
  cv::Mat i420;
  std::shared_ptr<const uint8_t> memory;
  cv::Size size;
  uint64_t tag = 0;  // what push() was given with its access unit
};

// I420 -> BGR (bgr8 images).
cv::Mat i420_to_bgr(const DecodedFrame& frame);
// I420 (CV_8UC1, height * 3 / 2 rows) -> BGR into `bgr` (CV_8UC3 of the picture's size, e.g.
// over a message's buffer), all on the calling thread (video_decoder.cpp says why).
void i420_to_bgr(const cv::Mat& i420, cv::Mat& bgr);

class VideoDecoder {
 public:
  // An error when GStreamer lacks the decoder (gstreamer1.0-libav).
  static Result<std::unique_ptr<VideoDecoder>> create(Codec codec);

  Codec codec() const { return codec_; }
  // Queues an access unit. Until the first key frame (and after resync()) access units are
  // skipped — they refer to pictures this decoder never saw — and false is returned.
  Result<bool> push(const uint8_t* data, size_t size, bool key_frame, uint64_t tag);
  // The next decoded frame, waiting up to `timeout`. One comes out per access unit pushed (no
  // frame reordering in zero-latency streams; slice threads only, so no frame delay).
  std::optional<DecodedFrame> pull(std::chrono::milliseconds timeout);
  // Instead of pull(): every frame, on the decoder's thread. Set before the first push.
  void on_frame(std::function<void(DecodedFrame)> callback);
  // Skips until the next key frame (after access units were left out).
  void resync() { synced_ = false; }
  std::string error() const { return pipeline_->error(); }

 private:
  VideoDecoder(Codec codec, std::unique_ptr<AppPipeline> pipeline)
      : codec_(codec), pipeline_(std::move(pipeline)) {}
  Codec codec_;
  std::unique_ptr<AppPipeline> pipeline_;
  bool synced_ = false;
};

struct EncoderOptions {
  int bitrate_kbps = 4000;
  int key_frame_interval = 30;  // frames
  int fps = 30;                 // for the rate control only
};
Status validate(const EncoderOptions& options);

struct EncodedUnit {
  std::vector<uint8_t> bytes;  // one H.264 access unit, Annex B, SPS/PPS before key frames
  bool key_frame = false;
};

class VideoEncoder {
 public:
  // `encoding`: a sensor_msgs image encoding with one plane (bgr8, rgb8, bgra8, rgba8, mono8);
  // x264 wants an even width and height.
  static Result<std::unique_ptr<VideoEncoder>> create(const std::string& encoding, int width,
                                                      int height, const EncoderOptions& options);
  bool accepts(const std::string& encoding, int width, int height) const {
    return encoding == encoding_ && width == width_ && height == height_;
  }
  // Encodes one frame (rows `step` bytes apart) and returns its access unit; x264's zero-latency
  // tuning gives one out per frame in.
  Result<EncodedUnit> encode(const uint8_t* data, size_t step);

 private:
  VideoEncoder(std::string encoding, int width, int height, int bytes_per_pixel,
               std::unique_ptr<AppPipeline> pipeline)
      : encoding_(std::move(encoding)),
        width_(width),
        height_(height),
        bytes_per_pixel_(bytes_per_pixel),
        pipeline_(std::move(pipeline)) {}
  std::string encoding_;
  int width_;
  int height_;
  int bytes_per_pixel_;
  std::unique_ptr<AppPipeline> pipeline_;
  uint64_t frames_ = 0;
};

}  // namespace k40t::video
