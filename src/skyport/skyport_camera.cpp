// The bridge's camera commands (0x04): work mode, photo, photo mode, record, SD card. Sets drive
// the pod from the worker; getters answer on the session thread from the pod's latest state.
#include <algorithm>

#include "k40t_driver/skyport/skyport_bridge.h"

namespace k40t::driver::skyport {

using namespace psdk;
using detail::refused;

namespace {
// CameraStatus constants (msg/CameraStatus.msg), kept here so the core needs no ROS header.
constexpr uint8_t kPhotoSingle = 0, kPhotoBurst = 1, kPhotoTimelapse = 2;
constexpr uint8_t kSdOk = 0, kSdAbnormal = 1, kSdMissing = 3, kSdFull = 4, kSdFormatError = 5;

// The pod checks every field of its photo settings, also those the mode does not use (a burst
// count of 0 is refused for a time-lapse): those keep the pod's current values, or its first valid
// ones before it said.
uint8_t usable_burst(uint8_t count) {
  return count == 3 || count == 5 ? count : 3;
}
uint8_t usable_interval(uint8_t s) {
  return s == 5 || s == 7 || s == 30 || s == 60 ? s : 5;
}
}  // namespace

void SkyportBridge::register_camera() {
  session_.handle<GetCameraCapability>([](const GetCameraCapability&) {
    CameraCapabilityAck ack;
    ack.supported = {true, true, true, true, true};
    return ack;
  });
  deferred<SetCameraWorkMode>([this](const SetCameraWorkMode& c) {
    return pod_code(pod_.set_video_mode(c.mode == CameraWorkMode::kRecordVideo), "work mode");
  });
  from_snapshot<GetCameraWorkMode>(&PodSnapshot::have_camera, [](const PodSnapshot& s) {
    CameraWorkModeAck ack;
    ack.mode = s.video_mode ? CameraWorkMode::kRecordVideo : CameraWorkMode::kShootPhoto;
    return ack;
  });
  deferred<ShootPhoto>([this](const ShootPhoto& c) {
    const bool stop = c.action == ShootPhotoAction::kStop;
    const PodSnapshot before = pod_.snapshot();
    const PodCall call = pod_.take_photo(stop);
    if (stop) return pod_code(call, "stop photo");
    if (!call.ok) return capture_code(call, "shoot photo");
    photo_progress_.started(before, PhotoProgress::Clock::now());
    return pod_code(call, "shoot photo");
  });
  from_snapshot<GetShootPhotoState>(&PodSnapshot::have_camera, [this](const PodSnapshot& s) {
    // The pod reports no state for single shots: what the bridge saw of it (photo_progress.h).
    return photo_progress_.state(s, PhotoProgress::Clock::now());
  });
  // 3.4.5 by its length: a uint8 interval (document) or a uint16 one (DJI's headers, P30).
  deferred_raw<SetShootPhotoMode>(decode_shoot_photo_mode, [this](const ShootPhotoModeWide& c) {
    const PodSnapshot now = pod_.snapshot();
    const uint8_t burst = usable_burst(now.burst_count);
    const uint8_t interval = usable_interval(now.timelapse_interval_s);
    switch (c.type) {
      case ShootPhotoType::kSingle:
        return capture_code(pod_.set_photo_mode(kPhotoSingle, interval, burst), "photo mode");
      case ShootPhotoType::kBurst:
        if (c.burst_count != 3 && c.burst_count != 5)
          return invalid("burst count " + std::to_string(c.burst_count) + ": the pod takes 3 or 5");
        return capture_code(pod_.set_photo_mode(kPhotoBurst, interval, c.burst_count),
                            "photo mode");
      case ShootPhotoType::kInterval:
        // The pod's time-lapse runs until stopped: a count it would not honour is refused, not
        // answered OK and ignored.
        if (c.interval_count != kIntervalShootUntilStopped)
          return invalid("interval count " + std::to_string(c.interval_count) +
                         ": the pod shoots time-lapses until stopped (255 only)");
        if (c.interval_s != 5 && c.interval_s != 7 && c.interval_s != 30 && c.interval_s != 60)
          return invalid("interval " + std::to_string(c.interval_s) +
                         " s: the pod's time-lapse intervals are 5, 7, 30 and 60 s");
        return capture_code(
            pod_.set_photo_mode(kPhotoTimelapse, static_cast<uint8_t>(c.interval_s), burst),
            "photo mode");
    }
    return invalid("shoot photo type " + std::to_string(static_cast<int>(c.type)));
  });
  session_.on_command(
      GetShootPhotoMode::key(), [this](const IncomingCommand&) -> std::optional<Data> {
        const PodSnapshot s = pod_.snapshot();
        if (!s.have_camera) return detail::reply_data(AckCode::kError);
        ShootPhotoModeWide mode;
        if (s.photo_mode == kPhotoBurst) {
          mode.type = ShootPhotoType::kBurst;
          mode.burst_count = s.burst_count;
        } else if (s.photo_mode == kPhotoTimelapse) {
          mode.type = ShootPhotoType::kInterval;
          mode.interval_count = kIntervalShootUntilStopped;
          mode.interval_s = s.timelapse_interval_s;
        }
        const Result<Data> data = encode_shoot_photo_mode_ack(mode, options_.interval_layout);
        return data ? data.value() : detail::reply_data(AckCode::kError);
      });
  deferred<RecordVideo>([this](const RecordVideo& c) {
    return capture_code(pod_.record(c.action == RecordAction::kStart), "record");
  });
  // Unknown while record/status went silent during a recording.
  from_snapshot<GetRecordState>(&PodSnapshot::recording_known, [](const PodSnapshot& s) {
    RecordStateAck ack;
    ack.recording = s.recording;
    ack.duration_s = s.recording ? s.record_duration_s : 0;
    return ack;
  });
  from_snapshot<GetSdCardInfo>(&PodSnapshot::have_camera, [this](const PodSnapshot& s) {
    SdCardInfoAck ack;
    ack.state.inserted = s.sd_state != kSdMissing;
    ack.state.formatted = s.sd_state == kSdOk || s.sd_state == kSdFull;
    ack.state.full = s.sd_state == kSdFull;
    ack.state.invalid_format = s.sd_state == kSdFormatError;
    ack.state.has_error = s.sd_state == kSdAbnormal || s.sd_state == kSdFormatError;
    ack.capacity_mb = static_cast<uint32_t>(std::max(0.0, s.sd_total_mb));
    ack.remaining_mb = static_cast<uint32_t>(std::max(0.0, s.sd_free_mb));
    // Remaining shots and record time: the pod does not say (0). The bits as `sd_card_layout`.
    return sd_card_ack_for(ack, options_.sd_card_layout);
  });
  deferred<FormatSdCard>([this](const FormatSdCard&) {
    return refused<FormatSdCardAck>(capture_code(pod_.format_sd(), "format SD card"));
  });
}

}  // namespace k40t::driver::skyport
