#include <opencv2/imgproc.hpp>

#include "k40t_driver/video/video_codec.h"

namespace k40t::video {

Result<Codec> parse_codec(const std::string& format) {
  if (format == "h264") return Codec::kH264;
  if (format == "h265") return Codec::kH265;
  return Result<Codec>::fail("video format '" + format + "' is not one of: h264, h265");
}

const char* to_string(Codec codec) {
  return codec == Codec::kH265 ? "h265" : "h264";
}

std::string access_unit_caps(Codec codec) {
  return std::string(codec == Codec::kH265 ? "video/x-h265" : "video/x-h264") +
         ",stream-format=byte-stream,alignment=au";
}

// OpenCV would split the conversion over its thread pool (TBB here), whose workers then spin
// between frames: on a 2-core machine that cost more CPU than the conversion itself saves
// (docs/video.md, "Passthrough, measured"). A parallel_for_ of one stripe runs its body on the
// calling thread, and OpenCV runs the parallel loops nested in it (the conversion's) serially;
// while it runs, other threads' OpenCV loops in the process run serially too (~1 ms a frame).
void i420_to_bgr(const cv::Mat& i420, cv::Mat& bgr) {
  cv::parallel_for_(cv::Range(0, 1),
                    [&](const cv::Range&) { cv::cvtColor(i420, bgr, cv::COLOR_YUV2BGR_I420); });
}

cv::Mat i420_to_bgr(const DecodedFrame& frame) {
  cv::Mat bgr(frame.size, CV_8UC3);
  i420_to_bgr(frame.i420, bgr);
  return bgr;
}

namespace {

// The sample's pixels as they are (no copy): the Mat points into them and `memory` holds them.
std::optional<DecodedFrame> to_frame(PipelineSample sample) {
  const size_t expected = static_cast<size_t>(sample.width) * sample.height * 3 / 2;
  if (sample.width <= 0 || sample.height <= 0 || sample.height % 2 != 0 ||
      sample.size() != expected)
    return std::nullopt;  // not I420 of the size it claims: never handed on as a picture
  DecodedFrame frame;
  frame.size = cv::Size(sample.width, sample.height);
  if (sample.held) {
    frame.memory = std::move(sample.held);
  } else {
    auto bytes = std::make_shared<std::vector<uint8_t>>(std::move(sample.bytes));
    frame.memory = std::shared_ptr<const uint8_t>(bytes, bytes->data());
  }
  // OpenCV wants a writable pointer; nothing here writes through it.
  frame.i420 = cv::Mat(sample.height * 3 / 2, sample.width, CV_8UC1,
                       const_cast<uint8_t*>(frame.memory.get()));
  frame.tag = sample.pts_ns.value_or(0);
  return frame;
}

}  // namespace

Result<std::unique_ptr<VideoDecoder>> VideoDecoder::create(Codec codec) {
  const std::string decoder = codec == Codec::kH265 ? "avdec_h265" : "avdec_h264";
  if (!has_gstreamer_element(decoder))
    return Status::fail("GStreamer has no " + decoder + " (Debian: gstreamer1.0-libav)");
  // Slice threads only: libav's frame threads hold one frame per thread back. No corrupt frames:
  // a picture whose references are missing is dropped, not shown grey.
  auto pipeline = AppPipeline::create(
      access_unit_caps(codec), decoder + " thread-type=slice output-corrupt=false ! videoconvert",
      "video/x-raw,format=I420");
  if (!pipeline) return pipeline.status();
  return std::unique_ptr<VideoDecoder>(new VideoDecoder(codec, std::move(pipeline.value())));
}

Result<bool> VideoDecoder::push(const uint8_t* data, size_t size, bool key_frame, uint64_t tag) {
  if (!synced_ && !key_frame) return false;
  synced_ = true;
  if (Status s = pipeline_->push(data, size, tag); !s) return s;
  return true;
}

std::optional<DecodedFrame> VideoDecoder::pull(std::chrono::milliseconds timeout) {
  std::optional<PipelineSample> sample = pipeline_->pull(timeout);
  if (!sample) return std::nullopt;
  return to_frame(std::move(*sample));
}

void VideoDecoder::on_frame(std::function<void(DecodedFrame)> callback) {
  pipeline_->on_sample([callback = std::move(callback)](PipelineSample sample) {
    if (std::optional<DecodedFrame> frame = to_frame(std::move(sample)))
      callback(std::move(*frame));
  });
}

}  // namespace k40t::video
