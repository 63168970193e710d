#include "k40t_driver/skyport/pod_state_tracker.h"

#include <algorithm>

namespace k40t::driver::skyport {

namespace {
bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}
}  // namespace

void PodStateTracker::joints(const std::vector<std::string>& names,
                             const std::vector<double>& positions,
                             const std::vector<double>& velocities, double now_s) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (size_t i = 0; i < names.size() && i < positions.size(); ++i) {
    const double velocity = i < velocities.size() ? velocities[i] : 0.0;
    if (ends_with(names[i], "yaw_joint")) {
      state_.yaw_rad = positions[i];
      state_.yaw_rate_rad_s = velocity;
    } else if (ends_with(names[i], "roll_joint")) {
      state_.roll_rad = positions[i];
      state_.roll_rate_rad_s = velocity;
    } else if (ends_with(names[i], "pitch_joint")) {
      state_.pitch_rad = positions[i];
      state_.pitch_rate_rad_s = velocity;
    }
  }
  state_.have_joints = true;
  heard(now_s);
}

void PodStateTracker::attitude(double roll_rad, double pitch_rad, double yaw_rad) {
  std::lock_guard<std::mutex> lock(mutex_);
  state_.have_attitude = true;
  state_.attitude_roll_rad = roll_rad;
  state_.attitude_pitch_rad = pitch_rad;
  state_.attitude_yaw_rad = yaw_rad;
}

void PodStateTracker::camera(const CameraReport& report, double now_s) {
  bool became_full = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    became_full =
        report.sd_state == kSdFull && (!state_.have_camera || state_.sd_state != report.sd_state);
    state_.have_camera = true;
    state_.video_mode = report.video_mode;
    video_mode_set_.reported(state_.video_mode, std::chrono::steady_clock::now());
    state_.photo_mode = report.photo_mode;
    state_.burst_count = report.burst_count;
    state_.timelapse_interval_s = report.timelapse_interval_s;
    state_.sd_state = report.sd_state;
    state_.image_mode = report.image_mode;
    state_.sd_total_mb = report.sd_total_mb;
    state_.sd_free_mb = report.sd_free_mb;
    heard(now_s);
  }
  if (became_full && events_) events_("K40T: SD card full");
}

void PodStateTracker::visible(double zoom_ratio, double focal_length_mm, double now_s) {
  std::lock_guard<std::mutex> lock(mutex_);
  state_.have_visible = true;
  state_.zoom_ratio = zoom_ratio;
  state_.focal_length_mm = focal_length_mm;
  heard(now_s);
}

void PodStateTracker::photo(uint8_t state) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++state_.photo_status_count;
  state_.photo_state = state;
}

void PodStateTracker::repair(uint8_t state, uint8_t percent) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++state_.repair_status_count;
  state_.repair_state = state;
  state_.repair_percent = percent;
}

void PodStateTracker::record(bool recording, uint16_t duration_s, const std::string& state_text,
                             double now_s) {
  bool started = false, stopped = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const bool was = state_.recording;
    started = recording && !was;
    stopped = !recording && was;
    state_.recording = recording;
    state_.record_duration_s = duration_s;
    record_status_at_s_ = now_s;
    record_commanded_at_s_.reset();  // the pod's own word replaces the command's
  }
  if (started && events_) events_("K40T: recording started");
  if (stopped && events_) events_("K40T: recording stopped (" + state_text + ")");
}

void PodStateTracker::record_accepted(bool start, double now_s) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (start) {
    record_commanded_at_s_ = now_s;
  } else {
    record_commanded_at_s_.reset();
    state_.recording = false;
  }
}

void PodStateTracker::video_mode_accepted(bool video) {
  std::lock_guard<std::mutex> lock(mutex_);
  video_mode_set_.accepted(video, std::chrono::steady_clock::now());
}

PodSnapshot PodStateTracker::snapshot(double now_s) const {
  std::lock_guard<std::mutex> lock(mutex_);
  PodSnapshot out = state_;
  const auto recent = [now_s](const std::optional<double>& t) {
    return t && now_s - *t < kRecordStatusFresh_s;
  };
  const bool started = record_commanded_at_s_.has_value();
  const bool said_recording = state_.recording;
  out.recording = (started && recent(record_commanded_at_s_)) ||
                  (said_recording && recent(record_status_at_s_));
  out.recording_known = out.recording || (!started && !said_recording);
  out.state_age_s = heard_at_s_ ? std::max(0.0, now_s - *heard_at_s_) : -1.0;
  out.video_mode = video_mode_set_.answer(state_.video_mode, std::chrono::steady_clock::now());
  return out;
}

}  // namespace k40t::driver::skyport
