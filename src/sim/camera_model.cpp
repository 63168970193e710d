#include "k40t_driver/sim/camera_model.h"

#include <algorithm>
#include <cmath>

#include "k40t_driver/codec/enum_names.h"

namespace k40t::sim {

namespace {
constexpr double kTfUpgradeS = 10;
constexpr double kBytesPerBit = 1.0 / 8.0;

bool is_one_of(int value, std::initializer_list<int> allowed) {
  return std::find(allowed.begin(), allowed.end(), value) != allowed.end();
}

// What a photo that cannot be taken reports for its refusal (a plain failure: by the card's
// state); any refusal not listed: failed.
PhotoState photo_state_for(Outcome refusal, SdState card) {
  if (refusal == Outcome::kFailure)
    return card == SdState::kFormatError ? PhotoState::kFormatError : PhotoState::kCardAbnormal;
  static constexpr EnumTo<Outcome, PhotoState> kStates[] = {
      {Outcome::kNoSdCard, PhotoState::kNoSdCard}, {Outcome::kNoSpace, PhotoState::kSdFull}};
  return lookup(kStates, refusal, PhotoState::kFailed);
}

// What a recording that cannot start reports for the card's state; any other: card abnormal.
RecordState record_state_for(SdState card) {
  static constexpr EnumTo<SdState, RecordState> kStates[] = {
      {SdState::kAbsent, RecordState::kNoSdCard},
      {SdState::kFull, RecordState::kSdFull},
      {SdState::kFormatError, RecordState::kFormatError},
      {SdState::kSlow, RecordState::kSlowCard}};
  return lookup(kStates, card, RecordState::kCardAbnormal);
}
}  // namespace

CameraModel::CameraModel(const CameraConfig& config)
    : config_(config), sd_(config.sd), clock_(config.start_utc_ms) {}

PhotoPixels photo_pixels(uint8_t resolution_code) {
  switch (resolution_code) {  // sections 3.2.3.3 and 3.2.4.7
    case 0x14:
      return {8000, 6000};
    case 0x15:
      return {4000, 3000};
    case 0x16:
      return {5160, 3890};
    case 0x17:
      return {5664, 4248};
    default:
      return {};
  }
}

double CameraModel::photo_size_mb(uint8_t lens_mode) const {
  return photo_size_mb(lens_mode, static_cast<uint8_t>(visible_.photo_resolution));
}

double CameraModel::photo_size_mb(uint8_t lens_mode, uint8_t resolution_code) const {
  // The two resolutions of the photo setting have their own sizes; the re-shoot's others scale
  // the 4000x3000 size by their pixel count.
  const PhotoPixels pixels = photo_pixels(resolution_code);
  const double visible = resolution_code == 0x14 ? config_.photo_8000x6000_mb
                         : resolution_code == 0x15
                             ? config_.photo_4000x3000_mb
                             : config_.photo_4000x3000_mb * pixels.width * pixels.height / 12e6;
  switch (lens_mode) {
    case 1:
      return config_.infrared_photo_mb;
    case 2:
      return visible;
    default:
      return config_.infrared_photo_mb + visible;  // 0 default and 3: both cameras
  }
}

double CameraModel::video_rate_mb_s(uint8_t lens_mode) const {
  const double infrared = config_.infrared_video_mbps * kBytesPerBit;
  const double visible = visible_video_mbps(static_cast<uint8_t>(visible_.video_resolution),
                                            visible_.video_bitrate_code) *
                         kBytesPerBit;
  switch (lens_mode) {
    case 1:
      return infrared;
    case 2:
      return visible;
    case 4:
      return stream_bitrate_mbps(settings_.stream_bitrate) * kBytesPerBit;  // the preview stream
    default:
      return infrared + visible;
  }
}

Outcome CameraModel::check_card_for(double mb) const {
  return sd_.can_write(mb);
}

Outcome CameraModel::set_capture_mode(CaptureMode mode) {
  if (recording_) return Outcome::kRecording;
  if (job_) return Outcome::kPhotoInProgress;
  settings_.capture_mode = mode;
  return Outcome::kOk;
}

Outcome CameraModel::set_photo_mode(PhotoMode mode, int interval_s, int burst_count) {
  if (job_) return Outcome::kPhotoInProgress;
  const bool interval_ok = is_one_of(interval_s, {5, 7, 30, 60});
  const bool burst_ok = is_one_of(burst_count, {3, 5});
  if ((mode == PhotoMode::kBurst && !burst_ok) || (mode == PhotoMode::kTimeLapse && !interval_ok)) {
    return Outcome::kFailure;
  }
  settings_.photo_mode = mode;
  if (interval_ok) settings_.time_lapse_interval_s = static_cast<uint8_t>(interval_s);
  if (burst_ok) settings_.burst_count = static_cast<uint8_t>(burst_count);
  return Outcome::kOk;
}

Outcome CameraModel::take_photo(uint8_t lens_mode, const std::string& folder,
                                const std::string& name) {
  if (settings_.capture_mode == CaptureMode::kVideo)
    return recording_ ? Outcome::kRecording : Outcome::kFailure;
  if (job_) return Outcome::kPhotoInProgress;
  if (upgrading()) return Outcome::kBusy;
  const Outcome card = check_card_for(photo_size_mb(lens_mode));
  if (card != Outcome::kOk) return card;
  ShootingJob job;
  job.lens_mode = lens_mode;
  job.mode = settings_.photo_mode;
  job.folder = folder;
  job.name = name;
  job.resolution = static_cast<uint8_t>(visible_.photo_resolution);
  if (self_timed(job)) job.next_shot_s = settings_.time_lapse_interval_s;
  job_ = job;
  return Outcome::kOk;
}

bool CameraModel::self_timed(const ShootingJob& job) const {
  return config_.self_timer && job.mode == PhotoMode::kTimeLapse && !job.precise;
}

Outcome CameraModel::stop_photo() {
  // "Stop shooting (only valid in continuous shooting mode)".
  if (!job_ || job_->precise || job_->mode == PhotoMode::kSingle || self_timed(*job_))
    return Outcome::kFailure;
  job_->stop_requested = true;
  return Outcome::kOk;
}

Outcome CameraModel::precise_reshoot(uint8_t lens_mode, uint8_t resolution_code,
                                     const std::string& folder, const std::string& name) {
  if (photo_pixels(resolution_code).width == 0) return Outcome::kFailure;
  const Outcome refused = take_photo(lens_mode, folder, name);
  if (refused != Outcome::kOk) return refused;
  const Outcome card = check_card_for(photo_size_mb(lens_mode, resolution_code));
  if (card != Outcome::kOk) {  // room for a photo at the setting, not at this resolution
    job_.reset();
    return card;
  }
  job_->mode = PhotoMode::kSingle;
  job_->precise = true;
  job_->resolution = resolution_code;
  return Outcome::kOk;
}

Outcome CameraModel::start_recording(uint8_t lens_mode, const std::string& folder,
                                     const std::string& name) {
  if (settings_.capture_mode == CaptureMode::kPhoto)
    return job_ ? Outcome::kPhotoInProgress : Outcome::kFailure;
  if (recording_) return Outcome::kBusy;  // "sending again will not stop recording"
  if (upgrading()) return Outcome::kBusy;
  const Outcome card = check_card_for(video_rate_mb_s(lens_mode));
  if (card != Outcome::kOk) return card;
  RecordingJob job;
  job.record.lens_mode = lens_mode;
  job.record.path = file_path(folder, name, "VID", "mp4", 0);
  recording_ = job;
  announce_recording_ = true;
  return Outcome::kOk;
}

Outcome CameraModel::stop_recording() {
  if (!recording_) return Outcome::kFailure;
  stop_recording_requested_ = true;
  return Outcome::kOk;
}

Outcome CameraModel::format_sd() {
  if (recording_) return Outcome::kRecording;
  if (job_) return Outcome::kPhotoInProgress;
  if (upgrading()) return Outcome::kBusy;
  return sd_.start_format();
}

Outcome CameraModel::start_tf_upgrade() {
  if (!sd_.present()) return Outcome::kNoSdCard;
  if (upgrading()) return Outcome::kBusy;
  if (recording_) return Outcome::kRecording;
  if (job_) return Outcome::kPhotoInProgress;
  upgrade_left_s_ = kTfUpgradeS;
  upgrade_next_report_s_ = 0;
  announce_upgrade_ = true;
  return Outcome::kOk;
}

Outcome CameraModel::set_backlight(bool on, uint8_t value) {
  if (on && visible_.strong_light_on) return Outcome::kFailure;
  visible_.backlight_on = on;
  visible_.backlight_value = value;
  return Outcome::kOk;
}

Outcome CameraModel::set_strong_light(bool on, uint8_t value) {
  if (on && visible_.backlight_on) return Outcome::kFailure;
  visible_.strong_light_on = on;
  visible_.strong_light_value = value;
  return Outcome::kOk;
}

bool CameraModel::attach_gps(uint64_t photo_id, const GpsAnswer& answer) {
  for (PhotoRecord& photo : photos_) {
    if (photo.id == photo_id) {
      photo.gps = answer;
      return true;
    }
  }
  return false;
}

void CameraModel::restore_defaults() {
  settings_ = CameraSettings{};
  visible_ = factory_visible_settings();
}

void CameraModel::abort_activity() {
  job_.reset();
  if (recording_) videos_.push_back(recording_->record);
  recording_.reset();
  stop_recording_requested_ = false;
  upgrade_left_s_ = 0;
}

std::string CameraModel::file_path(const std::string& folder, const std::string& name,
                                   const char* prefix, const char* extension, int index) const {
  std::string base = name.empty() ? std::string(prefix) + "_" + clock_.local_stamp() : name;
  if (index > 0) base += "_" + std::to_string(index);
  return (folder.empty() ? "" : folder + "/") + base + "." + extension;
}

void CameraModel::finish_job(PhotoState state, EventQueue& events) {
  const ShootingJob& job = *job_;
  const bool silent = job.mode == PhotoMode::kSingle && !job.precise &&
                      !config_.single_shot_status && state == PhotoState::kTaken;
  if (!silent) events.push_back(PhotoStatusEvent{job.lens_mode, state, job.taken, job.precise});
  job_.reset();
}

void CameraModel::shoot(ShootingJob& job, EventQueue& events) {
  const double mb = photo_size_mb(job.lens_mode, job.resolution);
  PhotoRecord photo;
  if (job.lens_mode != 1) {  // 1: thermal only
    const PhotoPixels pixels = photo_pixels(job.resolution);
    photo.width_px = pixels.width;
    photo.height_px = pixels.height;
  }
  photo.id = next_photo_id_++;
  const bool numbered = job.mode != PhotoMode::kSingle;
  photo.path = file_path(job.folder, job.name, "IMG", "jpg", numbered ? job.taken + 1 : 0);
  photo.lens_mode = job.lens_mode;
  photo.size_mb = sd_.write(mb);
  photo.taken_utc_ms = clock_.utc_ms();
  // Section 3.2.4.3 note: the pod asks the flight controller for GPS before each photo.
  events.push_back(GpsRequestEvent{photo.id, clock_.utc_time_of_day()});
  photos_.push_back(photo);
  ++job.taken;
}

void CameraModel::step_shooting(double dt_s, bool optics_busy, EventQueue& events) {
  if (!job_) return;
  ShootingJob& job = *job_;
  if (!job.started) {
    job.started = true;
    if (job.precise) {
      events.push_back(PhotoStatusEvent{job.lens_mode, PhotoState::kPreciseReshooting, 0, true});
    } else if (job.mode == PhotoMode::kSingle && config_.single_shot_status) {
      events.push_back(PhotoStatusEvent{job.lens_mode, PhotoState::kSingleInProgress, 0, false});
    }
  }
  if (job.stop_requested) return finish_job(PhotoState::kStopped, events);
  if (job.precise && optics_busy) return;  // the re-shoot waits for the zoom
  job.next_shot_s -= dt_s;
  if (job.next_shot_s > 0) return;

  const int planned = job.mode == PhotoMode::kBurst                       ? settings_.burst_count
                      : job.mode == PhotoMode::kSingle || self_timed(job) ? 1
                                                                          : 0;
  if (planned > 0 && job.taken >= planned) return finish_job(PhotoState::kTaken, events);
  const Outcome card = check_card_for(photo_size_mb(job.lens_mode, job.resolution));
  if (card != Outcome::kOk) return finish_job(photo_state_for(card, sd_.state()), events);
  shoot(job, events);
  switch (job.mode) {
    case PhotoMode::kSingle:
      job.next_shot_s += config_.single_shot_s;
      break;
    case PhotoMode::kBurst:
      events.push_back(
          PhotoStatusEvent{job.lens_mode, PhotoState::kBurstInProgress, job.taken, false});
      job.next_shot_s += config_.burst_interval_s;
      break;
    case PhotoMode::kTimeLapse:
      if (self_timed(job)) break;  // the one photo is taken: the next step finishes the job
      events.push_back(
          PhotoStatusEvent{job.lens_mode, PhotoState::kTimeLapseInProgress, job.taken, false});
      job.next_shot_s += settings_.time_lapse_interval_s;
      break;
  }
}

void CameraModel::step_recording(double dt_s, EventQueue& events) {
  if (!recording_) return;
  VideoRecord& video = recording_->record;
  const auto close = [&](RecordState state) {
    events.push_back(
        RecordStatusEvent{video.lens_mode, state, static_cast<uint16_t>(video.seconds)});
    videos_.push_back(video);
    recording_.reset();
    stop_recording_requested_ = false;
  };
  if (announce_recording_) {
    events.push_back(RecordStatusEvent{video.lens_mode, RecordState::kRecording, 0});
    announce_recording_ = false;
  }
  if (stop_recording_requested_) return close(RecordState::kStopped);
  const double wanted = video_rate_mb_s(video.lens_mode) * dt_s;
  const double written = sd_.write(wanted);
  video.size_mb += written;
  video.seconds += dt_s;
  if (written < wanted * 0.999 || sd_.state() == SdState::kFull)
    return close(record_state_for(sd_.state()));
  if (video.seconds >= recording_->next_status_s) {
    events.push_back(RecordStatusEvent{video.lens_mode, RecordState::kRecording,
                                       static_cast<uint16_t>(video.seconds)});
    recording_->next_status_s += 1.0;
  }
}

void CameraModel::step_upgrade(double dt_s, EventQueue& events) {
  if (!upgrading()) return;
  if (announce_upgrade_) {
    events.push_back(TfUpgradeStatusEvent{TfUpgradeState::kUpgrading});
    announce_upgrade_ = false;
  }
  const double elapsed = kTfUpgradeS - upgrade_left_s_;
  if (elapsed >= upgrade_next_report_s_) {
    events.push_back(
        MaintenanceEvent{MaintenanceState::kUpgrading,
                         static_cast<uint8_t>(std::lround(100 * elapsed / kTfUpgradeS))});
    upgrade_next_report_s_ += 1.0;
  }
  upgrade_left_s_ -= dt_s;
  if (upgrade_left_s_ <= 0) {
    upgrade_left_s_ = 0;
    events.push_back(TfUpgradeStatusEvent{TfUpgradeState::kSucceeded});
    events.push_back(MaintenanceEvent{MaintenanceState::kSucceeded, 100});
  }
}

void CameraModel::step(double dt_s, bool optics_busy, EventQueue& events) {
  clock_.advance(dt_s);
  if (sd_.step(dt_s, events)) {  // a format completed: the card is empty
    photos_.clear();
    videos_.clear();
  }
  step_shooting(dt_s, optics_busy, events);
  step_recording(dt_s, events);
  step_upgrade(dt_s, events);
}

}  // namespace k40t::sim
