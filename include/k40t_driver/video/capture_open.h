// Opening a cv::VideoCapture on the stream as CaptureOptions say (capture_options.h).
#pragma once

#include <memory>

#include <opencv2/videoio.hpp>

#include "k40t_driver/protocol/result.h"
#include "k40t_driver/video/capture_options.h"

namespace k40t::video {

// An open capture, or an error naming the URL and the back-end. In the low-latency configuration
// the server is asked first (rtsp_probe.h), so an absent pod costs no OpenCV pipeline. FFmpeg's
// options travel through
// the process-wide OPENCV_FFMPEG_CAPTURE_OPTIONS variable: it is set for the duration of the open
// only, under a lock, and restored afterwards.
Result<std::shared_ptr<cv::VideoCapture>> open_capture(const CaptureOptions& options);

// Whether frames read from a capture opened with `options` are I420 (one 8-bit plane of
// height * 3 / 2 rows) rather than BGR: the low-latency GStreamer pipeline leaves the colour
// conversion to the consumer.
bool delivers_i420(const CaptureOptions& options);

}  // namespace k40t::video
