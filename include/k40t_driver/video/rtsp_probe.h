// Asks the RTSP server whether it is there (an OPTIONS request, with GStreamer's RTSP library)
// before the stream is handed to OpenCV. OpenCV 4.6's GStreamer back-end leaves a pipeline that
// failed to start in PLAYING when it drops it (GStreamer-CRITICAL "Trying to dispose element ...
// in PLAYING"), which while the pod is switched off would happen on every reconnect attempt; the
// probe turns "connection refused" and "no answer" into a plain error instead.
#pragma once

#include <string>

#include "k40t_driver/protocol/result.h"

namespace k40t::video {

// OK when `url` (rtsp://HOST[:PORT]/PATH) answers OPTIONS with 200 within `timeout_s`; otherwise
// an error naming the URL and what went wrong.
Status probe_rtsp(const std::string& url, double timeout_s);

}  // namespace k40t::video
