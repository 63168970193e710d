#include "k40t_driver/ros/video/video_diagnostics.h"

#include <diagnostic_msgs/DiagnosticStatus.h>

namespace k40t::driver {

VideoDiagnostics::VideoDiagnostics(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh,
                                   const VideoConfig& config, StatsSource stats,
                                   PublishedSource published)
    : config_(config),
      stats_(std::move(stats)),
      published_(std::move(published)),
      // Named after the node or nodelet ("pod_a/video: video stream"), not the process: the
      // default (the manager's name) would be the same for two pods' nodelets in one manager.
      updater_(nh, private_nh, private_nh.getNamespace()),
      last_report_(std::chrono::steady_clock::now()) {
  updater_.setHardwareID(config.capture.url);
  updater_.add("video stream", this, &VideoDiagnostics::report);
  ros::NodeHandle timer_nh(nh);
  timer_ =
      timer_nh.createSteadyTimer(ros::WallDuration(config.diagnostic_period_s),
                                 [this](const ros::SteadyTimerEvent&) { updater_.force_update(); });
}

void VideoDiagnostics::report(diagnostic_updater::DiagnosticStatusWrapper& stat) {
  using diagnostic_msgs::DiagnosticStatus;
  const auto now = std::chrono::steady_clock::now();
  const video::GrabberStats s = stats_();
  const PublishedState p = published_();
  const double elapsed = std::chrono::duration<double>(now - last_report_).count();
  const double fps = elapsed > 0 ? (s.frames - last_frames_) / elapsed : 0;
  const double published_fps = elapsed > 0 ? (p.published - last_published_) / elapsed : 0;
  last_report_ = now;
  last_frames_ = s.frames;
  last_published_ = p.published;
  const double age = s.last_frame ? std::chrono::duration<double>(now - *s.last_frame).count() : -1;

  if (!s.streaming) {
    stat.summary(DiagnosticStatus::ERROR,
                 s.last_frame ? "stream lost, reconnecting" : "no stream yet, connecting");
  } else if (age > config_.stale_after_s) {
    stat.summaryf(DiagnosticStatus::ERROR, "no frame for %.2f s", age);
  } else if (fps < config_.expected_fps / 2) {
    stat.summaryf(DiagnosticStatus::WARN, "%.1f fps, expected %.0f", fps, config_.expected_fps);
  } else {
    stat.summaryf(DiagnosticStatus::OK, "streaming, %.1f fps", fps);
  }
  stat.add("url", config_.capture.url);
  stat.add("backend", std::string(video::to_string(config_.capture.backend)) +
                          (config_.capture.low_latency ? " (low latency)" : " (OpenCV defaults)"));
  stat.addf("frame rate received (fps)", "%.2f", fps);
  stat.addf("frame rate published (fps)", "%.2f", published_fps);
  stat.addf("age of the newest frame (s)", "%.3f", age);
  stat.add("frames", s.frames);
  stat.add("frames published", p.published);
  stat.add("access units published (passthrough)", p.units_published);
  stat.add("read errors", s.read_errors);
  stat.add("open failures", s.open_failures);
  stat.add("reconnects", s.reconnects);
  stat.add("last error", s.last_error);
  stat.addf("frame size", "%dx%d", p.width, p.height);
  stat.add("frame id", p.frame_id);
  stat.addf("latency estimate (s)", "%.3f", config_.stamps.latency_s);
}

}  // namespace k40t::driver
