// A GStreamer element, "k40tstallguard", that ends a stalled stream: it passes buffers through
// and, when none has come for `timeout` milliseconds (counted from PLAYING, so a stream that never
// starts is caught too), pushes end-of-stream downstream.
//
// Why: OpenCV 4.6's GStreamer back-end reads with a blocking gst_app_sink_pull_sample() and has no
// read timeout (CAP_PROP_READ_TIMEOUT_MSEC is FFmpeg-only there), and rtspsrc keeps waiting on a
// silent TCP connection for ever. With the guard before the appsink, VideoCapture::read() returns
// false within the timeout and the grabber can reconnect.
#pragma once

#include "k40t_driver/protocol/result.h"

namespace k40t::video {

constexpr const char* kStallGuardElement = "k40tstallguard";

// Registers the element with this process's GStreamer (once; later calls are no-ops). Calls
// gst_init() if nobody has.
Status register_stall_guard();

}  // namespace k40t::video
