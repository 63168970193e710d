// How the video client opens the pod's RTSP stream with OpenCV's videoio, and the two ways it can
// do so:
//   low_latency = true  (the driver's configuration)
//     GStreamer: rtspsrc latency=0 (no jitter buffer delay) over TCP or UDP ! decodebin !
//                k40tstallguard (stall_guard.h: EOS after read_timeout without a frame) !
//                I420 appsink max-buffers=1 drop=true sync=false — the decoder's output is never
//                queued, and the colour conversion is left to the consumer (OpenCV's, which is
//                much faster than GStreamer's videoconvert and runs only on frames published).
//     FFmpeg:    rtsp_transport, fflags=nobuffer, flags=low_delay, and OpenCV's open/read
//                timeouts.
//   low_latency = false (OpenCV's defaults, the benchmark's baseline): VideoCapture(url, backend)
//                and nothing else — what most RTSP camera drivers do.
#pragma once

#include <string>

#include "k40t_driver/protocol/result.h"

namespace k40t::video {

enum class Backend { kGStreamer, kFFmpeg };
enum class RtspTransport { kTcp, kUdp };

Result<Backend> parse_backend(const std::string& name);          // "gstreamer" | "ffmpeg"
Result<RtspTransport> parse_transport(const std::string& name);  // "tcp" | "udp"
const char* to_string(Backend backend);
const char* to_string(RtspTransport transport);

struct CaptureOptions {
  std::string url = "rtsp://192.168.144.64:558/live/single";
  Backend backend = Backend::kGStreamer;
  bool low_latency = true;
  RtspTransport transport = RtspTransport::kTcp;
  double open_timeout_s = 2.0;  // connecting and the first frame
  double read_timeout_s = 1.5;  // a stream silent this long is closed and opened again
};

// The URL must be rtsp:// or rtsps:// with a host, and free of characters that would change the
// meaning of a GStreamer pipeline description (spaces, quotes, '!'); timeouts 0.1..60 s.
Status validate(const CaptureOptions& options);

// The pipeline description given to cv::VideoCapture with CAP_GSTREAMER (low-latency only).
std::string gstreamer_pipeline(const CaptureOptions& options);
// OPENCV_FFMPEG_CAPTURE_OPTIONS for the low-latency FFmpeg configuration ("key;value|...").
std::string ffmpeg_capture_options(const CaptureOptions& options);

}  // namespace k40t::video
