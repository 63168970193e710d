// The camera system's capture side (section 3.2.4): photo/video mode and the rules between them,
// single/burst/time-lapse photos and precise re-shoots with their status frames, recordings with
// 1 Hz status, the SD card they fill, the clock their file names use, and the GPS answer each
// photo records.
//
// Refusals (document 3.2.4.1 note: "in photo mode it does not respond to the video recording
// command; in video mode it does not respond to the photo command": the protocol front-end,
// answer_request(), stays silent then; the model's own outcomes are these):
//   photo in video mode      -> kRecording while a recording runs, else kFailure
//   record in photo mode     -> kPhotoInProgress while a burst/time-lapse runs, else kFailure
//   photo while one is taken -> kPhotoInProgress;  record start while recording -> kBusy
//   no card -> kNoSdCard;  formatting -> kBusy;  card fault -> kFailure;  no room -> kNoSpace
//   mode change / format while recording -> kRecording, while shooting -> kPhotoInProgress
// The document sends no status frame for a single shot; `single_shot_status` adds them
// (1 "single shot in progress", then 0 "photo taken") for hosts that want completion.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/sim/camera_settings.h"
#include "k40t_driver/sim/events.h"
#include "k40t_driver/sim/geo_point.h"
#include "k40t_driver/sim/geometry.h"
#include "k40t_driver/sim/model_part.h"
#include "k40t_driver/sim/outcome.h"
#include "k40t_driver/sim/pod_clock.h"
#include "k40t_driver/sim/sd_card.h"

namespace k40t::sim {

struct CameraConfig {
  double single_shot_s = 0.5;  // a single photo keeps the camera busy this long
  double burst_interval_s = 0.35;
  double infrared_photo_mb = 1.0;
  double photo_4000x3000_mb = 6.0;
  double photo_8000x6000_mb = 18.0;
  double infrared_video_mbps = 2.0;
  bool single_shot_status = false;
  // Photo mode 2 is a self-timer (one photo after the interval, no stop) rather than a repeating
  // time-lapse (photo_mode_2, docs/protocol/decisions.md#conventions).
  bool self_timer = false;
  SdConfig sd;
  int64_t start_utc_ms = kDefaultPodEpochMs;
};

// The host's answer to 0x000310 (the ACK the flight controller sends).
struct GpsAnswer {
  TimeOfDay echoed;
  GeoPoint position;
  YawPitchRoll attitude_deg;
};

struct PhotoRecord {
  uint64_t id = 0;
  std::string path;
  uint8_t lens_mode = 0;
  double size_mb = 0;
  int64_t taken_utc_ms = 0;
  std::optional<GpsAnswer> gps;  // filled when the host answers the GPS request
  uint16_t width_px = 0;         // visible resolution (0 for a thermal-only photo)
  uint16_t height_px = 0;
};

// A visible photo resolution code of 0x000202 / 0x000307 byte 2 (0x14..0x17) in pixels; {0, 0}
// for a code the document does not list.
struct PhotoPixels {
  uint16_t width = 0;
  uint16_t height = 0;
};
PhotoPixels photo_pixels(uint8_t resolution_code);

struct VideoRecord {
  std::string path;
  uint8_t lens_mode = 0;
  double seconds = 0;
  double size_mb = 0;
};

class CameraModel {
 public:
  explicit CameraModel(const CameraConfig& config = {});

  K40T_MODEL_PART(CameraSettings, settings)
  K40T_MODEL_PART(VisibleSettings, visible)
  K40T_MODEL_PART(SdCard, sd)
  K40T_MODEL_PART(PodClock, clock)

  Outcome set_capture_mode(CaptureMode mode);                               // 0x000300
  Outcome set_photo_mode(PhotoMode mode, int interval_s, int burst_count);  // 0x000301
  Outcome take_photo(uint8_t lens_mode, const std::string& folder,
                     const std::string& name);  // 0x000302
  Outcome stop_photo();
  // 0x000307: the photo is taken at `resolution_code` (byte 2), not the photo setting.
  Outcome precise_reshoot(uint8_t lens_mode, uint8_t resolution_code, const std::string& folder,
                          const std::string& name);
  Outcome start_recording(uint8_t lens_mode, const std::string& folder,
                          const std::string& name);  // 0x000303
  Outcome stop_recording();
  Outcome format_sd();         // 0x00030D
  Outcome start_tf_upgrade();  // 0x00030C
  // Backlight compensation and strong light suppression exclude each other (3.2.3.9 note).
  Outcome set_backlight(bool on, uint8_t value);
  Outcome set_strong_light(bool on, uint8_t value);

  // `optics_busy`: a precise re-shoot waits for the zoom to settle.
  void step(double dt_s, bool optics_busy, EventQueue& events);

  bool attach_gps(uint64_t photo_id, const GpsAnswer& answer);
  void restore_defaults();  // factory reset: settings only, the card keeps its files
  void abort_activity();    // power loss: shooting stops, a recording is closed as it is

  bool recording() const { return recording_.has_value(); }
  double recording_seconds() const { return recording_ ? recording_->record.seconds : 0; }
  bool shooting() const { return job_.has_value(); }
  bool upgrading() const { return upgrade_left_s_ > 0; }
  const std::vector<PhotoRecord>& photos() const { return photos_; }
  const std::vector<VideoRecord>& videos() const { return videos_; }
  double photo_size_mb(uint8_t lens_mode) const;  // at the photo resolution setting
  double photo_size_mb(uint8_t lens_mode, uint8_t resolution_code) const;
  double video_rate_mb_s(uint8_t lens_mode) const;

 private:
  struct ShootingJob {
    uint8_t lens_mode = 0;
    PhotoMode mode = PhotoMode::kSingle;
    bool precise = false;
    uint8_t resolution = 0;  // visible resolution code; the photo setting's unless precise
    std::string folder;
    std::string name;
    uint16_t taken = 0;
    double next_shot_s = 0;  // countdown
    bool stop_requested = false;
    bool started = false;  // its opening status frame has gone out
  };
  struct RecordingJob {
    VideoRecord record;
    double next_status_s = 1;
  };

  Outcome check_card_for(double mb) const;
  bool self_timed(const ShootingJob& job) const;  // photo mode 2 read as a self-timer
  void shoot(ShootingJob& job, EventQueue& events);
  void step_shooting(double dt_s, bool optics_busy, EventQueue& events);
  void step_recording(double dt_s, EventQueue& events);
  void step_upgrade(double dt_s, EventQueue& events);
  void finish_job(PhotoState state, EventQueue& events);
  std::string file_path(const std::string& folder, const std::string& name, const char* prefix,
                        const char* extension, int index) const;

  CameraConfig config_;
  CameraSettings settings_;
  VisibleSettings visible_ = factory_visible_settings();
  SdCard sd_;
  PodClock clock_;
  std::optional<ShootingJob> job_;
  std::optional<RecordingJob> recording_;
  double upgrade_left_s_ = 0;
  double upgrade_next_report_s_ = 0;
  bool announce_recording_ = false;  // "recording, 0 s" goes out at the next step
  bool stop_recording_requested_ = false;
  bool announce_upgrade_ = false;
  std::vector<PhotoRecord> photos_;
  std::vector<VideoRecord> videos_;
  uint64_t next_photo_id_ = 1;
};

}  // namespace k40t::sim
