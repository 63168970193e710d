// The pod's latest state for the SKYPORT bridge (PodSnapshot), ROS-free: fed with the driver's
// status reports (RosPodPort reads them from its topics) and with the commands the pod accepted,
// it answers snapshot() and tells of events worth a floating-window message (recording started or
// stopped, SD card full). Thread-safe: reports come from subscription threads, snapshots from the
// bridge's session and worker threads.
//
// Times are seconds on the glue's clock (ROS time), passed in so that the rules can be checked
// without one:
//   - record/status comes at 1 Hz while recording, and at start and stop. A start the pod accepted
//     counts as recording until record/status confirms or denies it; a "recording" report counts
//     while record/status keeps coming. Either silent for kRecordStatusFresh_s: unknown.
//   - the work mode the pod accepted is answered until camera/status (1 Hz) says so too
//     (commanded_value.h, at most 3 s).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/skyport/commanded_value.h"
#include "k40t_driver/skyport/pod_port.h"

namespace k40t::driver::skyport {

constexpr double kRecordStatusFresh_s = 2.5;
// CameraStatus SD_FULL (camera/status), kept here so the core needs no ROS header.
constexpr uint8_t kSdFull = 4;

// camera/status, field by field (k40t_driver/CameraStatus).
struct CameraReport {
  bool video_mode = false;
  uint8_t photo_mode = 0;
  uint8_t burst_count = 0;
  uint8_t timelapse_interval_s = 0;
  uint8_t sd_state = 3;
  uint8_t image_mode = 0;
  double sd_total_mb = 0, sd_free_mb = 0;
};

class PodStateTracker {
 public:
  using Events = std::function<void(const std::string& text)>;
  explicit PodStateTracker(Events events) : events_(std::move(events)) {}

  // joint_states: the joints named "...yaw_joint", "...roll_joint", "...pitch_joint" (REP 103
  // radians); a missing velocity is 0.
  void joints(const std::vector<std::string>& names, const std::vector<double>& positions,
              const std::vector<double>& velocities, double now_s);
  // gimbal/attitude as REP 103 angles (the glue turns the quaternion into them).
  void attitude(double roll_rad, double pitch_rad, double yaw_rad);
  void camera(const CameraReport& report, double now_s);
  void visible(double zoom_ratio, double focal_length_mm, double now_s);
  void photo(uint8_t state);
  void repair(uint8_t state, uint8_t percent);
  // record/status: `recording` for RECORDING and TIMELAPSE_RECORDING; `state_text` names the
  // state in the "stopped" event.
  void record(bool recording, uint16_t duration_s, const std::string& state_text, double now_s);

  // The pod accepted a record start or stop, or a work mode.
  void record_accepted(bool start, double now_s);
  void video_mode_accepted(bool video);

  PodSnapshot snapshot(double now_s) const;

 private:
  void heard(double now_s) { heard_at_s_ = now_s; }  // under mutex_

  Events events_;
  mutable std::mutex mutex_;
  PodSnapshot state_;
  std::optional<double> record_status_at_s_;
  std::optional<double> record_commanded_at_s_;  // a start the pod accepted, not yet confirmed
  std::optional<double> heard_at_s_;             // the newest status message from the pod
  CommandedValue<bool> video_mode_set_{std::chrono::seconds(3)};
};

}  // namespace k40t::driver::skyport
