// The simulated pod's RTSP server (gst-rtsp-server): rtsp://ADDRESS:PORT/live/single serves
// H.264 (x264, zero-latency tuning: no B-frames, no look-ahead; or H.265 with x265) of frames
// rendered on demand from whatever the snapshot source says the pod shows. One shared media: every
// client sees the same frames (same frame counters), rendering and encoding run only while someone
// is connected. Frames are paced by a steady clock at `fps`; the frame size follows the image mode,
// and the encoder renegotiates in-stream (new SPS/PPS) when it changes.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "k40t_driver/protocol/result.h"
#include "k40t_driver/sim/video/video_snapshot.h"
#include "k40t_driver/video/video_codec.h"

namespace k40t::sim::video {

struct RtspServerOptions {
  std::string address = "127.0.0.1";
  int port = 8554;  // the pod's own is 558
  std::string path = "/live/single";
  int fps = 30;
  int bitrate_kbps = 4000;
  int key_frame_interval = 30;  // frames between IDR frames (a new client waits up to this long)
  // The pod sends either (0x00030B). H.265: x265 (gstreamer1.0-plugins-bad), same tuning.
  k40t::video::Codec codec = k40t::video::Codec::kH264;
};

// Checks ranges and the path's shape; the message names the offending option.
Status validate(const RtspServerOptions& options);

// Asked once per frame, on the server's frame thread, for what the pod shows now.
using SnapshotSource = std::function<VideoSnapshot()>;

struct StreamCounters {
  uint64_t frames_pushed = 0;  // handed to the encoder
  uint64_t media_started = 0;  // times the shared media was (re)built for a first client
};

class RtspStreamServer {
 public:
  // Binds the port and starts serving; an error when the options are invalid, the port is taken,
  // or a GStreamer element (x264enc|x265enc, rtph264pay|rtph265pay) is missing.
  static Result<std::unique_ptr<RtspStreamServer>> start(const RtspServerOptions& options,
                                                         SnapshotSource source);
  ~RtspStreamServer();  // disconnects every client and stops
  RtspStreamServer(const RtspStreamServer&) = delete;
  RtspStreamServer& operator=(const RtspStreamServer&) = delete;

  std::string url() const;
  StreamCounters counters() const;

  class Impl;

 private:
  explicit RtspStreamServer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace k40t::sim::video
