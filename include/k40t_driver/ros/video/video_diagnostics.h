// /diagnostics of the video stream (diagnostic_updater, updated every ~diagnostic_period on a
// steady timer), one status "<node or nodelet name>: video stream":
//   ERROR  not streaming (connecting, or the stream failed), or the newest frame is older than
//          stale_after — a killed or frozen stream is ERROR within stale_after + one period;
//   WARN   frame rate below half the expected one;
//   OK     otherwise.
// Values: URL, back-end, frame rate received and published, age of the newest frame, frames,
// frames and access units published, read (decode) errors, open failures, reconnects, last error,
// frame size, frame id, latency estimate.
#pragma once

#include <chrono>
#include <functional>
#include <mutex>
#include <string>

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/node_handle.h>
#include <ros/steady_timer.h>

#include "k40t_driver/ros/video/video_config.h"
#include "k40t_driver/video/frame_grabber.h"

namespace k40t::driver {

// What the publisher side adds to the grabber's counters.
struct PublishedState {
  uint64_t published = 0;        // image_raw
  uint64_t units_published = 0;  // image_raw/k40t_video (passthrough)
  std::string frame_id;
  int width = 0;
  int height = 0;
};

class VideoDiagnostics {
 public:
  using StatsSource = std::function<video::GrabberStats()>;
  using PublishedSource = std::function<PublishedState()>;

  VideoDiagnostics(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh,
                   const VideoConfig& config, StatsSource stats, PublishedSource published);

 private:
  void report(diagnostic_updater::DiagnosticStatusWrapper& stat);

  const VideoConfig& config_;
  StatsSource stats_;
  PublishedSource published_;
  diagnostic_updater::Updater updater_;
  ros::SteadyTimer timer_;
  // Counts at the previous report, for the rates.
  std::chrono::steady_clock::time_point last_report_;
  uint64_t last_frames_ = 0;
  uint64_t last_published_ = 0;
};

}  // namespace k40t::driver
