#include <map>

#include "k40t_driver/video/video_codec.h"

namespace k40t::video {

namespace {

struct RawFormat {
  const char* gstreamer;
  int bytes_per_pixel;
};

// sensor_msgs image encodings (one plane, 8 bits) and their GStreamer names.
const std::map<std::string, RawFormat>& raw_formats() {
  static const std::map<std::string, RawFormat> formats{{"bgr8", {"BGR", 3}},
                                                        {"rgb8", {"RGB", 3}},
                                                        {"bgra8", {"BGRA", 4}},
                                                        {"rgba8", {"RGBA", 4}},
                                                        {"mono8", {"GRAY8", 1}}};
  return formats;
}

}  // namespace

Status validate(const EncoderOptions& options) {
  if (options.bitrate_kbps < 50 || options.bitrate_kbps > 100000)
    return Status::fail("bitrate " + std::to_string(options.bitrate_kbps) +
                        " kbit/s is out of range 50..100000");
  if (options.key_frame_interval < 1 || options.key_frame_interval > 600)
    return Status::fail("key frame interval " + std::to_string(options.key_frame_interval) +
                        " is out of range 1..600 frames");
  if (options.fps < 1 || options.fps > 240)
    return Status::fail("fps " + std::to_string(options.fps) + " is out of range 1..240");
  return Status::ok();
}

Result<std::unique_ptr<VideoEncoder>> VideoEncoder::create(const std::string& encoding, int width,
                                                           int height,
                                                           const EncoderOptions& options) {
  const auto format = raw_formats().find(encoding);
  if (format == raw_formats().end())
    return Status::fail("image encoding '" + encoding +
                        "' cannot be encoded to H.264 (bgr8, rgb8, bgra8, rgba8, mono8 can)");
  if (width < 16 || height < 16 || width % 2 || height % 2 || width > 8192 || height > 8192)
    return Status::fail("a " + std::to_string(width) + "x" + std::to_string(height) +
                        " image cannot be encoded to H.264 (even sizes 16..8192)");
  if (Status s = validate(options); !s) return s;
  if (!has_gstreamer_element("x264enc"))
    return Status::fail("GStreamer has no x264enc (Debian: gstreamer1.0-plugins-ugly)");
  const std::string input = std::string("video/x-raw,format=") + format->second.gstreamer +
                            ",width=" + std::to_string(width) +
                            ",height=" + std::to_string(height) +
                            ",framerate=" + std::to_string(options.fps) + "/1";
  // Zero-latency tuning: no B-frames, no look-ahead, one access unit out per frame in; the
  // parser repeats SPS/PPS before every key frame so that a late subscriber can start there.
  const std::string middle =
      "videoconvert ! video/x-raw,format=I420 ! x264enc tune=zerolatency speed-preset=ultrafast "
      "threads=1 bitrate=" +
      std::to_string(options.bitrate_kbps) +
      " key-int-max=" + std::to_string(options.key_frame_interval) +
      " ! h264parse config-interval=-1";
  auto pipeline = AppPipeline::create(input, middle, access_unit_caps(Codec::kH264));
  if (!pipeline) return pipeline.status();
  return std::unique_ptr<VideoEncoder>(new VideoEncoder(
      encoding, width, height, format->second.bytes_per_pixel, std::move(pipeline.value())));
}

Result<EncodedUnit> VideoEncoder::encode(const uint8_t* data, size_t step) {
  const size_t row_bytes = static_cast<size_t>(width_) * bytes_per_pixel_;
  if (step < row_bytes) return Status::fail("image step is smaller than a row");
  // Presentation times at the nominal rate keep x264's rate control sane.
  const uint64_t pts = frames_++ * 33'333'333ULL;
  if (Status s = pipeline_->push_rows(data, step, row_bytes, height_, pts); !s) return s;
  std::optional<PipelineSample> sample = pipeline_->pull(std::chrono::seconds(2));
  if (!sample) {
    const std::string error = pipeline_->error();
    return Status::fail("x264 gave no access unit" + (error.empty() ? "" : ": " + error));
  }
  return EncodedUnit{std::move(sample->bytes), sample->key_frame};
}

}  // namespace k40t::video
