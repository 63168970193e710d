// What the SKYPORT bridge needs from the pod, ROS-free: commands (the glue calls the driver's ROS
// services and topics) and the pod's latest state (from the driver's status topics). Angles here
// follow REP 103 like the driver's interface: pitch positive = camera looks down, yaw positive =
// camera turns left.
#pragma once

#include <cstdint>
#include <string>

namespace k40t::driver::skyport {

struct PodCall {
  bool ok = false;
  std::string message;  // the service's message, or why it could not be called
  // Refused only because the pod is taking or storing a photo (response code 0x0203).
  bool photo_in_progress = false;
};

struct PodSnapshot {
  bool have_joints = false;
  double yaw_rad = 0, roll_rad = 0, pitch_rad = 0;
  double yaw_rate_rad_s = 0, roll_rate_rad_s = 0, pitch_rate_rad_s = 0;

  // gimbal/attitude: the stabilised attitude angles (0x000002 bytes 7-12), REP 103 signs like
  // the joints; the yaw's origin is the pod's (north once the pod is fed the aircraft's attitude).
  bool have_attitude = false;
  double attitude_yaw_rad = 0, attitude_roll_rad = 0, attitude_pitch_rad = 0;

  bool have_camera = false;  // camera/status
  bool video_mode = false;
  uint8_t photo_mode = 0;  // CameraStatus PHOTO_SINGLE / BURST / TIMELAPSE
  uint8_t burst_count = 0;
  uint8_t timelapse_interval_s = 0;
  uint8_t sd_state = 3;  // CameraStatus SD_*: missing until told
  double sd_total_mb = 0, sd_free_mb = 0;

  bool recording = false;  // record/status RECORDING (or time-lapse recording), recent
  // False when record/status went silent while the pod was (or was told to start) recording: the
  // pod may or may not still record.
  bool recording_known = true;
  uint16_t record_duration_s = 0;

  uint8_t image_mode = 0;  // CameraStatus IMAGE_*: 0 thermal, 5/6 visible, 7 split

  bool have_visible = false;  // visible/status
  double zoom_ratio = 1;
  double focal_length_mm = 0;

  uint64_t photo_status_count = 0;  // photo/status messages received so far
  uint8_t photo_state = 0;          // the last one's PhotoStatus STATE_*

  // camera/upgrade_status (0x000008): the pod's repair progress, which covers a gimbal
  // calibration (state 3 "repairing", then 0 succeeded or 1 failed).
  uint64_t repair_status_count = 0;  // messages received so far
  uint8_t repair_state = 0;          // CameraUpgradeStatus STATE_*
  uint8_t repair_percent = 0;

  // Seconds since the newest status message from the pod (joints, camera, visible); negative
  // before the first. Getters answer from this state however old; diagnostics mark it stale.
  double state_age_s = -1;
};

// CameraUpgradeStatus STATE_* (0x000008 byte 1, 3.2.1.4), kept here so the core needs no ROS
// header.
constexpr uint8_t kRepairSucceeded = 0, kRepairFailed = 1, kRepairUpgrading = 2, kRepairing = 3;

// The pod's zoom actions (k40t_driver/Zoom.srv) and focus modes (Focus.srv).
enum class PodZoom : uint8_t { kIn = 0, kOut = 1, kStop = 2 };
enum class PodFocus : uint8_t { kAuto = 0, kManualStop = 3, kArea = 4 };

class PodPort {
 public:
  virtual ~PodPort() = default;
  virtual PodCall take_photo(bool stop) = 0;
  virtual PodCall record(bool start) = 0;
  virtual PodCall set_photo_mode(uint8_t mode, uint8_t interval_s, uint8_t burst_count) = 0;
  virtual PodCall set_video_mode(bool video) = 0;
  virtual PodCall set_metering(int metering) = 0;  // K40t.cfg `metering`: 1 centre, 3 average
  virtual PodCall set_zoom(double ratio) = 0;      // hybrid, 1..160
  virtual PodCall zoom(PodZoom action) = 0;
  virtual PodCall focus(PodFocus mode, uint16_t x1, uint16_t y1, uint16_t x2, uint16_t y2) = 0;
  virtual PodCall format_sd() = 0;
  virtual PodCall set_angle(double pitch_rad, double yaw_rad) = 0;
  virtual PodCall set_rate(double pitch_rad_s, double yaw_rad_s) = 0;  // dead-man 0.5 s
  virtual PodCall center() = 0;
  virtual PodCall calibrate() = 0;
  virtual PodCall set_palette(int palette) = 0;        // K40t.cfg `palette` 1..20
  virtual PodCall set_image_mode(int image_mode) = 0;  // K40t.cfg `image_mode` 0, 5, 7
  // One laser ranging; `range_m` is +Inf when the laser got no return.
  virtual PodCall measure_range(double& range_m) = 0;
  virtual PodSnapshot snapshot() const = 0;
};

}  // namespace k40t::driver::skyport
