// A GStreamer pipeline fed and drained by the program: "appsrc name=in ! MIDDLE ! appsink
// name=out". The video codecs (video_codec.h) are built on it: x264enc or avdec_h264 in the
// middle, buffers pushed from ROS messages, RTSP access units or bag records, samples pulled or
// handed to a callback. Pushing never blocks (appsrc queues); a pipeline error (a missing
// element, a decoder that gave up) is kept and returned by the next push or pull.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/protocol/result.h"

namespace k40t::video {

// Calls gst_init() once per process if nobody has (OpenCV may have).
void ensure_gstreamer();

// True when this GStreamer has an element factory of that name (x264enc, avdec_h264...).
bool has_gstreamer_element(const std::string& name);

struct PipelineSample {
  // The buffer; raw video with its planes' rows tightly packed. Raw video that the pipeline
  // already laid out so (a decoder's I420 without padding) is not copied: `held` is then the
  // pipeline's own buffer, mapped and kept alive for as long as `held` or a copy of it lives,
  // and `bytes` is empty. data()/size() read whichever holds it.
  std::vector<uint8_t> bytes;
  std::shared_ptr<const uint8_t> held;
  size_t held_size = 0;
  const uint8_t* data() const { return held ? held.get() : bytes.data(); }
  size_t size() const { return held ? held_size : bytes.size(); }
  std::string media;  // the caps' structure name: "video/x-raw", "video/x-h264"...
  int width = 0;      // from the caps (0 if they give none)
  int height = 0;
  std::optional<uint64_t> pts_ns;
  bool key_frame = false;  // not a delta unit
};

class AppPipeline {
 public:
  // `input_caps` describes what push() gets; `output_caps` restricts what comes out (may be "").
  static Result<std::unique_ptr<AppPipeline>> create(const std::string& input_caps,
                                                     const std::string& middle,
                                                     const std::string& output_caps);
  ~AppPipeline();  // to NULL: no thread of the pipeline outlives it
  AppPipeline(const AppPipeline&) = delete;
  AppPipeline& operator=(const AppPipeline&) = delete;

  // Queues one buffer (copied) with that presentation time.
  Status push(const uint8_t* data, size_t size, uint64_t pts_ns);
  // Queues one single-plane raw frame (BGR, GRAY8...) whose `rows` rows of `row_bytes` are
  // `step` bytes apart, laid out as the input caps want (GStreamer pads rows to 4 bytes).
  Status push_rows(const uint8_t* data, size_t step, size_t row_bytes, size_t rows,
                   uint64_t pts_ns);
  // The next sample out, waiting up to `timeout`; nothing on timeout or error (see error()).
  std::optional<PipelineSample> pull(std::chrono::milliseconds timeout);
  // Instead of pull(): every sample, on the pipeline's streaming thread. Set before the first push.
  void on_sample(std::function<void(PipelineSample)> callback);
  // The first error the pipeline posted, empty if none.
  std::string error() const;

  struct Impl;

 private:
  explicit AppPipeline(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace k40t::video
